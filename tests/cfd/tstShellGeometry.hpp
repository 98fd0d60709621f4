// Cut-cell geometry of the drum shell: the measured fluid area converges to pi R^2, capacities
// are max(volume, minVolume) in fluid cells, apertures of a straight wall are exact, the
// aperture-weighted divergence of the rigid rotation (fluxes at the open-face centroids) is ~0,
// the wall layer hugs the shell, and the wall velocity is the rigid rotation.
#include "CfdTestUtils.hpp"
#include "kernels/cfd/ShellGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
constexpr double pi = hikiln::constants::pi;

struct Measured {
  double area = 0.0;          // sum of volume fraction x cell area
  double smallest = 1.0;      // smallest capacity of a fluid cell
  int badCapacity = 0;        // cells whose capacity is not max(volume, minVolume) or 0
  double wallLayerGap = 0.0;  // largest |r - R| over wall-layer cell centres, in cells
  double interiorLayer = 0.0; // wall-layer flags on cells deeper than 2 cells inside
};

Measured measure(int n, double minVolume, int samples) {
  const double diameter = 2.0;
  const Grid g = drumGrid(n, diameter);
  DrumShell shell;
  shell.radius = 0.5 * diameter;
  CutCellOptions options;
  options.minVolume = minVolume;
  options.samples = samples;
  const auto cc = buildCutCells(space{}, g, shell, options);
  const auto vol = test::toHost(cc.volume);
  const auto ax = test::toHost(cc.aperture[0]);
  const auto ay = test::toHost(cc.aperture[1]);
  const auto wall = test::toHost(cc.wallLayer);
  const auto cap = test::toHost(cc.capacity);
  Measured m;
  const int o = g.ghost;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double v = vol(i + o, j + o, 0);
      m.area += v * g.hx * g.hy;
      if (cap(i + o, j + o, 0) > 0.0) {
        m.smallest = std::min(m.smallest, cap(i + o, j + o, 0));
      }
      const double x = g.coordinate(Staggering::Cell, 0, i);
      const double y = g.coordinate(Staggering::Cell, 1, j);
      const double r = std::hypot(x, y);
      if (wall(i + o, j + o, 0) > 0.0) {
        m.wallLayerGap = std::max(m.wallLayerGap, std::fabs(r - shell.radius) / g.hx);
      }
      if (r < shell.radius - 2.0 * g.hx) {
        m.interiorLayer += wall(i + o, j + o, 0);
      }
      const bool open = ax(i + o, j + o, 0) > 0.0 || ax(i + 1 + o, j + o, 0) > 0.0 ||
                        ay(i + o, j + o, 0) > 0.0 || ay(i + o, j + 1 + o, 0) > 0.0;
      const double expected = open ? std::max(v, minVolume) : 0.0;
      m.badCapacity += cap(i + o, j + o, 0) == expected ? 0 : 1;
    }
  }
  return m;
}

TEST(TEST_CATEGORY, shell_geometry_area_converges) {
  const double exact = pi;
  double previous = 1.0;
  for (int n : {16, 32, 64}) {
    const Measured m = measure(n, 0.5, 16);
    const double error = std::fabs(m.area - exact) / exact;
    std::cout << "n " << n << ": area error " << error << "\n";
    EXPECT_LT(error, 2e-3) << "n " << n;
    EXPECT_LT(error, previous) << "n " << n;
    previous = error;
  }
}

TEST(TEST_CATEGORY, shell_geometry_capacity_and_wall_layer) {
  const Measured m = measure(48, 0.5, 8);
  EXPECT_GE(m.smallest, 0.5);
  EXPECT_EQ(m.badCapacity, 0);
  EXPECT_LT(m.wallLayerGap, 1.5);
  EXPECT_EQ(m.interiorLayer, 0.0);
}

