// Coarse-graining of blocky (superquadric) particles through DemSystem and FieldAverager:
// (1) virial identity: the contact stress integrated over all cells equals -W with
//     W = sum_walls x_w (x) f_w - sum_i x_i (x) (F_i - m_i g), the pair contact points cancelling
//     in pairs; exact (to round-off) without damping, where the sampled contact forces equal the
//     step's. It fails if the two partners of a pair name different contact points or levers;
// (2) the solid area deposited on each grid equals the sum of the true superquadric areas (the
//     bounding circles would give ~20 % more at N = 4);
// (3) an all-circle blocky system coarse-grains as the disc engine does.
#include "BlockyTestUtils.hpp"
#include "solvers/dem/FieldAverager.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
constexpr double drumRadius = 0.12;
constexpr double gravity = 9.81;

// Rotating drum, no damping (restitution 1): sampled forces are the step's.
DemConfig undampedDrum() {
  DemConfig cfg;
  cfg.gravityY = -gravity;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = drumRadius;
  cfg.walls.drum.angularVelocity = 3.0;
  cfg.particleContact.normalStiffness = 2.0e3;
  cfg.particleContact.tangentialStiffness = 1.0e3;
  cfg.particleContact.restitution = 1.0;
  cfg.wallContact = cfg.particleContact;
  return cfg;
}

AveragedFields averageOnce(const DemSystem<space>& sys) {
  AveragingSettings s;
  s.drumRadius = drumRadius;
  s.thickness = 0.01;
  FieldAverager<space> averager(s);
  averager.sample(sys, sys.time());
  return averager.result();
}

template <class Grid> double cellIntegral(const std::vector<double>& field, const Grid& grid) {
  double sum = 0.0;
  for (std::size_t k = 0; k < field.size(); ++k) {
    sum += field[k] * grid.cellArea(static_cast<int>(k));
  }
  return sum;
}

TEST(TEST_CATEGORY, blocky_coarse_grain_virial_identity_and_area) {
  auto h = test::drumParticles(150, drumRadius, 0.005, 0.1, 0.05, 21, 1.05, true);
  const auto shapes = test::blockify(h, 4.0, 1.5, 22);
  DemSystem<space> sys(undampedDrum());
  sys.setParticles(h, shapes);
  sys.advance(2500);
  const AveragedFields f = averageOnce(sys);
  const auto p = sys.hostParticles();
  const auto b = sys.hostShapes();
  const auto& walls = sys.wallContacts();
  const auto fn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, walls.normalForce);
  const auto ft = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, walls.tangentialForce);
  const DrumWall& drum = sys.forceSettings().walls.drum;

  double w[4] = {0, 0, 0, 0}, scale = 0.0, area = 0.0, boundingArea = 0.0;
  int wallContacts = 0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double x = p.position(i, 0), y = p.position(i, 1);
    const double ox = p.force(i, 0), oy = p.force(i, 1) + p.mass(i) * gravity; // contacts only
    double cx = 0.0, cy = 0.0, fx = 0.0, fy = 0.0;
    if (fn(i, 0) != 0.0 || ft(i, 0) != 0.0) {
      ContactFrame frame;
      double lx = 0.0, ly = 0.0;
      ASSERT_TRUE(blockyDrumContact(b.shape(i), BodyAxis{b.axis(i, 0), b.axis(i, 1)}, p.radius(i),
                                    drum, x, y, p.velocity(i, 0), p.velocity(i, 1),
                                    p.angularVelocity(i), frame, lx, ly));
      fx = -fn(i, 0) * frame.nx - ft(i, 0) * frame.ny;
      fy = -fn(i, 0) * frame.ny + ft(i, 0) * frame.nx;
      cx = x + lx;
      cy = y + ly;
      ++wallContacts;
    }
    w[0] += cx * fx - x * ox;
    w[1] += cx * fy - x * oy;
    w[2] += cy * fx - y * ox;
    w[3] += cy * fy - y * oy;
    scale += std::hypot(x, y) * p.mass(i) * gravity;
    area += superquadricArea(b.shape(i));
    boundingArea += hikiln::constants::pi * p.radius(i) * p.radius(i);
  }
  ASSERT_GT(wallContacts, 10);
  EXPECT_LT(w[3], -0.1 * scale); // compressive: the bed rests on the shell
  const auto expectGrid = [&](const CellFields& c, const auto& grid, const char* name) {
    const double t = f.thickness;
    EXPECT_NEAR(cellIntegral(c.contactXX, grid) * t, -w[0], 1e-9 * scale) << name;
    EXPECT_NEAR(cellIntegral(c.contactXY, grid) * t, -w[1], 1e-9 * scale) << name;
    EXPECT_NEAR(cellIntegral(c.contactYX, grid) * t, -w[2], 1e-9 * scale) << name;
    EXPECT_NEAR(cellIntegral(c.contactYY, grid) * t, -w[3], 1e-9 * scale) << name;
    EXPECT_NEAR(cellIntegral(c.volumeFraction, grid), area, 1e-10 * area) << name;
  };
  expectGrid(f.polar, f.polarGrid, "polar");
  expectGrid(f.cartesian, f.cartesianGrid, "cartesian");
  EXPECT_GT(boundingArea, 1.1 * area); // so (2) tells the two apart
}

TEST(TEST_CATEGORY, blocky_circles_coarse_grain_as_discs) {
  auto h = test::drumParticles(150, drumRadius, 0.005, 0.1, 0.05, 31, 1.05, true);
  const auto shapes = test::blockify(h, 2.0, 1.0, 0);
  DemConfig cfg = undampedDrum();
  cfg.particleContact.restitution = cfg.wallContact.restitution = 0.5;
  DemSystem<space> disc(cfg), blocky(cfg);
  disc.setParticles(h);
  blocky.setParticles(h, shapes);
  disc.advance(2000);
  blocky.advance(2000);
  const AveragedFields a = averageOnce(disc), c = averageOnce(blocky);
  double largest = 0.0;
  for (const double v : a.polar.contactYY) {
    largest = std::max(largest, std::abs(v));
  }
  ASSERT_GT(largest, 0.0);
  for (std::size_t k = 0; k < a.polar.size(); ++k) {
    EXPECT_NEAR(c.polar.contactXX[k], a.polar.contactXX[k], 1e-12 * largest) << "cell " << k;
    EXPECT_NEAR(c.polar.contactXY[k], a.polar.contactXY[k], 1e-12 * largest) << "cell " << k;
    EXPECT_NEAR(c.polar.contactYY[k], a.polar.contactYY[k], 1e-12 * largest) << "cell " << k;
    EXPECT_NEAR(c.polar.volumeFraction[k], a.polar.volumeFraction[k], 1e-12) << "cell " << k;
  }
  EXPECT_NEAR(c.wall.muWall, a.wall.muWall, 1e-12);
}

} // namespace
