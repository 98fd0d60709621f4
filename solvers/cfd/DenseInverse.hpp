#pragma once
/// \file DenseInverse.hpp
/// \brief Pseudo-inverse of a small symmetric matrix (the coarsest multigrid level), host only.

#include <vector>

namespace hikiln::cfd {

/// \brief Pseudo-inverse of the symmetric n x n matrix `matrix` (row-major; symmetrised first):
/// eigenvalues below relativeTolerance times the largest magnitude are treated as zero, so a
/// singular operator (Neumann or periodic null space) maps a right-hand side to the minimum-norm
/// solution of its consistent part. `rank` (optional) receives the number of kept eigenvalues.
std::vector<double> symmetricPseudoInverse(std::vector<double> const& matrix, int n,
                                           double relativeTolerance, int* rank = nullptr);

} // namespace hikiln::cfd
