#pragma once
/// \file CalibrationJson.hpp
/// \brief Every calibration fit as JSON (calibration.json; the plot script reads it).

#include "solvers/calibration/Calibration.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace hikiln::calibration {

/// \brief n, r_squared, rms_residual.
nlohmann::json toJson(const FitQuality& quality);
/// \brief intercept, slope, their standard errors and quality.
nlohmann::json toJson(const LinearFit& fit);
/// \brief coefficient, exponent, their standard errors, dropped points and quality.
nlohmann::json toJson(const PowerLawFit& fit);
/// \brief mu_fr, cohesion, phi_deg, their standard errors and quality.
nlohmann::json toJson(const CoulombFit& fit);
/// \brief m_s, m_2, I0, their standard errors, iterations, converged and quality.
nlohmann::json toJson(const MuIFit& fit);
/// \brief Counts of the cell selection.
nlohmann::json toJson(const SelectionCounts& counts);

/// \brief All results: each fit, the selection options, the wall statistics and per-run
/// conditions, counts and viscosity-pressure lines. NaN values come out as null.
nlohmann::json calibrationToJson(const CalibrationResult& result,
                                 const std::vector<CalibrationRun>& runs,
                                 const CalibrationOptions& options);

} // namespace hikiln::calibration
