#pragma once
/// \file CaseSchema.hpp
/// \brief The keys a stage accepts in its YAML case file: type, unit, range, default, meaning.
/// One schema per stage is the single source for validation, `--set`, the resolved-case dump and
/// the README key table.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <variant>
#include <vector>

namespace hikiln::cases {

class CaseFile;
class CaseSchema;

/// \brief What a key holds. Choice is a string restricted to KeySpec::choices.
enum class ValueType { Real, Integer, Boolean, String, Choice, RealList };

/// \brief A validated value; the alternative follows ValueType: Real double, Integer int64_t,
/// Boolean bool, String and Choice std::string, RealList std::vector<double>.
using Value = std::variant<double, std::int64_t, bool, std::string, std::vector<double>>;

/// \brief Human name of a type ("real", "integer", "list of reals", ...).
std::string typeName(ValueType type);

/// \brief Which ends of KeyBuilder::range() are excluded: Closed = [a, b], OpenMin = (a, b],
/// OpenMax = [a, b), Open = (a, b).
enum class Bounds { Closed, OpenMin, OpenMax, Open };

/// \brief One case-file key. Bounds apply to Real, Integer and each RealList item.
struct KeySpec {
  std::string key; ///< dotted path, e.g. "drum.diameter"
  ValueType type = ValueType::Real;
  std::optional<double> min, max;
  bool minExclusive = false, maxExclusive = false;
  std::vector<std::string> choices; ///< allowed values of a Choice key
  std::string defaultValue;         ///< YAML text; empty = the key is required
  std::string unit;                 ///< e.g. "m", "1/s"; empty for dimensionless or non-numeric
  std::string doc;                  ///< one-line meaning
  std::size_t minItems = 0;         ///< RealList length bounds
  std::optional<std::size_t> maxItems;

  /// \brief True when the case file must give this key (no default).
  bool required() const { return defaultValue.empty(); }
};

/// \brief Fluent editor of one KeySpec inside a schema, returned by CaseSchema::real() etc.:
/// `schema.real("drum.diameter").unit("m").positive().defaultsTo("2.0").doc("Drum inner
/// diameter");` Keep it only for the statement that created it.
class KeyBuilder {
public:
  /// \brief Sets the unit shown in messages, the resolved case and the reference table.
  KeyBuilder& unit(std::string text);
  /// \brief Sets the one-line meaning.
  KeyBuilder& doc(std::string text);
  /// \brief Makes the key optional with this default, written as YAML ("2.0", "[0, 0, -9.81]").
  KeyBuilder& defaultsTo(std::string yamlText);
  /// \brief Value must lie between lo and hi; an infinite end means unbounded on that side.
  KeyBuilder& range(double lo, double hi, Bounds bounds = Bounds::Closed);
  /// \brief Value must be > 0.
  KeyBuilder& positive() { return above(0.0); }
  /// \brief Value must be >= 0.
  KeyBuilder& nonNegative() { return atLeast(0.0); }
  /// \brief Value must be >= lo.
  KeyBuilder& atLeast(double lo);
  /// \brief Value must be > lo.
  KeyBuilder& above(double lo);
  /// \brief Value must be <= hi.
  KeyBuilder& atMost(double hi);
  /// \brief Value must be < hi.
  KeyBuilder& below(double hi);
  /// \brief A RealList must have exactly `count` items.
  KeyBuilder& items(std::size_t count) { return items(count, count); }
  /// \brief A RealList must have between minCount and maxCount items.
  KeyBuilder& items(std::size_t minCount, std::size_t maxCount);
  /// \brief The spec as edited so far.
  const KeySpec& spec() const;

private:
  friend class CaseSchema;
  KeyBuilder(CaseSchema& schema, std::size_t index) : _schema(&schema), _index(index) {}
  KeySpec& edit();

  CaseSchema* _schema;
  std::size_t _index;
};

/// \brief The keys of one stage's case file plus cross-key checks run after per-key validation.
class CaseSchema {
public:
  /// \brief A check that needs several keys; `run` throws (any std::exception) to reject a case.
  struct Check {
    std::string what;
    std::function<void(const CaseFile&)> run;
  };

  /// \brief Empty schema named after its stage ("dem", "continuum").
  explicit CaseSchema(std::string name) : _name(std::move(name)) {}

  /// \brief The stage name.
  const std::string& name() const { return _name; }

  /// \brief Adds a key; throws std::logic_error for a malformed or duplicate key, or one that
  /// collides with a section ("drum" next to "drum.diameter").
  KeyBuilder add(KeySpec spec);
  /// \brief Adds a real-number key.
  KeyBuilder real(const std::string& key) { return add(makeSpec(key, ValueType::Real)); }
  /// \brief Adds a 64-bit integer key.
  KeyBuilder integer(const std::string& key) { return add(makeSpec(key, ValueType::Integer)); }
  /// \brief Adds a true/false key.
  KeyBuilder boolean(const std::string& key) { return add(makeSpec(key, ValueType::Boolean)); }
  /// \brief Adds a free-text key.
  KeyBuilder string(const std::string& key) { return add(makeSpec(key, ValueType::String)); }
  /// \brief Adds a key restricted to one of `choices`.
  KeyBuilder choice(const std::string& key, std::vector<std::string> choices);
  /// \brief Adds a list-of-reals key (vectors, tables).
  KeyBuilder realList(const std::string& key) { return add(makeSpec(key, ValueType::RealList)); }

  /// \brief The spec of `key`, or nullptr.
  const KeySpec* find(const std::string& key) const;
  /// \brief Position of `key` in schema order, or nullopt.
  std::optional<std::size_t> indexOf(const std::string& key) const;
  /// \brief All specs in the order they were added.
  const std::vector<KeySpec>& specs() const { return _specs; }
  /// \brief All keys in the order they were added.
  std::vector<std::string> keys() const;
  /// \brief True if `path` is a proper prefix of some key ("drum" for "drum.diameter").
  bool isSection(const std::string& path) const { return _sections.count(path) != 0; }

  /// \brief The key closest to a misspelt one (edit distance over the full dotted path and over
  /// the last component), or "" when nothing is close enough to be a plausible typo.
  std::string nearestKey(const std::string& key) const;

  /// \brief Registers a cross-key check; `what` states the rule and prefixes its failure message.
  /// The check rejects a case by throwing (std::runtime_error or any other std::exception); a plain
  /// std::logic_error, which CaseFile's accessors throw for misuse, propagates as the bug it is.
  void addCheck(std::string what, std::function<void(const CaseFile&)> check);
  /// \brief Registers a cross-key rule that holds when `predicate` returns true.
  void require(std::string what, std::function<bool(const CaseFile&)> predicate);
  /// \brief The registered checks, in order.
  const std::vector<Check>& checks() const { return _checks; }

  /// \brief Throws std::logic_error if the schema itself is inconsistent (a default that fails its
  /// own validation, a Choice without choices, min > max). CaseFile calls it before loading.
  void validate() const;

  /// \brief Markdown table `key | type | default | unit | range | meaning`, then the cross-key
  /// rules, for the README.
  std::string markdownReference() const;

private:
  friend class KeyBuilder;
  static KeySpec makeSpec(const std::string& key, ValueType type);

  std::string _name;
  std::vector<KeySpec> _specs;
  std::map<std::string, std::size_t> _index;
  std::set<std::string> _sections;
  std::vector<Check> _checks;
};

} // namespace hikiln::cases
