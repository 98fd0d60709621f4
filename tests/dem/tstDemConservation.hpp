// Conservation checks of the whole DEM step: (1) elastic, frictionless discs bouncing in a closed
// drum under gravity keep their total energy (kinetic + gravitational + spring) within 1e-4 over
// 1e5 steps; (2) an isolated cluster with every dissipative force on (damping, friction, rolling
// resistance) keeps its linear momentum to round-off, because pair forces are exactly
// antisymmetric.
#include "DemTestUtils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using namespace hikiln::dem;

TEST(TEST_CATEGORY, dem_energy_bounded_elastic_drum) {
  DemConfig cfg;
  cfg.particleContact.friction = 0.0;
  cfg.particleContact.tangentialStiffness = 0.0;
  cfg.particleContact.restitution = 1.0;
  cfg.wallContact = cfg.particleContact;
  // dt = t_c / 100. The error is second order in dt and comes in jumps at contact onsets (where
  // the force has a kink): over this run it was measured 8e-4 at t_c/20, 1.7e-4 at t_c/50 and
  // 4e-5 at t_c/100, so the 1e-4 bound fails for a first-order or drifting integrator.
  cfg.timeStepSafety = 0.01;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = 0.2;
  auto h = test::drumParticles(40, 0.2, 0.01, 0.1, 0.5, 11);
  ASSERT_EQ(h.count(), 40u);
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  DemSystem<TEST_EXECSPACE> sys(cfg);
  sys.setParticles(h);
  // energy above the drum bottom, so that the reference is positive and meaningful
  double massSum = 0.0;
  for (std::size_t i = 0; i < h.count(); ++i) {
    massSum += h.mass(i);
  }
  const double offset = massSum * 9.81 * 0.2;
  const double e0 = sys.energy().total() + offset;
  double worst = 0.0, elasticSeen = 0.0;
  for (int block = 0; block < 1000; ++block) {
    sys.advance(100);
    const EnergyReport e = sys.energy();
    worst = std::max(worst, std::fabs(e.total() + offset - e0) / e0);
    elasticSeen = std::max(elasticSeen, e.elasticPair + e.elasticWall);
  }
  EXPECT_EQ(sys.stepCount(), 100000);
  EXPECT_LT(worst, 1e-4) << "relative energy error";
  EXPECT_GT(elasticSeen, 0.0);       // contacts happened
  EXPECT_GT(sys.rebuildCount(), 10); // and the list was rebuilt along the way
}

TEST(TEST_CATEGORY, dem_momentum_conserved_isolated_cluster) {
  DemConfig cfg; // base-case law with damping and friction, plus rolling resistance
  cfg.gravityY = 0.0;
  cfg.particleContact.rolling = RollingModel::ConstantTorque;
  cfg.particleContact.rollingFriction = 0.1;
  auto h = test::drumParticles(80, 0.2, 0.01, 0.2, 0.3, 12);
  ASSERT_EQ(h.count(), 80u);
  for (std::size_t i = 0; i < h.count(); ++i) { // converge onto the centre: many contacts
    h.velocity(i, 0) -= 4.0 * h.position(i, 0);
    h.velocity(i, 1) -= 4.0 * h.position(i, 1);
  }
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  DemSystem<TEST_EXECSPACE> sys(cfg);
  sys.setParticles(h);
  const MomentumReport p0 = sys.momentum();
  double scale = 0.0; // sum of |m v|: the size of the terms that cancel
  for (std::size_t i = 0; i < h.count(); ++i) {
    scale += h.mass(i) * std::hypot(h.velocity(i, 0), h.velocity(i, 1));
  }
  const double k0 = sys.energy().kinetic();
  double worst = 0.0;
  for (int block = 0; block < 40; ++block) {
    sys.advance(100);
    const MomentumReport p = sys.momentum();
    worst = std::max(worst, std::hypot(p.px - p0.px, p.py - p0.py) / scale);
  }
  EXPECT_GT(std::hypot(p0.px, p0.py), 1e-3 * scale);                 // a non-zero total to conserve
  EXPECT_LT(worst, 1e-14) << "momentum drift relative to sum |m v|"; // measured ~3e-16
  EXPECT_LT(sys.energy().kinetic(), 0.5 * k0); // the collisions dissipated energy
}

} // namespace
