/// \file DenseInverse.cpp
/// \brief Pseudo-inverse of a small symmetric matrix by an eigen-decomposition (Eigen).
#include "solvers/cfd/DenseInverse.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>
#include <string>

namespace hikiln::cfd {

std::vector<double> symmetricPseudoInverse(std::vector<double> const& matrix, int n,
                                           double relativeTolerance, int* rank) {
  if (n < 0 || matrix.size() != static_cast<std::size_t>(n) * static_cast<std::size_t>(n)) {
    throw std::invalid_argument("hikiln::cfd::symmetricPseudoInverse: matrix is not " +
                                std::to_string(n) + " x " + std::to_string(n));
  }
  Eigen::MatrixXd a(n, n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      a(r, c) = 0.5 * (matrix[static_cast<std::size_t>(r) * n + c] +
                       matrix[static_cast<std::size_t>(c) * n + r]);
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(a);
  if (eigen.info() != Eigen::Success) {
    throw std::runtime_error("hikiln::cfd::symmetricPseudoInverse: eigen-decomposition failed");
  }
  const Eigen::VectorXd& values = eigen.eigenvalues();
  const double largest = n > 0 ? values.cwiseAbs().maxCoeff() : 0.0;
  Eigen::VectorXd inverted(n);
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    if (std::fabs(values(i)) > relativeTolerance * largest) {
      inverted(i) = 1.0 / values(i);
      ++kept;
    } else {
      inverted(i) = 0.0;
    }
  }
  const Eigen::MatrixXd& v = eigen.eigenvectors();
  const Eigen::MatrixXd pinv = v * inverted.asDiagonal() * v.transpose();
  std::vector<double> out(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      out[static_cast<std::size_t>(r) * n + c] = pinv(r, c);
    }
  }
  if (rank != nullptr) {
    *rank = kept;
  }
  return out;
}

} // namespace hikiln::cfd
