#include "solvers/calibration/WallStatistics.hpp"

#include "solvers/calibration/FitQuality.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hikiln::calibration {

WallStatistics summarizeWall(const std::vector<double>& muWall,
                             const std::vector<double>& slipPercent) {
  if (muWall.size() != slipPercent.size())
    throw std::invalid_argument("wall statistics: mu_wall and slip lists differ in length");
  if (muWall.empty())
    throw std::invalid_argument("wall statistics: no runs");
  for (std::size_t i = 0; i < muWall.size(); ++i)
    if (!std::isfinite(muWall[i]) || !std::isfinite(slipPercent[i]))
      throw std::invalid_argument("wall statistics: run " + std::to_string(i) +
                                  " has a non-finite mu_wall or slip");
  WallStatistics stats;
  stats.muWallRuns = muWall;
  stats.slipPercent = slipPercent;
  stats.muWall = mean(muWall);
  stats.muWallStd = sampleStdDev(muWall);
  stats.meanSlipPercent = mean(slipPercent);
  return stats;
}

} // namespace hikiln::calibration
