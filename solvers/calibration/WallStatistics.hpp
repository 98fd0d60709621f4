#pragma once
/// \file WallStatistics.hpp
/// \brief Bed-shell friction and slip over the calibration runs.

#include <vector>

namespace hikiln::calibration {

/// \brief mu_wall to use in the continuum model (the runs' mean) with its spread, and the slip.
struct WallStatistics {
  double muWall = 0.0;             ///< mean of the runs' mu_wall
  double muWallStd = 0.0;          ///< sample standard deviation over runs (0 for one run)
  std::vector<double> muWallRuns;  ///< per run, input order
  std::vector<double> slipPercent; ///< per run, 100 (1 - bed speed at the wall / shell speed)
  double meanSlipPercent = 0.0;
};

/// \brief Combines per-run wall values (same length, at least one run). Throws
/// std::invalid_argument for mismatched lengths, no runs, or a non-finite value.
WallStatistics summarizeWall(const std::vector<double>& muWall,
                             const std::vector<double>& slipPercent);

} // namespace hikiln::calibration
