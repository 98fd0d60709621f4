// Straight-line, power-law, Coulomb and Newtonian fits: exact recovery from noise-free data,
// recovery within stated tolerances from seeded noisy data, and clear errors.
#include "solvers/calibration/CoulombFit.hpp"
#include "solvers/calibration/LinearFit.hpp"
#include "solvers/calibration/NewtonianTest.hpp"
#include "solvers/calibration/PowerLawFit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace {
using namespace hikiln::calibration;
constexpr double pi = 3.141592653589793238462643383279502884;

std::vector<double> uniformSamples(std::size_t n, double lo, double hi, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> x(n);
  for (double& v : x)
    v = u(random);
  return x;
}
} // namespace

TEST(calibration_linear, exact_line_recovered_to_rounding) {
  // x far from 0 (as pressures are): centring keeps the intercept exact.
  const std::vector<double> x = uniformSamples(50, 100.0, 3000.0, 7);
  std::vector<double> y;
  for (double v : x)
    y.push_back(2.5 - 0.75 * v);
  const LinearFit fit = fitLinear(x, y);
  EXPECT_NEAR(fit.slope, -0.75, 1e-12);
  EXPECT_NEAR(fit.intercept, 2.5, 1e-12 * 3000.0);
  EXPECT_NEAR(fit.quality.rSquared, 1.0, 1e-14);
  EXPECT_LT(fit.quality.rmsResidual, 1e-11);
  EXPECT_EQ(fit.quality.n, 50u);
  EXPECT_LT(fit.slopeStdError, 1e-13);
  EXPECT_DOUBLE_EQ(fit(2.0), fit.intercept + 2.0 * fit.slope);
}

TEST(calibration_linear, noisy_line_within_standard_errors) {
  const std::size_t n = 400;
  const double sigma = 0.05;
  const std::vector<double> x = uniformSamples(n, 0.0, 10.0, 11);
  std::mt19937_64 random(12);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<double> y;
  for (double v : x)
    y.push_back(0.35 + 0.05 * v + noise(random));
  const LinearFit fit = fitLinear(x, y);
  // Analytic standard error of the slope: sigma / sqrt(sum (x - mean)^2) ~ 0.05 / sqrt(400 * 100 /
  // 12).
  const double expectedSlopeError = sigma / std::sqrt(n * 100.0 / 12.0);
  EXPECT_NEAR(fit.slopeStdError, expectedSlopeError, 0.15 * expectedSlopeError);
  EXPECT_NEAR(fit.slope, 0.05, 4.0 * fit.slopeStdError);
  EXPECT_NEAR(fit.intercept, 0.35, 4.0 * fit.interceptStdError);
  EXPECT_NEAR(fit.quality.rmsResidual, sigma, 0.1 * sigma);
  // R^2 = 1 - sigma^2 / var(y) with var(y) = sigma^2 + 0.05^2 * 100 / 12 (= 0.893).
  const double r2 = 1.0 - sigma * sigma / (sigma * sigma + 0.05 * 0.05 * 100.0 / 12.0);
  EXPECT_NEAR(fit.quality.rSquared, r2, 0.02);
}

TEST(calibration_linear, integer_weights_equal_repeated_points) {
  const std::vector<double> x = {0.0, 1.0, 2.0, 3.0, 4.0};
  const std::vector<double> y = {1.0, 2.9, 5.2, 7.1, 8.8};
  const std::vector<double> w = {1.0, 3.0, 1.0, 2.0, 1.0};
  std::vector<double> xr, yr;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < static_cast<int>(w[i]); ++k) {
      xr.push_back(x[i]);
      yr.push_back(y[i]);
    }
  const LinearFit weighted = fitLinearWeighted(x, y, w);
  const LinearFit repeated = fitLinear(xr, yr);
  EXPECT_NEAR(weighted.slope, repeated.slope, 1e-12);
  EXPECT_NEAR(weighted.intercept, repeated.intercept, 1e-12);
  EXPECT_NEAR(weighted.quality.rSquared, repeated.quality.rSquared, 1e-12);
  // A point with a negligible weight does not move the line.
  const LinearFit outlier =
      fitLinearWeighted({0.0, 1.0, 2.0, 3.0}, {1.0, 3.0, 5.0, 100.0}, {1.0, 1.0, 1.0, 1e-14});
  EXPECT_NEAR(outlier.slope, 2.0, 1e-9);
  EXPECT_NEAR(outlier.intercept, 1.0, 1e-9);
}

TEST(calibration_linear, constant_data_fit_exactly_with_unit_r_squared) {
  const LinearFit fit = fitLinear({1.0, 2.0, 3.0}, {4.0, 4.0, 4.0});
  EXPECT_NEAR(fit.slope, 0.0, 1e-15);
  EXPECT_NEAR(fit.intercept, 4.0, 1e-14);
  EXPECT_EQ(fit.quality.rSquared, 1.0);
}

