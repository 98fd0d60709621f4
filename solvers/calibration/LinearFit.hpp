#pragma once
/// \file LinearFit.hpp
/// \brief Straight line y = a + b x by (optionally weighted) least squares.

#include "solvers/calibration/FitQuality.hpp"

#include <vector>

namespace hikiln::calibration {

/// \brief A fitted straight line with its uncertainty.
struct LinearFit {
  double intercept = 0.0;         ///< a
  double slope = 0.0;             ///< b
  double interceptStdError = 0.0; ///< standard error of a (NaN with only two points)
  double slopeStdError = 0.0;     ///< standard error of b (NaN with only two points)
  FitQuality quality;

  /// \brief a + b x.
  double operator()(double x) const { return intercept + slope * x; }
};

/// \brief Ordinary least squares line through (x, y). Throws std::invalid_argument for
/// mismatched sizes, fewer than two points or a constant x.
LinearFit fitLinear(const std::vector<double>& x, const std::vector<double>& y);

/// \brief Weighted least squares line, minimising sum w_i (y_i - a - b x_i)^2; weights > 0
/// (e.g. 1 / variance of y_i). R^2 is the weighted one; the RMS residual is unweighted.
LinearFit fitLinearWeighted(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<double>& weights);

} // namespace hikiln::calibration
