#pragma once
/// \file ComparisonReport.hpp
/// \brief comparison.json (spot values, wall slip, surfaces, map differences, how each number was
/// made) and comparison.csv (both maps on the common grid, one row per cell).

#include "drivers/compare/FieldComparison.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace hikiln::compare {

/// \brief The comparison as JSON; non-finite numbers become null.
nlohmann::json comparisonJson(const Comparison& comparison, const DemRun& dem,
                              const ContinuumRun& continuum, const std::string& label);

/// \brief One row per cell of the common grid: i, j, x, y, dem_valid, continuum_valid, then
/// dem_FIELD and continuum_FIELD for every mapFields() entry ("nan" where a value is missing).
std::string comparisonCsv(const Comparison& comparison);

} // namespace hikiln::compare
