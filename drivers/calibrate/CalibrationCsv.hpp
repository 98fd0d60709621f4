#pragma once
/// \file CalibrationCsv.hpp
/// \brief The calibration scatter data as CSV: one row per selected cell of every run.

#include "solvers/calibration/Calibration.hpp"

#include <string>
#include <vector>

namespace hikiln::calibrate {

/// \brief CSV text with header run,r,theta,volume_fraction,pressure,shear_stress,strain_rate,
/// viscosity,m,inertial_number (SI units; numbers in shortest round-trip form).
std::string formatCalibrationCsv(const std::vector<calibration::CalibrationRun>& runs);

} // namespace hikiln::calibrate
