// The Drucker-Prager viscous-plastic rheology (kernels/cfd/GranularRheology.hpp):
// - the strain-rate kernel gives gamma_dot = |a| for a simple shear u = a y and 0 for a rigid
//   rotation;
// - simple shear at yield: tau / sigma_n = q / p = m(gamma_dot) (= tan(phi) for constant m), and
//   the wall layer caps it at mu_wall; the regularisation and the cap act where documented;
// - a pressure-driven channel flow with m = m0 + m1 gamma_dot at uniform p (a Bingham fluid with
//   yield stress m0 p and plastic viscosity m1 p), solved by Picard iteration with the implicit
//   viscous multigrid: analytic velocity profile and plug width.
#include "CfdTestUtils.hpp"
#include "kernels/cfd/GranularRheology.hpp"
#include "solvers/cfd/ViscousMultigrid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using field = Field<space::memory_space>;
using velocity = VelocityFields<space::memory_space>;

velocity velocityFrom(Grid const& g, test::Fn3 const& fu, test::Fn3 const& fv) {
  velocity u;
  u.comp[0] = test::fieldFrom(space{}, g, faceStaggering(0), fu);
  u.comp[1] = test::fieldFrom(space{}, g, faceStaggering(1), fv);
  return u;
}

// gamma_dot over the interior cells (one cell away from the edges: ghosts not filled).
void strainRateRange(Grid const& g, velocity const& u, double& lo, double& hi) {
  const field gd = makeField(space{}, g, Staggering::Cell, "gd");
  strainRateInvariant(space{}, g, u, gd);
  const auto h = test::toHost(gd);
  lo = 1e300;
  hi = -1e300;
  for (int j = 1; j < g.ny - 1; ++j) {
    for (int i = 1; i < g.nx - 1; ++i) {
      lo = std::min(lo, h(i + g.ghost, j + g.ghost, 0));
      hi = std::max(hi, h(i + g.ghost, j + g.ghost, 0));
    }
  }
}

TEST(TEST_CATEGORY, rheology_strain_rate_invariant) {
  const Grid g = makeGrid(8, 8, 1, 1.0, 1.0, 1.0, -0.5, -0.5);
  double lo, hi;
  strainRateRange(g,
                  velocityFrom(
                      g, [](double, double y, double) { return 0.7 * y; },
                      [](double, double, double) { return 0.0; }),
                  lo, hi);
  EXPECT_NEAR(lo, 0.7, 1e-12);
  EXPECT_NEAR(hi, 0.7, 1e-12);
  strainRateRange(g,
                  velocityFrom(
                      g, [](double, double y, double) { return -1.3 * y; },
                      [](double x, double, double) { return 1.3 * x; }),
                  lo, hi);
  EXPECT_NEAR(hi, 0.0, 1e-12);
  // pure extension u = (a x, -a y): D' = diag(a, -a), gamma_dot = 2 a
  strainRateRange(g,
                  velocityFrom(
                      g, [](double x, double, double) { return 0.4 * x; },
                      [](double, double y, double) { return -0.4 * y; }),
                  lo, hi);
  EXPECT_NEAR(lo, 0.8, 1e-12);
  EXPECT_NEAR(hi, 0.8, 1e-12);
}

TEST(TEST_CATEGORY, rheology_simple_shear_at_yield) {
  GranularRheology r;
  r.m0 = std::tan(28.0 * hikiln::constants::pi / 180.0);
  r.m1 = 0.05;
  r.muWall = 0.3;
  r.strainRateFloor = 1e-3;
  r.viscosityMax = 1e9;
  const double p = 2000.0;
  for (double rate : {0.01, 1.0, 10.0}) {
    // simple shear: sigma_n = p, tau = q = eta gamma_dot
    const double tau = r.bedViscosity(p, rate, false) * rate;
    EXPECT_NEAR(tau / p, r.m0 + r.m1 * rate, 1e-12) << rate;
    const double tauWall = r.bedViscosity(p, rate, true) * rate;
    EXPECT_NEAR(tauWall / p, std::min(r.m0 + r.m1 * rate, r.muWall), 1e-12) << rate;
  }
  // m constant: tau / sigma_n = tan(phi)
  r.m1 = 0.0;
  EXPECT_NEAR(r.bedViscosity(p, 2.0, false) * 2.0 / p,
              std::tan(28.0 * hikiln::constants::pi / 180.0), 1e-12);
  // regularisation below the floor, cap, no stress without confining pressure
  EXPECT_DOUBLE_EQ(r.bedViscosity(p, 1e-6, false), r.bedViscosity(p, r.strainRateFloor, false));
  r.viscosityMax = 1e4;
  EXPECT_DOUBLE_EQ(r.bedViscosity(p, 1e-6, false), 1e4);
  EXPECT_DOUBLE_EQ(r.bedViscosity(-5.0, 1.0, false), 0.0);
  // the floor: a bed without confining pressure keeps viscosityMin; above it nothing changes
  r.viscosityMin = 10.0;
  EXPECT_DOUBLE_EQ(r.bedViscosity(-5.0, 1.0, false), 10.0);
  EXPECT_DOUBLE_EQ(r.bedViscosity(p, 1e-6, false), 1e4);
  EXPECT_DOUBLE_EQ(r.bedViscosity(p, 2.0, true), r.muWall * p / 2.0);
  r.viscosityMin = 0.0;
  EXPECT_DOUBLE_EQ(r.mixtureViscosity(0.0, p, 1.0, false), r.gasViscosity);
  EXPECT_NEAR(r.mixtureViscosity(0.5 * r.phiMax, p, 1.0, false),
              r.gasViscosity + 0.5 * r.bedViscosity(p, 1.0, false), 1e-12);
  EXPECT_THROW(
      [] {
        GranularRheology bad;
        bad.strainRateFloor = 0.0;
        bad.validate("test");
      }(),
      std::invalid_argument);
}

