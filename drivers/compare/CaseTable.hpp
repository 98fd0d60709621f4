#pragma once
/// \file CaseTable.hpp
/// \brief One table over several comparisons (physics.md 5: the five drum cases): spot values,
/// wall slip, surface angle and map differences per case, from their comparison.json documents.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hikiln::compare {

/// \brief cases.csv: one row per comparison, DEM and continuum side by side ("nan" for null).
std::string casesCsv(const std::vector<nlohmann::json>& comparisons);

/// \brief cases.md: the same as a Markdown table, "DEM / continuum" per cell, 3 digits.
std::string casesMarkdown(const std::vector<nlohmann::json>& comparisons);

} // namespace hikiln::compare
