#pragma once
/// \file Grid.hpp
/// \brief Uniform Cartesian grid with ghost cells, the MAC (staggered) field layout and boundary
/// kinds per side. Written for 3D; a 2D grid is one cell deep (nz = 1), periodic in z, and has no
/// ghost layers in z.
///
/// Layout: every field is a 3D View (LayoutLeft, so i is contiguous on every backend) whose
/// extent along an axis is n (cell-centred) or n + 1 (node-centred, i.e. on the faces normal to
/// that axis) plus 2 ghost layers of width `ghost` (0 along z in 2D). Logical index i of a field
/// is stored at i + ghost: field(i + g, j + g, k + gz). Face x-index i is the face on the low
/// side of cell i, so faces 0 and nx lie on the domain boundary.

#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace hikiln::cfd {

/// \brief Where a field's values sit: bit d set means node-centred along axis d (on the faces
/// normal to d), clear means cell-centred. Velocity components are the faces, viscosities on
/// cell edges the pairs.
enum class Staggering : int {
  Cell = 0,
  FaceX = 1,
  FaceY = 2,
  FaceZ = 4,
  EdgeXY = 3,
  EdgeXZ = 5,
  EdgeYZ = 6,
};

/// \brief True when a field of staggering s is node-centred along axis (0, 1, 2).
KOKKOS_INLINE_FUNCTION constexpr bool isNodeCentred(Staggering s, int axis) {
  return ((static_cast<int>(s) >> axis) & 1) != 0;
}

/// \brief The face staggering of velocity component c (0: u on x-faces, 1: v, 2: w).
KOKKOS_INLINE_FUNCTION constexpr Staggering faceStaggering(int c) {
  return static_cast<Staggering>(1 << c);
}

/// \brief A uniform Cartesian grid of nx * ny * nz cells of size hx * hy * hz whose low corner is
/// (x0, y0, z0), with `ghost` ghost layers around it (none along z when nz == 1).
struct Grid {
  int nx = 1, ny = 1, nz = 1;
  int ghost = 1;
  double hx = 1.0, hy = 1.0, hz = 1.0;
  double x0 = 0.0, y0 = 0.0, z0 = 0.0;

  /// \brief True for a 3D grid (nz > 1).
  KOKKOS_INLINE_FUNCTION bool is3D() const { return nz > 1; }
  /// \brief Number of cells along axis (0, 1, 2).
  KOKKOS_INLINE_FUNCTION int cells(int axis) const {
    return axis == 0 ? nx : (axis == 1 ? ny : nz);
  }
  /// \brief Cell size along axis.
  KOKKOS_INLINE_FUNCTION double spacing(int axis) const {
    return axis == 0 ? hx : (axis == 1 ? hy : hz);
  }
  /// \brief Ghost layers along axis (0 along z for a 2D grid).
  KOKKOS_INLINE_FUNCTION int ghostAlong(int axis) const { return axis == 2 && nz == 1 ? 0 : ghost; }
  /// \brief Storage offset of logical index 0 along z (ghost layers below it).
  KOKKOS_INLINE_FUNCTION int ghostZ() const { return nz > 1 ? ghost : 0; }
  /// \brief ghostZ() of a grid whose dimension count Dims is known at compile time: a constant
  /// in 2D, so that a stencil's index arithmetic has no select per cell (vectorised rows).
  template <int Dims> KOKKOS_INLINE_FUNCTION int ghostZOf() const { return Dims == 3 ? ghost : 0; }
  /// \brief Coordinate of logical index i along axis for a field centred as s.
  KOKKOS_INLINE_FUNCTION double coordinate(Staggering s, int axis, int i) const {
    const double origin = axis == 0 ? x0 : (axis == 1 ? y0 : z0);
    return origin + (static_cast<double>(i) + (isNodeCentred(s, axis) ? 0.0 : 0.5)) * spacing(axis);
  }
  /// \brief Storage extent along axis of a field centred as s (interior, boundary nodes, ghosts).
  int extent(Staggering s, int axis) const {
    return cells(axis) + (isNodeCentred(s, axis) ? 1 : 0) + 2 * ghostAlong(axis);
  }
  /// \brief Total number of cells.
  std::int64_t numCells() const {
    return static_cast<std::int64_t>(nx) * static_cast<std::int64_t>(ny) *
           static_cast<std::int64_t>(nz);
  }
};

