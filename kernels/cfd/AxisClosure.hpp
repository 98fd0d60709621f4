#pragma once
/// \file AxisClosure.hpp
/// \brief How a grid operator sees its neighbours along one axis, boundaries included, without
/// ghost cells: the stencils, smoothers and transfer operators ask an AxisClosure for the
/// neighbour of unknown i, and get an index plus weights that encode periodic wrap-around,
/// zero-gradient walls and Dirichlet values. No ghost exchange is then needed between the two
/// colours of a red-black sweep, and every level of a multigrid hierarchy reuses the same code.
///
/// Unknowns along an axis: cell-centred fields have cells [0, n); node-centred fields (the face
/// normal velocity) have nodes [1, n) between two non-periodic boundaries, whose boundary nodes 0
/// and n hold given data (the boundary velocity on the finest level, 0 for a correction), and
/// nodes [0, n) when periodic (node n is node 0).

#include "kernels/cfd/Grid.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::cfd {

/// \brief A neighbour seen from unknown x_c: its value is
/// (1 - diag) * x_c + off * x(index) + lift.
/// An ordinary neighbour has off = diag = 1; a zero-gradient boundary off = diag = 0 (the ghost
/// mirrors x_c); a Dirichlet boundary between cells off = 0, diag = 2, lift = 2 value (the ghost
/// is 2 value - x_c, so the face value is `value`).
struct Neighbour {
  int index;
  double off;
  double diag;
  double lift;
};

/// \brief Treatment of one non-periodic side of an axis.
enum class ClosureKind : int {
  Neumann = 0,       ///< zero normal gradient (cell-centred scalar at a wall)
  DirichletCell = 1, ///< value given on the boundary face half a cell away (ghost = 2v - x_c)
  DirichletNode = 2, ///< the boundary node itself holds the given value (normal velocity)
};

/// \brief One axis of one field as an operator sees it (see the file comment).
struct AxisClosure {
  int n = 1;            ///< cells along the axis
  bool node = false;    ///< node-centred along this axis
  bool periodic = true; ///< periodic axis (node n is node 0, cell -1 is cell n - 1)
  bool active = true;   ///< false for z on a 2D grid: no stencil terms along this axis
  ClosureKind low = ClosureKind::Neumann;
  ClosureKind high = ClosureKind::Neumann;
  double lowValue = 0.0;  ///< Dirichlet value at the low side (DirichletCell only)
  double highValue = 0.0; ///< Dirichlet value at the high side (DirichletCell only)

  /// \brief First unknown index.
  KOKKOS_INLINE_FUNCTION int begin() const { return node && !periodic ? 1 : 0; }
  /// \brief One past the last unknown index.
  KOKKOS_INLINE_FUNCTION int end() const { return n; }
  /// \brief Number of unknowns.
  KOKKOS_INLINE_FUNCTION int count() const { return end() - begin(); }
  /// \brief Index i (cell or node) brought into [0, n) on a periodic axis (unchanged otherwise):
  /// cell -1 is cell n - 1 and node n is node 0.
  KOKKOS_INLINE_FUNCTION int wrap(int i) const {
    return !periodic ? i : (i < 0 ? i + n : (i >= n ? i - n : i));
  }
  /// \brief Neighbour i + 1 of unknown i; `affine` includes the Dirichlet values (lift).
  KOKKOS_INLINE_FUNCTION Neighbour up(int i, bool affine) const {
    const int j = i + 1;
    if (j < n) {
      return Neighbour{j, 1.0, 1.0, 0.0};
    }
    if (periodic) {
      return Neighbour{0, 1.0, 1.0, 0.0};
    }
    return node ? Neighbour{n, 1.0, 1.0, 0.0} : sideClosure(high, i, highValue, affine);
  }
  /// \brief Neighbour i - 1 of unknown i; `affine` includes the Dirichlet values (lift).
  KOKKOS_INLINE_FUNCTION Neighbour down(int i, bool affine) const {
    const int j = i - 1;
    if (j >= 0) {
      return Neighbour{j, 1.0, 1.0, 0.0};
    }
    if (periodic) {
      return Neighbour{n - 1, 1.0, 1.0, 0.0};
    }
    return sideClosure(low, i, lowValue, affine);
  }

private:
  /// \brief Ghost of a cell-centred unknown i at a non-periodic side.
  KOKKOS_INLINE_FUNCTION static Neighbour sideClosure(ClosureKind kind, int i, double value,
                                                      bool affine) {
    if (kind == ClosureKind::DirichletCell) {
      return Neighbour{i, 0.0, 2.0, affine ? 2.0 * value : 0.0};
    }
    return Neighbour{i, 0.0, 0.0, 0.0};
  }
};

