#pragma once
/// \file CaseFile.hpp
/// \brief A stage's YAML case file after validation against its CaseSchema, with `--set`
/// overrides applied and defaults filled in.

#include "drivers/case/CaseError.hpp"
#include "drivers/case/CaseSchema.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hikiln::cases {

/// \brief Validated, fully resolved case: every schema key has a value. Loading reports all
/// problems of a file at once as one CaseError ("file:line:col: reason" per line).
class CaseFile {
public:
  /// \brief Where a key's final value came from.
  enum class Origin { Default, File, Override };

  /// \brief Reads and validates `path`; `overrides` are "dotted.key=value" texts from `--set`
  /// (the value is YAML) and win over the file. Throws CaseError.
  static CaseFile load(const std::string& path, const CaseSchema& schema,
                       const std::vector<std::string>& overrides = {});

  /// \brief As load(), from text; `sourceName` stands for the file in messages.
  static CaseFile fromString(const std::string& yamlText, const std::string& sourceName,
                             const CaseSchema& schema,
                             const std::vector<std::string>& overrides = {});

  /// \brief Value of a Real key. Throws std::logic_error for a key not in the schema or of
  /// another type (a programming error, not a user one); so do the other accessors.
  double real(const std::string& key) const;
  /// \brief Value of an Integer key.
  std::int64_t integer(const std::string& key) const;
  /// \brief Value of a Boolean key.
  bool boolean(const std::string& key) const;
  /// \brief Value of a String or Choice key.
  const std::string& string(const std::string& key) const;
  /// \brief Value of a RealList key.
  const std::vector<double>& realList(const std::string& key) const;
  /// \brief Whether `key` was given by the file, by `--set`, or left at its default.
  Origin origin(const std::string& key) const;

  /// \brief Every schema key with its final value as nested YAML in schema order, each with a
  /// comment giving unit, meaning and origin, under a header naming source and overrides.
  /// Loading it again with the same schema gives identical values.
  std::string resolvedYaml() const;
  /// \brief "key: value" lines of every key in schema order except `exclude`: a fingerprint of
  /// the case that ignores where values came from (used to check a restart's case).
  std::string valuesText(const std::vector<std::string>& exclude = {}) const;
  /// \brief Writes resolvedYaml() to `path` atomically (for the run directory).
  void writeResolved(const std::string& path) const;

  /// \brief The file name (or sourceName) the case was read from.
  const std::string& source() const { return _source; }
  /// \brief The `--set` texts applied, in order.
  const std::vector<std::string>& overrides() const { return _overrides; }
  /// \brief The schema the case was validated against.
  const CaseSchema& schema() const { return _schema; }

private:
  CaseFile(const CaseSchema& schema, std::string source, std::vector<std::string> overrides,
           std::vector<Value> values, std::vector<Origin> origins);
  std::size_t indexFor(const std::string& key, ValueType type, ValueType alternative) const;

  CaseSchema _schema;
  std::string _source;
  std::vector<std::string> _overrides;
  std::vector<Value> _values;   ///< schema order
  std::vector<Origin> _origins; ///< schema order
};

} // namespace hikiln::cases
