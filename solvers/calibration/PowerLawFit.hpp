#pragma once
/// \file PowerLawFit.hpp
/// \brief Power law y = K x^n, fitted as a straight line in log-log space.

#include "solvers/calibration/FitQuality.hpp"

#include <vector>

namespace hikiln::calibration {

/// \brief A fitted power law with its uncertainty.
struct PowerLawFit {
  double coefficient = 0.0;         ///< K
  double exponent = 0.0;            ///< n
  double coefficientStdError = 0.0; ///< K * standard error of ln K (first-order propagation)
  double exponentStdError = 0.0;    ///< standard error of n
  FitQuality quality;               ///< of ln y against ln K + n ln x (the fitted problem)
  std::size_t dropped = 0;          ///< points skipped: x <= 0, y <= 0 or not finite

  /// \brief K x^n.
  double operator()(double x) const;
};

/// \brief Least squares fit of ln y = ln K + n ln x over the finite points with x > 0, y > 0 (the
/// others are counted in `dropped`). Throws std::invalid_argument when fewer than two usable
/// points remain or all usable x are equal.
PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y);

} // namespace hikiln::calibration
