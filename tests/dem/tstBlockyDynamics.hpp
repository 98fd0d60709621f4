// Dynamics of blocky (superquadric) particles (DemSystem with shapes): an all-circle system follows
// the disc engine bitwise; an elastic frictionless blocky bed in a drum keeps its energy; an
// isolated frictional cluster keeps linear and angular momentum; the backend at any thread count
// matches Kokkos::Serial bitwise; on an incline a block sticks where a disc rolls and slides at the
// Coulomb rate beyond the friction angle; a collapsed column of blocks stands steeper than one of
// discs.
#include "BlockyTestUtils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
constexpr bool bitwiseVsHost =
    Kokkos::SpaceAccessibility<Kokkos::HostSpace, space::memory_space>::accessible;

TEST(TEST_CATEGORY, blocky_circles_reproduce_disc_engine) {
  auto h = test::blockyDrumBed(150, 3);
  const auto shapes = test::blockify(h, 2.0, 1.0, 0); // circles: radius, mass, inertia as discs
  DemSystem<space> disc(test::blockyDrumConfig());
  disc.setParticles(h);
  DemSystem<space> blocky(test::blockyDrumConfig());
  blocky.setParticles(h, shapes);
  ASSERT_EQ(disc.timeStep(), blocky.timeStep());
  for (int block = 0; block < 4; ++block) {
    disc.advance(500);
    blocky.advance(500);
    test::expectBitwiseEqual(test::byId(disc), test::byId(blocky));
  }
  EXPECT_GT(disc.energy().elasticPair, 0.0); // a packed bed: contacts all along
  EXPECT_NEAR(blocky.energy().elasticPair, disc.energy().elasticPair,
              1e-12 * disc.energy().elasticPair);
}

TEST(TEST_CATEGORY, blocky_energy_bounded_elastic_drum) {
  DemConfig cfg;
  cfg.particleContact.friction = 0.0;
  cfg.particleContact.tangentialStiffness = 0.0;
  cfg.particleContact.restitution = 1.0;
  cfg.wallContact = cfg.particleContact;
  cfg.timeStepSafety = 0.02; // dt = t_c / 50
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = 0.25;
  auto h = test::drumParticles(200, 0.25, 0.01, 0.1, 0.3, 11, 1.1);
  ASSERT_EQ(h.count(), 200u);
  auto shapes = test::blockify(h, 4.0, 1.5, 12);
  for (std::size_t i = 0; i < h.count(); i += 2) { // every other one blockier and rounder
    shapes.shape(i).n = 6.0;
  }
  assignBlockyMassPropertiesHost(h, shapes, 2700.0, MassConvention::Disc, 0.01);
  DemSystem<space> sys(cfg);
  sys.setParticles(h, shapes);
  double massSum = 0.0;
  for (std::size_t i = 0; i < h.count(); ++i) {
    massSum += h.mass(i);
  }
  const double offset = massSum * 9.81 * 0.25; // energy above the drum bottom
  const double e0 = sys.energy().total() + offset;
  double worst = 0.0, elasticSeen = 0.0, rotationalSeen = 0.0;
  for (int block = 0; block < 100; ++block) {
    sys.advance(100);
    const EnergyReport e = sys.energy();
    worst = std::max(worst, std::fabs(e.total() + offset - e0) / e0);
    elasticSeen = std::max(elasticSeen, e.elasticPair + e.elasticWall);
    rotationalSeen = std::max(rotationalSeen, e.rotational);
  }
  std::printf("elastic blocky drum: worst relative energy error %.2g\n", worst);
  // measured 3e-7 over these 1e4 steps at dt = t_c / 50: bounded, with no drift
  EXPECT_LT(worst, 1e-5) << "relative energy error";
  EXPECT_GT(elasticSeen, 0.0);
  // frictionless: only the off-centre normal forces of non-round shapes spin the particles
  EXPECT_GT(rotationalSeen, 1e-3 * e0);
}

