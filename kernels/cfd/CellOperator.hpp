#pragma once
/// \file CellOperator.hpp
/// \brief The cell-centred variable-coefficient operator A x = alpha x - div(beta grad x) (per
/// unit volume, alpha >= 0 in cells, beta > 0 on faces): the pressure Poisson operator for
/// alpha = 0 and beta = 1/rho, and the implicit diffusion operator of a scalar (rho c / dt,
/// kappa). A is symmetric positive (semi-)definite, so -A is the discrete div(beta grad) and the
/// pressure equation div(beta grad p) = f is A p = -f.
///
/// Kernels: apply, residual (with its squared norm), a red-black Gauss-Seidel half sweep, and
/// the harmonic-mean face coefficients. Boundaries come from AxisClosure (no ghost cells read);
/// `affine` includes the Dirichlet values of the boundary conditions (the finest level of a solve),
/// without it the operator is the linear part (corrections, Krylov directions).

#include "kernels/cfd/AxisClosure.hpp"
#include "kernels/cfd/BoxSplit.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/SplitLoop.hpp"
#include "kernels/cfd/StencilBodies.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>
#include <type_traits>

namespace hikiln::cfd {

/// \brief The operator A x = alpha x - div(beta grad x) on a grid with its boundary closures.
/// alpha may be an empty View (alpha = 0); beta[2] is unused on a 2D grid.
template <class MemorySpace> struct CellOperator {
  using memory_space = MemorySpace;
  Grid grid;
  AxisClosure axis[3];
  Field<MemorySpace> alpha;   ///< cell-centred, or empty for alpha = 0
  Field<MemorySpace> beta[3]; ///< FaceX, FaceY, FaceZ coefficients

  /// \brief True when the operator has an alpha term.
  KOKKOS_INLINE_FUNCTION bool hasAlpha() const { return alpha.extent(0) > 0; }
};

/// \brief Splits A x at cell (i, j, k) into diag * x(i, j, k) - rest: diag is the diagonal of
/// A (boundary closures folded in), rest the neighbour and (affine) boundary terms. Axes: the
/// axes along which (i, j, k) is known to have its neighbours inside the grid (no closures
/// evaluated there; BoxSplit.hpp).
/// scale = GridScales(op.grid), computed once per launch.
template <unsigned Axes, int Dims, bool HasAlpha, class MemorySpace, class XView>
KOKKOS_FORCEINLINE_FUNCTION void cellStencil(CellOperator<MemorySpace> const& op,
                                             GridScales const& scale, XView const& x, int i, int j,
                                             int k, bool affine, double& diag, double& rest) {
  const int g = op.grid.ghost;
  const int gz = op.grid.template ghostZOf<Dims>();
  if constexpr (HasAlpha) {
    diag = op.alpha(i + g, j + g, k + gz);
  } else {
    diag = 0.0;
  }
  rest = 0.0;
  const double cx = scale.inv2(0);
  {
    constexpr bool inside = interiorAlong(Axes, 0);
    const Neighbour up = upOf<inside>(op.axis[0], i, affine);
    const Neighbour dn = downOf<inside>(op.axis[0], i, affine);
    const double bu = cx * op.beta[0](i + 1 + g, j + g, k + gz);
    const double bd = cx * op.beta[0](i + g, j + g, k + gz);
    diag += bu * up.diag + bd * dn.diag;
    rest += bu * neighbourValue<inside>(up, x(up.index + g, j + g, k + gz)) +
            bd * neighbourValue<inside>(dn, x(dn.index + g, j + g, k + gz));
  }
  const double cy = scale.inv2(1);
  {
    constexpr bool inside = interiorAlong(Axes, 1);
    const Neighbour up = upOf<inside>(op.axis[1], j, affine);
    const Neighbour dn = downOf<inside>(op.axis[1], j, affine);
    const double bu = cy * op.beta[1](i + g, j + 1 + g, k + gz);
    const double bd = cy * op.beta[1](i + g, j + g, k + gz);
    diag += bu * up.diag + bd * dn.diag;
    rest += bu * neighbourValue<inside>(up, x(i + g, up.index + g, k + gz)) +
            bd * neighbourValue<inside>(dn, x(i + g, dn.index + g, k + gz));
  }
  if constexpr (Dims == 3) {
    const double cz = scale.inv2(2);
    constexpr bool inside = interiorAlong(Axes, 2);
    const Neighbour up = upOf<inside>(op.axis[2], k, affine);
    const Neighbour dn = downOf<inside>(op.axis[2], k, affine);
    const double bu = cz * op.beta[2](i + g, j + g, k + 1 + gz);
    const double bd = cz * op.beta[2](i + g, j + g, k + gz);
    diag += bu * up.diag + bd * dn.diag;
    rest += bu * neighbourValue<inside>(up, x(i + g, j + g, up.index + gz)) +
            bd * neighbourValue<inside>(dn, x(i + g, j + g, dn.index + gz));
  }
}

/// \brief The interior/shell split of the cells of op's grid.
template <class MemorySpace> BoxSplit cellSplit(CellOperator<MemorySpace> const& op) {
  const int lo[3] = {0, 0, 0};
  const int hi[3] = {op.grid.nx, op.grid.ny, op.grid.nz};
  return splitUnknowns(op.grid, lo, hi);
}

namespace detail {

/// The cell stencil at (i, j, k) of op applied to x (a stencil for StencilBodies.hpp).
template <class MemorySpace, int Dims, bool HasAlpha> struct CellStencil {
  using field_type = Field<MemorySpace>;
  CellOperator<MemorySpace> op;
  GridScales scale;
  field_type x;
  bool affine;
  int ghost, ghostZ;
  CellStencil(CellOperator<MemorySpace> const& o, field_type const& xIn, bool aff)
      : op(o), scale(o.grid), x(xIn), affine(aff), ghost(o.grid.ghost), ghostZ(o.grid.ghostZ()) {}
  template <unsigned Axes>
  KOKKOS_FORCEINLINE_FUNCTION void stencil(int i, int j, int k, double& diag, double& rest) const {
    cellStencil<Axes, Dims, HasAlpha>(op, scale, x, i, j, k, affine, diag, rest);
  }
};

/// Calls f(dims, hasAlpha) with op's dimension count and alpha term as compile-time constants
/// (std::integral_constant), so that a launch's stencil has no run-time branch per cell.
template <class MemorySpace, class F>
void withCellForm(CellOperator<MemorySpace> const& op, F&& f) {
  const bool alpha = op.hasAlpha();
  if (op.grid.is3D()) {
    alpha ? f(std::integral_constant<int, 3>(), std::true_type())
          : f(std::integral_constant<int, 3>(), std::false_type());
  } else {
    alpha ? f(std::integral_constant<int, 2>(), std::true_type())
          : f(std::integral_constant<int, 2>(), std::false_type());
  }
}

/// The CellStencil type of withCellForm()'s arguments.
template <class MemorySpace, class D, class A>
using CellStencilOf = CellStencil<MemorySpace, D::value, A::value>;

} // namespace detail

/// \brief y = A x on every cell (affine: with the boundary values).
template <class ExecutionSpace, class MemorySpace>
void applyCellOperator(ExecutionSpace const& space, CellOperator<MemorySpace> const& op,
                       Field<MemorySpace> const& x, Field<MemorySpace> const& y, bool affine) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::applyCellOperator: fields not accessible from the execution space");
  detail::withCellForm(op, [&](auto dims, auto alpha) {
    using Stencil = detail::CellStencilOf<MemorySpace, decltype(dims), decltype(alpha)>;
    forEachSplitCell(space, "hikiln::cfd::applyCellOperator", cellSplit(op),
                     StencilApply<Stencil>{{op, x, affine}, y});
  });
}

