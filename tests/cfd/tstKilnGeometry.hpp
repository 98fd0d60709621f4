// Geometry pieces of the 3D kiln (kernels/cfd/KilnGeometry.hpp):
// - segmentHeight inverts the circular-segment area: half the circle at its centre, and the
//   feed (4.6 %) and air (35 %) patches of physics.md 7 cover those fractions of a finely
//   sampled inlet face;
// - the cut cells of a kiln with and without its dam ring hold the analytic volumes
//   (pi R^2 L, less the ring's pi (R^2 - (R - h)^2) w), with closed end faces and the ring's
//   inner face open over its opening;
// - bad sizes and overlapping patches are refused naming the key.
#include "CfdTestUtils.hpp"
#include "kernels/cfd/KilnGeometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
constexpr double pi = hikiln::constants::pi;

TEST(TEST_CATEGORY, kiln_segment_height_inverts_area) {
  EXPECT_NEAR(segmentHeight(0.5, 2.0), 2.0, 1e-13);
  EXPECT_EQ(segmentHeight(0.0, 2.0), 0.0);
  EXPECT_NEAR(segmentHeight(1.0, 2.0), 4.0, 1e-13);
  for (double f : {0.01, 0.046, 0.2, 0.65, 0.99}) {
    const double h = segmentHeight(f, 1.0);
    const double theta = 2.0 * std::acos(1.0 - h);
    EXPECT_NEAR((theta - std::sin(theta)) / (2.0 * pi), f, 1e-13) << "fraction " << f;
    // symmetry: the chord leaving f above it is as far below the top as this one is above
    // the bottom
    EXPECT_NEAR(segmentHeight(1.0 - f, 1.0), 2.0 - h, 1e-12) << "fraction " << f;
  }
}

TEST(TEST_CATEGORY, kiln_inlet_patches_cover_their_fractions) {
  KilnShell shell;
  shell.cx = 0.3;
  shell.cy = -0.2;
  shell.radius = 2.5;
  const KilnInlet inlet = makeKilnInlet(shell, 0.046, 0.35, 0.05, 2.0, 0.57, "test");
  const int n = 2000; // sample points per side of the face's bounding square
  double feed = 0.0, air = 0.0, wall = 0.0, disc = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = shell.cx + shell.radius * (2.0 * (i + 0.5) / n - 1.0);
      const double y = shell.cy + shell.radius * (2.0 * (j + 0.5) / n - 1.0);
      const bool inDisc = std::hypot(x - shell.cx, y - shell.cy) < shell.radius;
      disc += inDisc;
      const InletPatch p = inlet.patch(x, y);
      feed += p == InletPatch::Feed;
      air += p == InletPatch::Air;
      wall += inDisc && p == InletPatch::Wall;
      if (p == InletPatch::Feed) {
        EXPECT_EQ(inlet.axialVelocity(x, y), 0.05);
      }
    }
  }
  // sampling error of a 2000 x 2000 point raster: about 1e-4 of the disc
  EXPECT_NEAR(feed / disc, 0.046, 3e-4);
  EXPECT_NEAR(air / disc, 0.35, 3e-4);
  EXPECT_NEAR(wall / disc, 1.0 - 0.046 - 0.35, 3e-4);
  EXPECT_EQ(inlet.patch(shell.cx + 2.0 * shell.radius, shell.cy - 0.99 * shell.radius),
            InletPatch::Wall);
  EXPECT_EQ(inlet.axialVelocity(shell.cx, shell.cy), 0.0);
  EXPECT_EQ(inlet.axialVelocity(shell.cx, shell.cy + 0.9 * shell.radius), 2.0);
}

struct KilnVolumes {
  double volume = 0.0;       // sum of volume fraction x cell volume
  double endApertures = 0.0; // largest aperture of a z face on the domain's end faces
  double ringFace = 0.0;     // open area of the z faces at the ring's inner face
};

KilnVolumes measureKiln(KilnShell const& shell, Grid const& g, int ringFace) {
  CutCellOptions options;
  options.periodic[2] = false;
  options.faceSamples = 32;
  const auto cc = buildCutCells(space{}, g, shell, options);
  const auto vol = test::toHost(cc.volume);
  const auto az = test::toHost(cc.aperture[2]);
  KilnVolumes m;
  const int o = g.ghost;
  for (int k = 0; k <= g.nz; ++k) {
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        if (k < g.nz) {
          m.volume += vol(i + o, j + o, k + o) * g.hx * g.hy * g.hz;
        }
        const double a = az(i + o, j + o, k + o);
        if (k == 0 || k == g.nz) {
          m.endApertures = std::max(m.endApertures, a);
        }
        if (k == ringFace) {
          m.ringFace += a * g.hx * g.hy;
        }
      }
    }
  }
  return m;
}