/// \brief 1 / h^2 and 1 / (h_a h_b) of a grid, computed once per kernel launch (a division per
/// cell would cost more than the memory traffic of a stencil).
///
/// The factors are kept as the bit patterns of the doubles (std::uint64_t) and read through
/// inv2() and invMixed(). A host stencil row writes doubles (the unknowns) while it reads the
/// factors from the launch's functor; stored as doubles, the compiler cannot rule out that a
/// write changed them and reloads each one per vector of cells. As integers no double write may
/// change them (the language's type-based aliasing rules), so they stay in registers across the
/// row (perf/README.md, "Grid scales kept in registers").
struct GridScales {
  /// \brief The scales of grid.
  explicit GridScales(Grid const& grid) {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        invMixedBits[a][b] = bitsOf(1.0 / (grid.spacing(a) * grid.spacing(b)));
      }
    }
  }
  /// \brief 1 / h_a^2.
  KOKKOS_INLINE_FUNCTION double inv2(int a) const { return valueOf(invMixedBits[a][a]); }
  /// \brief 1 / (h_a h_b).
  KOKKOS_INLINE_FUNCTION double invMixed(int a, int b) const { return valueOf(invMixedBits[a][b]); }

private:
  std::uint64_t invMixedBits[3][3]; ///< every entry set by the constructor

  KOKKOS_INLINE_FUNCTION static std::uint64_t bitsOf(double v) {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }
  /// The caller's read of the integer is the load the aliasing rules protect; this only
  /// reinterprets the register.
  KOKKOS_INLINE_FUNCTION static double valueOf(std::uint64_t bits) {
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
};

/// \brief A grid of nx * ny * nz cells covering [x0, x0 + lx] x [y0, y0 + ly] x [z0, z0 + lz]
/// (nz = 1 for 2D: lz is then the depth of the slab). Throws on empty or non-positive input.
inline Grid makeGrid(int nx, int ny, int nz, double lx, double ly, double lz, double x0 = 0.0,
                     double y0 = 0.0, double z0 = 0.0, int ghost = 1) {
  if (nx < 1 || ny < 1 || nz < 1 || ghost < 1) {
    throw std::invalid_argument("hikiln::cfd::makeGrid: cell counts and ghost width must be >= 1");
  }
  if (!(lx > 0.0) || !(ly > 0.0) || !(lz > 0.0)) {
    throw std::invalid_argument("hikiln::cfd::makeGrid: domain lengths must be positive");
  }
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.nz = nz;
  g.ghost = ghost;
  g.hx = lx / nx;
  g.hy = ly / ny;
  g.hz = lz / nz;
  g.x0 = x0;
  g.y0 = y0;
  g.z0 = z0;
  return g;
}

/// \brief A grid field in MemorySpace: i contiguous, ghost layers included.
template <class MemorySpace> using Field = Kokkos::View<double***, Kokkos::LayoutLeft, MemorySpace>;

/// \brief Allocates a zero-filled field of staggering s on grid, first touched by space.
template <class ExecutionSpace>
Field<typename ExecutionSpace::memory_space>
makeField(ExecutionSpace const& space, Grid const& grid, Staggering s, std::string const& label) {
  return Field<typename ExecutionSpace::memory_space>(
      Kokkos::view_alloc(space, label), grid.extent(s, 0), grid.extent(s, 1), grid.extent(s, 2));
}

/// \brief The 3D iteration policy used for grid kernels: i innermost (matches LayoutLeft).
template <class ExecutionSpace>
using GridPolicy =
    Kokkos::MDRangePolicy<ExecutionSpace,
                          Kokkos::Rank<3, Kokkos::Iterate::Left, Kokkos::Iterate::Left>,
                          Kokkos::IndexType<int>>;

/// \brief f(std::integral_constant<int, a>()) for an axis a in {0, 1, 2}: a kernel written for a
/// compile-time axis indexes its small index arrays by a constant, so the compiler keeps them in
/// registers (with a run-time axis the face densities took 4x as long on the host, the FCT
/// face fluxes 1.1x).
template <class F> void withAxis(int a, F&& f) {
  if (a == 0) {
    f(std::integral_constant<int, 0>());
  } else if (a == 1) {
    f(std::integral_constant<int, 1>());
  } else {
    f(std::integral_constant<int, 2>());
  }
}

/// \brief Policy over the logical index box [lo, hi) of a grid kernel.
template <class ExecutionSpace>
GridPolicy<ExecutionSpace> gridPolicy(ExecutionSpace const& space, int const (&lo)[3],
                                      int const (&hi)[3]) {
  return GridPolicy<ExecutionSpace>(
      space, {lo[0], lo[1], lo[2]},
      {math::max(hi[0], lo[0]), math::max(hi[1], lo[1]), math::max(hi[2], lo[2])});
}

