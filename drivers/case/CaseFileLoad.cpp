/// \file CaseFileLoad.cpp
/// \brief CaseFile::fromString: walks the YAML tree against the schema, applies `--set`, fills
/// defaults, runs cross-key checks, and gathers every problem before throwing.

#include "drivers/case/CaseFile.hpp"

#include "drivers/case/CaseValue.hpp"

#include <map>
#include <optional>
#include <typeinfo>

namespace hikiln::cases {

namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
    return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// Collects values and errors from the file and the overrides, in schema order.
class Resolver {
public:
  Resolver(const CaseSchema& schema, std::string source)
      : _schema(schema), _source(std::move(source)), _fromFile(schema.specs().size()),
        _fromOverride(schema.specs().size()), _givenInFile(schema.specs().size(), false) {}

  /// "file:line:col" with 1-based numbers, or just "file" when the position is unknown.
  std::string at(const YAML::Mark& mark) const {
    if (mark.is_null())
      return _source;
    return _source + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
  }

  void error(std::string message) { _errors.push_back(std::move(message)); }
  const std::vector<std::string>& errors() const { return _errors; }

  /// Parses the text into `root` (left null for an empty file); false, with the error recorded,
  /// when the text cannot be read as a case at all.
  bool parse(const std::string& text, YAML::Node& root) {
    std::vector<YAML::Node> documents;
    try {
      documents = YAML::LoadAll(text);
    } catch (const YAML::Exception& e) {
      error(at(e.mark) + ": malformed YAML: " + e.msg);
      return false;
    }
    if (documents.size() > 1)
      error(at(documents[1].Mark()) + ": a case file holds one YAML document, found " +
            std::to_string(documents.size()));
    if (documents.empty() || documents[0].IsNull())
      return true; // an empty file is a valid case when every key has a default
    root = documents[0];
    if (!root.IsMap()) {
      error(at(root.Mark()) + ": a case file must be a map of keys (such as 'drum: {diameter: " +
            "2.0}'), got " + (root.IsSequence() ? "a list" : "'" + root.Scalar() + "'"));
      return false;
    }
    return true;
  }

  void walk(const YAML::Node& map, const std::string& prefix) {
    for (auto it = map.begin(); it != map.end(); ++it) {
      const YAML::Node keyNode = it->first;
      const YAML::Node value = it->second;
      if (!keyNode.IsScalar()) {
        error(at(keyNode.Mark()) + ": keys must be plain names" +
              (prefix.empty() ? "" : " (in '" + prefix + "')"));
        continue;
      }
      const std::string path = prefix.empty() ? keyNode.Scalar() : prefix + "." + keyNode.Scalar();
      // yaml-cpp keeps repeated keys as separate pairs, so duplicates are caught here, including
      // "drum: {rpm: 1}" next to "drum.rpm: 2".
      if (const auto seen = _firstSeen.find(path); seen != _firstSeen.end()) {
        error(at(keyNode.Mark()) + ": duplicate key '" + path + "' (first given at line " +
              std::to_string(seen->second.line + 1) + ")");
        continue;
      }
      _firstSeen.emplace(path, keyNode.Mark());

      if (const auto index = _schema.indexOf(path)) {
        _givenInFile[*index] = true;
        auto conversion = detail::convertValue(_schema.specs()[*index], value);
        if (conversion.value)
          _fromFile[*index] = std::move(conversion.value);
        else
          error(at(conversion.mark.is_null() ? keyNode.Mark() : conversion.mark) + ": " +
                conversion.error);
      } else if (_schema.isSection(path)) {
        if (value.IsMap())
          walk(value, path);
        else if (!value.IsNull()) // "drum:" with nothing under it is an empty section
          error(at(value.Mark()) + ": '" + path + "' must be a map of keys such as '" +
                firstKeyUnder(path) + "', got " +
                (value.IsSequence() ? "a list" : "'" + value.Scalar() + "'"));
      } else {
        error(at(keyNode.Mark()) + ": " + unknownKey(path));
      }
    }
  }