// Bingham channel -H < y < H driven by a body force G along x, periodic in x:
// plug |y| < y0 = tau_y / G moving at u(y0), u = G / (2 mu_p) (H^2 - y^2) - tau_y / mu_p (H - |y|).
struct Channel {
  double H = 1.0, G = 1.0, tauY = 0.3, muP = 1.0;
  double exact(double y) const {
    const double a = std::max(std::fabs(y), tauY / G);
    return G / (2.0 * muP) * (H * H - a * a) - tauY / muP * (H - a);
  }
};

struct BinghamResult {
  double maxError = 0.0; // max |u - exact| / max exact
  double plugHalfWidth = 0.0;
  int picard = 0;
};

BinghamResult solveBingham(int ny, double floor) {
  const Channel ch;
  const Grid g = makeGrid(4, ny, 1, 4.0 * 2.0 / ny, 2.0 * ch.H, 1.0, 0.0, -ch.H);
  VelocityBoundaries bc;
  bc.kind[XLow] = bc.kind[XHigh] = BoundaryKind::Periodic;
  const double p = 1000.0;
  GranularRheology r;
  r.m0 = ch.tauY / p;
  r.m1 = ch.muP / p;
  r.strainRateFloor = floor;
  r.viscosityMax = 1e12;
  r.gasViscosity = 1e-12;
  velocity u, f;
  for (int c = 0; c < 2; ++c) {
    u.comp[c] = makeField(space{}, g, faceStaggering(c), "u");
    f.comp[c] = makeField(space{}, g, faceStaggering(c), "f");
  }
  Kokkos::deep_copy(f.comp[0], ch.G);
  const field phi = test::fieldFrom(space{}, g, Staggering::Cell,
                                    [&](double, double, double) { return r.phiMax; });
  const field pBed =
      test::fieldFrom(space{}, g, Staggering::Cell, [&](double, double, double) { return p; });
  const field wall = makeField(space{}, g, Staggering::Cell, "wall");
  const field gd = makeField(space{}, g, Staggering::Cell, "gd");
  const field mu = makeField(space{}, g, Staggering::Cell, "mu");
  const field noAlpha[3];
  MultigridOptions options;
  options.tolerance = 1e-10;
  BinghamResult result;
  std::vector<double> previous(ny, 0.0);
  for (result.picard = 1; result.picard <= 400; ++result.picard) {
    for (int c = 0; c < 2; ++c) {
      fillGhostsVelocity(space{}, g, bc, c, u.comp[c]);
    }
    strainRateInvariant(space{}, g, u, gd);
    mixtureViscosity(space{}, g, r, phi, pBed, gd, wall, mu);
    ViscousMultigrid<space> mg(space{}, g, bc, noAlpha, mu, options);
    const SolveStats stats = mg.solvePcg(u, f);
    EXPECT_TRUE(stats.converged);
    const auto h = test::toHost(u.comp[0]);
    double change = 0.0;
    for (int j = 0; j < ny; ++j) {
      change = std::max(change, std::fabs(h(1 + g.ghost, j + g.ghost, 0) - previous[j]));
      previous[j] = h(1 + g.ghost, j + g.ghost, 0);
    }
    if (change < 1e-7) {
      break;
    }
  }
  const double peak = ch.exact(0.0);
  const auto gh = test::toHost(gd);
  for (int j = 0; j < ny; ++j) {
    const double y = g.coordinate(faceStaggering(0), 1, j);
    result.maxError = std::max(result.maxError, std::fabs(previous[j] - ch.exact(y)) / peak);
    // plug: the cells whose strain rate is below 1 % of the wall strain rate
    if (gh(1 + g.ghost, j + g.ghost, 0) < 0.01 * (ch.G * ch.H - ch.tauY) / ch.muP) {
      result.plugHalfWidth = std::max(result.plugHalfWidth, std::fabs(y) + 0.5 * g.hy);
    }
  }
  return result;
}

TEST(TEST_CATEGORY, rheology_bingham_channel_plug) {
  const Channel ch;
  const double y0 = ch.tauY / ch.G;
  double previous = 1.0;
  for (int ny : {32, 64}) {
    const BinghamResult r = solveBingham(ny, 1e-4);
    const double h = 2.0 * ch.H / ny;
    // the strain rate grows as (G |y| - tau_y) / mu_p outside the plug: 1 % of the wall rate
    // is reached 0.007 H beyond y0
    const double plugEdge = y0 + 0.01 * (ch.G * ch.H - ch.tauY) / ch.G;
    std::cout << "ny " << ny << ": Picard " << r.picard << ", max error " << r.maxError
              << ", plug half width " << r.plugHalfWidth << " (analytic " << plugEdge << ")\n";
    EXPECT_LT(r.picard, 400) << "Picard iteration did not converge";
    // measured 0.032 and 0.013: the kink at the plug edge limits the order to about 1
    EXPECT_LT(r.maxError, 1.2 / ny) << ny;
    EXPECT_LT(r.maxError, 0.6 * previous) << ny;
    EXPECT_NEAR(r.plugHalfWidth, plugEdge, 1.01 * h) << ny;
    previous = r.maxError;
  }
}

} // namespace