/// \brief r = f - A x on every cell.
template <class ExecutionSpace, class MemorySpace>
void cellResidual(ExecutionSpace const& space, CellOperator<MemorySpace> const& op,
                  Field<MemorySpace> const& x, Field<MemorySpace> const& f,
                  Field<MemorySpace> const& r, bool affine) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::cellResidual: fields not accessible from the execution space");
  detail::withCellForm(op, [&](auto dims, auto alpha) {
    using Stencil = detail::CellStencilOf<MemorySpace, decltype(dims), decltype(alpha)>;
    forEachSplitCell(space, "hikiln::cfd::cellResidual", cellSplit(op),
                     StencilResidual<Stencil>{{op, x, affine}, f, r});
  });
}

/// \brief r = f - A x on every cell; returns the sum of r^2.
template <class ExecutionSpace, class MemorySpace>
double cellResidualNorm2(ExecutionSpace const& space, CellOperator<MemorySpace> const& op,
                         Field<MemorySpace> const& x, Field<MemorySpace> const& f,
                         Field<MemorySpace> const& r, bool affine) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::cellResidualNorm2: fields not accessible from the execution space");
  double sum = 0.0;
  detail::withCellForm(op, [&](auto dims, auto alpha) {
    using Stencil = detail::CellStencilOf<MemorySpace, decltype(dims), decltype(alpha)>;
    sum = sumOverSplitCells(space, "hikiln::cfd::cellResidualNorm2", cellSplit(op),
                            StencilResidual<Stencil>{{op, x, affine}, f, r});
  });
  return sum;
}

