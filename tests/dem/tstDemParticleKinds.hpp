// Fixed and shell-attached particles (ParticleKind): a fixed disc is a body of infinite mass (a
// free disc bounces off it with the restitution and contact duration of m_eff = m), never moves,
// and two fixed discs ignore each other; shell discs follow the drum rotation exactly (no drift)
// and carry the bed along; a rough drum stays bitwise reproducible across thread counts, rebuilds,
// reorders and export/import; bad kinds are clear errors.
#include "DemTestUtils.hpp"

#include "solvers/dem/DrumAnalysis.hpp"
#include "solvers/dem/DrumFill.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
constexpr bool bitwiseVsHost =
    Kokkos::SpaceAccessibility<Kokkos::HostSpace, space::memory_space>::accessible;
constexpr auto fixedKind = static_cast<std::uint8_t>(ParticleKind::Fixed);
constexpr auto shellKind = static_cast<std::uint8_t>(ParticleKind::Shell);

// Free disc 0 flies at speed v0 along +x into fixed disc 1 (no gravity); returns the rebound
// speed ratio and the contact duration.
std::pair<double, double> bounceOffFixed(const ContactParameters& law, double v0) {
  DemConfig cfg;
  cfg.gravityY = 0.0;
  cfg.particleContact = law;
  cfg.timeStepSafety = 0.005; // the duration to a fraction of a percent
  auto h = test::hostParticles(2);
  h.radius(0) = h.radius(1) = 0.01;
  h.position(0, 0) = -0.0101;
  h.position(1, 0) = 0.0101;
  h.velocity(0, 0) = v0;
  h.kind(1) = fixedKind;
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  DemSystem<space> sys(cfg);
  sys.setParticles(h);
  double contactTime = 0.0;
  for (int s = 0; s < 20000; ++s) {
    sys.step();
    const auto k = test::byId(sys);
    const bool touching = k.at(h.id(1)).x - k.at(h.id(0)).x < 0.02;
    if (touching) {
      contactTime += sys.timeStep();
    } else if (contactTime > 0.0) {
      break;
    }
  }
  const auto k = test::byId(sys);
  EXPECT_EQ(k.at(h.id(1)).x, 0.0101); // the fixed disc has not moved at all
  EXPECT_EQ(k.at(h.id(1)).vx, 0.0);
  EXPECT_EQ(k.at(h.id(1)).w, 0.0);
  return {-k.at(h.id(0)).vx / v0, contactTime};
}

TEST(TEST_CATEGORY, dem_fixed_particle_has_infinite_mass) {
  ContactParameters law;
  law.restitution = 0.7;
  law.limitDamping = false; // the closed forms are those of the unclamped spring-dashpot
  const auto [e, tc] = bounceOffFixed(law, 0.5);
  EXPECT_NEAR(e, 0.7, 2e-3);
  // the duration of m_eff = m (a free pair would have m/2: sqrt(2) shorter)
  const double m = particleMass(MassConvention::Sphere, 0.01, 2700.0, 1.0);
  const ContactCoefficients c = prepareContact(law);
  const double expected = contactDuration(law.normalStiffness, m, normalDampingCoefficient(c, m));
  EXPECT_NEAR(tc / expected, 1.0, 1e-2) << "measured " << tc << " s, expected " << expected;
}

TEST(TEST_CATEGORY, dem_fixed_particles_ignore_each_other_and_gravity) {
  DemConfig cfg; // gravity on
  auto h = test::hostParticles(3);
  for (int i = 0; i < 3; ++i) {
    h.radius(i) = 0.01;
  }
  h.position(1, 0) = 0.015; // overlapping fixed pair: no force between them
  h.position(2, 1) = 0.05;  // a free disc falling onto them
  h.kind(0) = h.kind(1) = fixedKind;
  h.velocity(0, 0) = 1.0; // a fixed particle's velocity is set to zero
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  DemSystem<space> sys(cfg);
  sys.setParticles(h);
  const auto before = test::byId(sys);
  EXPECT_EQ(before.at(h.id(0)).fx, 0.0);
  EXPECT_EQ(before.at(h.id(0)).fy, 0.0);
  sys.advance(20000); // 0.45 s: the free disc lands and comes to rest
  const auto after = test::byId(sys);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(after.at(h.id(i)).x, h.position(i, 0));
    EXPECT_EQ(after.at(h.id(i)).y, h.position(i, 1));
    EXPECT_EQ(after.at(h.id(i)).vx, 0.0);
  }
  const auto& top = after.at(h.id(2));
  EXPECT_GT(top.y, 0.0);              // resting on the pair
  EXPECT_LT(std::fabs(top.vy), 1e-3); // at rest
  EXPECT_LT(sys.energy().kinetic(), 1e-8);
  // the pair carries the free disc's weight: the contact forces on the fixed discs sum to -mg
  EXPECT_NEAR(after.at(h.id(0)).fy + after.at(h.id(1)).fy, cfg.gravityY * h.mass(2),
              1e-6 * h.mass(2) * 9.81);
}