TEST(TEST_CATEGORY, kiln_cut_cells_hold_the_analytic_volumes) {
  KilnShell shell;
  shell.radius = 1.0;
  shell.zInlet = 0.0;
  shell.zOutlet = 3.0;
  const int n = 36, nz = 15;
  const double h = 2.2 / n; // the circle and a margin of 0.1 on each side
  const Grid g = makeGrid(n, n, nz, n * h, n * h, shell.length(), -1.1, -1.1, 0.0);
  const double R = shell.radius, L = shell.length();
  const KilnVolumes open = measureKiln(shell, g, 13);
  std::cout << "kiln volume " << open.volume << " (pi R^2 L = " << pi * R * R * L << ")\n";
  // 8 samples per cell edge: the sampled circle's area is within about 1e-3 of pi R^2
  EXPECT_NEAR(open.volume, pi * R * R * L, 2e-3 * pi * R * R * L);
  EXPECT_EQ(open.endApertures, 0.0);

  shell.damHeight = 0.3;
  shell.damWidth = 0.4; // 2 cells: the ring's inner face is the face k = 13 (on a grid face,
                        // where only the sampling on both sides of a face finds the opening)
  const KilnVolumes dammed = measureKiln(shell, g, 13);
  const double ring = pi * (R * R - (R - 0.3) * (R - 0.3)) * 0.4;
  const double opening = pi * 0.7 * 0.7;
  std::cout << "ring volume " << open.volume - dammed.volume << " (analytic " << ring
            << "), open area of the ring's inner face " << dammed.ringFace
            << " (pi (R - h)^2 = " << opening << ", without the ring " << open.ringFace << ")\n";
  EXPECT_NEAR(open.volume - dammed.volume, ring, 1e-2 * ring);
  EXPECT_NEAR(dammed.ringFace, opening, 5e-3 * opening);
  EXPECT_NEAR(open.ringFace, pi * R * R, 5e-3 * pi * R * R);
  EXPECT_EQ(dammed.endApertures, 0.0);
  // the ring turns with the shell
  EXPECT_DOUBLE_EQ(shell.wallVelocity(0, 0.0, 0.9, 2.8), -shell.omega * 0.9);
}

template <class Fn> std::string refusal(Fn const& fn) {
  try {
    fn();
  } catch (std::invalid_argument const& e) {
    return e.what();
  }
  return "accepted";
}

TEST(TEST_CATEGORY, kiln_geometry_refuses_bad_input) {
  KilnShell shell;
  shell.radius = 2.5;
  shell.zOutlet = 15.0;
  EXPECT_EQ(refusal([&] { shell.validate("kiln.yaml"); }), "accepted");
  KilnShell bad = shell;
  bad.radius = -1.0;
  EXPECT_EQ(refusal([&] { bad.validate("kiln.yaml"); }), "kiln.yaml: radius must be > 0");
  bad = shell;
  bad.damHeight = 2.5;
  bad.damWidth = 0.3;
  EXPECT_NE(refusal([&] { bad.validate("kiln.yaml"); }).find("dam_height"), std::string::npos);
  bad.damHeight = 0.5;
  bad.damWidth = 0.0;
  EXPECT_NE(refusal([&] { bad.validate("kiln.yaml"); }).find("dam_width"), std::string::npos);
  bad = shell;
  bad.zOutlet = bad.zInlet;
  EXPECT_NE(refusal([&] { bad.validate("kiln.yaml"); }).find("length"), std::string::npos);
  EXPECT_NE(refusal([&] {
              makeKilnInlet(shell, 0.7, 0.35, 0.05, 2.0, 0.57, "kiln.yaml");
            }).find("overlap"),
            std::string::npos);
  EXPECT_NE(refusal([&] {
              makeKilnInlet(shell, 0.046, 0.35, -1.0, 2.0, 0.57, "kiln.yaml");
            }).find("velocity"),
            std::string::npos);
}

} // namespace
