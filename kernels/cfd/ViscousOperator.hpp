#pragma once
/// \file ViscousOperator.hpp
/// \brief The implicit momentum operator on the MAC grid,
///   A u = alpha u - div(mu (grad u + grad u^T)),
/// alpha = rho / dt on the faces of each component (>= 0), mu > 0 in cells. Component c at its
/// face is coupled to itself through the normal stress 2 mu du_c/dx_c (mu at the cells beside
/// the face) and the shear stresses mu (du_c/dx_a + du_a/dx_c) (mu on the cell edges, the
/// arithmetic or harmonic mean of the four cells around each edge, EdgeViscosity); the du_a/dx_c
/// parts couple the components. The discretisation is symmetric positive definite (symmetric
/// positive semi-definite when alpha = 0 and every axis is periodic).
///
/// Boundaries: tangential components are no-slip with the side's velocity (ghost 2 V - u), the
/// normal component is given on the boundary faces (stored in the field's boundary nodes; 0 on
/// coarse levels). Kernels: apply, residual, red-black Gauss-Seidel per component, edge
/// viscosities.
///
/// Closed faces (optional `open`, the cut-cell face apertures): a stress whose strain reads a
/// closed face (aperture 0, held at the wall velocity by the caller's penalty) is left out: the
/// normal stress of a cell along axis a when one of its two a-faces is closed, the shear stress
/// on an edge when one of its four faces is closed (edgeViscosities). The wall's pull on the
/// fluid is then only what the caller's wall law puts on the cut faces (a Coulomb cap). Whole
/// stress terms are dropped, so the operator stays a sum of squares (symmetric, semi-definite).

#include "kernels/cfd/AxisClosure.hpp"
#include "kernels/cfd/BoxSplit.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/SplitLoop.hpp"
#include "kernels/cfd/StencilBodies.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>
#include <type_traits>

