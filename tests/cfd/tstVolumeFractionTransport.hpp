// The volume fraction's transport and its step bound (kernels/cfd/VolumeFractionFct.hpp), on a
// closed box (every cell whole) with settling along -y:
// - grains over an empty cell: maxCourantRate() is |w| / h, and that is the bound that
//   matters: at dt = 1 / rate the low-order step empties the cell exactly, at 1.5 / rate phi
//   goes negative;
// - transportVolumeFractionInSubsteps() at the advective step of a divergence-free vortex with
//   grains above the gas: several sub-steps, phi bounded (one plain step of the same length is
//   not), the solids conserved, and the summed fluxes it leaves reproduce phi's change in every
//   cell (what the heat advection reads).
#include "CfdTestUtils.hpp"
#include "kernels/cfd/VolumeFractionFct.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using memory_space = space::memory_space;

constexpr double h = 0.1, phiMax = 0.6, settlingSpeed = 0.5;
constexpr double settling[3] = {0.0, -settlingSpeed, 0.0};
constexpr double noSettling[3] = {0.0, 0.0, 0.0};

/// Every point inside: a closed box of whole cells.
struct WholeBox {
  KOKKOS_INLINE_FUNCTION bool inside(double, double, double) const { return true; }
  KOKKOS_INLINE_FUNCTION double wallVelocity(int, double, double, double) const { return 0.0; }
};

Grid boxGrid(int nx, int ny) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.hx = g.hy = g.hz = h;
  return g;
}

/// phi from a function of the cell indices (i, j).
template <class Fn> Field<memory_space> phiByCell(Grid const& g, Fn const& f) {
  return hikiln::cfd::test::fieldFrom(
      space{}, g, Staggering::Cell, [&](double x, double y, double) {
        return f(static_cast<int>(std::floor(x / h)), static_cast<int>(std::floor(y / h)));
      });
}

VelocityFields<memory_space> still(Grid const& g) {
  VelocityFields<memory_space> u;
  for (int a = 0; a < 3; ++a) {
    u.comp[a] = makeField(space{}, g, faceStaggering(a), "test::u");
  }
  return u;
}

double minOf(Field<memory_space> const& phi, Grid const& g, double& maxOut) {
  const auto p = hikiln::cfd::test::toHost(phi);
  double lo = 1e300;
  maxOut = -1e300;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      lo = std::min(lo, p(i + g.ghost, j + g.ghost, 0));
      maxOut = std::max(maxOut, p(i + g.ghost, j + g.ghost, 0));
    }
  }
  return lo;
}

// Transports a copy of phi by dt (still velocity) and returns its min and max.
void stepRange(CutCells<memory_space> const& cc, Field<memory_space> const& phi0, double dt,
               double& lo, double& hi) {
  const Grid g = cc.grid;
  auto phi = makeField(space{}, g, Staggering::Cell, "test::phi");
  Kokkos::deep_copy(phi, phi0);
  const auto work = makeFctWork(space{}, g);
  transportVolumeFraction(space{}, cc, still(g), settling, dt, phiMax, phi, work);
  lo = minOf(phi, g, hi);
}

TEST(TEST_CATEGORY, settling_rate_of_grains_over_an_empty_cell_bounds_phi_below) {
  const Grid g = boxGrid(4, 6);
  const auto cc = buildCutCells(space{}, g, WholeBox{});
  const auto phi = phiByCell(g, [](int i, int j) { return i == 1 && j == 4 ? 0.3 : 0.0; });
  const double rate = maxCourantRate(space{}, cc, still(g), settling);
  EXPECT_NEAR(rate, settlingSpeed / h, 1e-12 * settlingSpeed / h);
  double lo = 0.0, hi = 0.0;
  stepRange(cc, phi, 1.0 / rate, lo, hi); // the grains leave the cell whole
  EXPECT_GE(lo, -1e-15);
  stepRange(cc, phi, 1.5 / rate, lo, hi); // more than they are
  EXPECT_LT(lo, -0.1);
}

