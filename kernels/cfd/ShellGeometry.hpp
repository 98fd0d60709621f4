#pragma once
/// \file ShellGeometry.hpp
/// \brief The rotating drum shell on the Cartesian grid as cut cells: a fluid volume fraction per
/// cell and an open fraction (aperture) per face, plus the wall velocity of the shell.
///
/// Method (and why): a cut-cell / immersed-boundary hybrid.
/// - Fluxes: every face carries its aperture (the fraction of the face inside the shell), so mass
///   and volume fluxes are aperture x velocity and vanish exactly through the wall: the solids are
///   conserved to round-off and the pressure projection (face coefficient aperture / rho) makes
///   the aperture-weighted divergence zero. This keeps the bed's contact with the curved wall
///   (the fluid volume in the wall cells) instead of a staircase.
/// - Small cells: the volume a cell offers to the transported volume fraction (its capacity) is
///   max(volume fraction, minVolume) (default 1/2), so slivers neither limit the advective time
///   step nor lose boundedness; the solids content is counted with the same capacities, so it is
///   conserved exactly. (Removing small cells and closing their faces was tried first: the closed
///   faces carry no flux of the rigid rotation, whose aperture-weighted divergence then reached
///   omega x 7 at 32 cells per diameter, and the projection spread a 25 % velocity error.)
/// - Wall velocity: faces that are not fully open are driven to the shell velocity omega x r
///   by an implicit (Brinkman) drag in the momentum solve (solid fraction 1 - aperture), taken
///   at the centroid of the open part of the face. omega x r is the exact rigid rotation
///   everywhere, so the forcing outside the shell is consistent. On the cut faces beside the bed
///   the drag is capped by Coulomb friction, mu_wall sigma_n per unit wall area
///   (ProjectionKernels.hpp, WallFriction), which lets the bed slip.
/// Fractions are measured by sampling (samples^d points per cell, samples^(d-1) per face, a face
/// point open when the shape holds it a hair, 1e-9 cells, before and after the face): exact for
/// any shape that offers `inside`, which keeps geometry composable (the 3D kiln's end faces and
/// dam ring: KilnShell in KilnGeometry.hpp; shapes combine with ShapeIntersection).

#include "kernels/cfd/Grid.hpp"

#include <Kokkos_Core.hpp>

#include <stdexcept>
#include <string>

namespace hikiln::cfd {

/// \brief A circular shell (cylinder along z) of given radius about (cx, cy), turning at omega
/// (rad/s, counter-clockwise positive about +z).
struct DrumShell {
  double cx = 0.0, cy = 0.0;
  double radius = 1.0;
  double omega = 0.0;

