#pragma once
/// \file AveragesReader.hpp
/// \brief Reads a DEM run's averaged-field file (docs/averaged-fields.md) into calibration data.

#include "solvers/calibration/Calibration.hpp"

#include <string>
#include <vector>

namespace hikiln::calibrate {

/// \brief Which grid of the averaged-field file to calibrate from.
enum class AveragesGrid { Polar, Cartesian };

/// \brief "polar" or "cartesian".
std::string gridName(AveragesGrid grid);

/// \brief Path of the averaged-field file of a run: `runPath` itself when it is a file,
/// else `runPath`/averages.h5. Throws std::runtime_error naming the path when it does not exist.
std::string averagesFileOf(const std::string& runPath);

/// \brief Every cell of `grid` in the file at `path`, with r and theta about the drum centre
/// (polar: cell-centre radius and angle; cartesian: measured from the middle of the grid).
/// Throws std::runtime_error naming the file and the dataset that is missing or misshapen.
calibration::GridFields readGridFields(const std::string& path, AveragesGrid grid);

/// \brief The shell's angular bins of a run (/wall datasets), with the per-bin friction ratio
/// and slip: the wall law as the DEM sees it along the shell, not just its shell average.
struct WallProfile {
  std::vector<double> thetaDeg;     ///< bin centre angle (degrees)
  std::vector<double> normalStress; ///< time-averaged normal wall stress (Pa)
  std::vector<double> shearStress;  ///< time-averaged shear wall stress along the motion (Pa)
  std::vector<double> ratio;        ///< shear / normal (NaN where normal <= 0)
  std::vector<double> slipPercent;  ///< 100 (1 - bed speed / shell speed) (NaN without speed)
};

/// \brief The wall profile of the file at `path` for a shell turning at omega (rad/s, signed as
/// the file's) with radius R. Throws std::runtime_error naming the file and the dataset that is
/// missing or whose length differs from theta_centres'.
WallProfile readWallProfile(const std::string& path, double omega, double drumRadius);

/// \brief Conditions (root attributes) and wall values (/wall attributes) of the file at `path`;
/// the cells are left empty. Throws std::runtime_error naming the file and the missing attribute.
calibration::CalibrationRun readRunHeader(const std::string& path);

} // namespace hikiln::calibrate
