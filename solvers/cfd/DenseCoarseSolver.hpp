#pragma once
/// \file DenseCoarseSolver.hpp
/// \brief Direct solve on the coarsest multigrid level: the level's matrix is probed column by
/// column with the device operator (so it is exactly the operator the smoothers use), inverted
/// once on the host (pseudo-inverse: singular Neumann/periodic problems are fine) and applied on
/// the device as a dense matrix-vector product, row by row in a fixed order (deterministic).

#include "solvers/cfd/DenseInverse.hpp"

#include <Kokkos_Core.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace hikiln::cfd {

/// \brief Dense pseudo-inverse of a small operator, applied on ExecutionSpace.
template <class ExecutionSpace> class DenseCoarseSolver {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using vector_type = Kokkos::View<double*, Kokkos::LayoutLeft, memory_space>;

  /// \brief Builds the inverse of the n x n operator whose columns probe(space, unit, column)
  /// computes on the device (unit: e_col, column: A e_col). Eigenvalues below
  /// relativeTolerance * max |eigenvalue| are dropped.
  template <class Probe>
  void build(ExecutionSpace const& space, int n, Probe&& probe, double relativeTolerance) {
    _n = n;
    rhs = vector_type(Kokkos::view_alloc(space, "hikiln::cfd::coarse::rhs"), n);
    solution = vector_type(Kokkos::view_alloc(space, "hikiln::cfd::coarse::solution"), n);
    vector_type unit(Kokkos::view_alloc(space, "hikiln::cfd::coarse::unit"), n);
    vector_type column(Kokkos::view_alloc(space, "hikiln::cfd::coarse::column"), n);
    auto hostColumn = Kokkos::create_mirror_view(Kokkos::HostSpace{}, column);
    std::vector<double> matrix(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    for (int col = 0; col < n; ++col) {
      // deep_copy, not a KOKKOS_LAMBDA: nvcc rejects extended lambdas in a function templated on
      // a lambda type (Probe)
      Kokkos::deep_copy(space, unit, 0.0);
      Kokkos::deep_copy(space, Kokkos::subview(unit, col), 1.0);
      probe(unit, column);
      Kokkos::deep_copy(space, hostColumn, column);
      space.fence();
      for (int row = 0; row < n; ++row) {
        matrix[static_cast<std::size_t>(row) * n + col] = hostColumn(row);
      }
    }
    const std::vector<double> inverse =
        symmetricPseudoInverse(matrix, n, relativeTolerance, &_rank);
    _inverse = Kokkos::View<double**, Kokkos::LayoutRight, memory_space>(
        Kokkos::view_alloc(space, Kokkos::WithoutInitializing, "hikiln::cfd::coarse::inverse"), n,
        n);
    Kokkos::View<const double**, Kokkos::LayoutRight, Kokkos::HostSpace,
                 Kokkos::MemoryTraits<Kokkos::Unmanaged>>
        hostInverse(inverse.data(), n, n);
    Kokkos::deep_copy(space, _inverse, hostInverse);
    space.fence();
  }

  /// \brief solution = inverse * rhs (the public work vectors).
  void apply(ExecutionSpace const& space) const {
    const auto inv = _inverse;
    const auto b = rhs;
    const auto x = solution;
    const int n = _n;
    Kokkos::parallel_for(
        "hikiln::cfd::coarse::apply", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
        KOKKOS_LAMBDA(const int row) {
          double sum = 0.0;
          for (int col = 0; col < n; ++col) {
            sum += inv(row, col) * b(col);
          }
          x(row) = sum;
        });
  }

  /// \brief Number of unknowns.
  int size() const { return _n; }
  /// \brief Rank of the probed matrix (n when it is non-singular).
  int rank() const { return _rank; }

  vector_type rhs;      ///< right-hand side, packed by the caller
  vector_type solution; ///< result of apply()

private:
  int _n = 0;
  int _rank = 0;
  Kokkos::View<double**, Kokkos::LayoutRight, memory_space> _inverse;
};

} // namespace hikiln::cfd
