#include "solvers/calibration/FitQuality.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hikiln::calibration {

FitQuality assessFit(const std::vector<double>& observed, const std::vector<double>& predicted,
                     const std::vector<double>& weights) {
  const std::size_t n = observed.size();
  if (predicted.size() != n || (!weights.empty() && weights.size() != n))
    throw std::invalid_argument("assessFit: observed, predicted and weights differ in size");
  FitQuality quality;
  quality.n = n;
  if (n == 0)
    return quality;
  double sumW = 0.0, sumWy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    sumW += w;
    sumWy += w * observed[i];
  }
  const double yMean = sumWy / sumW;
  double ssr = 0.0, sst = 0.0, plainSsr = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    const double residual = observed[i] - predicted[i];
    ssr += w * residual * residual;
    sst += w * (observed[i] - yMean) * (observed[i] - yMean);
    plainSsr += residual * residual;
  }
  quality.rmsResidual = std::sqrt(plainSsr / static_cast<double>(n));
  if (sst > 0.0) {
    quality.rSquared = 1.0 - ssr / sst;
  } else {
    // Constant data: "explained" only if reproduced to rounding.
    const double tolerance = 1e-12 * std::fabs(yMean);
    quality.rSquared = quality.rmsResidual <= tolerance ? 1.0 : 0.0;
  }
  return quality;
}

double mean(const std::vector<double>& values) {
  if (values.empty())
    return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (double v : values)
    sum += v;
  return sum / static_cast<double>(values.size());
}

double sampleStdDev(const std::vector<double>& values) {
  if (values.empty())
    return std::numeric_limits<double>::quiet_NaN();
  if (values.size() == 1)
    return 0.0;
  const double m = mean(values);
  double sum = 0.0;
  for (double v : values)
    sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(values.size() - 1));
}

} // namespace hikiln::calibration