// max |aperture-weighted divergence| of the rigid rotation over fluid cells, relative to
// omega R / h, with the face velocities at the open-face centroids (as the wall forcing uses).
double rigidRotationDivergence(int n, int faceSamples) {
  const Grid g = drumGrid(n, 1.0);
  DrumShell shell;
  shell.radius = 0.5;
  shell.omega = 2.0;
  CutCellOptions options;
  options.faceSamples = faceSamples;
  const auto cc = buildCutCells(space{}, g, shell, options);
  const int o = g.ghost;
  double worst = 0.0;
  auto ap0 = test::toHost(cc.aperture[0]);
  auto ap1 = test::toHost(cc.aperture[1]);
  const auto flux = [&](int c, int i, int j) {
    const auto& ap = c == 0 ? ap0 : ap1;
    const auto cx = test::toHost(cc.centroid[c][0]);
    const auto cy = test::toHost(cc.centroid[c][1]);
    return ap(i + o, j + o, 0) *
           shell.wallVelocity(c, cx(i + o, j + o, 0), cy(i + o, j + o, 0), 0.0);
  };
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double div =
          (flux(0, i + 1, j) - flux(0, i, j)) / g.hx + (flux(1, i, j + 1) - flux(1, i, j)) / g.hy;
      worst = std::max(worst, std::fabs(div));
    }
  }
  return worst / (shell.omega * shell.radius / g.hx);
}

TEST(TEST_CATEGORY, shell_geometry_rigid_rotation_flux_balance) {
  const double coarse = rigidRotationDivergence(32, 64);
  const double fine = rigidRotationDivergence(32, 1024);
  std::cout << "rigid-rotation divergence / (omega R / h): " << coarse << " (64 face samples), "
            << fine << " (1024)\n";
  EXPECT_LT(fine, 2e-3);
  EXPECT_LT(fine, 0.5 * coarse); // the sampling error, not a geometric one, is what remains
}

// A half-plane y < c with c on a face line and one off it: apertures are exactly 0, 1 or the
// fraction c cuts from the x-faces.
struct HalfPlane {
  double level;
  KOKKOS_INLINE_FUNCTION bool inside(double, double y, double) const { return y < level; }
  KOKKOS_INLINE_FUNCTION double wallVelocity(int, double, double, double) const { return 0.0; }
};

TEST(TEST_CATEGORY, shell_geometry_straight_wall_apertures) {
  const Grid g = makeGrid(8, 8, 1, 1.0, 1.0, 1.0);
  const double level = 0.5 + 0.75 * g.hy; // cuts row 4 at three quarters of its height
  CutCellOptions options;
  options.samples = 8;
  const auto cc = buildCutCells(space{}, g, HalfPlane{level}, options);
  const auto vol = test::toHost(cc.volume);
  const auto ax = test::toHost(cc.aperture[0]);
  const auto ay = test::toHost(cc.aperture[1]);
  const int o = g.ghost;
  for (int i = 1; i < g.nx; ++i) {
    EXPECT_DOUBLE_EQ(ax(i + o, 4 + o, 0), 0.75);
    EXPECT_DOUBLE_EQ(ax(i + o, 3 + o, 0), 1.0);
    EXPECT_DOUBLE_EQ(vol(i + o, 4 + o, 0), 0.75);
    EXPECT_DOUBLE_EQ(ay(i + o, 4 + o, 0), 1.0); // between rows 3 and 4
    EXPECT_DOUBLE_EQ(ay(i + o, 5 + o, 0), 0.0); // between row 4 and the empty row 5
  }
  EXPECT_DOUBLE_EQ(ax(0 + o, 2 + o, 0), 0.0); // domain boundary faces are closed
}

TEST(TEST_CATEGORY, shell_wall_velocity_is_rigid_rotation) {
  DrumShell shell;
  shell.cx = 0.3;
  shell.cy = -0.2;
  shell.radius = 1.0;
  shell.omega = 0.5;
  EXPECT_DOUBLE_EQ(shell.wallVelocity(0, 1.3, -0.2, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(shell.wallVelocity(1, 1.3, -0.2, 0.0), 0.5);
  EXPECT_DOUBLE_EQ(shell.wallVelocity(0, 0.3, 0.8, 0.0), -0.5);
  EXPECT_TRUE(shell.inside(0.3, 0.79, 0.0));
  EXPECT_FALSE(shell.inside(0.3, 0.81, 0.0));
}

} // namespace
