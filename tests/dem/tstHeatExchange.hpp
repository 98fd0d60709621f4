// Heat exchange between two particles held still (the heat model stepped without mechanical
// steps): contact conduction through the boundary layers conserves the heat content to round-off
// and equilibrates at the heat-capacity weighted mean temperature; the rescaled contact areas give
// initial rates in the ratio of the areas; radiation between surfaces passes
// sigma eps_pair A_pair (T_1^4 - T_2^4) and also conserves; the environment exchange is
// accounted apart.
#include "HeatTestUtils.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
constexpr double pi = 3.14159265358979323846;
constexpr double sigma = 5.670374419e-8;

const double ra = 0.01, rb = 0.007;

// Particle a at the origin, b to its right with the given surface gap (< 0: overlap).
DemSystem<space> pair(MassConvention g, double gap) {
  DemSystem<space> sys(test::staticConfig());
  sys.setParticles(test::placedParticles({{0.0, 0.0, ra}, {ra + rb + gap, 0.0, rb}}, g));
  return sys;
}

// Heat capacity m c of particles a (id 100) and b (id 107).
std::array<double, 2> capacities(const DemSystem<space>& sys, const HeatParameters& p) {
  const auto h = sys.hostParticles();
  std::map<std::int64_t, double> c;
  for (std::size_t i = 0; i < h.count(); ++i) {
    c[h.id(i)] = h.mass(i) * p.specificHeat;
  }
  return {c.at(100), c.at(107)};
}

TEST(TEST_CATEGORY, heat_contact_pair_conserves_and_equilibrates) {
  for (MassConvention g : {MassConvention::Sphere, MassConvention::Disc}) {
    HeatParameters p = test::quietHeat(g, 4);
    p.contactConduction = true;
    p.contactArea = ContactAreaModel::Overlap; // a large area: equilibrium within 2e4 sub-steps
    const double overlap = g == MassConvention::Sphere ? 5e-4 : 4e-5;
    DemSystem<space> sys = pair(g, -overlap);
    DemHeat<space> heat(p);
    heat.initialize(sys, [](double x, double, std::int64_t) { return x < 0.005 ? 1073.0 : 673.0; });
    const auto c = capacities(sys, p);
    const double mean = (c[0] * 1073.0 + c[1] * 673.0) / (c[0] + c[1]);
    const double e0 = heat.energy();
    EXPECT_NEAR(e0, c[0] * 1073.0 + c[1] * 673.0, 1e-14 * e0);
    double worst = 0.0;
    for (int block = 0; block < 40; ++block) {
      heat.step(sys, 500 * heat.stableTimeStep());
      worst = std::max(worst, std::fabs(heat.energy() - e0) / e0);
    }
    EXPECT_EQ(heat.subStepCount(), 20000);
    EXPECT_LT(worst, 1e-12) << "relative drift of the heat content";
    EXPECT_NEAR(heat.meanTemperature(), mean, 1e-12 * mean);
    // equilibrium: every shell and layer at the capacity-weighted mean
    const DemHeatState s = heat.exportState();
    for (double t : s.temperature) {
      EXPECT_NEAR(t, mean, 1e-3) << (g == MassConvention::Sphere ? "sphere" : "disc");
    }
    ASSERT_EQ(s.contactId.size(), 2u); // one layer per side
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_NEAR(s.contactLayer[k], mean, 1e-3);
      EXPECT_EQ(s.contactLayer[k], s.contactLayerOther[1 - k]); // the two copies agree bitwise
      EXPECT_EQ(s.contactArea[k], s.contactArea[0]);
    }
  }
}

// Heat (J) that particle b gains in the first sub-step with the given area model.
double firstStepHeat(MassConvention g, ContactAreaModel model, double overlap) {
  HeatParameters p = test::quietHeat(g, 8);
  p.contactConduction = true;
  p.contactArea = model;
  DemSystem<space> sys = pair(g, -overlap);
  DemHeat<space> heat(p);
  heat.initialize(sys, [](double x, double, std::int64_t) { return x < 0.005 ? 2.0 : 1.0; });
  const auto c = capacities(sys, p);
  heat.step(sys, heat.stableTimeStep());
  EXPECT_EQ(heat.subStepCount(), 1);
  return (test::meanById(heat).at(107) - 1.0) * c[1];
}