  void applyOverride(const std::string& text) {
    const std::string label = "--set " + text;
    const auto equals = text.find('=');
    if (equals == std::string::npos) {
      error(label + ": expected dotted.key=value");
      return;
    }
    const std::string key = trim(text.substr(0, equals));
    const auto index = _schema.indexOf(key);
    if (!index) {
      error(label + ": " +
            (_schema.isSection(key) ? "'" + key + "' is a section; set one of its keys, such as '" +
                                          firstKeyUnder(key) + "'"
                                    : unknownKey(key)));
      return;
    }
    YAML::Node value;
    try {
      value = YAML::Load(text.substr(equals + 1));
    } catch (const YAML::Exception& e) {
      error(label + ": malformed YAML value: " + e.msg);
      return;
    }
    auto conversion = detail::convertValue(_schema.specs()[*index], value);
    if (conversion.value)
      _fromOverride[*index] = std::move(conversion.value); // a later --set of the same key wins
    else
      error(label + ": " + conversion.error);
  }

  /// Final values in schema order: --set, else file, else default; records missing keys.
  void resolve(std::vector<Value>& values, std::vector<CaseFile::Origin>& origins) {
    const auto& specs = _schema.specs();
    for (std::size_t i = 0; i < specs.size(); ++i) {
      if (_fromOverride[i]) {
        values.push_back(*_fromOverride[i]);
        origins.push_back(CaseFile::Origin::Override);
      } else if (_fromFile[i]) {
        values.push_back(*_fromFile[i]);
        origins.push_back(CaseFile::Origin::File);
      } else if (!specs[i].required()) {
        // CaseSchema::validate() has already proven the default converts.
        values.push_back(*detail::convertValue(specs[i], YAML::Load(specs[i].defaultValue)).value);
        origins.push_back(CaseFile::Origin::Default);
      } else if (!_givenInFile[i]) { // given but invalid: already reported
        const std::string meaning = detail::describeMeaning(specs[i]);
        error(_source + ": missing required key '" + specs[i].key + "'" +
              (meaning.empty() ? "" : " " + meaning));
      }
    }
  }

private:
  std::string unknownKey(const std::string& path) const {
    const std::string suggestion = _schema.nearestKey(path);
    return "unknown key '" + path + "'" +
           (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)");
  }

  std::string firstKeyUnder(const std::string& section) const {
    for (const auto& spec : _schema.specs())
      if (spec.key.compare(0, section.size() + 1, section + ".") == 0)
        return spec.key;
    return section;
  }

  const CaseSchema& _schema;
  std::string _source;
  std::vector<std::optional<Value>> _fromFile;
  std::vector<std::optional<Value>> _fromOverride;
  std::vector<bool> _givenInFile;
  std::map<std::string, YAML::Mark> _firstSeen;
  std::vector<std::string> _errors;
};

} // namespace

CaseFile CaseFile::fromString(const std::string& yamlText, const std::string& sourceName,
                              const CaseSchema& schema, const std::vector<std::string>& overrides) {
  schema.validate();
  Resolver resolver(schema, sourceName);
  YAML::Node root;
  if (!resolver.parse(yamlText, root)) // nothing read: "missing key" messages would be noise
    throw CaseError(resolver.errors());
  if (root.IsMap())
    resolver.walk(root, "");
  for (const auto& text : overrides)
    resolver.applyOverride(text);
  std::vector<Value> values;
  std::vector<Origin> origins;
  resolver.resolve(values, origins);
  if (!resolver.errors().empty())
    throw CaseError(resolver.errors());

  CaseFile result(schema, sourceName, overrides, std::move(values), std::move(origins));
  std::vector<std::string> failures;
  for (const auto& check : schema.checks()) {
    try {
      check.run(result);
    } catch (const detail::RuleViolated&) {
      failures.push_back(sourceName + ": check failed: " + check.what);
    } catch (const std::exception& e) {
      if (typeid(e) == typeid(std::logic_error))
        throw; // accessor misuse inside the check: a bug, not a bad case
      failures.push_back(sourceName + ": check failed: " + check.what + ": " + e.what());
    }
  }
  if (!failures.empty())
    throw CaseError(std::move(failures));
  return result;
}

} // namespace hikiln::cases
