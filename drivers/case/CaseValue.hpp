#pragma once
/// \file CaseValue.hpp
/// \brief Internal: turning one YAML node into a typed, range-checked value and back into YAML
/// text. Shared by CaseSchema (defaults, reference table) and CaseFile (file values, `--set`).

#include "drivers/case/CaseSchema.hpp"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <stdexcept>
#include <string>

namespace hikiln::cases::detail {

/// \brief Thrown by a CaseSchema::require() rule whose predicate is false; the rule text is the
/// whole message.
struct RuleViolated : std::runtime_error {
  RuleViolated() : std::runtime_error("") {}
};

/// \brief Result of convertValue: a value, or a reason (without location) and where it applies.
struct Conversion {
  std::optional<Value> value;
  std::string error; ///< e.g. "'drum.rpm' must be a real number, got 'fast'"
  YAML::Mark mark;   ///< offending node; null_mark() when the node has no useful position
};

/// \brief Validates `node` against `spec` (type, finiteness, range, choices, list length).
Conversion convertValue(const KeySpec& spec, const YAML::Node& node);

/// \brief YAML text for a value that re-reads to the identical value (shortest round-trip reals).
std::string formatValue(const Value& value);

/// \brief The allowed interval, "(0, 1]", "> 0", "<= 5", or "" when unbounded.
std::string describeRange(const KeySpec& spec);

/// \brief "(doc [unit])", "(doc)", "([unit])" or "" for messages.
std::string describeMeaning(const KeySpec& spec);

/// \brief A real in the shortest form that parses back to the same double, always with a '.' or
/// an exponent so it reads as a real ("2.0", "1e-05", "0.1").
std::string formatReal(double x);

} // namespace hikiln::cases::detail
