// drivers/fit/TemperatureMaps: particles and cells onto comparison blocks, and the measures.
// - particles: area-weighted block temperature, bed fraction = particle area / block area, glued
//   (non-free) particles ignored, particles outside the blocks ignored;
// - cells: capacity x phi weighted temperature, bed fraction = mean capacity x phi / phi_max;
// - mixed fraction of a linear ramp across the bed equals the share of blocks inside 0.1..0.9;
// - theta rms of identical maps is 0, of maps offset by d (K) is d / (hot - cold).
#include "drivers/fit/TemperatureMaps.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace hikiln::fit;

constexpr double pi = 3.14159265358979323846;

TEST(TemperatureMaps, particles_are_area_weighted_per_block) {
  BlockGrid blocks;
  blocks.n = 2;
  blocks.h = 1.0;
  blocks.x0 = -1.0;
  blocks.y0 = -1.0;
  ParticleTemperatureSnapshot s;
  // block 0 (lower left): radii 0.1 at 600 K and 0.2 at 900 K; block 3: one at 700 K;
  // a glued disc in block 0 and a particle outside the grid are ignored
  s.x = {-0.5, -0.4, 0.5, -0.5, 3.0};
  s.y = {-0.5, -0.4, 0.5, -0.6, 0.0};
  s.radius = {0.1, 0.2, 0.3, 0.3, 0.3};
  s.temperature = {600.0, 900.0, 700.0, 5000.0, 5000.0};
  s.kind = {0, 0, 0, 2, 0};
  const TemperatureMap m = binParticles(blocks, s);
  ASSERT_EQ(m.temperature.size(), 4u);
  EXPECT_NEAR(m.temperature[0], (0.01 * 600.0 + 0.04 * 900.0) / 0.05, 1e-12);
  EXPECT_NEAR(m.bedFraction[0], pi * 0.05, 1e-12);
  EXPECT_TRUE(std::isnan(m.temperature[1]));
  EXPECT_EQ(m.bedFraction[1], 0.0);
  EXPECT_NEAR(m.temperature[3], 700.0, 1e-12);
  EXPECT_EQ(blocks.index(-1.0, -1.0), 0);
  EXPECT_EQ(blocks.index(0.99, 0.99), 3);
  EXPECT_EQ(blocks.index(1.0, 0.0), -1);
}

TEST(TemperatureMaps, cells_are_heat_capacity_weighted_per_block) {
  // 4 x 2 cells into 2 x 1 blocks of 2 x 2; block 0: phi/phimax 1, 1, 0.5, 0 with capacities
  // 1, 0.5, 1, 1 and temperatures 600, 800, 1000, 5000 (the empty cell carries no weight)
  const std::vector<double> T = {600, 800, 1, 2, 1000, 5000, 3, 4};
  const std::vector<double> cap = {1, 0.5, 1, 1, 1, 1, 1, 1};
  const std::vector<double> phi = {1, 1, 0, 0, 0.5, 0, 0, 0};
  const TemperatureMap m = coarsenCells(4, 2, 2, T, cap, phi);
  ASSERT_EQ(m.temperature.size(), 2u);
  EXPECT_NEAR(m.temperature[0], (600.0 + 0.5 * 800.0 + 0.5 * 1000.0) / 2.0, 1e-12);
  EXPECT_NEAR(m.bedFraction[0], 2.0 / 4.0, 1e-15);
  EXPECT_TRUE(std::isnan(m.temperature[1]));
  EXPECT_THROW(coarsenCells(3, 2, 2, T, cap, phi), std::invalid_argument);
}

TEST(TemperatureMaps, mixed_fraction_and_theta_rms) {
  // 10 bed blocks with theta = 0.05, 0.15, ..., 0.95: 8 of them in (0.1, 0.9); two gas blocks
  // in the middle of the ramp must not count
  TemperatureMap m;
  const double cold = 673.0, hot = 1073.0;
  for (int b = 0; b < 12; ++b) {
    const double theta = b < 10 ? 0.05 + 0.1 * b : 0.5;
    m.temperature.push_back(cold + theta * (hot - cold));
    m.bedFraction.push_back(b < 10 ? 0.8 : 0.1);
  }
  EXPECT_NEAR(mixedFraction(m, cold, hot, 0.4), 0.8, 1e-15);
  EXPECT_EQ(thetaRms(m, 0.4, m, 0.4, cold, hot), 0.0);
  TemperatureMap shifted = m;
  for (double& t : shifted.temperature)
    t += 20.0;
  EXPECT_NEAR(thetaRms(m, 0.4, shifted, 0.4, cold, hot), 20.0 / (hot - cold), 1e-12);
  TemperatureMap gas = m;
  for (double& f : gas.bedFraction)
    f = 0.0;
  EXPECT_TRUE(std::isnan(mixedFraction(gas, cold, hot, 0.4)));
  EXPECT_TRUE(std::isnan(thetaRms(m, 0.4, gas, 0.4, cold, hot)));
}

} // namespace