// A small drum with a ring of glued discs and a bed.
DemConfig roughDrumConfig() {
  DemConfig cfg;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = 0.12;
  cfg.walls.drum.angularVelocity = 0.0;
  cfg.particleContact.normalStiffness = 2.0e3;
  cfg.particleContact.tangentialStiffness = 1.0e3;
  cfg.wallContact = cfg.particleContact;
  cfg.sortEveryRebuilds = 2;
  return cfg;
}

ParticleArrays<Kokkos::HostSpace> roughDrumFill() {
  FillSpec spec;
  spec.drumRadius = 0.12;
  spec.fill = 0.3;
  spec.meanDiameter = 0.01;
  spec.sizeRange = 0.1;
  spec.shellBumpDiameter = 0.01;
  spec.shellBumpSpacing = 1.2;
  return generateDrumLattice(spec);
}

// The rough drum turned at 3 rad/s for 2000 steps after 2000 at rest (computed once).
const DemState& turningRoughDrum() {
  static const DemState state = [] {
    DemSystem<space> sys(roughDrumConfig());
    sys.setParticles(roughDrumFill());
    sys.advance(2000);
    sys.setDrumAngularVelocity(3.0);
    sys.advance(2000);
    return sys.exportState();
  }();
  return state;
}

TEST(TEST_CATEGORY, dem_shell_particles_follow_the_drum_exactly) {
  const auto h = roughDrumFill();
  std::map<std::int64_t, std::pair<double, double>> home;
  for (std::size_t i = 0; i < h.count(); ++i) {
    if (h.kind(i) == shellKind) {
      home[h.id(i)] = {h.position(i, 0), h.position(i, 1)};
    }
  }
  ASSERT_GT(home.size(), 50u);
  DemSystem<space> sys(roughDrumConfig());
  sys.setParticles(h);
  sys.advance(500);
  const double omega = 3.0;
  sys.setDrumAngularVelocity(omega);
  const std::int64_t steps = 20000;
  sys.advance(steps);
  double angle = 0.0; // the system's own sum of omega dt
  for (std::int64_t s = 0; s < steps; ++s) {
    angle += omega * sys.timeStep();
  }
  EXPECT_EQ(sys.shellAngle(), angle);
  ShellMotion m;
  m.cosAngle = std::cos(angle);
  m.sinAngle = std::sin(angle);
  m.angularVelocity = omega;
  const auto after = sys.hostParticles();
  for (std::size_t i = 0; i < after.count(); ++i) {
    if (after.kind(i) != shellKind) {
      continue;
    }
    const auto [hx, hy] = home.at(after.id(i));
    double x, y, vx, vy, w;
    placeOnShell(m, hx, hy, x, y, vx, vy, w);
    EXPECT_EQ(after.position(i, 0), x);
    EXPECT_EQ(after.position(i, 1), y);
    EXPECT_EQ(after.velocity(i, 0), vx);
    EXPECT_EQ(after.velocity(i, 1), vy);
    EXPECT_EQ(after.angularVelocity(i), omega);
    // on its circle to round-off, however long the run
    EXPECT_NEAR(std::hypot(x, y), std::hypot(hx, hy), 1e-15);
  }
  // the rough shell drags the bed: the first layer moves with the bump tops (little slip)
  const double slip = wallSlip(after, 0.12, omega);
  EXPECT_LT(slip, 0.5) << "wall slip " << slip;
  EXPECT_GT(sys.energy().kinetic(), 0.0);
}