namespace hikiln::cfd {

/// \brief The MAC velocity components u, v, w (w unused in 2D).
template <class MemorySpace> struct VelocityFields { Field<MemorySpace> comp[3]; };

/// \brief Slot of the edge viscosity normal-centred along axes a and b (a != b): 0 = XY, 1 = XZ,
/// 2 = YZ.
KOKKOS_INLINE_FUNCTION constexpr int edgeSlot(int a, int b) {
  return a + b - 1;
}

/// \brief The staggering of edge slot s.
KOKKOS_INLINE_FUNCTION constexpr Staggering edgeStaggering(int slot) {
  return slot == 0 ? Staggering::EdgeXY : (slot == 1 ? Staggering::EdgeXZ : Staggering::EdgeYZ);
}

/// \brief True when the face of component c at p (face indices without the ghost offset) lies
/// in the grid and is closed (aperture <= 0: held at the shell's velocity). Ghost faces, beyond
/// a side of the grid, hold that side's boundary values and count as open.
/// shellHeldFaceOf<Dims> is the same test on a grid of Dims dimensions known at compile time.
template <int Dims, class ApertureView>
KOKKOS_INLINE_FUNCTION bool shellHeldFaceOf(ApertureView const& aperture, Grid const& grid, int c,
                                            int const (&p)[3]) {
  const int n[3] = {grid.nx, grid.ny, grid.nz};
  for (int e = 0; e < Dims; ++e) {
    if (p[e] < 0 || p[e] >= n[e] + (e == c ? 1 : 0)) {
      return false;
    }
  }
  return aperture(p[0] + grid.ghost, p[1] + grid.ghost, p[2] + grid.ghostZ()) <= 0.0;
}
template <class ApertureView>
KOKKOS_INLINE_FUNCTION bool shellHeldFace(ApertureView const& aperture, Grid const& grid, int c,
                                          int const (&p)[3]) {
  return grid.is3D() ? shellHeldFaceOf<3>(aperture, grid, c, p)
                     : shellHeldFaceOf<2>(aperture, grid, c, p);
}

/// \brief The operator alpha u - div(mu (grad u + grad u^T)) with its boundary closures
/// (axis[component][axis]).
template <class MemorySpace> struct ViscousOperator {
  using memory_space = MemorySpace;
  Grid grid;
  AxisClosure axis[3][3];
  Field<MemorySpace> alpha[3];      ///< per component on its faces; empty: alpha = 0
  Field<MemorySpace> mu;            ///< cell-centred viscosity
  Field<MemorySpace> muEdge[3];     ///< edge viscosities (edgeSlot)
  VelocityFields<MemorySpace> open; ///< face apertures (see the file comment); empty: all open

  /// \brief Number of velocity components (2 or 3).
  KOKKOS_INLINE_FUNCTION int numComponents() const { return grid.is3D() ? 3 : 2; }
  /// \brief True when the operator has an alpha term.
  KOKKOS_INLINE_FUNCTION bool hasAlpha() const { return alpha[0].extent(0) > 0; }
  /// \brief True when stresses that read closed faces are left out.
  KOKKOS_INLINE_FUNCTION bool masksClosedFaces() const { return open.comp[0].extent(0) > 0; }
};

/// \brief The part of viscousStencil along axis A (a compile-time axis, so that the index
/// arithmetic and the `A == C` choice fold away; as a loop over the axes GCC kept the axis in a
/// register and the index arrays on the stack, perf/README.md).
template <unsigned Axes, int Dims, bool Masks, int C, int A, class MemorySpace>
KOKKOS_FORCEINLINE_FUNCTION void
viscousStencilAxis(ViscousOperator<MemorySpace> const& op, GridScales const& scale,
                   VelocityFields<MemorySpace> const& vel, int i, int j, int k, bool affine,
                   double& diag, double& rest) {
  constexpr int c = C;
  constexpr int a = A;
  constexpr bool insideA = interiorAlong(Axes, a), insideC = interiorAlong(Axes, c);
  const int off[3] = {op.grid.ghost, op.grid.ghost, op.grid.template ghostZOf<Dims>()};
  const int idx[3] = {i, j, k};
  const auto& x = vel.comp[c];
  const AxisClosure& ax = op.axis[c][a];
  double cu, cd;
  if constexpr (a == c) {
    // normal stress: 2 mu in the cells above and below the face
    int cell[3] = {i, j, k};
    cell[a] = idx[a];
    cu = 2.0 * op.mu(cell[0] + off[0], cell[1] + off[1], cell[2] + off[2]);
    cell[a] = wrapOf<insideA>(ax, idx[a] - 1);
    cd = 2.0 * op.mu(cell[0] + off[0], cell[1] + off[1], cell[2] + off[2]);
  } else {
    // shear stress on the (c, a) edges above and below along a
    const auto& me = op.muEdge[edgeSlot(a < c ? a : c, a < c ? c : a)];
    int e[3] = {i, j, k};
    e[a] = idx[a] + 1;
    cu = me(e[0] + off[0], e[1] + off[1], e[2] + off[2]);
    e[a] = idx[a];
    cd = me(e[0] + off[0], e[1] + off[1], e[2] + off[2]);
    // coupling: d u_a / d x_c on those edges (u_a is node-centred along a, cell-centred along c)
    const auto& ua = vel.comp[a];
    const AxisClosure& alongA = op.axis[a][a];
    const AxisClosure& alongC = op.axis[a][c];
    int p[3] = {i, j, k};
    const int cAbove = idx[c];
    const int cBelow = wrapOf<insideC>(alongC, idx[c] - 1);
    p[a] = wrapOf<insideA>(alongA, idx[a] + 1);
    p[c] = cAbove;
    const double upHigh = ua(p[0] + off[0], p[1] + off[1], p[2] + off[2]);
    p[c] = cBelow;
    const double upLow = ua(p[0] + off[0], p[1] + off[1], p[2] + off[2]);
    p[a] = idx[a];
    p[c] = cAbove;
    const double dnHigh = ua(p[0] + off[0], p[1] + off[1], p[2] + off[2]);
    p[c] = cBelow;
    const double dnLow = ua(p[0] + off[0], p[1] + off[1], p[2] + off[2]);
    rest += (cu * (upHigh - upLow) - cd * (dnHigh - dnLow)) * scale.invMixed(a, c);
  }
  const Neighbour up = upOf<insideA>(ax, idx[a], affine);
  const Neighbour dn = downOf<insideA>(ax, idx[a], affine);
  if constexpr (a == c && Masks) {
    // the normal strain of the cell above (below) reads this face and the one above (below).
    // The stress is kept by a factor 1 or 0 (exact for the finite cu, cd >= 0) rather than a
    // select, which GCC turns into branches that stop it vectorising the row.
    const auto& open = op.open.comp[c];
    int q[3] = {i + off[0], j + off[1], k + off[2]};
    const double here = open(q[0], q[1], q[2]) > 0.0 ? 1.0 : 0.0;
    q[a] = up.index + off[a];
    const double above = open(q[0], q[1], q[2]) > 0.0 ? 1.0 : 0.0;
    q[a] = dn.index + off[a];
    const double below = open(q[0], q[1], q[2]) > 0.0 ? 1.0 : 0.0;
    cu *= here * above;
    cd *= here * below;
  }
  const double inv2 = scale.inv2(a);
  cu *= inv2;
  cd *= inv2;
  diag += cu * up.diag + cd * dn.diag;
  int q[3] = {i, j, k};
  q[a] = up.index;
  rest += cu * neighbourValue<insideA>(up, x(q[0] + off[0], q[1] + off[1], q[2] + off[2]));
  q[a] = dn.index;
  rest += cd * neighbourValue<insideA>(dn, x(q[0] + off[0], q[1] + off[1], q[2] + off[2]));
}

/// \brief Splits (A u)_C at unknown (i, j, k) of component C (Dims axes) into diag * u_c(i, j, k) -
/// rest: rest holds the neighbours of the same component, the other components (shear coupling)
/// and, when affine, the boundary values. Axes (BoxSplit.hpp): along these axes no neighbour,
/// viscosity or coupling read needs a boundary closure or wrap-around (see componentSplit; the
/// part along axis a reads along a, and its coupling term along C too). Forced inline (with the
/// bodies of StencilBodies.hpp): left to itself, the compiler keeps it out of line in the large
/// solver translation units, a call per unknown that doubled the cost of a V-cycle.
template <unsigned Axes, int Dims, int C, bool HasAlpha, bool Masks, class MemorySpace>
KOKKOS_FORCEINLINE_FUNCTION void
viscousStencil(ViscousOperator<MemorySpace> const& op, GridScales const& scale,
               VelocityFields<MemorySpace> const& vel, int i, int j, int k, bool affine,
               double& diag, double& rest) {
  if constexpr (HasAlpha) {
    diag = op.alpha[C](i + op.grid.ghost, j + op.grid.ghost, k + op.grid.template ghostZOf<Dims>());
  } else {
    diag = 0.0;
  }
  rest = 0.0;
  // the axes in order, as the sums have always been taken (bitwise the same results)
  viscousStencilAxis<Axes, Dims, Masks, C, 0>(op, scale, vel, i, j, k, affine, diag, rest);
  viscousStencilAxis<Axes, Dims, Masks, C, 1>(op, scale, vel, i, j, k, affine, diag, rest);
  if constexpr (Dims == 3) {
    viscousStencilAxis<Axes, Dims, Masks, C, 2>(op, scale, vel, i, j, k, affine, diag, rest);
  }
}

/// \brief Interior/shell split of the unknowns of component c: the interior excludes the first
/// and last unknown along every active axis, so no read there needs a closure or wrap-around.
template <class MemorySpace>
BoxSplit componentSplit(ViscousOperator<MemorySpace> const& op, int c) {
  const int lo[3] = {op.axis[c][0].begin(), op.axis[c][1].begin(), op.axis[c][2].begin()};
  const int hi[3] = {op.axis[c][0].end(), op.axis[c][1].end(), op.axis[c][2].end()};
  return splitUnknowns(op.grid, lo, hi);
}

namespace detail {

/// The viscous stencil of component C at (i, j, k) of op applied to u (a stencil for
/// StencilBodies.hpp; x is u.comp[C], the other components enter the coupling terms). HasAlpha
/// and Masks are op.hasAlpha() and op.masksClosedFaces() (withViscousForm()).
template <int Dims, int C, bool HasAlpha, bool Masks, class MemorySpace> struct ViscousStencil {
  using field_type = Field<MemorySpace>;
  ViscousOperator<MemorySpace> op;
  GridScales scale;
  VelocityFields<MemorySpace> u;
  field_type x;
  bool affine;
  int ghost, ghostZ;
  ViscousStencil(ViscousOperator<MemorySpace> const& o, VelocityFields<MemorySpace> const& uIn,
                 bool aff)
      : op(o), scale(o.grid), u(uIn), x(uIn.comp[C]), affine(aff), ghost(o.grid.ghost),
        ghostZ(o.grid.ghostZ()) {}
  template <unsigned Axes>
  KOKKOS_FORCEINLINE_FUNCTION void stencil(int i, int j, int k, double& diag, double& rest) const {
    viscousStencil<Axes, Dims, C, HasAlpha, Masks>(op, scale, u, i, j, k, affine, diag, rest);
  }
};

/// Calls f(hasAlpha, masks) with op.hasAlpha() and op.masksClosedFaces() as compile-time
/// constants (std::bool_constant): a launch's stencil then has no run-time branch per unknown,
/// which lets the compiler vectorise its interior rows.
template <class MemorySpace, class F>
void withViscousForm(ViscousOperator<MemorySpace> const& op, F&& f) {
  const bool alpha = op.hasAlpha(), masks = op.masksClosedFaces();
  if (alpha) {
    masks ? f(std::true_type(), std::true_type()) : f(std::true_type(), std::false_type());
  } else {
    masks ? f(std::false_type(), std::true_type()) : f(std::false_type(), std::false_type());
  }
}

/// The ViscousStencil type of withViscousForm()'s arguments.
template <int Dims, int C, class MemorySpace, class A, class M>
using ViscousStencilOf = ViscousStencil<Dims, C, A::value, M::value, MemorySpace>;

/// \brief out_C = (A u)_C (see applyViscousOperator).
template <int Dims, int C, class ExecutionSpace, class MemorySpace>
void applyViscousComponent(ExecutionSpace const& space, ViscousOperator<MemorySpace> const& op,
                           VelocityFields<MemorySpace> const& u,
                           VelocityFields<MemorySpace> const& out, bool affine) {
  withViscousForm(op, [&](auto alpha, auto masks) {
    using Stencil = ViscousStencilOf<Dims, C, MemorySpace, decltype(alpha), decltype(masks)>;
    forEachSplitCell(space, "hikiln::cfd::applyViscousOperator", componentSplit(op, C),
                     StencilApply<Stencil>{{op, u, affine}, out.comp[C]});
  });
}

/// \brief r_C = f_C - (A u)_C; returns the sum of r_C^2 (see viscousResidual).
template <int Dims, int C, class ExecutionSpace, class MemorySpace>
double viscousResidualComponent(ExecutionSpace const& space, ViscousOperator<MemorySpace> const& op,
                                VelocityFields<MemorySpace> const& u,
                                VelocityFields<MemorySpace> const& f,
                                VelocityFields<MemorySpace> const& r, bool affine) {
  double sum = 0.0;
  withViscousForm(op, [&](auto alpha, auto masks) {
    using Stencil = ViscousStencilOf<Dims, C, MemorySpace, decltype(alpha), decltype(masks)>;
    sum = sumOverSplitCells(space, "hikiln::cfd::viscousResidual", componentSplit(op, C),
                            StencilResidual<Stencil>{{op, u, affine}, f.comp[C], r.comp[C]});
  });
  return sum;
}

/// \brief Red-black sweep over component C: colour `colour` alone, or (both) that colour and then
/// the other (see smoothViscousColour and smoothViscousRedBlack).
template <int Dims, int C, class ExecutionSpace, class MemorySpace>
void smoothViscousComponent(ExecutionSpace const& space, ViscousOperator<MemorySpace> const& op,
                            VelocityFields<MemorySpace> const& u,
                            VelocityFields<MemorySpace> const& f, int colour, bool both,
                            bool affine) {
  withViscousForm(op, [&](auto alpha, auto masks) {
    using Stencil = ViscousStencilOf<Dims, C, MemorySpace, decltype(alpha), decltype(masks)>;
    forEachSplitSweepCell(space, "hikiln::cfd::smoothViscous", componentSplit(op, C), colour, both,
                          StencilGaussSeidel<Stencil>{{op, u, affine}, f.comp[C]});
  });
}

/// \brief smoothViscousComponent for the run-time dimension count and component c.
template <class ExecutionSpace, class MemorySpace>
void smoothViscous(ExecutionSpace const& space, ViscousOperator<MemorySpace> const& op,
                   VelocityFields<MemorySpace> const& u, VelocityFields<MemorySpace> const& f,
                   int c, int colour, bool both, bool affine) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::smoothViscous: fields not accessible");
  if (op.grid.is3D()) {
    if (c == 0) {
      smoothViscousComponent<3, 0>(space, op, u, f, colour, both, affine);
    } else if (c == 1) {
      smoothViscousComponent<3, 1>(space, op, u, f, colour, both, affine);
    } else {
      smoothViscousComponent<3, 2>(space, op, u, f, colour, both, affine);
    }
  } else if (c == 0) {
    smoothViscousComponent<2, 0>(space, op, u, f, colour, both, affine);
  } else {
    smoothViscousComponent<2, 1>(space, op, u, f, colour, both, affine);
  }
}

} // namespace detail