/// \brief What happens at one side of the domain.
/// - Wall: impermeable; a scalar has zero normal gradient (Neumann), velocity is no-slip with the
///   wall's (tangential) velocity.
/// - Periodic: the opposite side continues the domain (must be set on both sides of an axis).
/// - Value: a given value (scalar Dirichlet; velocity: a prescribed velocity vector, e.g. inflow).
/// - Inflow (velocity only): the normal velocity varies over the side and is data kept in the
///   field's boundary nodes (set by the caller, never overwritten by ghost fills); tangential
///   components as for Wall.
/// - Outflow (velocity only): the normal velocity is data in the boundary nodes (set by the
///   caller, e.g. the projection); tangential components have zero normal gradient.
enum class BoundaryKind : int { Wall = 0, Periodic = 1, Value = 2, Inflow = 3, Outflow = 4 };

/// \brief Side numbering: 2 * axis + (0 low, 1 high).
enum Side : int { XLow = 0, XHigh = 1, YLow = 2, YHigh = 3, ZLow = 4, ZHigh = 5 };

/// \brief Boundary conditions of a cell-centred scalar: a kind and (for Value) a value per side.
struct ScalarBoundaries {
  BoundaryKind kind[6] = {BoundaryKind::Wall, BoundaryKind::Wall,     BoundaryKind::Wall,
                          BoundaryKind::Wall, BoundaryKind::Periodic, BoundaryKind::Periodic};
  double value[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};

  /// \brief True when axis is periodic.
  KOKKOS_INLINE_FUNCTION bool periodic(int axis) const {
    return kind[2 * axis] == BoundaryKind::Periodic;
  }
};

/// \brief Boundary conditions of a MAC velocity: a kind and a velocity vector per side (the wall
/// velocity for Wall, whose normal component must be 0; the imposed velocity for Value).
struct VelocityBoundaries {
  BoundaryKind kind[6] = {BoundaryKind::Wall, BoundaryKind::Wall,     BoundaryKind::Wall,
                          BoundaryKind::Wall, BoundaryKind::Periodic, BoundaryKind::Periodic};
  double velocity[6][3] = {};

  /// \brief True when axis is periodic.
  KOKKOS_INLINE_FUNCTION bool periodic(int axis) const {
    return kind[2 * axis] == BoundaryKind::Periodic;
  }
};

/// \brief Throws unless periodic sides come in pairs, a 2D grid is periodic in z, and walls have
/// no normal velocity (kinds[6] from either boundary type).
inline void checkBoundaryKinds(Grid const& grid, BoundaryKind const (&kind)[6], char const* who) {
  for (int axis = 0; axis < 3; ++axis) {
    const bool lo = kind[2 * axis] == BoundaryKind::Periodic;
    const bool hi = kind[2 * axis + 1] == BoundaryKind::Periodic;
    if (lo != hi) {
      throw std::invalid_argument(std::string(who) + ": periodic sides must come in pairs (axis " +
                                  std::to_string(axis) + ")");
    }
    if (lo && axis < 2 && grid.cells(axis) < 2) {
      throw std::invalid_argument(std::string(who) + ": a periodic axis needs at least 2 cells");
    }
  }
  if (!grid.is3D() && kind[ZLow] != BoundaryKind::Periodic) {
    throw std::invalid_argument(std::string(who) + ": a 2D grid (nz = 1) must be periodic in z");
  }
}

/// \brief Validates scalar boundary conditions on grid (see checkBoundaryKinds).
inline void checkBoundaries(Grid const& grid, ScalarBoundaries const& bc) {
  checkBoundaryKinds(grid, bc.kind, "hikiln::cfd::ScalarBoundaries");
}

/// \brief Validates velocity boundary conditions on grid; a Wall must not move along its normal.
inline void checkBoundaries(Grid const& grid, VelocityBoundaries const& bc) {
  checkBoundaryKinds(grid, bc.kind, "hikiln::cfd::VelocityBoundaries");
  for (int side = 0; side < 6; ++side) {
    if (bc.kind[side] == BoundaryKind::Wall && bc.velocity[side][side / 2] != 0.0) {
      throw std::invalid_argument("hikiln::cfd::VelocityBoundaries: a wall's normal velocity "
                                  "must be 0 (use Value for inflow), side " +
                                  std::to_string(side));
    }
  }
}

} // namespace hikiln::cfd
