#pragma once
/// \file FitQuality.hpp
/// \brief How well a fitted curve describes its data: the numbers every calibration fit reports.

#include <cstddef>
#include <vector>

namespace hikiln::calibration {

/// \brief Goodness of fit in the units of the fitted quantity.
struct FitQuality {
  std::size_t n = 0;        ///< data points used
  double rSquared = 0.0;    ///< coefficient of determination, 1 - SSR / SST (weighted if weighted)
  double rmsResidual = 0.0; ///< sqrt(mean of squared unweighted residuals)
};

/// \brief Quality of `predicted` against `observed`; `weights` (same size, or empty for equal
/// weights) weigh R^2 as in weighted least squares. R^2 is 1 when the data are constant and
/// reproduced to rounding (1e-12 relative), 0 when they are constant and not.
FitQuality assessFit(const std::vector<double>& observed, const std::vector<double>& predicted,
                     const std::vector<double>& weights = {});

/// \brief Arithmetic mean; NaN for no values.
double mean(const std::vector<double>& values);

/// \brief Sample standard deviation (n - 1 in the denominator); 0 for one value, NaN for none.
double sampleStdDev(const std::vector<double>& values);

} // namespace hikiln::calibration