/// \brief out = A u for every component (affine: with the boundary values).
template <class ExecutionSpace, class MemorySpace>
void applyViscousOperator(ExecutionSpace const& space, ViscousOperator<MemorySpace> const& op,
                          VelocityFields<MemorySpace> const& u,
                          VelocityFields<MemorySpace> const& out, bool affine) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::applyViscousOperator: fields not accessible");
  if (op.grid.is3D()) {
    detail::applyViscousComponent<3, 0>(space, op, u, out, affine);
    detail::applyViscousComponent<3, 1>(space, op, u, out, affine);
    detail::applyViscousComponent<3, 2>(space, op, u, out, affine);
  } else {
    detail::applyViscousComponent<2, 0>(space, op, u, out, affine);
    detail::applyViscousComponent<2, 1>(space, op, u, out, affine);
  }
}

/// \brief r = f - A u for every component; returns the sum of r^2 over all unknowns.
template <class ExecutionSpace, class MemorySpace>
double viscousResidual(ExecutionSpace const& space, ViscousOperator<MemorySpace> const& op,
                       VelocityFields<MemorySpace> const& u, VelocityFields<MemorySpace> const& f,
                       VelocityFields<MemorySpace> const& r, bool affine) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::viscousResidual: fields not accessible");
  if (op.grid.is3D()) {
    return detail::viscousResidualComponent<3, 0>(space, op, u, f, r, affine) +
           detail::viscousResidualComponent<3, 1>(space, op, u, f, r, affine) +
           detail::viscousResidualComponent<3, 2>(space, op, u, f, r, affine);
  }
  return detail::viscousResidualComponent<2, 0>(space, op, u, f, r, affine) +
         detail::viscousResidualComponent<2, 1>(space, op, u, f, r, affine);
}

