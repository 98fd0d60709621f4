#pragma once
/// \file DenseCoarseSolver.hpp
/// \brief Direct solve on the coarsest multigrid level: the level's matrix is probed with the
/// device operator (so it is exactly the operator the smoothers use), inverted once on the host
/// (pseudo-inverse: singular Neumann/periodic problems are fine) and applied on the device as a
/// dense matrix-vector product, row by row in a fixed order (deterministic).
///
/// Probing: the grid operators couple an unknown only to unknowns at most one index away along
/// each axis (any component). Unknowns of one component whose indices are congruent modulo 3
/// (or a divisor >= 3 of a periodic axis' count) along every axis therefore never reach a common
/// row, so one operator application on the sum of their unit vectors gives all their columns at
/// once: 9 applications per component in 2D (27 in 3D) instead of one per unknown. Every entry
/// is the same single stencil term as in a one-column probe, so the matrix is bitwise the same
/// (test_cfd_coarse_probe).

#include "kernels/cfd/FieldOps.hpp"
#include "solvers/cfd/DenseInverse.hpp"

#include <Kokkos_Core.hpp>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace hikiln::cfd {

/// \brief Where the coarsest level's unknowns sit: per component its box of indices (packed
/// i fastest, components one after another) and which axes wrap around.
struct CoarseUnknowns {
  int numComponents = 1;
  UnknownBox box[3];
  bool periodic[3] = {false, false, false};

  std::int64_t size() const {
    std::int64_t n = 0;
    for (int c = 0; c < numComponents; ++c) {
      n += box[c].size();
    }
    return n;
  }
};

