// Tangential contact law on walls against closed forms (validation.md "Contact mechanics"):
// a disc launched sliding on a floor rolls at v0 / (1 + I/(m r^2)) = 2/3 v0 (disc inertia) or
// 5/7 v0 (sphere inertia); a disc at rest dragged by a moving wall (a conveyor floor, and the
// bottom of a huge rotating drum) ends rolling at U f / (1 + f), f = I/(m r^2); and with the
// constant-torque rolling resistance a rolling disc decelerates at mu_r g / (1 + f).
#include "DemTestUtils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using namespace hikiln::dem;
constexpr double radius = 0.01;
constexpr double density = 2700.0;
constexpr double g = 9.81;

double inertiaFactor(MassConvention c) {
  return c == MassConvention::Sphere ? 0.4 : 0.5;
}

// One disc on the floor y = 0 (or at the bottom of a drum of radius drumRadius > 0), resting at
// its equilibrium overlap, with the given velocity and spin.
DemSystem<TEST_EXECSPACE> discOnWall(const ContactParameters& wallLaw, MassConvention convention,
                                     double vx, double spin, double floorSpeed, double drumRadius) {
  DemConfig cfg;
  cfg.gravityY = -g;
  cfg.wallContact = wallLaw;
  auto h = test::hostParticles(1);
  h.radius(0) = radius;
  assignMassPropertiesHost(h, density, convention);
  const double sag = h.mass(0) * g / wallLaw.normalStiffness;
  if (drumRadius > 0.0) {
    cfg.walls.drum.enabled = true;
    cfg.walls.drum.radius = drumRadius;
    cfg.walls.drum.angularVelocity = floorSpeed / drumRadius;
    h.position(0, 1) = -(drumRadius - radius + sag);
  } else {
    cfg.walls.numFlat = 1;
    cfg.walls.flat[0].tangentialVelocity = floorSpeed;
    h.position(0, 1) = radius - sag;
  }
  h.velocity(0, 0) = vx;
  h.angularVelocity(0) = spin;
  DemSystem<TEST_EXECSPACE> sys(cfg);
  sys.setParticles(h);
  return sys;
}

void checkSlideToRoll(MassConvention convention) {
  ContactParameters law; // base case: mu 0.5, e 0.5, c_t = c_n / 2
  const double v0 = 1.0;
  const double f = inertiaFactor(convention);
  auto sys = discOnWall(law, convention, v0, 0.0, 0.0, 0.0);
  const double slideTime = v0 * (1.0 - 1.0 / (1.0 + f)) / (law.friction * g);
  sys.advance(static_cast<std::int64_t>((slideTime + 0.3) / sys.timeStep())); // + time to damp
  const auto k = test::byId(sys).begin()->second;
  EXPECT_NEAR(k.vx / v0, 1.0 / (1.0 + f), 1e-3) << "final speed " << k.vx;
  EXPECT_NEAR(k.vx + k.w * radius, 0.0, 1e-3 * v0); // rolling without slip
  const double m = particleMass(convention, radius, density, 1.0);
  EXPECT_NEAR(k.y, radius - m * g / law.normalStiffness, 1e-7); // resting on the floor
}

TEST(TEST_CATEGORY, dem_sliding_disc_rolls_at_two_thirds) {
  checkSlideToRoll(MassConvention::Disc); // 2/3
}

TEST(TEST_CATEGORY, dem_sliding_sphere_rolls_at_five_sevenths) {
  checkSlideToRoll(MassConvention::Sphere); // 5/7
}

TEST(TEST_CATEGORY, dem_moving_walls_drag_disc_to_rolling) {
  ContactParameters law;
  const double u = 1.0;
  for (MassConvention c : {MassConvention::Disc, MassConvention::Sphere}) {
    const double f = inertiaFactor(c);
    const double slideTime = u * (f / (1.0 + f)) / (law.friction * g);
    for (double drumRadius : {0.0, 1000.0}) { // conveyor floor; bottom of a huge drum
      auto sys = discOnWall(law, c, 0.0, 0.0, u, drumRadius);
      sys.advance(static_cast<std::int64_t>((slideTime + 0.1) / sys.timeStep())); // + time to damp
      const auto k = test::byId(sys).begin()->second;
      EXPECT_NEAR(k.vx / u, f / (1.0 + f), 1e-3) << "drum radius " << drumRadius;
      EXPECT_NEAR(k.vx + k.w * radius, u, 1e-3 * u); // contact point moves with the wall
    }
  }
}

TEST(TEST_CATEGORY, dem_rolling_resistance_deceleration) {
  ContactParameters law;
  law.rolling = RollingModel::ConstantTorque;
  law.rollingFriction = 0.2;
  const double v0 = 1.0;
  for (MassConvention c : {MassConvention::Disc, MassConvention::Sphere}) {
    const double f = inertiaFactor(c);
    auto sys = discOnWall(law, c, v0, -v0 / radius, 0.0, 0.0);
    // least-squares slope of v(t) over 0.05 .. 0.35 s (the disc stops after ~0.7 s)
    const auto steps = static_cast<int>(0.35 / sys.timeStep());
    double st = 0, sv = 0, stt = 0, stv = 0, num = 0;
    for (int s = 0; s < steps; ++s) {
      sys.step();
      if (sys.time() < 0.05 || s % 10 != 0) {
        continue;
      }
      const double v = test::byId(sys).begin()->second.vx;
      st += sys.time();
      sv += v;
      stt += sys.time() * sys.time();
      stv += sys.time() * v;
      num += 1;
    }
    const double slope = (num * stv - st * sv) / (num * stt - st * st);
    const double expected = -law.rollingFriction * g / (1.0 + f);
    EXPECT_NEAR(slope / expected, 1.0, 1e-3) << "deceleration " << slope << " vs " << expected;
  }
}

} // namespace