/// \brief One colour of a red-black Gauss-Seidel sweep over component c (the other components
/// held fixed): every unknown with (i + j + k) % 2 == colour is solved for.
template <class ExecutionSpace, class MemorySpace>
void smoothViscousColour(ExecutionSpace const& space, ViscousOperator<MemorySpace> const& op,
                         VelocityFields<MemorySpace> const& u, VelocityFields<MemorySpace> const& f,
                         int c, int colour, bool affine) {
  detail::smoothViscous(space, op, u, f, c, colour, false, affine);
}

/// \brief A red-black sweep over component c: colour `first`, then the other, as two
/// smoothViscousColour() calls give it (on the host in one pass, forEachSplitRedBlackCell()).
template <class ExecutionSpace, class MemorySpace>
void smoothViscousRedBlack(ExecutionSpace const& space, ViscousOperator<MemorySpace> const& op,
                           VelocityFields<MemorySpace> const& u,
                           VelocityFields<MemorySpace> const& f, int c, int first, bool affine) {
  detail::smoothViscous(space, op, u, f, c, first, true, affine);
}

/// \brief How an edge's viscosity is made from the four cells around it.
///
/// Harmonic: where a flowing layer (tens of Pa s) meets the bed's plug (the 1e5 Pa s cap) the
/// shear stress is continuous, so the cells act in series. The arithmetic mean gives such an edge
/// half the plug's viscosity and holds the flowing layer: a 2D drum of m = 0.6 (31 deg) stood at
/// 44 deg on 16^2 and 32^2 cells and 42.7 deg on 64^2 under the incremental projection; with the
/// harmonic mean at 30.1, 32.7 and 33.9 deg (docs/compare.md, test_cfd_drum_repose_angle).
/// Arithmetic stays the default until the shipped cases are rerun with the harmonic mean.
enum class EdgeViscosity { Arithmetic, Harmonic };

