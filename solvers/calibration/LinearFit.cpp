#include "solvers/calibration/LinearFit.hpp"

#include "solvers/calibration/LeastSquares.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hikiln::calibration {

LinearFit fitLinearWeighted(const std::vector<double>& x, const std::vector<double>& y,
                            const std::vector<double>& weights) {
  const std::size_t n = x.size();
  if (y.size() != n || (!weights.empty() && weights.size() != n))
    throw std::invalid_argument("linear fit: x, y and weights differ in length");
  if (n < 2)
    throw std::invalid_argument("linear fit: needs at least 2 points, got " + std::to_string(n));
  // Centre x on its weighted mean so that a and b are fitted from well-conditioned columns.
  double sumW = 0.0, sumWx = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = weights.empty() ? 1.0 : weights[i];
    sumW += w;
    sumWx += w * x[i];
  }
  const double xMean = sumWx / sumW;
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd values(n);
  Eigen::VectorXd w = weights.empty() ? Eigen::VectorXd() : Eigen::VectorXd(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    design(row, 0) = 1.0;
    design(row, 1) = x[i] - xMean;
    values[row] = y[i];
    if (!weights.empty())
      w[row] = weights[i];
  }
  const LeastSquaresSolution solution = solveLeastSquares(design, values, w);

  LinearFit fit;
  fit.slope = solution.coefficients[1];
  fit.intercept = solution.coefficients[0] - xMean * fit.slope;
  // a = a' - xMean b  =>  Var(a) = Var(a') + xMean^2 Var(b) - 2 xMean Cov(a', b).
  const Eigen::MatrixXd& c = solution.covariance;
  fit.interceptStdError =
      std::sqrt(std::fmax(0.0, c(0, 0) + xMean * xMean * c(1, 1) - 2.0 * xMean * c(0, 1)));
  if (std::isnan(c(0, 0)))
    fit.interceptStdError = c(0, 0);
  fit.slopeStdError = std::sqrt(c(1, 1));

  std::vector<double> predicted(n);
  for (std::size_t i = 0; i < n; ++i)
    predicted[i] = fit(x[i]);
  fit.quality = assessFit(y, predicted, weights);
  return fit;
}

LinearFit fitLinear(const std::vector<double>& x, const std::vector<double>& y) {
  return fitLinearWeighted(x, y, {});
}

} // namespace hikiln::calibration
