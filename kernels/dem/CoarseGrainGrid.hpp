#pragma once
/// \file CoarseGrainGrid.hpp
/// \brief Cells of the coarse-graining grids of a drum slice (polar about the drum axis and
/// Cartesian over the drum's bounding square) and the layout of their accumulators.
///
/// Each particle is assigned wholly to the cell of its centre. Centres outside a grid (a particle
/// pressed into the shell, or a grid smaller than the domain) go to the nearest edge cell, so every
/// particle is counted exactly once and the integrated mass is conserved.

#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem::cg {

/// \brief Columns of a cell accumulator (cells x CellSum::Size): sums over the particles whose
/// centre lies in the cell, and over samples.
struct CellSum {
  enum : int {
    Count,     ///< particle-samples
    Area,      ///< disc areas pi r^2 (m^2)
    Mass,      ///< m (kg)
    MomentumX, ///< m v_x
    MomentumY, ///< m v_y
    MvvXX,     ///< m v_x v_x
    MvvXY,     ///< m v_x v_y
    MvvYY,     ///< m v_y v_y
    VirialXX,  ///< sum over the particle's contacts of (x_c - x_i)_x f_x (tension positive)
    VirialXY,  ///< (x_c - x_i)_x f_y
    VirialYX,  ///< (x_c - x_i)_y f_x
    VirialYY,  ///< (x_c - x_i)_y f_y
    Size
  };
};

/// \brief Columns of a shell accumulator (angular bins x WallSum::Size), sums over samples.
struct WallSum {
  enum : int {
    NormalForce, ///< drum contact F_n of the particles in the bin (N, compressive positive)
    ShearForce,  ///< drum contact F_t along the shell's motion (N)
    Contacts,    ///< particle-samples with a drum contact force
    Touching,    ///< particle-samples within touchGap of the shell (wallSlip()'s criterion)
    SpeedSum,    ///< sum of v_theta (counter-clockwise) of the touching particles (m/s)
    Size
  };
};

/// \brief Angle of (x, y) in [0, 2 pi), counter-clockwise from +x.
KOKKOS_INLINE_FUNCTION double polarAngle(double x, double y) {
  const double t = math::atan2(y, x);
  return t < 0.0 ? t + 2.0 * constants::pi : t;
}

/// \brief floor(u) limited to [0, n - 1] (clamped as a double first: no overflowing cast).
KOKKOS_INLINE_FUNCTION int clampedIndex(double u, int n) {
  return static_cast<int>(math::clamp(math::floor(u), 0.0, static_cast<double>(n - 1)));
}

/// \brief Index of the equal sector (of `sectors` over [0, 2 pi)) holding angle theta.
KOKKOS_INLINE_FUNCTION int sectorOf(double theta, int sectors) {
  return clampedIndex(theta * (sectors / (2.0 * constants::pi)), sectors);
}

/// \brief The paper's cylindrical grid: nr rings of width R/nr from the axis to R, ntheta sectors
/// counter-clockwise from +x; cell c = itheta * nr + ir (arrays shaped [ntheta][nr]).
struct PolarGrid {
  double radius = 1.0; ///< drum radius R (m)
  int nr = 15;
  int ntheta = 60;

  /// \brief Number of cells.
  KOKKOS_INLINE_FUNCTION int cellCount() const { return nr * ntheta; }
  /// \brief Cell of a particle centred at (x, y) (radii >= R go to the outer ring).
  KOKKOS_INLINE_FUNCTION int cellOf(double x, double y) const {
    const double rho = math::sqrt(x * x + y * y);
    const int ir = clampedIndex(rho * (nr / radius), nr);
    return sectorOf(polarAngle(x, y), ntheta) * nr + ir;
  }
  /// \brief Radius of ring edge i (0..nr).
  KOKKOS_INLINE_FUNCTION double rEdge(int i) const { return radius * i / nr; }
  /// \brief Angle of sector edge i (0..ntheta).
  KOKKOS_INLINE_FUNCTION double thetaEdge(int i) const { return 2.0 * constants::pi * i / ntheta; }
  /// \brief Angular width of a sector (rad).
  KOKKOS_INLINE_FUNCTION double sectorWidth() const { return 2.0 * constants::pi / ntheta; }
  /// \brief Area of a cell of ring ir (all sectors are equal).
  KOKKOS_INLINE_FUNCTION double ringCellArea(int ir) const {
    const double r1 = rEdge(ir), r2 = rEdge(ir + 1);
    return 0.5 * (r2 * r2 - r1 * r1) * sectorWidth();
  }
  /// \brief Area of cell c.
  KOKKOS_INLINE_FUNCTION double cellArea(int c) const { return ringCellArea(c % nr); }
  /// \brief Distance of a ring-ir cell's area centroid from the axis. The cell average of a linear
  /// field is its value there (not at the mid radius: 2/3 h instead of h/2 in the inner ring).
  KOKKOS_INLINE_FUNCTION double centroidRadius(int ir) const {
    const double r1 = rEdge(ir), r2 = rEdge(ir + 1);
    const double half = 0.5 * sectorWidth();
    return 2.0 / 3.0 * (r2 * r2 * r2 - r1 * r1 * r1) / (r2 * r2 - r1 * r1) * math::sin(half) / half;
  }
};

/// \brief Uniform Cartesian grid of nx x ny cells from (x0, y0); cell c = iy * nx + ix (arrays
/// shaped [ny][nx]).
struct CartesianGrid {
  double x0 = -1.0, y0 = -1.0; ///< lower-left corner (m)
  double dx = 1.0, dy = 1.0;   ///< cell size (m)
  int nx = 1, ny = 1;

  /// \brief Number of cells.
  KOKKOS_INLINE_FUNCTION int cellCount() const { return nx * ny; }
  /// \brief Cell of a particle centred at (x, y) (outside: the nearest edge cell).
  KOKKOS_INLINE_FUNCTION int cellOf(double x, double y) const {
    const int ix = clampedIndex((x - x0) / dx, nx);
    const int iy = clampedIndex((y - y0) / dy, ny);
    return iy * nx + ix;
  }
  /// \brief Area of any cell.
  KOKKOS_INLINE_FUNCTION double cellArea(int) const { return dx * dy; }
  /// \brief x of the centre of column ix.
  KOKKOS_INLINE_FUNCTION double xCentre(int ix) const { return x0 + (ix + 0.5) * dx; }
  /// \brief y of the centre of row iy.
  KOKKOS_INLINE_FUNCTION double yCentre(int iy) const { return y0 + (iy + 0.5) * dy; }
};

/// \brief nx x ny cells over the drum's bounding square [-R, R]^2.
inline CartesianGrid drumCartesianGrid(double drumRadius, int nx, int ny) {
  CartesianGrid g;
  g.x0 = -drumRadius;
  g.y0 = -drumRadius;
  g.dx = 2.0 * drumRadius / nx;
  g.dy = 2.0 * drumRadius / ny;
  g.nx = nx;
  g.ny = ny;
  return g;
}

} // namespace hikiln::dem::cg