TEST(TEST_CATEGORY, blocky_momentum_conserved_isolated_cluster) {
  DemConfig cfg; // damping and friction on
  cfg.gravityY = 0.0;
  auto h = test::drumParticles(80, 0.2, 0.01, 0.2, 0.3, 12);
  for (std::size_t i = 0; i < h.count(); ++i) { // converge onto the centre: many contacts
    h.velocity(i, 0) -= 4.0 * h.position(i, 0);
    h.velocity(i, 1) -= 4.0 * h.position(i, 1);
  }
  const auto shapes = test::blockify(h, 4.0, 2.0, 5);
  DemSystem<space> sys(cfg);
  sys.setParticles(h, shapes);
  const MomentumReport p0 = sys.momentum();
  double scale = 0.0, angularScale = 0.0;
  for (std::size_t i = 0; i < h.count(); ++i) {
    const double speed = std::hypot(h.velocity(i, 0), h.velocity(i, 1));
    scale += h.mass(i) * speed;
    angularScale += h.mass(i) * speed * std::hypot(h.position(i, 0), h.position(i, 1));
  }
  const double k0 = sys.energy().kinetic();
  double worst = 0.0, worstAngular = 0.0;
  for (int block = 0; block < 40; ++block) {
    sys.advance(100);
    const MomentumReport p = sys.momentum();
    worst = std::max(worst, std::hypot(p.px - p0.px, p.py - p0.py) / scale);
    worstAngular = std::max(worstAngular, std::fabs(p.angular - p0.angular) / angularScale);
  }
  EXPECT_LT(worst, 1e-14) << "momentum drift relative to sum |m v|";
  // torques about the common contact point: angular momentum is conserved to round-off too
  EXPECT_LT(worstAngular, 1e-12) << "angular momentum drift relative to sum m |v| |x|";
  std::printf("cluster drift: momentum %.2g, angular momentum %.2g, kinetic energy left %.2f\n",
              worst, worstAngular, sys.energy().kinetic() / k0);
  EXPECT_LT(sys.energy().kinetic(), 0.9 * k0); // the collisions dissipated energy
}

TEST(TEST_CATEGORY, blocky_thread_count_independent) {
  auto h = test::blockyDrumBed(150, 7);
  const auto shapes = test::blockify(h, 4.0, 1.5, 8);
  DemSystem<space> sys(test::blockyDrumConfig());
  DemSystem<Kokkos::Serial> reference(test::blockyDrumConfig());
  sys.setParticles(h, shapes);
  reference.setParticles(h, shapes);
  sys.advance(1500);
  reference.advance(1500);
  const auto a = test::byId(sys), b = test::byId(reference);
  const auto ta = test::orientationById(sys), tb = test::orientationById(reference);
  if (bitwiseVsHost) {
    test::expectBitwiseEqual(a, b);
    for (const auto& [id, t] : ta) {
      EXPECT_EQ(t, tb.at(id)) << "id " << id;
    }
  } else {
    for (const auto& [id, k] : a) {
      EXPECT_NEAR(k.x, b.at(id).x, 1e-9) << "id " << id;
      EXPECT_NEAR(k.y, b.at(id).y, 1e-9) << "id " << id;
    }
  }
  EXPECT_GT(sys.energy().elasticPair, 0.0);
  EXPECT_GT(sys.rebuildCount(), 2);
}