namespace detail {
/// \brief Red-black sweep for A x = f: colour `colour` alone, or (both) that colour and then
/// the other (see smoothCellColour and smoothCellRedBlack).
template <class ExecutionSpace, class MemorySpace>
void smoothCell(ExecutionSpace const& space, CellOperator<MemorySpace> const& op,
                Field<MemorySpace> const& x, Field<MemorySpace> const& f, int colour, bool both,
                bool affine) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::smoothCell: fields not accessible from the execution space");
  withCellForm(op, [&](auto dims, auto alpha) {
    using Stencil = CellStencilOf<MemorySpace, decltype(dims), decltype(alpha)>;
    forEachSplitSweepCell(space, "hikiln::cfd::smoothCell", cellSplit(op), colour, both,
                          StencilGaussSeidel<Stencil>{{op, x, affine}, f});
  });
}
} // namespace detail

/// \brief One colour of a red-black Gauss-Seidel sweep for A x = f: every cell with
/// (i + j + k) % 2 == colour is solved for with its neighbours (the other colour) fixed. The
/// result does not depend on the order or the thread count.
template <class ExecutionSpace, class MemorySpace>
void smoothCellColour(ExecutionSpace const& space, CellOperator<MemorySpace> const& op,
                      Field<MemorySpace> const& x, Field<MemorySpace> const& f, int colour,
                      bool affine) {
  detail::smoothCell(space, op, x, f, colour, false, affine);
}

/// \brief A red-black Gauss-Seidel sweep for A x = f: colour `first`, then the other, as two
/// smoothCellColour() calls give it (on the host in one pass, forEachSplitRedBlackCell()).
template <class ExecutionSpace, class MemorySpace>
void smoothCellRedBlack(ExecutionSpace const& space, CellOperator<MemorySpace> const& op,
                        Field<MemorySpace> const& x, Field<MemorySpace> const& f, int first,
                        bool affine) {
  detail::smoothCell(space, op, x, f, first, true, affine);
}

/// \brief Harmonic mean 2 a b / (a + b) of two positive coefficients (0 if both are 0).
KOKKOS_INLINE_FUNCTION double harmonicMean(double a, double b) {
  const double s = a + b;
  return s > 0.0 ? 2.0 * a * b / s : 0.0;
}

/// \brief Face coefficients beta[axis] from cell values c (e.g. 1/rho) by harmonic means of the
/// two cells beside each face; on a non-periodic boundary face the inside cell's value, on a
/// periodic one the wrapped neighbour. Every face (boundary faces included) is written.
template <class ExecutionSpace, class MemorySpace>
void harmonicFaceCoefficients(ExecutionSpace const& space, Grid const& grid,
                              AxisClosure const (&axes)[3], Field<MemorySpace> const& c,
                              Field<MemorySpace> const (&beta)[3]) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::harmonicFaceCoefficients: fields not accessible");
  const int g = grid.ghost;
  const int gz = grid.ghostZ();
  const int numAxes = grid.is3D() ? 3 : 2;
  for (int a = 0; a < numAxes; ++a) {
    const AxisClosure ax = axes[a];
    const auto b = beta[a];
    const int hi[3] = {grid.nx + (a == 0), grid.ny + (a == 1), grid.nz + (a == 2)};
    Kokkos::parallel_for(
        "hikiln::cfd::harmonicFaceCoefficients", gridPolicy(space, {0, 0, 0}, hi),
        KOKKOS_LAMBDA(const int i, const int j, const int k) {
          int idx[3] = {i, j, k};
          const int face = idx[a];
          // the cells on the low and high side of the face, wrapped or mirrored at boundaries
          int lo = face - 1;
          int up = face;
          if (ax.periodic) {
            lo = ax.wrap(lo);
            up = ax.wrap(up);
          } else {
            lo = lo < 0 ? 0 : lo;
            up = up >= ax.n ? ax.n - 1 : up;
          }
          idx[a] = lo;
          const double cl = c(idx[0] + g, idx[1] + g, idx[2] + gz);
          idx[a] = up;
          const double cu = c(idx[0] + g, idx[1] + g, idx[2] + gz);
          b(i + g, j + g, k + gz) = harmonicMean(cl, cu);
        });
  }
}

} // namespace hikiln::cfd
