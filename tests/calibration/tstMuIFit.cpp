// Levenberg-Marquardt fit of m(I) = m_s + (m_2 - m_s) / (1 + I0 / I): recovers the glass-bead
// values of validation.md (Jop et al. 2006: 0.383, 0.643, 0.279).
#include "solvers/calibration/MuIFit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace {
using namespace hikiln::calibration;

const MuIParameters glassBeads{0.383, 0.643, 0.279};

std::vector<double> logSpaced(std::size_t n, double lo, double hi) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = lo * std::pow(hi / lo, static_cast<double>(i) / static_cast<double>(n - 1));
  return x;
}
} // namespace

TEST(calibration_mu_i, inertial_number_and_law_values) {
  // I = 2 * 0.01 / sqrt(100 / 2500) = 0.1.
  EXPECT_NEAR(inertialNumber(2.0, 0.01, 100.0, 2500.0), 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(evaluateMuI(glassBeads, 0.0), 0.383);
  EXPECT_NEAR(evaluateMuI(glassBeads, 0.279), 0.5 * (0.383 + 0.643), 1e-15);
  EXPECT_NEAR(evaluateMuI(glassBeads, 1e12), 0.643, 1e-12);
}

TEST(calibration_mu_i, recovers_glass_beads_from_exact_data) {
  const std::vector<double> inertial = logSpaced(60, 1e-3, 10.0);
  std::vector<double> m;
  for (double i : inertial)
    m.push_back(evaluateMuI(glassBeads, i));
  const MuIFit fit = fitMuI(inertial, m);
  EXPECT_TRUE(fit.converged);
  EXPECT_NEAR(fit.parameters.staticFriction, 0.383, 1e-12);
  EXPECT_NEAR(fit.parameters.limitFriction, 0.643, 1e-12);
  EXPECT_NEAR(fit.parameters.inertialScale, 0.279, 1e-12);
  EXPECT_NEAR(fit.quality.rSquared, 1.0, 1e-14);
  EXPECT_LT(fit.quality.rmsResidual, 1e-13);
  EXPECT_EQ(fit.quality.n, 60u);
}

TEST(calibration_mu_i, recovers_glass_beads_from_noisy_data) {
  // 400 cells, I log-uniform over 1e-3..3, noise 0.005 on m (about 1 % of m).
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.005);
  std::vector<double> inertial, m;
  for (int k = 0; k < 400; ++k) {
    const double i = 1e-3 * std::pow(3000.0, u(random));
    inertial.push_back(i);
    m.push_back(evaluateMuI(glassBeads, i) + noise(random));
  }
  const MuIFit fit = fitMuI(inertial, m);
  EXPECT_TRUE(fit.converged);
  EXPECT_NEAR(fit.parameters.staticFriction, 0.383, 0.01);
  EXPECT_NEAR(fit.parameters.limitFriction, 0.643, 0.02);
  EXPECT_NEAR(fit.parameters.inertialScale, 0.279, 0.15 * 0.279);
  // Within 4 standard errors, and the standard errors are meaningful (not 0, not huge).
  EXPECT_NEAR(fit.parameters.staticFriction, 0.383, 4.0 * fit.standardErrors.staticFriction);
  EXPECT_NEAR(fit.parameters.limitFriction, 0.643, 4.0 * fit.standardErrors.limitFriction);
  EXPECT_NEAR(fit.parameters.inertialScale, 0.279, 4.0 * fit.standardErrors.inertialScale);
  EXPECT_GT(fit.standardErrors.staticFriction, 1e-4);
  EXPECT_LT(fit.standardErrors.inertialScale, 0.1);
  EXPECT_NEAR(fit.quality.rmsResidual, 0.005, 0.001);
}

TEST(calibration_mu_i, starts_far_from_the_answer) {
  // A law with I0 outside the data range on the low side still converges (the scan finds it).
  const MuIParameters target{0.25, 0.9, 0.004};
  const std::vector<double> inertial = logSpaced(30, 1e-3, 1.0);
  std::vector<double> m;
  for (double i : inertial)
    m.push_back(evaluateMuI(target, i));
  const MuIFit fit = fitMuI(inertial, m);
  EXPECT_TRUE(fit.converged);
  EXPECT_NEAR(fit.parameters.staticFriction, 0.25, 1e-10);
  EXPECT_NEAR(fit.parameters.limitFriction, 0.9, 1e-10);
  EXPECT_NEAR(fit.parameters.inertialScale, 0.004, 1e-12);
}

TEST(calibration_mu_i, rejects_bad_input) {
  EXPECT_THROW(fitMuI({0.1, 0.2}, {0.4, 0.5}), std::invalid_argument);
  EXPECT_THROW(fitMuI({0.1, 0.0, 0.3}, {0.4, 0.5, 0.6}), std::invalid_argument);
  EXPECT_THROW(fitMuI({0.1, std::numeric_limits<double>::quiet_NaN(), 0.3}, {0.4, 0.5, 0.6}),
               std::invalid_argument);
  EXPECT_THROW(fitMuI({0.1, 0.2, 0.3}, {0.4, 0.5}), std::invalid_argument);
}
