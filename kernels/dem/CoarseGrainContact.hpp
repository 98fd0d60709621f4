#pragma once
/// \file CoarseGrainContact.hpp
/// \brief Contact virial of one particle: sum over its contacts of (x_c - x_i) (x) f_i, as point
/// functions shared by the deposition kernel and the tests.
///
/// Conventions of ContactLaw.hpp: n points from particle i to the other body, t = perp(n), the
/// force on i is f_i = -F_n n + F_t t, and F_n, F_t are stored in i's row. The contact point is
/// the middle of the overlap, at r_i - delta/2 from i's centre along n; both partners of a pair
/// name the same point, so their two halves add up to l_ij (x) f_ij exactly (l_ij the branch
/// vector between the centres). The sum is tension positive: a repulsive contact gives a negative
/// diagonal.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem::cg {

/// \brief A 2x2 tensor, row index first (xy = branch_x force_y for a virial).
struct Tensor2 {
  double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;
};

/// \brief Distance from a particle's centre to its contact point: the middle of the overlap.
KOKKOS_INLINE_FUNCTION double contactBranchLength(double radius, double overlap) {
  return radius - 0.5 * overlap;
}

/// \brief Adds (x_c - x_i) (x) f_i of one contact with unit normal (nx, ny) (from i to the other
/// body), branch length b and stored forces F_n, F_t to w.
KOKKOS_INLINE_FUNCTION void addContactVirial(double nx, double ny, double b, double fn, double ft,
                                             Tensor2& w) {
  const double fx = -fn * nx - ft * ny; // -F_n n + F_t t, t = (-n_y, n_x)
  const double fy = -fn * ny + ft * nx;
  w.xx += b * nx * fx;
  w.xy += b * nx * fy;
  w.yx += b * ny * fx;
  w.yy += b * ny * fy;
}

/// \brief Normal and overlap of particle i (radius ri) with particle j at dx = x_j - x_i (minimum
/// image); false when the centres coincide.
KOKKOS_INLINE_FUNCTION bool pairGeometry(double dx, double dy, double ri, double rj, double& nx,
                                         double& ny, double& overlap) {
  const double d2 = dx * dx + dy * dy;
  if (!(d2 > 0.0)) {
    return false;
  }
  const double d = math::sqrt(d2);
  nx = dx / d;
  ny = dy / d;
  overlap = ri + rj - d;
  return true;
}

/// \brief Normal and overlap of a particle (centre x, y, radius r) with wall slot `slot` (0: the
/// drum, 1 + k: flat wall k), as drumFrame() / flatFrame() define them; false for an absent wall.
KOKKOS_INLINE_FUNCTION bool wallGeometry(const WallSet& walls, int slot, double x, double y,
                                         double r, double& nx, double& ny, double& overlap) {
  if (slot == 0) {
    const double d2 = x * x + y * y;
    if (!walls.drum.enabled || !(d2 > 0.0)) {
      return false;
    }
    const double d = math::sqrt(d2);
    nx = x / d;
    ny = y / d;
    overlap = r - (walls.drum.radius - d);
    return true;
  }
  const int k = slot - 1;
  if (k >= walls.numFlat) {
    return false;
  }
  const FlatWall& w = walls.flat[k];
  nx = -w.normalX;
  ny = -w.normalY;
  overlap = r - ((x - w.pointX) * w.normalX + (y - w.pointY) * w.normalY);
  return true;
}

} // namespace hikiln::dem::cg
