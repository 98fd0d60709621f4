// Intra-particle conduction against the analytic series (validation.md "Heat conduction"): one
// particle whose surface exchanges with a fixed environment at Bi = h R / k = 1, sphere and
// infinite cylinder (disc). The series is computed here (eigenvalues by bracketing and bisection)
// and checked against the table of validation.md first; the finite-volume centre node (at
// r = dr/2) is then compared with the series at that radius at Fo = 0.05, 0.2, 0.5, 1. The error
// must fall at second order with the shell count and be small at the default count. Measured
// (max over the four Fo, theta units): sphere 2.1e-2 / 5.7e-3 / 1.4e-3 / 3.6e-4 and cylinder
// 1.4e-2 / 3.1e-3 / 8.2e-4 / 2.1e-4 at 2 / 4 / 8 / 16 shells (heat step at safety 0.5).
#include "HeatTestUtils.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;

constexpr double pi = 3.14159265358979323846;

// Roots z > 0 of f, the first `count` of them, by scanning for sign changes and bisecting.
template <class F> std::vector<double> roots(F f, int count) {
  std::vector<double> z;
  const double step = 1.0e-2;
  double a = 1.0e-6, fa = f(a);
  while (static_cast<int>(z.size()) < count) {
    const double b = a + step, fb = f(b);
    if ((fa < 0.0) != (fb < 0.0)) {
      double lo = a, hi = b, flo = fa;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if ((fm < 0.0) == (flo < 0.0)) {
          lo = mid, flo = fm;
        } else {
          hi = mid;
        }
      }
      z.push_back(0.5 * (lo + hi));
    }
    a = b, fa = fb;
  }
  return z;
}

// theta* = (T - T_env) / (T_0 - T_env) at radius rStar = r/R and Fourier number fo.
// (the eigenvalues are computed once per Biot number)
double sphereSeries(double bi, double rStar, double fo) {
  // 1 - z cot z = Bi, multiplied by sin z (no poles)
  static std::map<double, std::vector<double>> cache;
  if (cache.count(bi) == 0) {
    cache[bi] = roots([bi](double x) { return (1.0 - bi) * std::sin(x) - x * std::cos(x); }, 60);
  }
  const std::vector<double>& z = cache[bi];
  double theta = 0.0;
  for (double zn : z) {
    const double c = 4.0 * (std::sin(zn) - zn * std::cos(zn)) / (2.0 * zn - std::sin(2.0 * zn));
    const double shape = rStar > 0.0 ? std::sin(zn * rStar) / (zn * rStar) : 1.0;
    theta += c * std::exp(-zn * zn * fo) * shape;
  }
  return theta;
}

double cylinderSeries(double bi, double rStar, double fo) {
  static std::map<double, std::vector<double>> cache;
  if (cache.count(bi) == 0) {
    cache[bi] = roots(
        [bi](double x) { return x * std::cyl_bessel_j(1.0, x) - bi * std::cyl_bessel_j(0.0, x); },
        60);
  }
  const std::vector<double>& z = cache[bi];
  double theta = 0.0;
  for (double zn : z) {
    const double j0 = std::cyl_bessel_j(0.0, zn), j1 = std::cyl_bessel_j(1.0, zn);
    const double c = 2.0 / zn * j1 / (j0 * j0 + j1 * j1);
    theta += c * std::exp(-zn * zn * fo) * std::cyl_bessel_j(0.0, zn * rStar);
  }
  return theta;
}

double series(MassConvention g, double bi, double rStar, double fo) {
  return g == MassConvention::Sphere ? sphereSeries(bi, rStar, fo) : cylinderSeries(bi, rStar, fo);
}

const std::array<double, 4> fourier = {0.05, 0.2, 0.5, 1.0};

TEST(TEST_CATEGORY, heat_analytic_series_matches_validation_table) {
  const std::array<double, 4> sphere = {0.9969, 0.7723, 0.3708, 0.1080};
  const std::array<double, 4> cylinder = {0.9989, 0.8702, 0.5486, 0.2494};
  for (int f = 0; f < 4; ++f) {
    EXPECT_NEAR(sphereSeries(1.0, 0.0, fourier[f]), sphere[f], 6e-5) << "Fo " << fourier[f];
    EXPECT_NEAR(cylinderSeries(1.0, 0.0, fourier[f]), cylinder[f], 6e-5) << "Fo " << fourier[f];
  }
  // first eigenvalues and coefficients (validation.md)
  const double zs = roots([](double x) { return -x * std::cos(x); }, 1)[0];
  EXPECT_NEAR(zs, 1.5708, 1e-4);
  EXPECT_NEAR(4.0 * (std::sin(zs) - zs * std::cos(zs)) / (2.0 * zs - std::sin(2.0 * zs)), 1.2732,
              1e-4);
  const double zc = roots(
      [](double x) { return x * std::cyl_bessel_j(1.0, x) - std::cyl_bessel_j(0.0, x); }, 1)[0];
  EXPECT_NEAR(zc, 1.2558, 1e-4);
}

// Largest |node - series| over the four Fourier numbers for one particle with `shells` shells.
double centreError(MassConvention g, int shells) {
  const double radius = 0.01, tEnv = 300.0, t0 = 400.0;
  HeatParameters p = test::quietHeat(g, shells);
  p.environmentExchange = true;
  p.environmentRadiation = false;
  p.environmentTemperature = tEnv;
  p.environmentHeatTransfer = p.conductivity / radius; // Bi = 1
  DemSystem<space> sys(test::staticConfig());
  sys.setParticles(test::placedParticles({{0.0, 0.0, radius}}, g));
  DemHeat<space> heat(p);
  heat.initialize(sys, uniformTemperature(t0));
  const auto host = sys.hostParticles();
  const double volume = particleVolume(g, radius, p.thickness);
  const double alpha = p.conductivity / (host.mass(0) / volume * p.specificHeat);
  double now = 0.0, worst = 0.0;
  for (double fo : fourier) {
    const double t = fo * radius * radius / alpha;
    heat.step(sys, t - now);
    now = t;
    const DemHeatState s = heat.exportState();
    const double node = (s.temperature[0] - tEnv) / (t0 - tEnv);
    const double exact = series(g, 1.0, 0.5 / shells, fo);
    worst = std::max(worst, std::fabs(node - exact));
    // the environment heat is the only change of the heat content
    EXPECT_NEAR(heat.energy() - heat.environmentHeat(), heat.initialEnergy(),
                1e-12 * heat.initialEnergy());
  }
  EXPECT_LT(heat.environmentHeat(), 0.0); // the particle cooled
  return worst;
}

void convergence(MassConvention g, const char* name) {
  std::vector<double> err;
  const std::array<int, 4> shells = {2, 4, 8, 16};
  for (int n : shells) {
    err.push_back(centreError(g, n));
    std::printf("[ heat ] %s, %2d shells: max centre error %.3e\n", name, n, err.back());
  }
  for (std::size_t k = 1; k < err.size(); ++k) {
    EXPECT_LT(err[k], 0.4 * err[k - 1]) << name << ": not converging at " << shells[k];
  }
  const int defaults = HeatParameters{}.shells;
  EXPECT_LT(centreError(g, defaults), 2e-3) << name << " at the default shell count";
}

TEST(TEST_CATEGORY, heat_sphere_centre_converges_to_series) {
  convergence(MassConvention::Sphere, "sphere");
}

TEST(TEST_CATEGORY, heat_cylinder_centre_converges_to_series) {
  convergence(MassConvention::Disc, "cylinder");
}

} // namespace