/// \brief Neighbour i + 1 along ax; in the interior of the box (Interior = true) no boundary or
/// wrap-around can occur and the branches disappear at compile time.
template <bool Interior>
KOKKOS_INLINE_FUNCTION Neighbour upOf(AxisClosure const& ax, int i, bool affine) {
  if constexpr (Interior) {
    (void)ax;
    (void)affine;
    return Neighbour{i + 1, 1.0, 1.0, 0.0};
  } else {
    return ax.up(i, affine);
  }
}

/// \brief Neighbour i - 1 along ax (see upOf).
template <bool Interior>
KOKKOS_INLINE_FUNCTION Neighbour downOf(AxisClosure const& ax, int i, bool affine) {
  if constexpr (Interior) {
    (void)ax;
    (void)affine;
    return Neighbour{i - 1, 1.0, 1.0, 0.0};
  } else {
    return ax.down(i, affine);
  }
}

/// \brief The neighbour's value off * x + lift as a stencil's rest term takes it (x its stored
/// value); x itself in the interior, where off = 1 and lift = 0. The dropped `+ 0.0` could only
/// turn a -0.0 into +0.0, which the stencils' sums (started at +0.0, so never -0.0) do anyway:
/// the results are bitwise those of the full form, one add fewer per neighbour.
template <bool Interior>
KOKKOS_FORCEINLINE_FUNCTION double neighbourValue(Neighbour const& nb, double x) {
  if constexpr (Interior) {
    (void)nb;
    return x;
  } else {
    return nb.off * x + nb.lift;
  }
}

/// \brief ax.wrap(i), the identity in the interior.
template <bool Interior> KOKKOS_INLINE_FUNCTION int wrapOf(AxisClosure const& ax, int i) {
  if constexpr (Interior) {
    (void)ax;
    return i;
  } else {
    return ax.wrap(i);
  }
}

/// \brief The closures of a cell-centred scalar with boundary conditions bc on grid.
inline void scalarClosures(Grid const& grid, ScalarBoundaries const& bc, AxisClosure (&axes)[3]) {
  for (int a = 0; a < 3; ++a) {
    AxisClosure& c = axes[a];
    c = AxisClosure{};
    c.n = grid.cells(a);
    c.node = false;
    c.periodic = bc.periodic(a);
    c.active = a < 2 || grid.is3D();
    const auto kindOf = [](BoundaryKind k) {
      return k == BoundaryKind::Value ? ClosureKind::DirichletCell : ClosureKind::Neumann;
    };
    c.low = kindOf(bc.kind[2 * a]);
    c.high = kindOf(bc.kind[2 * a + 1]);
    c.lowValue = bc.value[2 * a];
    c.highValue = bc.value[2 * a + 1];
  }
}

/// \brief The closures of MAC velocity component `component` with boundary conditions bc: the
/// normal component is given on non-periodic sides (DirichletNode), the tangential ones are
/// no-slip with the side's velocity (DirichletCell), or zero-gradient at an Outflow side.
inline void velocityClosures(Grid const& grid, VelocityBoundaries const& bc, int component,
                             AxisClosure (&axes)[3]) {
  for (int a = 0; a < 3; ++a) {
    AxisClosure& c = axes[a];
    c = AxisClosure{};
    c.n = grid.cells(a);
    c.node = a == component;
    c.periodic = bc.periodic(a);
    c.active = a < 2 || grid.is3D();
    // the normal component's boundary nodes are data; tangential components are no-slip, or
    // free (zero gradient) at an Outflow side
    const auto kindOf = [&](BoundaryKind k) {
      return c.node
                 ? ClosureKind::DirichletNode
                 : (k == BoundaryKind::Outflow ? ClosureKind::Neumann : ClosureKind::DirichletCell);
    };
    c.low = kindOf(bc.kind[2 * a]);
    c.high = kindOf(bc.kind[2 * a + 1]);
    c.lowValue = bc.velocity[2 * a][component];
    c.highValue = bc.velocity[2 * a + 1][component];
  }
}

/// \brief Storage offsets (ghost widths) of a field on grid.
struct GhostOffsets {
  int x = 1, y = 1, z = 0;
};

/// \brief The storage offsets of grid's fields.
inline GhostOffsets ghostOffsets(Grid const& grid) {
  return GhostOffsets{grid.ghost, grid.ghost, grid.ghostZ()};
}

} // namespace hikiln::cfd
