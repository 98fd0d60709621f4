#include "solvers/calibration/PowerLawFit.hpp"

#include "solvers/calibration/LinearFit.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hikiln::calibration {

double PowerLawFit::operator()(double x) const {
  return coefficient * std::pow(x, exponent);
}

PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size())
    throw std::invalid_argument("power-law fit: x and y differ in length");
  std::vector<double> logX, logY;
  logX.reserve(x.size());
  logY.reserve(y.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (x[i] > 0.0 && y[i] > 0.0 && std::isfinite(x[i]) && std::isfinite(y[i])) {
      logX.push_back(std::log(x[i]));
      logY.push_back(std::log(y[i]));
    }
  }
  PowerLawFit fit;
  fit.dropped = x.size() - logX.size();
  if (logX.size() < 2)
    throw std::invalid_argument(
        "power-law fit: needs at least 2 points with x > 0 and y > 0, got " +
        std::to_string(logX.size()));
  const LinearFit line = fitLinear(logX, logY);
  fit.coefficient = std::exp(line.intercept);
  fit.exponent = line.slope;
  fit.coefficientStdError = fit.coefficient * line.interceptStdError;
  fit.exponentStdError = line.slopeStdError;
  fit.quality = line.quality;
  return fit;
}

} // namespace hikiln::calibration