/// \brief Dense pseudo-inverse of a small operator, applied on ExecutionSpace.
template <class ExecutionSpace> class DenseCoarseSolver {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using vector_type = Kokkos::View<double*, Kokkos::LayoutLeft, memory_space>;

  /// \brief Builds the inverse of the operator on `unknowns` whose columns probe(unit, column)
  /// computes on the device (column = A unit). `coloured`: many columns per application (file
  /// comment); else one. Eigenvalues below relativeTolerance * max |eigenvalue| are dropped.
  template <class Probe>
  void build(ExecutionSpace const& space, CoarseUnknowns const& unknowns, bool coloured,
             Probe&& probe, double relativeTolerance) {
    const int n = static_cast<int>(unknowns.size());
    if (n != _n || _inverse.extent(0) == 0) { // a rebuild of the same size reuses the Views
      _n = n;
      rhs = vector_type(Kokkos::view_alloc(space, "hikiln::cfd::coarse::rhs"), n);
      solution = vector_type(Kokkos::view_alloc(space, "hikiln::cfd::coarse::solution"), n);
      _unit = vector_type(Kokkos::view_alloc(space, "hikiln::cfd::coarse::unit"), n);
      _column = vector_type(Kokkos::view_alloc(space, "hikiln::cfd::coarse::column"), n);
      _inverse = Kokkos::View<double**, Kokkos::LayoutRight, memory_space>(
          Kokkos::view_alloc(space, Kokkos::WithoutInitializing, "hikiln::cfd::coarse::inverse"), n,
          n);
    }
    const vector_type unit = _unit, column = _column;
    auto hostUnit = Kokkos::create_mirror_view(Kokkos::HostSpace{}, unit);
    auto hostColumn = Kokkos::create_mirror_view(Kokkos::HostSpace{}, column);
    std::vector<double> matrix(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    const ProbeClasses classes(unknowns, coloured);
    for (std::vector<int> const& members : classes.members) {
      Kokkos::deep_copy(hostUnit, 0.0);
      for (int col : members) {
        hostUnit(col) = 1.0;
      }
      Kokkos::deep_copy(space, unit, hostUnit);
      probe(unit, column);
      Kokkos::deep_copy(space, hostColumn, column);
      space.fence();
      for (int col : members) {
        if (!coloured) {
          for (int row = 0; row < n; ++row) {
            matrix[static_cast<std::size_t>(row) * n + col] = hostColumn(row);
          }
          continue;
        }
        classes.forEachNeighbour(unknowns, col, [&](int row) {
          matrix[static_cast<std::size_t>(row) * n + col] = hostColumn(row);
        });
      }
    }
    const std::vector<double> inverse =
        symmetricPseudoInverse(matrix, n, relativeTolerance, &_rank);
    Kokkos::View<const double**, Kokkos::LayoutRight, Kokkos::HostSpace,
                 Kokkos::MemoryTraits<Kokkos::Unmanaged>>
        hostInverse(inverse.data(), n, n);
    Kokkos::deep_copy(space, _inverse, hostInverse);
    space.fence();
    _probes = static_cast<int>(classes.members.size());
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
  /// \brief Operator applications the last build took.
  int probes() const { return _probes; }

  vector_type rhs;      ///< right-hand side, packed by the caller
  vector_type solution; ///< result of apply()

private:
  /// The unknowns probed together (file comment), and the rows a column can reach.
  struct ProbeClasses {
    std::vector<std::vector<int>> members;
    int spacing[3] = {3, 3, 3};

    ProbeClasses(CoarseUnknowns const& u, bool coloured) {
      if (!coloured) {
        const int n = static_cast<int>(u.size());
        for (int col = 0; col < n; ++col) {
          members.push_back({col});
        }
        return;
      }
      for (int a = 0; a < 3; ++a) {
        spacing[a] = u.periodic[a] ? periodicSpacing(u.box[0].hi[a] - u.box[0].lo[a]) : 3;
      }
      int first = 0;
      for (int c = 0; c < u.numComponents; ++c) {
        UnknownBox const& b = u.box[c];
        std::vector<std::vector<int>> byClass(spacing[0] * spacing[1] * spacing[2]);
        for (int k = b.lo[2]; k < b.hi[2]; ++k) {
          for (int j = b.lo[1]; j < b.hi[1]; ++j) {
            for (int i = b.lo[0]; i < b.hi[0]; ++i) {
              const int cls =
                  residue(i, 0) + spacing[0] * (residue(j, 1) + spacing[1] * residue(k, 2));
              byClass[cls].push_back(first + static_cast<int>(b.linear(i, j, k)));
            }
          }
        }
        for (auto& m : byClass) {
          if (!m.empty()) {
            members.push_back(std::move(m));
          }
        }
        first += static_cast<int>(b.size());
      }
    }

    int residue(int index, int axis) const {
      return (index % spacing[axis] + spacing[axis]) % spacing[axis];
    }

    /// The smallest divisor >= 3 of a periodic axis' count (n itself below 3): class members
    /// then stay 3 apart across the wrap too.
    static int periodicSpacing(int n) {
      for (int s = 3; s < n; ++s) {
        if (n % s == 0) {
          return s;
        }
      }
      return n > 0 ? n : 1;
    }

    /// Calls f(row) for every unknown (any component) at most one index from column col along
    /// each axis (wrapping around periodic axes).
    template <class F> void forEachNeighbour(CoarseUnknowns const& u, int col, F&& f) const {
      int c = 0, start = 0;
      while (col - start >= u.box[c].size()) {
        start += static_cast<int>(u.box[c].size());
        ++c;
      }
      UnknownBox const& b = u.box[c];
      const std::int64_t local = col - start;
      const std::int64_t nx = b.hi[0] - b.lo[0], ny = b.hi[1] - b.lo[1];
      const int at[3] = {b.lo[0] + static_cast<int>(local % nx),
                         b.lo[1] + static_cast<int>((local / nx) % ny),
                         b.lo[2] + static_cast<int>(local / (nx * ny))};
      int rowStart = 0;
      for (int rc = 0; rc < u.numComponents; ++rc) {
        UnknownBox const& rb = u.box[rc];
        for (int dk = -1; dk <= 1; ++dk) {
          for (int dj = -1; dj <= 1; ++dj) {
            for (int di = -1; di <= 1; ++di) {
              int idx[3] = {at[0] + di, at[1] + dj, at[2] + dk};
              bool inside = true;
              for (int a = 0; a < 3; ++a) {
                const int extent = rb.hi[a] - rb.lo[a];
                if (u.periodic[a] && extent > 0) {
                  idx[a] = rb.lo[a] + ((idx[a] - rb.lo[a]) % extent + extent) % extent;
                }
                inside = inside && idx[a] >= rb.lo[a] && idx[a] < rb.hi[a];
              }
              if (inside) {
                f(rowStart + static_cast<int>(rb.linear(idx[0], idx[1], idx[2])));
              }
            }
          }
        }
        rowStart += static_cast<int>(rb.size());
      }
    }
  };

  int _n = 0;
  int _rank = 0;
  int _probes = 0;
  vector_type _unit, _column; ///< probe vectors
  Kokkos::View<double**, Kokkos::LayoutRight, memory_space> _inverse;
};

} // namespace hikiln::cfd
