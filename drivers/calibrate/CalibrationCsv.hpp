#pragma once
/// \file CalibrationCsv.hpp
/// \brief The calibration scatter data as CSV: one row per selected cell of every run; and the
/// runs' wall profiles, one row per shell bin.

#include "drivers/calibrate/AveragesReader.hpp"
#include "solvers/calibration/Calibration.hpp"

#include <string>
#include <vector>

namespace hikiln::calibrate {

/// \brief CSV text with header run,r,theta,volume_fraction,pressure,shear_stress,strain_rate,
/// viscosity,m,inertial_number (SI units; numbers in shortest round-trip form).
std::string formatCalibrationCsv(const std::vector<calibration::CalibrationRun>& runs);

/// \brief CSV text with header run,theta_deg,normal_stress,shear_stress,friction_ratio,
/// slip_percent: walls[i] belongs to runs[i] (labels from there); NaN written as `nan`.
std::string formatWallProfileCsv(const std::vector<calibration::CalibrationRun>& runs,
                                 const std::vector<WallProfile>& walls);

} // namespace hikiln::calibrate