TEST(TEST_CATEGORY, substepped_transport_is_bounded_and_leaves_the_summed_fluxes) {
  const int n = 12;
  const Grid g = boxGrid(n, n);
  const auto cc = buildCutCells(space{}, g, WholeBox{});
  // a vortex from a stream function psi at the nodes (psi = 0 on the walls): the face fluxes
  // are divergence-free to round-off
  const double length = n * h, amplitude = 0.04, pi = hikiln::constants::pi;
  const auto psi = [&](double x, double y) {
    return amplitude * std::sin(pi * x / length) * std::sin(pi * y / length);
  };
  VelocityFields<memory_space> u = still(g);
  u.comp[0] =
      hikiln::cfd::test::fieldFrom(space{}, g, faceStaggering(0), [&](double x, double y, double) {
        return (psi(x, y + 0.5 * h) - psi(x, y - 0.5 * h)) / h;
      });
  u.comp[1] =
      hikiln::cfd::test::fieldFrom(space{}, g, faceStaggering(1), [&](double x, double y, double) {
        return -(psi(x + 0.5 * h, y) - psi(x - 0.5 * h, y)) / h;
      });
  // grains (below phiMax) in the upper middle, gas under them
  const auto phi0 =
      phiByCell(g, [&](int i, int j) { return j >= 8 && i >= 3 && i < 9 ? 0.5 : 0.0; });
  const double cfl = 0.5;
  const double dt = cfl / maxCourantRate(space{}, cc, u, noSettling);

  auto plain = makeField(space{}, g, Staggering::Cell, "test::plain");
  Kokkos::deep_copy(plain, phi0);
  transportVolumeFraction(space{}, cc, u, settling, dt, phiMax, plain, makeFctWork(space{}, g));
  double plainHi = 0.0;
  const double plainLo = minOf(plain, g, plainHi);
  EXPECT_LT(plainLo, -1e-3) << "one plain step of this length should leave the bounds";

  auto phi = makeField(space{}, g, Staggering::Cell, "test::phi");
  Kokkos::deep_copy(phi, phi0);
  auto work = makeFctWork(space{}, g);
  const int substeps =
      transportVolumeFractionInSubsteps(space{}, cc, u, settling, dt, phiMax, cfl, phi, work);
  EXPECT_GE(substeps, 3);
  double hi = 0.0;
  const double lo = minOf(phi, g, hi);
  EXPECT_GE(lo, -1e-14);
  EXPECT_LE(hi, phiMax * (1.0 + 1e-14));
  const double before = solidsContent(space{}, cc, phi0), after = solidsContent(space{}, cc, phi);
  EXPECT_NEAR(after, before, 1e-13 * before);

  // w.low: the step's summed fluxes, whose net outflow is phi's whole change; w.anti: zero
  const auto p0 = hikiln::cfd::test::toHost(phi0), p1 = hikiln::cfd::test::toHost(phi);
  const auto cap = hikiln::cfd::test::toHost(cc.capacity);
  const auto l0 = hikiln::cfd::test::toHost(work.low[0]),
             l1 = hikiln::cfd::test::toHost(work.low[1]);
  const auto a0 = hikiln::cfd::test::toHost(work.anti[0]),
             a1 = hikiln::cfd::test::toHost(work.anti[1]);
  double worst = 0.0, anti = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int I = i + g.ghost, J = j + g.ghost;
      const double net = l0(I + 1, J, 0) - l0(I, J, 0) + l1(I, J + 1, 0) - l1(I, J, 0);
      worst = std::max(worst, std::fabs(cap(I, J, 0) * (p0(I, J, 0) - p1(I, J, 0)) - net));
      anti = std::max({anti, std::fabs(a0(I, J, 0)), std::fabs(a1(I, J, 0))});
    }
  }
  EXPECT_LT(worst, 1e-14);
  EXPECT_EQ(anti, 0.0);
}

} // namespace
