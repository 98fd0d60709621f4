#include "drivers/case/CaseValue.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

namespace hikiln::cases::detail {

namespace {

/// Quoted scalars are strings in YAML; a number or boolean must be written plain.
bool isQuoted(const YAML::Node& node) {
  return node.Tag() == "!" || node.Tag() == "tag:yaml.org,2002:str";
}

/// What the user wrote, shortened so one bad value cannot flood the message.
std::string describeNode(const YAML::Node& node) {
  switch (node.Type()) {
  case YAML::NodeType::Map:
    return "a map";
  case YAML::NodeType::Sequence:
    return "a list";
  case YAML::NodeType::Scalar: {
    std::string text = node.Scalar();
    if (text.size() > 40)
      text = text.substr(0, 37) + "...";
    return (isQuoted(node) ? "the quoted string '" : "'") + text + "'";
  }
  default:
    return "nothing";
  }
}

std::string expected(const KeySpec& spec) {
  switch (spec.type) {
  case ValueType::Real:
    return "a real number";
  case ValueType::Integer:
    return "an integer";
  case ValueType::Boolean:
    return "true or false";
  case ValueType::String:
    return "a string";
  case ValueType::Choice: {
    std::string list;
    for (const auto& c : spec.choices)
      list += (list.empty() ? "'" : ", '") + c + "'";
    return "one of " + list;
  }
  case ValueType::RealList:
    return "a list of real numbers such as [1.0, 2.0]";
  }
  return "a value";
}

/// YAML 1.2 core-schema decimal: [-+]? (digits [. digits?] | . digits) ([eE] [-+]? digits)?
bool isDecimal(const std::string& text, bool& isInteger) {
  std::size_t i = 0;
  const std::size_t n = text.size();
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < n && std::isdigit(static_cast<unsigned char>(text[i])))
      ++i;
    return i - start;
  };
  if (i < n && (text[i] == '+' || text[i] == '-'))
    ++i;
  std::size_t mantissaDigits = digits();
  isInteger = true;
  if (i < n && text[i] == '.') {
    ++i;
    mantissaDigits += digits();
    isInteger = false;
  }
  if (mantissaDigits == 0)
    return false;
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < n && (text[i] == '+' || text[i] == '-'))
      ++i;
    if (digits() == 0)
      return false;
    isInteger = false;
  }
  return i == n;
}

bool isNonFiniteSpelling(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (!text.empty() && (text[0] == '+' || text[0] == '-'))
    text.erase(0, 1);
  if (!text.empty() && text[0] == '.')
    text.erase(0, 1);
  return text == "nan" || text == "inf" || text == "infinity";
}

/// from_chars takes no leading '+'.
std::string withoutPlus(const std::string& text) {
  return (!text.empty() && text[0] == '+') ? text.substr(1) : text;
}

std::string rangeForMessage(const KeySpec& spec) {
  const std::string range = describeRange(spec);
  return (!range.empty() && (range[0] == '(' || range[0] == '[')) ? "in " + range : range;
}

bool inRange(const KeySpec& spec, double x) {
  if (spec.min && (spec.minExclusive ? !(x > *spec.min) : !(x >= *spec.min)))
    return false;
  if (spec.max && (spec.maxExclusive ? !(x < *spec.max) : !(x <= *spec.max)))
    return false;
  return true;
}

/// Empty string when `x` is allowed, else the reason. `subject` is "'key'" or "'key' item 3".
std::string rangeError(const KeySpec& spec, double x, const std::string& subject,
                       const std::string& text) {
  if (inRange(spec, x))
    return {};
  const std::string meaning = describeMeaning(spec);
  return subject + " = " + text + " is out of range: must be " + rangeForMessage(spec) +
         (meaning.empty() ? "" : " " + meaning);
}

/// Parses a real scalar; on failure returns nullopt and sets `error`.
std::optional<double> parseReal(const YAML::Node& node, const std::string& subject,
                                std::string& error) {
  const std::string got = describeNode(node);
  if (!node.IsScalar()) {
    error = subject + " must be a real number, got " + got;
    return std::nullopt;
  }
  const std::string& text = node.Scalar();
  bool isInteger = false;
  if (isQuoted(node)) {
    error = subject + " must be a real number, got " + got + " (remove the quotes)";
    return std::nullopt;
  }
  if (isNonFiniteSpelling(text)) {
    error = subject + " must be a finite real number, got " + got;
    return std::nullopt;
  }
  if (!isDecimal(text, isInteger)) {
    error = subject + " must be a real number, got " + got;
    return std::nullopt;
  }
  const std::string digits = withoutPlus(text);
  double x = 0.0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), x);
  if (result.ec != std::errc() || !std::isfinite(x)) {
    error = subject + " = " + text + " cannot be represented as a double";
    return std::nullopt;
  }
  return x;
}

Conversion fail(std::string error, const YAML::Node& node) {
  return Conversion{std::nullopt, std::move(error), node.Mark()};
}

Conversion convertReal(const KeySpec& spec, const YAML::Node& node, const std::string& subject) {
  std::string error;
  const auto x = parseReal(node, subject, error);
  if (!x)
    return fail(error, node);
  if (auto bad = rangeError(spec, *x, subject, node.Scalar()); !bad.empty())
    return fail(bad, node);
  return Conversion{Value(*x), {}, node.Mark()};
}