TEST(calibration_linear, rejects_too_few_points_and_constant_x) {
  EXPECT_THROW(fitLinear({1.0}, {2.0}), std::invalid_argument);
  EXPECT_THROW(fitLinear({1.0, 2.0}, {2.0}), std::invalid_argument);
  EXPECT_THROW(fitLinear({3.0, 3.0, 3.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(fitLinearWeighted({1.0, 2.0}, {1.0, 2.0}, {1.0, -1.0}), std::invalid_argument);
  // Two points: the line is exact, its standard errors are undefined.
  const LinearFit two = fitLinear({1.0, 3.0}, {2.0, 6.0});
  EXPECT_NEAR(two.slope, 2.0, 1e-15);
  EXPECT_TRUE(std::isnan(two.slopeStdError));
}

TEST(calibration_power_law, exact_and_noisy_recovery) {
  const std::vector<double> x = uniformSamples(40, 0.1, 50.0, 3);
  std::vector<double> y;
  for (double v : x)
    y.push_back(3.2 * std::pow(v, 0.45));
  const PowerLawFit exact = fitPowerLaw(x, y);
  EXPECT_NEAR(exact.exponent, 0.45, 1e-12);
  EXPECT_NEAR(exact.coefficient, 3.2, 1e-12);
  EXPECT_NEAR(exact.quality.rSquared, 1.0, 1e-14);
  EXPECT_EQ(exact.dropped, 0u);

  // 5 % multiplicative (log-normal) noise, 300 points: n within 0.02, K within 5 %.
  const std::vector<double> xn = uniformSamples(300, 0.1, 50.0, 4);
  std::mt19937_64 random(5);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<double> yn;
  for (double v : xn)
    yn.push_back(3.2 * std::pow(v, 0.45) * std::exp(noise(random)));
  const PowerLawFit noisy = fitPowerLaw(xn, yn);
  EXPECT_NEAR(noisy.exponent, 0.45, 0.02);
  EXPECT_NEAR(noisy.exponent, 0.45, 4.0 * noisy.exponentStdError);
  EXPECT_NEAR(noisy.coefficient, 3.2, 0.05 * 3.2);
}

TEST(calibration_power_law, skips_non_positive_points) {
  const PowerLawFit fit = fitPowerLaw({0.0, 1.0, 2.0, 4.0, 8.0}, {5.0, 2.0, -1.0, 8.0, 16.0});
  EXPECT_EQ(fit.dropped, 2u);
  EXPECT_EQ(fit.quality.n, 3u);
  EXPECT_NEAR(fit.exponent, 1.0, 1e-12);
  EXPECT_NEAR(fit.coefficient, 2.0, 1e-12);
  EXPECT_THROW(fitPowerLaw({0.0, 1.0}, {1.0, 1.0}), std::invalid_argument);
}

TEST(calibration_coulomb, friction_angle_from_exact_and_noisy_data) {
  const std::vector<double> p = uniformSamples(60, 50.0, 3000.0, 21);
  std::vector<double> tau;
  for (double v : p)
    tau.push_back(12.0 + 0.6 * v);
  const CoulombFit exact = fitCoulomb(p, tau);
  EXPECT_NEAR(exact.frictionCoefficient, 0.6, 1e-12);
  EXPECT_NEAR(exact.cohesion, 12.0, 1e-9);
  // phi = atan(0.6) = 30.96375653207352 degrees.
  EXPECT_NEAR(exact.frictionAngleDeg, 30.96375653207352, 1e-11);
  EXPECT_NEAR(std::tan(exact.frictionAngleDeg * pi / 180.0), 0.6, 1e-12);
  EXPECT_NEAR(exact.quality.rSquared, 1.0, 1e-14);

  std::mt19937_64 random(22);
  std::normal_distribution<double> noise(0.0, 20.0); // Pa
  std::vector<double> noisyTau;
  for (double v : p)
    noisyTau.push_back(12.0 + 0.6 * v + noise(random));
  const CoulombFit noisy = fitCoulomb(p, noisyTau);
  EXPECT_NEAR(noisy.frictionCoefficient, 0.6, 4.0 * noisy.frictionCoefficientStdError);
  EXPECT_NEAR(noisy.frictionCoefficient, 0.6, 0.02);
  EXPECT_NEAR(noisy.cohesion, 12.0, 4.0 * noisy.cohesionStdError);
  // d phi / d mu = 1 / (1 + mu^2) (in radians).
  EXPECT_NEAR(noisy.frictionAngleDegStdError,
              noisy.frictionCoefficientStdError /
                  (1.0 + noisy.frictionCoefficient * noisy.frictionCoefficient) * 180.0 / pi,
              1e-15);
}

TEST(calibration_newtonian, exponent_one_is_newtonian_granular_is_not) {
  const std::vector<double> rate = uniformSamples(100, 0.1, 20.0, 31);
  std::mt19937_64 random(32);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::vector<double> fluid, granular;
  for (double g : rate) {
    fluid.push_back(0.8 * g * std::exp(noise(random)));
    granular.push_back(50.0 * std::pow(g, 0.2));
  }
  const NewtonianTest newtonian = testNewtonian(rate, fluid);
  EXPECT_TRUE(newtonian.newtonian);
  EXPECT_NEAR(newtonian.fit.exponent, 1.0, 0.02);
  EXPECT_NEAR(newtonian.fit.coefficient, 0.8, 0.02);

  const NewtonianTest bed = testNewtonian(rate, granular);
  EXPECT_FALSE(bed.newtonian);
  EXPECT_NEAR(bed.fit.exponent, 0.2, 1e-12);
  EXPECT_NEAR(bed.fit.coefficient, 50.0, 1e-10);
  EXPECT_EQ(bed.tolerance, 0.1);
  // The tolerance decides: n = 0.95 passes at 0.1, fails at 0.01.
  std::vector<double> almost;
  for (double g : rate)
    almost.push_back(std::pow(g, 0.95));
  EXPECT_TRUE(testNewtonian(rate, almost, 0.1).newtonian);
  EXPECT_FALSE(testNewtonian(rate, almost, 0.01).newtonian);
}
