// Head-on collisions (no gravity, no friction) against the closed-form linear spring-dashpot
// (validation.md "Contact mechanics"): restitution e = exp(-pi zeta / sqrt(1 - zeta^2)) and contact
// duration t_c = pi / sqrt(k/m_eff - (c/2m_eff)^2), to 1e-3 relative, for disc-disc impacts at two
// restitutions, with the LAMMPS rate damping, on a wall (m_eff = m), and with the tensile clamp
// (whose exact solution ends the contact when k x + c x' = 0).
#include "DemTestUtils.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace hikiln::dem;
constexpr double pi = hikiln::constants::pi;
constexpr double radius = 0.01;
constexpr double density = 2700.0;
constexpr double approachSpeed = 1.0;

struct Collision {
  double restitution = 0.0;
  double duration = 0.0;
};

// Runs a head-on impact (two discs, or one disc on the wall x = 0) with the time step
// t_c / stepsPerContact and measures e from the separation speed and t_c from the times where
// the overlap crosses zero (linear interpolation between steps).
Collision headOn(const ContactParameters& law, bool onWall, double expectedDuration,
                 int stepsPerContact) {
  DemConfig cfg;
  cfg.gravityY = 0.0;
  cfg.particleContact = law;
  cfg.wallContact = law;
  cfg.timeStep = expectedDuration / stepsPerContact;
  if (onWall) {
    cfg.walls.numFlat = 1;
    cfg.walls.flat[0].normalX = 1.0;
    cfg.walls.flat[0].normalY = 0.0;
  }
  const std::size_t n = onWall ? 1 : 2;
  auto h = test::hostParticles(n);
  const double gap = 1.0e-4;
  for (std::size_t i = 0; i < n; ++i) {
    h.radius(i) = radius;
  }
  if (onWall) {
    h.position(0, 0) = radius + gap;
    h.velocity(0, 0) = -approachSpeed;
  } else {
    h.position(0, 0) = -radius - 0.5 * gap;
    h.position(1, 0) = radius + 0.5 * gap;
    h.velocity(0, 0) = 0.5 * approachSpeed;
    h.velocity(1, 0) = -0.5 * approachSpeed;
  }
  assignMassPropertiesHost(h, density, MassConvention::Sphere);
  DemSystem<TEST_EXECSPACE> sys(cfg);
  sys.setParticles(h);
  const std::int64_t a = h.id(0), b = onWall ? -1 : h.id(1);
  const auto overlapAndSpeed = [&](double& speed) {
    const auto k = test::byId(sys);
    if (onWall) {
      speed = -k.at(a).vx; // approach speed, < 0 once separating
      return radius - k.at(a).x;
    }
    speed = k.at(a).vx - k.at(b).vx;
    return 2.0 * radius - (k.at(b).x - k.at(a).x);
  };
  double speed = 0.0;
  double previous = overlapAndSpeed(speed);
  double start = -1.0, end = -1.0;
  const double dt = sys.timeStep();
  for (int s = 0; s < 4 * stepsPerContact && end < 0.0; ++s) {
    sys.step();
    const double overlap = overlapAndSpeed(speed);
    const double t = sys.time();
    if (start < 0.0 && previous <= 0.0 && overlap > 0.0) {
      start = t - dt * overlap / (overlap - previous);
    } else if (start >= 0.0 && previous > 0.0 && overlap <= 0.0) {
      end = t - dt * overlap / (overlap - previous);
    }
    previous = overlap;
  }
  EXPECT_GT(start, 0.0);
  EXPECT_GT(end, start);
  sys.step(); // one more free step: the separation speed is final
  overlapAndSpeed(speed);
  return Collision{-speed / approachSpeed, end - start};
}

double pairMass() {
  return particleMass(MassConvention::Sphere, radius, density, 1.0);
}

void checkUnclamped(const ContactParameters& law, double meff, bool onWall) {
  const ContactCoefficients c = prepareContact(law);
  const double cn = normalDampingCoefficient(c, meff);
  const double zeta = cn / (2.0 * std::sqrt(c.kn * meff));
  const double eExact = std::exp(-pi * zeta / std::sqrt(1.0 - zeta * zeta));
  const double tExact = pi / std::sqrt(c.kn / meff - std::pow(cn / (2.0 * meff), 2));
  const Collision r = headOn(law, onWall, tExact, 2000);
  EXPECT_NEAR(r.restitution / eExact, 1.0, 1e-3) << "e " << r.restitution << " vs " << eExact;
  EXPECT_NEAR(r.duration / tExact, 1.0, 1e-3) << "t_c " << r.duration << " vs " << tExact;
  if (law.dampingMode == DampingMode::Restitution) {
    EXPECT_NEAR(eExact, law.restitution, 1e-12);
  }
}

TEST(TEST_CATEGORY, dem_head_on_restitution_and_duration_two_e) {
  for (double e : {0.5, 0.9}) {
    ContactParameters law;
    law.friction = 0.0;
    law.restitution = e;
    law.limitDamping = false; // the closed form lets the dashpot pull at the end
    checkUnclamped(law, 0.5 * pairMass(), false);
  }
}

TEST(TEST_CATEGORY, dem_head_on_lammps_rate_damping) {
  ContactParameters law; // gran/hooke/history 1e5 5e4 1813 906 0.5 1 (LAMMPS default: no clamp)
  law.dampingMode = DampingMode::Rate;
  law.normalDampingRate = 1813.0;
  law.tangentialDampingRate = 906.0;
  law.limitDamping = false;
  checkUnclamped(law, 0.5 * pairMass(), false);
}

TEST(TEST_CATEGORY, dem_head_on_wall_uses_particle_mass) {
  ContactParameters law;
  law.friction = 0.0;
  law.restitution = 0.7;
  law.limitDamping = false;
  checkUnclamped(law, pairMass(), true);
}

TEST(TEST_CATEGORY, dem_head_on_clamped_dashpot) {
  ContactParameters law;
  law.friction = 0.0;
  law.restitution = 0.5;
  law.limitDamping = true;
  const ContactCoefficients c = prepareContact(law);
  const double meff = 0.5 * pairMass();
  const double cn = normalDampingCoefficient(c, meff);
  const double a = cn / (2.0 * meff);
  const double wd = std::sqrt(c.kn / meff - a * a);
  // x = v0/wd e^{-at} sin(wd t) until k x + c x' = 0, then free flight at x'(t*)
  const double tStar = (pi - std::atan(cn * wd / (c.kn - cn * a))) / wd;
  const double x = approachSpeed / wd * std::exp(-a * tStar) * std::sin(wd * tStar);
  const double v =
      approachSpeed * std::exp(-a * tStar) * (std::cos(wd * tStar) - a / wd * std::sin(wd * tStar));
  ASSERT_LT(v, 0.0);
  const double eExact = -v / approachSpeed;
  const double tExact = tStar + x / (-v);
  EXPECT_GT(eExact, 0.5); // the clamp makes impacts more elastic than e
  const Collision r = headOn(law, false, tExact, 2000);
  EXPECT_NEAR(r.restitution / eExact, 1.0, 1e-3) << "e " << r.restitution << " vs " << eExact;
  EXPECT_NEAR(r.duration / tExact, 1.0, 1e-3) << "t_c " << r.duration << " vs " << tExact;
}

} // namespace
