#include "drivers/case/CaseSchema.hpp"

#include "drivers/case/CaseValue.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace hikiln::cases {

namespace {

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string lastComponent(const std::string& key) {
  const auto dot = key.rfind('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

/// Edits a typo of this length may plausibly contain; short words need an exact-ish match or
/// every one-letter key would "suggest" every other.
std::size_t typoBudget(std::size_t length) {
  if (length <= 2)
    return 0;
  if (length <= 5)
    return 1;
  return length / 3;
}

bool validComponent(const std::string& part) {
  if (part.empty())
    return false;
  return std::all_of(part.begin(), part.end(),
                     [](unsigned char c) { return std::isalnum(c) != 0 || c == '_' || c == '-'; });
}

std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

std::string markdownType(const KeySpec& spec) {
  if (spec.type != ValueType::Choice)
    return typeName(spec.type);
  std::string list;
  for (const auto& c : spec.choices)
    list += (list.empty() ? "`" : ", `") + c + "`";
  return "one of " + list;
}

std::string markdownRange(const KeySpec& spec) {
  std::string range = detail::describeRange(spec);
  if (spec.type != ValueType::RealList)
    return range;
  if (!range.empty())
    range = "each " + range;
  std::string length;
  if (spec.maxItems && *spec.maxItems == spec.minItems)
    length = std::to_string(spec.minItems) + " items";
  else if (spec.maxItems)
    length = std::to_string(spec.minItems) + " to " + std::to_string(*spec.maxItems) + " items";
  else if (spec.minItems > 0)
    length = "at least " + std::to_string(spec.minItems) + " items";
  if (!range.empty() && !length.empty())
    return range + "; " + length;
  return range + length;
}

} // namespace

std::string typeName(ValueType type) {
  switch (type) {
  case ValueType::Real:
    return "real";
  case ValueType::Integer:
    return "integer";
  case ValueType::Boolean:
    return "boolean";
  case ValueType::String:
    return "string";
  case ValueType::Choice:
    return "choice";
  case ValueType::RealList:
    return "list of reals";
  }
  return "unknown";
}

// ---- KeyBuilder -------------------------------------------------------------------------------

KeySpec& KeyBuilder::edit() {
  return _schema->_specs[_index];
}

const KeySpec& KeyBuilder::spec() const {
  return _schema->_specs[_index];
}

KeyBuilder& KeyBuilder::unit(std::string text) {
  edit().unit = std::move(text);
  return *this;
}

KeyBuilder& KeyBuilder::doc(std::string text) {
  edit().doc = std::move(text);
  return *this;
}

KeyBuilder& KeyBuilder::defaultsTo(std::string yamlText) {
  edit().defaultValue = std::move(yamlText);
  return *this;
}

KeyBuilder& KeyBuilder::range(double lo, double hi, Bounds bounds) {
  KeySpec& s = edit();
  s.min = std::isinf(lo) && lo < 0 ? std::nullopt : std::optional<double>(lo);
  s.max = std::isinf(hi) && hi > 0 ? std::nullopt : std::optional<double>(hi);
  s.minExclusive = bounds == Bounds::OpenMin || bounds == Bounds::Open;
  s.maxExclusive = bounds == Bounds::OpenMax || bounds == Bounds::Open;
  return *this;
}

KeyBuilder& KeyBuilder::atLeast(double lo) {
  edit().min = lo;
  edit().minExclusive = false;
  return *this;
}

KeyBuilder& KeyBuilder::above(double lo) {
  edit().min = lo;
  edit().minExclusive = true;
  return *this;
}

KeyBuilder& KeyBuilder::atMost(double hi) {
  edit().max = hi;
  edit().maxExclusive = false;
  return *this;
}

KeyBuilder& KeyBuilder::below(double hi) {
  edit().max = hi;
  edit().maxExclusive = true;
  return *this;
}

KeyBuilder& KeyBuilder::items(std::size_t minCount, std::size_t maxCount) {
  edit().minItems = minCount;
  edit().maxItems = maxCount;
  return *this;
}

// ---- CaseSchema -------------------------------------------------------------------------------

KeySpec CaseSchema::makeSpec(const std::string& key, ValueType type) {
  KeySpec spec;
  spec.key = key;
  spec.type = type;
  return spec;
}

KeyBuilder CaseSchema::choice(const std::string& key, std::vector<std::string> choices) {
  KeySpec spec = makeSpec(key, ValueType::Choice);
  spec.choices = std::move(choices);
  return add(std::move(spec));
}

KeyBuilder CaseSchema::add(KeySpec spec) {
  const std::string where = "schema '" + _name + "': key '" + spec.key + "'";
  std::vector<std::string> prefixes;
  std::size_t start = 0;
  while (true) {
    const auto dot = spec.key.find('.', start);
    if (!validComponent(spec.key.substr(start, dot == std::string::npos ? dot : dot - start)))
      throw std::logic_error(where + ": components must be non-empty [A-Za-z0-9_-]");
    if (dot == std::string::npos)
      break;
    prefixes.push_back(spec.key.substr(0, dot));
    start = dot + 1;
  }
  if (_index.count(spec.key) != 0)
    throw std::logic_error(where + " is declared twice");
  if (_sections.count(spec.key) != 0)
    throw std::logic_error(where + " is already a section of other keys");
  for (const auto& prefix : prefixes)
    if (_index.count(prefix) != 0)
      throw std::logic_error(where + " lies inside key '" + prefix + "'");

  _sections.insert(prefixes.begin(), prefixes.end());
  _index.emplace(spec.key, _specs.size());
  _specs.push_back(std::move(spec));
  return KeyBuilder(*this, _specs.size() - 1);
}

const KeySpec* CaseSchema::find(const std::string& key) const {
  const auto it = _index.find(key);
  return it == _index.end() ? nullptr : &_specs[it->second];
}

std::optional<std::size_t> CaseSchema::indexOf(const std::string& key) const {
  const auto it = _index.find(key);
  return it == _index.end() ? std::nullopt : std::optional<std::size_t>(it->second);
}

std::vector<std::string> CaseSchema::keys() const {
  std::vector<std::string> result;
  result.reserve(_specs.size());
  for (const auto& s : _specs)
    result.push_back(s.key);
  return result;
}

std::string CaseSchema::nearestKey(const std::string& key) const {
  // Candidates are keys and sections, so a misspelt section ("drm:") is also caught.
  std::vector<std::string> candidates = keys();
  candidates.insert(candidates.end(), _sections.begin(), _sections.end());
  const std::string queryLast = lastComponent(key);
  std::string best;
  std::pair<std::size_t, std::size_t> bestScore{SIZE_MAX, SIZE_MAX};
  for (const auto& candidate : candidates) {
    const std::size_t full = editDistance(key, candidate);
    const std::size_t last = editDistance(queryLast, lastComponent(candidate));
    const bool plausible = full <= typoBudget(key.size()) || last <= typoBudget(queryLast.size());
    // Prefer the smaller of the two distances, then the closer full path ("diameter" at top
    // level matches both drum.diameter and particles.diameter by its last component).
    const std::pair<std::size_t, std::size_t> score{std::min(full, last), full};
    if (plausible && score < bestScore) {
      bestScore = score;
      best = candidate;
    }
  }
  return best;
}

void CaseSchema::addCheck(std::string what, std::function<void(const CaseFile&)> check) {
  _checks.push_back(Check{std::move(what), std::move(check)});
}

void CaseSchema::require(std::string what, std::function<bool(const CaseFile&)> predicate) {
  // The rule text is the whole message, so the check throws without a reason of its own.
  auto check = [predicate = std::move(predicate)](const CaseFile& c) {
    if (!predicate(c))
      throw detail::RuleViolated();
  };
  _checks.push_back(Check{std::move(what), std::move(check)});
}

void CaseSchema::validate() const {
  for (const auto& spec : _specs) {
    const std::string where = "schema '" + _name + "': key '" + spec.key + "'";
    const bool numeric = spec.type == ValueType::Real || spec.type == ValueType::Integer ||
                         spec.type == ValueType::RealList;
    if (!numeric && (spec.min || spec.max))
      throw std::logic_error(where + ": a range only applies to numbers");
    if (spec.type == ValueType::Choice && spec.choices.empty())
      throw std::logic_error(where + ": a choice needs at least one allowed value");
    if (spec.min && spec.max &&
        (*spec.min > *spec.max ||
         (*spec.min == *spec.max && (spec.minExclusive || spec.maxExclusive))))
      throw std::logic_error(where + ": empty range " + detail::describeRange(spec));
    if (spec.maxItems && *spec.maxItems < spec.minItems)
      throw std::logic_error(where + ": maximum list length below minimum");
    if (spec.required())
      continue;
    YAML::Node node;
    try {
      node = YAML::Load(spec.defaultValue);
    } catch (const YAML::Exception& e) {
      throw std::logic_error(where + ": default '" + spec.defaultValue +
                             "' is not valid YAML: " + e.msg);
    }
    const auto conversion = detail::convertValue(spec, node);
    if (!conversion.value)
      throw std::logic_error(where + ": default '" + spec.defaultValue +
                             "' is invalid: " + conversion.error);
  }
}

std::string CaseSchema::markdownReference() const {
  std::string out = "| key | type | default | unit | range | meaning |\n"
                    "|-----|------|---------|------|-------|---------|\n";
  for (const auto& spec : _specs) {
    const std::string defaultText =
        spec.required() ? "**required**" : "`" + cell(spec.defaultValue) + "`";
    out += "| `" + spec.key + "` | " + cell(markdownType(spec)) + " | " + defaultText + " | " +
           cell(spec.unit) + " | " + cell(markdownRange(spec)) + " | " + cell(spec.doc) + " |\n";
  }
  if (!_checks.empty()) {
    out += "\nRules that involve several keys:\n\n";
    for (const auto& check : _checks)
      out += "- " + check.what + "\n";
  }
  return out;
}

} // namespace hikiln::cases
