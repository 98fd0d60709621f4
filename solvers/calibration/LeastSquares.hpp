#pragma once
/// \file LeastSquares.hpp
/// \brief Weighted linear least squares with the parameter covariance, the core of every fit.

#include <Eigen/Dense>

namespace hikiln::calibration {

/// \brief Solution of min sum w_i (y_i - X_i beta)^2.
struct LeastSquaresSolution {
  Eigen::VectorXd coefficients; ///< beta
  /// \brief s^2 (X^T W X)^-1 with s^2 = weighted SSR / (n - p); NaN when n <= p.
  Eigen::MatrixXd covariance;
  double weightedSsr = 0.0; ///< sum w_i r_i^2 at the solution
};

/// \brief Solves the weighted problem by column-pivoting QR of sqrt(W) X (no normal equations, so
/// exact data give coefficients to rounding). `weights` may be empty (all 1); all must be > 0.
/// Throws std::invalid_argument on mismatched sizes, fewer rows than columns or a rank-deficient X.
LeastSquaresSolution solveLeastSquares(const Eigen::MatrixXd& design, const Eigen::VectorXd& y,
                                       const Eigen::VectorXd& weights = Eigen::VectorXd());

/// \brief Square roots of the covariance diagonal (NaN where the covariance is NaN).
Eigen::VectorXd standardErrors(const Eigen::MatrixXd& covariance);

} // namespace hikiln::calibration
