#pragma once
/// \file CrsBaseline.hpp
/// \brief The assembled-matrix baseline the matrix-free multigrid is measured against: the
/// cell operator A x = alpha x - div(beta grad x) assembled on the device as a Kokkos Kernels
/// CrsMatrix (one row per cell, i fastest), solved by conjugate gradients with a Jacobi
/// preconditioner using KokkosSparse::spmv and KokkosBlas dot / axpby / nrm2 / mult.
///
/// The matrix is the linear (homogeneous) operator; the Dirichlet boundary values move into the
/// right-hand side b = f + lift, computed as the affine residual of a zero field. A singular
/// operator (no alpha, no Dirichlet side) gets its right-hand side and solution projected to
/// zero mean, as in CellMultigrid.

#include "kernels/cfd/AxisClosure.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/FieldOps.hpp"
#include "kernels/cfd/Grid.hpp"
#include "solvers/cfd/SolveStats.hpp"

#include <KokkosBlas1_axpby.hpp>
#include <KokkosBlas1_dot.hpp>
#include <KokkosBlas1_mult.hpp>
#include <KokkosBlas1_nrm2.hpp>
#include <KokkosSparse_CrsMatrix.hpp>
#include <KokkosSparse_spmv.hpp>
#include <Kokkos_Core.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace hikiln::cfd {

namespace detail {

/// \brief Row entries of cell (i, j, k) of the linear cell operator: visit(column, value) for
/// the diagonal first, then one entry per distinct neighbour with a non-zero coupling (periodic
/// axes of 2 cells merge up and down).
template <class MemorySpace, class Visit>
KOKKOS_INLINE_FUNCTION void visitCellRow(CellOperator<MemorySpace> const& op, UnknownBox const& box,
                                         int i, int j, int k, Visit&& visit) {
  const int g = op.grid.ghost;
  const int gz = op.grid.ghostZ();
  double diag = op.hasAlpha() ? op.alpha(i + g, j + g, k + gz) : 0.0;
  const int idx[3] = {i, j, k};
  double coef[6] = {0, 0, 0, 0, 0, 0};
  int col[6] = {-1, -1, -1, -1, -1, -1};
  for (int a = 0; a < 3; ++a) {
    if (!op.axis[a].active) {
      continue;
    }
    const double h = op.grid.spacing(a);
    for (int side = 0; side < 2; ++side) {
      const Neighbour nb = side ? op.axis[a].up(idx[a], false) : op.axis[a].down(idx[a], false);
      int face[3] = {i, j, k};
      face[a] = idx[a] + side;
      const double b = op.beta[a](face[0] + g, face[1] + g, face[2] + gz) / (h * h);
      diag += b * nb.diag;
      if (nb.off != 0.0) {
        int other[3] = {i, j, k};
        other[a] = nb.index;
        col[2 * a + side] = static_cast<int>(box.linear(other[0], other[1], other[2]));
        coef[2 * a + side] = -b * nb.off;
      }
    }
    if (col[2 * a] >= 0 && col[2 * a] == col[2 * a + 1]) {
      coef[2 * a + 1] += coef[2 * a];
      col[2 * a] = -1;
    }
  }
  visit(static_cast<int>(box.linear(i, j, k)), diag);
  for (int e = 0; e < 6; ++e) {
    if (col[e] >= 0) {
      visit(col[e], coef[e]);
    }
  }
}

} // namespace detail

/// \brief CSR arrays of a cell operator (row = UnknownBox::linear) and its inverse diagonal.
template <class MemorySpace> struct CellMatrixArrays {
  Kokkos::View<int*, Kokkos::LayoutLeft, MemorySpace> rowMap, columns;
  Kokkos::View<double*, Kokkos::LayoutLeft, MemorySpace> values, inverseDiagonal;
  int numEntries = 0;
};

