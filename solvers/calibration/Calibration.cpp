#include "solvers/calibration/Calibration.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

namespace hikiln::calibration {

std::vector<double> inertialNumbers(const CalibrationRun& run) {
  std::vector<double> values(run.cells.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = inertialNumber(run.cells.strainRate[i], run.conditions.particleDiameter,
                               run.cells.pressure[i], run.conditions.particleDensity);
  return values;
}

namespace {
std::pair<double, double> rangeOf(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return {*lo, *hi};
}
} // namespace

CalibrationResult calibrate(const std::vector<CalibrationRun>& runs,
                            const CalibrationOptions& options) {
  if (runs.empty())
    throw std::invalid_argument("calibration: no runs");
  CalibrationResult result;
  CellSamples pooled;
  std::vector<double> inertial, muWall, slip;
  for (const CalibrationRun& run : runs) {
    if (run.cells.size() < 2)
      throw std::invalid_argument("calibration: run '" + run.label + "' has " +
                                  std::to_string(run.cells.size()) + " cells, needs at least 2");
    pooled.append(run.cells);
    const std::vector<double> runInertial = inertialNumbers(run);
    inertial.insert(inertial.end(), runInertial.begin(), runInertial.end());
    muWall.push_back(run.muWall);
    slip.push_back(run.slipPercent);
    result.viscosityVsPressure.push_back(fitLinear(run.cells.pressure, run.cells.viscosity));
  }
  result.cellCount = pooled.size();
  std::tie(result.strainRateMin, result.strainRateMax) = rangeOf(pooled.strainRate);
  std::tie(result.pressureMin, result.pressureMax) = rangeOf(pooled.pressure);
  std::tie(result.inertialMin, result.inertialMax) = rangeOf(inertial);

  result.frictionLine = fitLinear(pooled.strainRate, pooled.frictionM);
  result.coulomb = fitCoulomb(pooled.pressure, pooled.shearStress);
  result.newtonian =
      testNewtonian(pooled.strainRate, pooled.shearStress, options.newtonianTolerance);
  result.wall = summarizeWall(muWall, slip);

  if (!options.fitMuI) {
    result.muIStatus = "not requested";
  } else {
    try {
      result.muI = fitMuI(inertial, pooled.frictionM, options.muI);
      result.muIStatus = result.muI->converged ? "fitted" : "iteration limit reached";
    } catch (const std::invalid_argument& error) {
      result.muIStatus = error.what(); // e.g. no particle diameter/density: I is NaN
    }
  }
  return result;
}

} // namespace hikiln::calibration