  /// \brief True when (x, y, z) is inside the shell.
  KOKKOS_INLINE_FUNCTION bool inside(double x, double y, double) const {
    const double dx = x - cx, dy = y - cy;
    return dx * dx + dy * dy < radius * radius;
  }
  /// \brief Component c of the shell (rigid rotation) velocity omega x r at (x, y, z).
  KOKKOS_INLINE_FUNCTION double wallVelocity(int c, double x, double y, double) const {
    return c == 0 ? -omega * (y - cy) : (c == 1 ? omega * (x - cx) : 0.0);
  }
};

/// \brief The intersection of two shapes; its wall velocity is the first shape's (for the kiln:
/// shell, end walls and dam ring all turn with the shell).
template <class A, class B> struct ShapeIntersection {
  A first;
  B second;
  KOKKOS_INLINE_FUNCTION bool inside(double x, double y, double z) const {
    return first.inside(x, y, z) && second.inside(x, y, z);
  }
  KOKKOS_INLINE_FUNCTION double wallVelocity(int c, double x, double y, double z) const {
    return first.wallVelocity(c, x, y, z);
  }
};

/// \brief How the cut cells are measured.
struct CutCellOptions {
  int samples = 8;        ///< sample points per cell edge (volume fractions)
  int faceSamples = 1024; ///< sample points per face edge (apertures; at most 32 in 3D)
  double minVolume = 0.5; ///< smallest capacity of a cell with an open face
  bool periodic[3] = {false, false, true}; ///< periodic axes (their boundary faces stay open)
  /// open non-periodic sides (2 axis + 0 low / 1 high, e.g. a kiln's inlet and discharge
  /// faces): their boundary faces are measured like interior faces, the shape saying what lies
  /// beyond the grid; the other non-periodic sides are closed walls
  bool open[6] = {false, false, false, false, false, false};
};

/// \brief Volume fractions and face apertures of a shape on a grid (see the file comment).
template <class MemorySpace> struct CutCells {
  Grid grid;
  Field<MemorySpace> volume;      ///< fluid volume fraction per cell
  Field<MemorySpace> capacity;    ///< max(volume, minVolume) with an open face, else 0
  Field<MemorySpace> aperture[3]; ///< open fraction per face
  /// centroid[a][d]: coordinate d of the centroid of the open part of the faces normal to a
  /// (the face centre where closed or fully open); the forced wall velocity is taken there, so
  /// aperture x velocity is the exact flux of a linear (rigid-rotation) wall velocity
  Field<MemorySpace> centroid[3][3];
  Field<MemorySpace> wallLayer; ///< 1 in fluid cells touching the wall, else 0
  /// periodic axes; an open boundary face of a non-periodic axis (CutCellOptions::open) lies
  /// between an interior cell and a ghost cell holding what flows in or out
  bool periodic[3] = {false, false, true};
};

/// \brief Measures the cut cells of `shape` on grid (ghosts of every field left 0).
template <class ExecutionSpace, class Shape>
CutCells<typename ExecutionSpace::memory_space>
buildCutCells(ExecutionSpace const& space, Grid const& grid, Shape const& shape,
              CutCellOptions const& options = CutCellOptions()) {
  if (options.samples < 1 || options.faceSamples < 1 ||
      !(options.minVolume > 0.0 && options.minVolume <= 1.0)) {
    throw std::invalid_argument("hikiln::cfd::buildCutCells: samples must be >= 1 and "
                                "minVolume in (0, 1]");
  }
  for (int side = 0; side < 6; ++side) {
    if (options.open[side] && options.periodic[side / 2]) {
      throw std::invalid_argument("hikiln::cfd::buildCutCells: side " + std::to_string(side) +
                                  " cannot be both open and periodic");
    }
  }
  using memory_space = typename ExecutionSpace::memory_space;
  CutCells<memory_space> cc;
  cc.grid = grid;
  for (int a = 0; a < 3; ++a) {
    cc.periodic[a] = options.periodic[a];
  }
  cc.volume = makeField(space, grid, Staggering::Cell, "hikiln::cfd::cut::volume");
  cc.capacity = makeField(space, grid, Staggering::Cell, "hikiln::cfd::cut::capacity");
  cc.wallLayer = makeField(space, grid, Staggering::Cell, "hikiln::cfd::cut::wallLayer");
  const int dims = grid.is3D() ? 3 : 2;
  const int S = options.samples;
  const int SF = dims == 3 ? math::min(options.faceSamples, 32) : options.faceSamples;
  const double minVolume = options.minVolume;
  const int g = grid.ghost, gz = grid.ghostZ();
  const auto volume = cc.volume;
  Kokkos::parallel_for(
      "hikiln::cfd::cutCellVolumes", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const int sz = dims == 3 ? S : 1;
        int count = 0;
        for (int c = 0; c < sz; ++c) {
          for (int b = 0; b < S; ++b) {
            for (int a = 0; a < S; ++a) {
              const double x = grid.x0 + (i + (a + 0.5) / S) * grid.hx;
              const double y = grid.y0 + (j + (b + 0.5) / S) * grid.hy;
              const double z = grid.z0 + (k + (c + 0.5) / sz) * grid.hz;
              count += shape.inside(x, y, z) ? 1 : 0;
            }
          }
        }
        volume(i + g, j + g, k + gz) = static_cast<double>(count) / (S * S * sz);
      });
  for (int axis = 0; axis < 3; ++axis) {
    cc.aperture[axis] = makeField(space, grid, faceStaggering(axis), "hikiln::cfd::cut::aperture");
    if (axis >= dims) {
      continue;
    }
    const auto ap = cc.aperture[axis];
    for (int d = 0; d < 3; ++d) {
      cc.centroid[axis][d] =
          makeField(space, grid, faceStaggering(axis), "hikiln::cfd::cut::centroid");
    }
    const auto cx = cc.centroid[axis][0], cy = cc.centroid[axis][1], cz = cc.centroid[axis][2];
    const bool periodic = options.periodic[axis];
    const bool openLow = options.open[2 * axis], openHigh = options.open[2 * axis + 1];
    const int n = grid.cells(axis);
    const double sideOffset = 1e-9 * grid.spacing(axis);
    const int hi[3] = {grid.nx + (axis == 0), grid.ny + (axis == 1), grid.nz + (axis == 2)};
    Kokkos::parallel_for(
        "hikiln::cfd::cutCellApertures", gridPolicy(space, {0, 0, 0}, hi),
        KOKKOS_LAMBDA(const int i, const int j, const int k) {
          int idx[3] = {i, j, k};
          const int face = idx[axis];
          const Staggering st = faceStaggering(axis);
          cx(i + g, j + g, k + gz) = grid.coordinate(st, 0, i);
          cy(i + g, j + g, k + gz) = grid.coordinate(st, 1, j);
          cz(i + g, j + g, k + gz) = grid.coordinate(st, 2, k);
          if (!periodic && ((face == 0 && !openLow) || (face == n && !openHigh))) {
            ap(i + g, j + g, k + gz) = 0.0;
            return;
          }
          // sample the face: tangential axes t1, t2 (t2 only in 3D)
          const int t1 = axis == 0 ? 1 : 0;
          const int t2 = 3 - axis - t1;
          const int s2 = dims == 3 ? SF : 1;
          int count = 0;
          double sum[3] = {0.0, 0.0, 0.0};
          for (int b = 0; b < s2; ++b) {
            for (int a = 0; a < SF; ++a) {
              double p[3];
              p[axis] = grid.coordinate(faceStaggering(axis), axis, face);
              p[t1] = grid.coordinate(Staggering::Cell, t1, t1 == 0 ? i : (t1 == 1 ? j : k)) +
                      ((a + 0.5) / SF - 0.5) * grid.spacing(t1);
              p[t2] = grid.coordinate(Staggering::Cell, t2, t2 == 1 ? j : k) +
                      (dims == 3 ? ((b + 0.5) / SF - 0.5) * grid.spacing(t2) : 0.0);
              // open when inside just before and just after the face: a face lying on a
              // shape's own face (the dam ring's) is open only where both sides are fluid
              double before[3] = {p[0], p[1], p[2]}, after[3] = {p[0], p[1], p[2]};
              before[axis] -= sideOffset;
              after[axis] += sideOffset;
              if (shape.inside(before[0], before[1], before[2]) &&
                  shape.inside(after[0], after[1], after[2])) {
                ++count;
                for (int d = 0; d < 3; ++d) {
                  sum[d] += p[d];
                }
              }
            }
          }
          ap(i + g, j + g, k + gz) = static_cast<double>(count) / (SF * s2);
          if (count > 0 && count < SF * s2) {
            cx(i + g, j + g, k + gz) = sum[0] / count;
            cy(i + g, j + g, k + gz) = sum[1] / count;
            cz(i + g, j + g, k + gz) = sum[2] / count;
          }
        });
  }
  const auto wall = cc.wallLayer;
  const auto capacity = cc.capacity;
  const auto ax = cc.aperture[0], ay = cc.aperture[1], az = cc.aperture[2];
  Kokkos::parallel_for(
      "hikiln::cfd::cutCellWallLayer", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const int I = i + g, J = j + g, K = k + gz;
        double minOpen = volume(I, J, K);
        double maxOpen = math::fmax(math::fmax(ax(I, J, K), ax(I + 1, J, K)),
                                    math::fmax(ay(I, J, K), ay(I, J + 1, K)));
        minOpen = math::fmin(minOpen, math::fmin(ax(I, J, K), ax(I + 1, J, K)));
        minOpen = math::fmin(minOpen, math::fmin(ay(I, J, K), ay(I, J + 1, K)));
        if (dims == 3) {
          minOpen = math::fmin(minOpen, math::fmin(az(I, J, K), az(I, J, K + 1)));
          maxOpen = math::fmax(maxOpen, math::fmax(az(I, J, K), az(I, J, K + 1)));
        }
        const bool fluid = maxOpen > 0.0;
        capacity(I, J, K) = fluid ? math::fmax(volume(I, J, K), minVolume) : 0.0;
        wall(I, J, K) = fluid && minOpen < 1.0 ? 1.0 : 0.0;
      });
  return cc;
}

/// \brief A square (2D: one cell deep) grid of n x n cells around a drum of diameter D centred
/// at the origin, with `margin` cells between the shell and the domain boundary.
inline Grid drumGrid(int n, double diameter, double depth = 1.0, int margin = 2) {
  if (n <= 2 * margin + 2) {
    throw std::invalid_argument("hikiln::cfd::drumGrid: too few cells for the margin");
  }
  const double h = diameter / (n - 2 * margin);
  const double side = h * n;
  return makeGrid(n, n, 1, side, side, depth, -0.5 * side, -0.5 * side, 0.0);
}

} // namespace hikiln::cfd