/// \brief Assembles the linear part of op on the device: count entries per row, prefix sum,
/// fill.
template <class ExecutionSpace, class MemorySpace>
CellMatrixArrays<MemorySpace> assembleCellMatrix(ExecutionSpace const& space,
                                                 CellOperator<MemorySpace> const& op,
                                                 UnknownBox const& box) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::assembleCellMatrix: operator not accessible");
  const int n = static_cast<int>(box.size());
  CellMatrixArrays<MemorySpace> m;
  m.rowMap = decltype(m.rowMap)(Kokkos::view_alloc(space, "hikiln::cfd::crs::rowMap"), n + 1);
  const auto rowMap = m.rowMap;
  Kokkos::parallel_for(
      "hikiln::cfd::crs::countRow", gridPolicy(space, box.lo, box.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        int count = 0;
        detail::visitCellRow(op, box, i, j, k, [&](int, double) { ++count; });
        rowMap(box.linear(i, j, k) + 1) = count;
      });
  int total = 0;
  Kokkos::parallel_scan(
      "hikiln::cfd::crs::rowOffsets", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n + 1),
      KOKKOS_LAMBDA(const int r, int& partial, const bool final) {
        partial += rowMap(r);
        if (final) {
          rowMap(r) = partial;
        }
      },
      total);
  m.numEntries = total;
  m.columns = decltype(m.columns)(
      Kokkos::view_alloc(space, Kokkos::WithoutInitializing, "hikiln::cfd::crs::columns"), total);
  m.values = decltype(m.values)(
      Kokkos::view_alloc(space, Kokkos::WithoutInitializing, "hikiln::cfd::crs::values"), total);
  m.inverseDiagonal = decltype(m.inverseDiagonal)(
      Kokkos::view_alloc(space, "hikiln::cfd::crs::inverseDiagonal"), n);
  const auto columns = m.columns;
  const auto values = m.values;
  const auto inverseDiagonal = m.inverseDiagonal;
  Kokkos::parallel_for(
      "hikiln::cfd::crs::fillRow", gridPolicy(space, box.lo, box.hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const int row = static_cast<int>(box.linear(i, j, k));
        int slot = rowMap(row);
        detail::visitCellRow(op, box, i, j, k, [&](int column, double value) {
          if (slot == rowMap(row)) {
            inverseDiagonal(row) = value != 0.0 ? 1.0 / value : 0.0;
          }
          columns(slot) = column;
          values(slot) = value;
          ++slot;
        });
      });
  return m;
}

/// \brief Subtracts the mean of v (length n).
template <class ExecutionSpace, class VectorView>
void removeVectorMean(ExecutionSpace const& space, VectorView const& v) {
  const int n = static_cast<int>(v.extent(0));
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::crs::sum", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(const int i, double& s) { s += v(i); }, sum);
  const double mean = n > 0 ? sum / n : 0.0;
  Kokkos::parallel_for(
      "hikiln::cfd::crs::shift", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(const int i) { v(i) -= mean; });
}