/// \brief Edge viscosities from cell viscosities: the `mean` of the four cells around each edge
/// (harmonic: 0 if one of them is 0; cells beyond a non-periodic boundary mirror the inside ones;
/// periodic axes wrap). Every edge, boundary edges included, is written. With `open` (face
/// apertures), an edge whose shear strain reads a closed face gets 0 (see the file comment).
template <class ExecutionSpace, class MemorySpace>
void edgeViscosities(ExecutionSpace const& space, Grid const& grid, bool const (&periodic)[3],
                     Field<MemorySpace> const& mu, Field<MemorySpace> const (&muEdge)[3],
                     VelocityFields<MemorySpace> const& open = VelocityFields<MemorySpace>(),
                     EdgeViscosity mean = EdgeViscosity::Arithmetic) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::cfd::edgeViscosities: fields not accessible");
  const int off[3] = {grid.ghost, grid.ghost, grid.ghostZ()};
  const int n[3] = {grid.nx, grid.ny, grid.nz};
  const bool per[3] = {periodic[0], periodic[1], periodic[2]};
  const int numSlots = grid.is3D() ? 3 : 1;
  const bool masked = open.comp[0].extent(0) > 0;
  const bool harmonic = mean == EdgeViscosity::Harmonic;
  for (int slot = 0; slot < numSlots; ++slot) {
    const int a = slot == 2 ? 1 : 0;
    const int b = slot == 0 ? 1 : 2;
    const auto out = muEdge[slot];
    const int hi[3] = {n[0] + (a == 0 || b == 0), n[1] + (a == 1 || b == 1),
                       n[2] + (a == 2 || b == 2)};
    Kokkos::parallel_for(
        "hikiln::cfd::edgeViscosities", gridPolicy(space, {0, 0, 0}, hi),
        KOKKOS_LAMBDA(const int i, const int j, const int k) {
          const auto cellIndex = [&](int axis, int node, int side) {
            int cell = node - 1 + side;
            if (per[axis]) {
              cell = cell < 0 ? cell + n[axis] : (cell >= n[axis] ? cell - n[axis] : cell);
            } else {
              cell = cell < 0 ? 0 : (cell >= n[axis] ? n[axis] - 1 : cell);
            }
            return cell;
          };
          int idx[3] = {i, j, k};
          if (masked) {
            // the shear strain du_a/dx_b + du_b/dx_a: u_a at node idx[a] in the cells beside
            // the edge along b, and u_b the other way round
            for (int side = 0; side < 2; ++side) {
              int fa[3] = {i, j, k}, fb[3] = {i, j, k};
              fa[a] = per[a] && idx[a] == n[a] ? 0 : idx[a];
              fa[b] = cellIndex(b, idx[b], side);
              fb[b] = per[b] && idx[b] == n[b] ? 0 : idx[b];
              fb[a] = cellIndex(a, idx[a], side);
              if (open.comp[a](fa[0] + off[0], fa[1] + off[1], fa[2] + off[2]) <= 0.0 ||
                  open.comp[b](fb[0] + off[0], fb[1] + off[1], fb[2] + off[2]) <= 0.0) {
                out(i + off[0], j + off[1], k + off[2]) = 0.0;
                return;
              }
            }
          }
          double sum = 0.0; // of the viscosities, or of their inverses
          for (int sa = 0; sa < 2; ++sa) {
            for (int sb = 0; sb < 2; ++sb) {
              int cell[3] = {i, j, k};
              cell[a] = cellIndex(a, idx[a], sa);
              cell[b] = cellIndex(b, idx[b], sb);
              const double m = mu(cell[0] + off[0], cell[1] + off[1], cell[2] + off[2]);
              if (harmonic && !(m > 0.0)) {
                out(i + off[0], j + off[1], k + off[2]) = 0.0;
                return;
              }
              sum += harmonic ? 1.0 / m : m;
            }
          }
          out(i + off[0], j + off[1], k + off[2]) = harmonic ? 4.0 / sum : 0.25 * sum;
        });
  }
}

} // namespace hikiln::cfd