TEST(TEST_CATEGORY, heat_rescaled_contact_area_scales_initial_rate) {
  const double overlap = 4e-5, kn = 1.0e5, estar = 70e9 / (2 * (1 - 0.25 * 0.25));
  const double rEff = ra * rb / (ra + rb), t = 0.02;
  for (MassConvention g : {MassConvention::Sphere, MassConvention::Disc}) {
    const bool sphere = g == MassConvention::Sphere;
    const double unscaled = firstStepHeat(g, ContactAreaModel::Overlap, overlap);
    ASSERT_GT(unscaled, 0.0);
    // stiffness ratio: the geometric area at the overlap delta k_sim / k_real, k_real = E* 2 r_eff:
    // area ratio k_sim / k_real for spheres (area ~ overlap), its square root for disc chords
    const double kRatio = kn / (estar * 2 * rEff);
    EXPECT_NEAR(firstStepHeat(g, ContactAreaModel::StiffnessRatio, overlap) / unscaled,
                sphere ? kRatio : std::sqrt(kRatio), 1e-7 * (sphere ? kRatio : std::sqrt(kRatio)));
    // Hertz area of the material at the spring force over the geometric area
    const double f = kn * overlap;
    const double a3 = 0.75 * f * rEff / estar;
    const double hertz = sphere ? pi * std::cbrt(a3 * a3) / (pi * rEff * overlap)
                                : 2 * t * std::sqrt(4 * f * rEff / (pi * estar * t)) /
                                      (2 * std::sqrt(2 * rEff * overlap) * t);
    EXPECT_NEAR(firstStepHeat(g, ContactAreaModel::Hertz, overlap) / unscaled, hertz, 1e-7 * hertz);
    EXPECT_LT(hertz, 0.2); // the soft spring overstates the contact several times
  }
}

TEST(TEST_CATEGORY, heat_radiation_pair_flux_and_conservation) {
  const MassConvention g = MassConvention::Sphere;
  HeatParameters p = test::quietHeat(g, 8);
  p.radiation = true;
  p.radiationRange = 2e-3;
  DemSystem<space> sys = pair(g, 1e-3);
  ASSERT_GE(sys.skin(), 2e-3);
  DemHeat<space> heat(p);
  heat.initialize(sys, [](double x, double, std::int64_t) { return x < 0.005 ? 1073.0 : 673.0; });
  const auto c = capacities(sys, p);
  // first sub-step: sigma eps_pair A_pair (T_a^4 - T_b^4) from a to b, the outer shells at T_0
  const double dt = heat.stableTimeStep();
  heat.step(sys, dt);
  const double epsPair = 1.0 / (2.0 / p.emissivity - 1.0);
  const double area = 4 * pi * rb * rb / p.neighborShare; // the smaller surface, shared
  const double q = dt * sigma * epsPair * area * (std::pow(1073.0, 4) - std::pow(673.0, 4));
  const auto t1 = test::meanById(heat);
  EXPECT_NEAR((1073.0 - t1.at(100)) * c[0], q, 1e-9 * q);
  EXPECT_NEAR((t1.at(107) - 673.0) * c[1], q, 1e-9 * q);
  // long run: conserved, and equal temperatures at the capacity-weighted mean
  const double e0 = c[0] * 1073.0 + c[1] * 673.0;
  double worst = 0.0;
  for (int block = 0; block < 18; ++block) {
    heat.step(sys, 1000 * dt);
    worst = std::max(worst, std::fabs(heat.energy() - e0) / e0);
  }
  EXPECT_LT(worst, 1e-12);
  const double mean = e0 / (c[0] + c[1]);
  const auto t2 = test::meanById(heat);
  EXPECT_NEAR(t2.at(100), mean, 0.05);
  EXPECT_NEAR(t2.at(107), mean, 0.05);

  // out of range: nothing passes
  DemSystem<space> far = pair(g, 2.5e-3);
  DemHeat<space> apart(p);
  apart.initialize(far, [](double x, double, std::int64_t) { return x < 0.005 ? 1073.0 : 673.0; });
  apart.step(far, 100 * dt);
  const auto t3 = test::meanById(apart);
  EXPECT_EQ(t3.at(100), 1073.0);
  EXPECT_EQ(t3.at(107), 673.0);
}

TEST(TEST_CATEGORY, heat_environment_exchange_accounted_apart) {
  const MassConvention g = MassConvention::Disc;
  HeatParameters p = test::quietHeat(g, 8);
  p.radiation = true;
  p.radiationRange = 2e-3;
  p.environmentExchange = true;
  p.environmentTemperature = 300.0;
  p.environmentRadiation = true;
  DemSystem<space> sys = pair(g, 1e-3);
  DemHeat<space> heat(p);
  heat.initialize(sys, uniformTemperature(1000.0));
  const double dt = heat.stableTimeStep();
  heat.step(sys, dt);
  // each particle has one neighbour in range: 5/6 of its surface sees the environment
  const double t = 0.02, loss = std::pow(300.0, 4) - std::pow(1000.0, 4);
  const double expected = dt * sigma * p.emissivity * (5.0 / 6.0) * 2 * pi * (ra + rb) * t * loss;
  EXPECT_NEAR(heat.environmentHeat(), expected, 1e-12 * std::fabs(expected));
  for (int block = 0; block < 20; ++block) {
    heat.step(sys, 100 * dt);
  }
  EXPECT_LT(heat.meanTemperature(), 1000.0 - 1.0); // it cooled
  EXPECT_NEAR(heat.energy() - heat.environmentHeat(), heat.initialEnergy(),
              1e-12 * heat.initialEnergy());
  EXPECT_NEAR(heat.energyDrift(), 0.0, 1e-12);
}

} // namespace