TEST(TEST_CATEGORY, dem_scaling_free_motion_leaves_prescribed_motion) {
  // the same steps twice: `twin` is read as it is, `sys` scaled with its half kick still pending
  DemSystem<space> sys(roughDrumConfig()), twin(roughDrumConfig());
  for (auto* s : {&sys, &twin}) {
    s->importState(turningRoughDrum());
    s->setDrumAngularVelocity(3.0);
    s->advance(3);
  }
  sys.scaleFreeMotion(0.25); // a power of two: the products are exact
  const auto before = test::byId(twin);
  const auto kinds = twin.hostParticles();
  const double kineticBefore = twin.energy().kinetic();
  const auto after = test::byId(sys);
  int free = 0, shell = 0;
  for (std::size_t i = 0; i < kinds.count(); ++i) {
    const auto& b = before.at(kinds.id(i));
    const auto& a = after.at(kinds.id(i));
    const bool onShell = kinds.kind(i) == shellKind;
    const double f = onShell ? 1.0 : 0.25;
    (onShell ? shell : free) += 1;
    if (onShell) {
      EXPECT_NE(b.vx * b.vx + b.vy * b.vy, 0.0); // the shell turns
    }
    EXPECT_EQ(a.vx, f * b.vx);
    EXPECT_EQ(a.vy, f * b.vy);
    EXPECT_EQ(a.w, f * b.w);
    EXPECT_EQ(a.x, b.x);
    EXPECT_EQ(a.y, b.y);
    EXPECT_EQ(a.fx, b.fx);
  }
  ASSERT_GT(free, 100);
  ASSERT_GT(shell, 50);
  EXPECT_GT(kineticBefore, 0.0);
  // the shell ring (3 rad/s) is not counted in the kinetic energy: the bed's falls 16x
  EXPECT_NEAR(sys.energy().kinetic(), kineticBefore / 16.0, 1e-12 * kineticBefore);
  EXPECT_THROW(sys.scaleFreeMotion(1.5), std::invalid_argument);
  EXPECT_THROW(sys.scaleFreeMotion(std::nan("")), std::invalid_argument);
  sys.advance(100);
  EXPECT_TRUE(std::isfinite(sys.energy().kinetic()));
}

TEST(TEST_CATEGORY, dem_rough_drum_bitwise_across_threads_reorders_and_restart) {
  DemSystem<space> plain(roughDrumConfig()), shuffled(roughDrumConfig());
  plain.importState(turningRoughDrum());
  shuffled.importState(turningRoughDrum());
  EXPECT_EQ(plain.shellAngle(), turningRoughDrum().shellAngle);
  plain.setDrumAngularVelocity(3.0);
  shuffled.setDrumAngularVelocity(3.0);
  for (int s = 0; s < 300; ++s) {
    if (s % 3 == 0) {
      shuffled.sortByCell();
    }
    plain.step();
    shuffled.step();
  }
  test::expectBitwiseEqual(test::byId(plain), test::byId(shuffled));
  const DemState mid = plain.exportState();
  plain.advance(300);
  DemSystem<space> resumed(roughDrumConfig());
  resumed.setDrumAngularVelocity(3.0);
  resumed.importState(mid);
  resumed.advance(300);
  test::expectBitwiseEqual(test::byId(plain), test::byId(resumed));
#ifdef KOKKOS_ENABLE_SERIAL
  DemSystem<Kokkos::Serial> ref(roughDrumConfig());
  ref.setDrumAngularVelocity(3.0);
  ref.importState(mid);
  ref.advance(300);
  if (bitwiseVsHost) {
    test::expectBitwiseEqual(test::byId(plain), test::byId(ref));
  }
#endif
}

// The wall slip of a rough drum is measured against the bump tops and does not depend on the
// particle order (a restarted run has another order: its sums must not change).
TEST(TEST_CATEGORY, dem_rough_wall_slip_independent_of_particle_order) {
  DemSystem<space> sys(roughDrumConfig());
  sys.importState(turningRoughDrum());
  const auto h = sys.hostParticles();
  const std::size_t n = h.count();
  ParticleArrays<Kokkos::HostSpace> reversed(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = n - 1 - i;
    for (int c = 0; c < 2; ++c) {
      reversed.position(j, c) = h.position(i, c);
      reversed.velocity(j, c) = h.velocity(i, c);
    }
    reversed.radius(j) = h.radius(i);
    reversed.id(j) = h.id(i);
    reversed.kind(j) = h.kind(i);
  }
  const double slip = wallSlip(h, 0.12, 3.0);
  EXPECT_TRUE(std::isfinite(slip));
  EXPECT_EQ(slip, wallSlip(reversed, 0.12, 3.0));
  EXPECT_NEAR(shellInnerRadius(h, 0.12), 0.12 - 0.01, 1e-12); // the bump tops: R - d_b
}

TEST(TEST_CATEGORY, dem_bad_particle_kinds_are_errors) {
  const auto expectError = [](DemConfig cfg, const ParticleArrays<Kokkos::HostSpace>& h,
                              const std::string& text) {
    DemSystem<space> sys(cfg);
    try {
      sys.setParticles(h);
      ADD_FAILURE() << "expected an error containing '" << text << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  auto h = test::hostParticles(3); // ids 100, 107, 114
  for (int i = 0; i < 3; ++i) {
    h.radius(i) = 0.01;
    h.position(i, 0) = 0.03 * i;
  }
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  h.kind(0) = 7;
  expectError(DemConfig{}, h, "unknown kind");
  h.kind(0) = shellKind;
  expectError(DemConfig{}, h, "needs a drum wall");
  h.kind(1) = shellKind; // ids 100 and 107: not consecutive
  expectError(roughDrumConfig(), h, "consecutive ids");
}

} // namespace
