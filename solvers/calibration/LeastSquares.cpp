#include "solvers/calibration/LeastSquares.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hikiln::calibration {

LeastSquaresSolution solveLeastSquares(const Eigen::MatrixXd& design, const Eigen::VectorXd& y,
                                       const Eigen::VectorXd& weights) {
  const Eigen::Index n = design.rows();
  const Eigen::Index p = design.cols();
  if (y.size() != n || (weights.size() != 0 && weights.size() != n))
    throw std::invalid_argument("least squares: design, data and weights differ in length");
  if (n < p)
    throw std::invalid_argument("least squares: " + std::to_string(n) + " points for " +
                                std::to_string(p) + " parameters");
  Eigen::VectorXd sqrtW = Eigen::VectorXd::Ones(n);
  if (weights.size() != 0) {
    if ((weights.array() <= 0.0).any() || !weights.allFinite())
      throw std::invalid_argument("least squares: weights must be finite and positive");
    sqrtW = weights.array().sqrt();
  }
  const Eigen::MatrixXd a = sqrtW.asDiagonal() * design;
  const Eigen::VectorXd b = sqrtW.asDiagonal() * y;
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < p)
    throw std::invalid_argument("least squares: the data do not determine all " +
                                std::to_string(p) + " parameters (rank " +
                                std::to_string(qr.rank()) + ")");
  LeastSquaresSolution solution;
  solution.coefficients = qr.solve(b);
  solution.weightedSsr = (a * solution.coefficients - b).squaredNorm();
  if (n > p) {
    // (A^T A)^-1 from R: A P = Q R  =>  (A^T A)^-1 = P (R^T R)^-1 P^T.
    const Eigen::MatrixXd r = qr.matrixR().topLeftCorner(p, p).triangularView<Eigen::Upper>();
    const Eigen::MatrixXd rInv =
        r.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(p, p));
    const Eigen::MatrixXd unscaled =
        qr.colsPermutation() * (rInv * rInv.transpose()) * qr.colsPermutation().transpose();
    solution.covariance = unscaled * (solution.weightedSsr / static_cast<double>(n - p));
  } else {
    solution.covariance = Eigen::MatrixXd::Constant(p, p, std::numeric_limits<double>::quiet_NaN());
  }
  return solution;
}

Eigen::VectorXd standardErrors(const Eigen::MatrixXd& covariance) {
  Eigen::VectorXd errors(covariance.rows());
  for (Eigen::Index i = 0; i < covariance.rows(); ++i)
    errors[i] = std::sqrt(covariance(i, i));
  return errors;
}

} // namespace hikiln::calibration