// exportState()/importState() of a blocky bed (reordered by cell along the way) continue bitwise:
// positions, velocities, orientations and the pair directions kept as history.
TEST(TEST_CATEGORY, blocky_restart_continues_bitwise) {
  auto h = test::blockyDrumBed(150, 11);
  const auto shapes = test::blockify(h, 6.0, 1.3, 12);
  DemConfig cfg = test::blockyDrumConfig();
  cfg.sortEveryRebuilds = 2;
  DemSystem<space> original(cfg);
  original.setParticles(h, shapes);
  original.advance(900);
  const DemState state = original.exportState();
  ASSERT_EQ(state.orientation.size(), state.size());
  ASSERT_EQ(state.contactAngle.size(), state.contactId.size());
  DemSystem<space> restarted(cfg);
  restarted.importState(state);
  ASSERT_TRUE(restarted.blocky());
  original.advance(900);
  restarted.advance(900);
  test::expectBitwiseEqual(test::byId(original), test::byId(restarted));
  const auto ta = test::orientationById(original), tb = test::orientationById(restarted);
  for (const auto& [id, angle] : ta) {
    EXPECT_EQ(angle, tb.at(id)) << "id " << id;
  }
  EXPECT_GT(original.sortCount(), 2);
  EXPECT_GT(original.energy().elasticPair, 0.0);
}

// One particle on the floor y = 0 under gravity tilted by alpha (down-slope along +x) for 0.3 s;
// returns the distance it moved along x.
double slopeTravel(const SuperquadricShape& shape, double alphaDegrees) {
  const double alpha = alphaDegrees * hikiln::constants::pi / 180.0, g = 9.81;
  DemConfig cfg;
  cfg.gravityX = g * std::sin(alpha);
  cfg.gravityY = -g * std::cos(alpha);
  cfg.walls.numFlat = 1;
  auto h = test::hostParticles(1);
  BlockyArrays<Kokkos::HostSpace> b(1);
  b.shape(0) = shape;
  assignBlockyMassPropertiesHost(h, b, 2700.0, MassConvention::Disc, 0.01);
  // resting on its flat side, pressed in by its weight
  h.position(0, 1) = shape.b - h.mass(0) * g * std::cos(alpha) / cfg.wallContact.normalStiffness;
  DemSystem<space> sys(cfg);
  sys.setParticles(h, b);
  sys.advance(static_cast<std::int64_t>(0.3 / sys.timeStep()));
  return sys.hostParticles().position(0, 0);
}

// Analytic incline checks with mu = 0.5 (tan 26.6 deg): at 20 degrees a disc rolls without
// slipping, x = g sin(alpha) t^2 / 3, while a square block (N = 8) sticks; at 30 degrees the block
// slides, x = g (sin(alpha) - mu cos(alpha)) t^2 / 2.
TEST(TEST_CATEGORY, blocky_block_sticks_where_disc_rolls) {
  const double t = 0.3, g = 9.81;
  const double pi = hikiln::constants::pi;
  const SuperquadricShape disc{0.01, 0.01, 2.0}, block{0.01, 0.01, 8.0};
  const double rolled = slopeTravel(disc, 20.0);
  EXPECT_NEAR(rolled, g * std::sin(pi / 9.0) * t * t / 3.0, 0.01 * rolled);
  EXPECT_LT(std::fabs(slopeTravel(block, 20.0)), 1e-5);
  const double slid = slopeTravel(block, 30.0);
  // the friction torque rocks the sliding block on its front corner (a single contact point),
  // with short lift-offs: it travels ~5 % further than a block that keeps its face on the slope
  EXPECT_NEAR(slid, g * (std::sin(pi / 6.0) - 0.5 * std::cos(pi / 6.0)) * t * t / 2.0, 0.1 * slid);
  EXPECT_LT(slid, 0.5 * rolled); // on a steeper slope, still well short of the rolling disc
}

struct Heap {
  double angle = 0.0;     ///< degrees
  double restShare = 0.0; ///< share of particles slower than 1 cm/s
};