Conversion convertInteger(const KeySpec& spec, const YAML::Node& node, const std::string& subject) {
  const std::string got = describeNode(node);
  bool isInteger = false;
  if (!node.IsScalar() || isQuoted(node) || !isDecimal(node.Scalar(), isInteger) || !isInteger)
    return fail(subject + " must be an integer, got " + got, node);
  const std::string digits = withoutPlus(node.Scalar());
  std::int64_t i = 0;
  const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), i);
  if (result.ec != std::errc())
    return fail(subject + " = " + node.Scalar() + " does not fit in a 64-bit integer", node);
  if (auto bad = rangeError(spec, static_cast<double>(i), subject, node.Scalar()); !bad.empty())
    return fail(bad, node);
  return Conversion{Value(i), {}, node.Mark()};
}

Conversion convertBoolean(const YAML::Node& node, const std::string& subject) {
  // YAML 1.2 core schema only: yes/no/on/off are YAML 1.1 and a classic source of surprises.
  static const char* const trueSpellings[] = {"true", "True", "TRUE"};
  static const char* const falseSpellings[] = {"false", "False", "FALSE"};
  if (node.IsScalar() && !isQuoted(node)) {
    for (const char* t : trueSpellings)
      if (node.Scalar() == t)
        return Conversion{Value(true), {}, node.Mark()};
    for (const char* f : falseSpellings)
      if (node.Scalar() == f)
        return Conversion{Value(false), {}, node.Mark()};
  }
  return fail(subject + " must be true or false, got " + describeNode(node), node);
}

Conversion convertText(const KeySpec& spec, const YAML::Node& node, const std::string& subject) {
  if (!node.IsScalar())
    return fail(subject + " must be " + expected(spec) + ", got " + describeNode(node), node);
  const std::string& text = node.Scalar();
  if (spec.type == ValueType::Choice &&
      std::find(spec.choices.begin(), spec.choices.end(), text) == spec.choices.end())
    return fail(subject + " must be " + expected(spec) + ", got " + describeNode(node), node);
  return Conversion{Value(text), {}, node.Mark()};
}

Conversion convertRealList(const KeySpec& spec, const YAML::Node& node,
                           const std::string& subject) {
  if (!node.IsSequence())
    return fail(subject + " must be " + expected(spec) + ", got " + describeNode(node), node);
  const std::size_t n = node.size();
  if (n < spec.minItems || (spec.maxItems && n > *spec.maxItems)) {
    const std::string want = (spec.maxItems && *spec.maxItems == spec.minItems)
                                 ? fmt::format("exactly {}", spec.minItems)
                             : spec.maxItems
                                 ? fmt::format("between {} and {}", spec.minItems, *spec.maxItems)
                                 : fmt::format("at least {}", spec.minItems);
    return fail(fmt::format("{} must have {} items, got {}", subject, want, n), node);
  }
  std::vector<double> values;
  values.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const YAML::Node item = node[i];
    const std::string itemSubject = fmt::format("{} item {}", subject, i + 1);
    std::string error;
    const auto x = parseReal(item, itemSubject, error);
    if (!x)
      return fail(error, item);
    if (auto bad = rangeError(spec, *x, itemSubject, item.Scalar()); !bad.empty())
      return fail(bad, item);
    values.push_back(*x);
  }
  return Conversion{Value(std::move(values)), {}, node.Mark()};
}

std::string quoteString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (u < 0x20 || u == 0x7f)
      out += fmt::format("\\x{:02x}", u);
    else
      out += c;
  }
  return out + "\"";
}

} // namespace

Conversion convertValue(const KeySpec& spec, const YAML::Node& node) {
  const std::string subject = "'" + spec.key + "'";
  if (!node.IsDefined() || node.IsNull()) // yaml-cpp gives null nodes a misleading position
    return Conversion{std::nullopt, subject + " has no value (expected " + expected(spec) + ")",
                      YAML::Mark::null_mark()};
  switch (spec.type) {
  case ValueType::Real:
    return convertReal(spec, node, subject);
  case ValueType::Integer:
    return convertInteger(spec, node, subject);
  case ValueType::Boolean:
    return convertBoolean(node, subject);
  case ValueType::String:
  case ValueType::Choice:
    return convertText(spec, node, subject);
  case ValueType::RealList:
    return convertRealList(spec, node, subject);
  }
  return fail(subject + " has an unknown type", node);
}

std::string formatReal(double x) {
  std::string text = fmt::format("{}", x);
  if (text.find_first_of(".eEn") == std::string::npos)
    text += ".0";
  return text;
}

std::string formatValue(const Value& value) {
  struct Formatter {
    std::string operator()(double x) const { return formatReal(x); }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(const std::string& s) const { return quoteString(s); }
    std::string operator()(const std::vector<double>& list) const {
      std::string out = "[";
      for (std::size_t i = 0; i < list.size(); ++i)
        out += (i == 0 ? "" : ", ") + formatReal(list[i]);
      return out + "]";
    }
  };
  return std::visit(Formatter{}, value);
}

std::string describeRange(const KeySpec& spec) {
  if (spec.min && spec.max)
    return fmt::format("{}{}, {}{}", spec.minExclusive ? '(' : '[', *spec.min, *spec.max,
                       spec.maxExclusive ? ')' : ']');
  if (spec.min)
    return fmt::format("{} {}", spec.minExclusive ? ">" : ">=", *spec.min);
  if (spec.max)
    return fmt::format("{} {}", spec.maxExclusive ? "<" : "<=", *spec.max);
  return {};
}

std::string describeMeaning(const KeySpec& spec) {
  if (spec.doc.empty() && spec.unit.empty())
    return {};
  if (spec.unit.empty())
    return "(" + spec.doc + ")";
  return "(" + spec.doc + (spec.doc.empty() ? "[" : " [") + spec.unit + "])";
}

} // namespace hikiln::cases::detail