/// \brief The cell operator as a CrsMatrix and a Jacobi-preconditioned CG on it.
template <class ExecutionSpace> class CrsBaseline {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using device_type = Kokkos::Device<ExecutionSpace, memory_space>;
  using matrix_type = KokkosSparse::CrsMatrix<double, int, device_type, void, int>;
  using vector_type = Kokkos::View<double*, Kokkos::LayoutLeft, memory_space>;
  using field_type = Field<memory_space>;

  /// \brief Assembles op (referenced coefficients are read once, here).
  CrsBaseline(ExecutionSpace const& space, CellOperator<memory_space> const& op)
      : _space(space), _op(op) {
    _box = unknownBox(op.grid, op.axis);
    if (_box.size() > static_cast<std::int64_t>(2147483647)) {
      throw std::invalid_argument("hikiln::cfd::CrsBaseline: too many cells for int indices");
    }
    _n = static_cast<int>(_box.size());
    _singular = !op.hasAlpha();
    for (int a = 0; a < 3; ++a) {
      if (!op.axis[a].periodic && (op.axis[a].low == ClosureKind::DirichletCell ||
                                   op.axis[a].high == ClosureKind::DirichletCell)) {
        _singular = false;
      }
    }
    const CellMatrixArrays<memory_space> m = assembleCellMatrix(_space, _op, _box);
    _space.fence();
    _inverseDiagonal = m.inverseDiagonal;
    _matrix = matrix_type("hikiln::cfd::crs::matrix", _n, _n, m.numEntries, m.values, m.rowMap,
                          m.columns);
    _b = vector("hikiln::cfd::crs::b");
    _x = vector("hikiln::cfd::crs::x");
    _r = vector("hikiln::cfd::crs::r");
    _z = vector("hikiln::cfd::crs::z");
    _p = vector("hikiln::cfd::crs::p");
    _q = vector("hikiln::cfd::crs::q");
  }

  /// \brief Solves A x = f (boundary values included) by Jacobi-preconditioned CG from the
  /// initial guess x; stops at ||r|| <= tolerance ||r_0|| or after maxIterations.
  SolveStats solve(field_type const& x, field_type const& f, double tolerance, int maxIterations) {
    // b = f + lift: the affine residual of a zero field
    field_type zero = makeField(_space, _op.grid, Staggering::Cell, "hikiln::cfd::crs::zero");
    field_type rhs = makeField(_space, _op.grid, Staggering::Cell, "hikiln::cfd::crs::rhs");
    cellResidual(_space, _op, zero, f, rhs, true);
    packUnknowns(_space, _box, rhs, _b, 0);
    if (_singular) {
      removeVectorMean(_space, _b);
    }
    packUnknowns(_space, _box, x, _x, 0);
    const SolveStats stats = solveVectors(tolerance, maxIterations);
    if (_singular) {
      removeVectorMean(_space, _x);
    }
    unpackUnknowns(_space, _box, _x, 0, x);
    return stats;
  }

  /// \brief Jacobi-PCG on the packed vectors b and x (x: initial guess in, solution out).
  SolveStats solveVectors(double tolerance, int maxIterations) {
    SolveStats stats;
    // r = b - A x
    Kokkos::deep_copy(_space, _r, _b);
    KokkosSparse::spmv("N", -1.0, _matrix, _x, 1.0, _r);
    double residual = KokkosBlas::nrm2(_r);
    stats.initialResidual = stats.referenceResidual = residual;
    stats.history.push_back(residual);
    if (residual > 0.0) {
      KokkosBlas::mult(0.0, _z, 1.0, _inverseDiagonal, _r);
      Kokkos::deep_copy(_space, _p, _z);
      double rz = KokkosBlas::dot(_r, _z);
      while (residual > tolerance * stats.initialResidual && stats.iterations < maxIterations) {
        KokkosSparse::spmv("N", 1.0, _matrix, _p, 0.0, _q);
        const double step = rz / KokkosBlas::dot(_p, _q);
        KokkosBlas::axpby(step, _p, 1.0, _x);
        KokkosBlas::axpby(-step, _q, 1.0, _r);
        residual = KokkosBlas::nrm2(_r);
        stats.history.push_back(residual);
        ++stats.iterations;
        if (residual <= tolerance * stats.initialResidual) {
          break;
        }
        KokkosBlas::mult(0.0, _z, 1.0, _inverseDiagonal, _r);
        const double rzNew = KokkosBlas::dot(_r, _z);
        KokkosBlas::axpby(1.0, _z, rzNew / rz, _p);
        rz = rzNew;
      }
    }
    stats.converged = residual <= tolerance * stats.initialResidual;
    Kokkos::deep_copy(_space, _q, _b);
    KokkosSparse::spmv("N", -1.0, _matrix, _x, 1.0, _q);
    stats.finalResidual = KokkosBlas::nrm2(_q);
    return stats;
  }

  /// \brief The assembled matrix.
  matrix_type const& matrix() const { return _matrix; }
  /// \brief Number of rows (cells).
  int size() const { return _n; }
  /// \brief Stored entries.
  int numEntries() const { return static_cast<int>(_matrix.nnz()); }
  /// \brief The packed right-hand side / solution vectors used by solveVectors().
  vector_type const& rhsVector() const { return _b; }
  /// \brief The packed solution vector.
  vector_type const& solutionVector() const { return _x; }

private:
  vector_type vector(const char* label) const {
    return vector_type(Kokkos::view_alloc(_space, std::string(label)), _n);
  }

  ExecutionSpace _space;
  CellOperator<memory_space> _op;
  UnknownBox _box;
  int _n = 0;
  bool _singular = false;
  matrix_type _matrix;
  vector_type _inverseDiagonal, _b, _x, _r, _z, _p, _q;
};

} // namespace hikiln::cfd