// A column of 6 x 10 polydisperse particles (sizes and row offsets drawn from `seed`) against the
// wall x = 0 on the floor y = 0, released to the right, runs for 1.5 s. The slope of the half heap
// is atan(y_c / x_c) of the particles' centroid (for a right triangle of height H and runout L, y_c
// / x_c = H / L), without the particles that left the heap.
Heap collapsedColumn(double blockiness, unsigned seed) {
  DemConfig cfg;
  cfg.particleContact.normalStiffness = 1.0e4;
  cfg.particleContact.tangentialStiffness = 5.0e3;
  cfg.particleContact.restitution = 0.3;
  cfg.particleContact.friction = 0.5;
  cfg.wallContact = cfg.particleContact;
  cfg.walls.numFlat = 2;
  cfg.walls.flat[0].normalY = 1.0; // floor
  cfg.walls.flat[1].normalX = 1.0; // left wall
  cfg.walls.flat[1].normalY = 0.0;
  const double r = 0.01, pitch = 2.1 * 1.15 * r;
  const int columns = 6, rows = 10;
  auto h = test::hostParticles(columns * rows);
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < columns * rows; ++k) {
    const int row = k / columns;
    h.radius(k) = r * (1.0 + 0.15 * u(gen));
    h.position(k, 0) = (k % columns + 0.5 + 0.25 * (row % 2)) * pitch;
    h.position(k, 1) = (row + 0.5) * pitch;
  }
  const auto shapes = test::blockify(h, blockiness, 1.0, 6, 2500.0, 2.0 * r);
  DemSystem<space> sys(cfg);
  sys.setParticles(h, shapes);
  sys.advance(static_cast<std::int64_t>(1.5 / sys.timeStep()));
  const auto p = sys.hostParticles();
  double mx = 0.0, my = 0.0;
  std::size_t atRest = 0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    bool inHeap = false; // a particle alone on the floor has slid or rolled away from the heap
    for (std::size_t j = 0; j < p.count() && !inHeap; ++j) {
      const double reach = 1.05 * (p.radius(i) + p.radius(j));
      inHeap = j != i && std::hypot(p.position(j, 0) - p.position(i, 0),
                                    p.position(j, 1) - p.position(i, 1)) < reach;
    }
    if (!inHeap) {
      continue;
    }
    mx += p.mass(i) * p.position(i, 0);
    my += p.mass(i) * p.position(i, 1);
    atRest += std::hypot(p.velocity(i, 0), p.velocity(i, 1)) < 0.01 ? 1 : 0;
  }
  return Heap{std::atan(my / mx) * 180.0 / hikiln::constants::pi,
              static_cast<double>(atRest) / static_cast<double>(p.count())};
}

// Discs (no rolling resistance) keep rolling down the slope; blocks come to rest at a steeper one.
// Each collapse is chaotic: over 12 seeds of the column the share of blocks at rest after 0.8 s
// ranged from 30 % to 95 %, and a change at round-off (the contact search's iterates) moved the
// seed this test used from 85 % to 60 %, so the test averages three columns (seeds 1-3) and lets
// them settle for 1.5 s. Measured (2026-12-05, the
// Newton search): discs 5.9 deg on average, N = 4 blocks 13.6 deg with 96 % at rest (seeds 1-12
// at 1.5 s, with the search before it too: blocks 88-97 % at rest, 10.7-16.9 deg).
TEST(TEST_CATEGORY, blocky_heap_steeper_than_discs) {
  Heap discs, blocks;
  const unsigned seeds[] = {1, 2, 3};
  for (const unsigned seed : seeds) {
    const Heap d = collapsedColumn(2.0, seed), b = collapsedColumn(4.0, seed);
    std::printf("collapsed column %u: discs %.1f deg (%.0f %% at rest), blocks (N = 4) %.1f deg "
                "(%.0f %% at rest)\n",
                seed, d.angle, 100.0 * d.restShare, b.angle, 100.0 * b.restShare);
    discs.angle += d.angle / 3.0;
    discs.restShare += d.restShare / 3.0;
    blocks.angle += b.angle / 3.0;
    blocks.restShare += b.restShare / 3.0;
  }
  EXPECT_GT(blocks.restShare, 0.8);
  EXPECT_GT(blocks.angle, discs.angle + 5.0);
}

} // namespace
