#include "solvers/calibration/CoulombFit.hpp"

#include "solvers/calibration/LinearFit.hpp"

#include <cmath>

namespace hikiln::calibration {

namespace {
constexpr double degreesPerRadian = 57.295779513082320876798154814105;
}

CoulombFit fitCoulomb(const std::vector<double>& pressure, const std::vector<double>& shearStress) {
  const LinearFit line = fitLinear(pressure, shearStress);
  CoulombFit fit;
  fit.frictionCoefficient = line.slope;
  fit.cohesion = line.intercept;
  fit.frictionAngleDeg = std::atan(line.slope) * degreesPerRadian;
  fit.frictionCoefficientStdError = line.slopeStdError;
  fit.cohesionStdError = line.interceptStdError;
  fit.frictionAngleDegStdError =
      line.slopeStdError / (1.0 + line.slope * line.slope) * degreesPerRadian;
  fit.quality = line.quality;
  return fit;
}

} // namespace hikiln::calibration
