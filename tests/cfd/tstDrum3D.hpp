// A short 3D drum, periodic along its axis, against the 2D solver on the same cross-section
// (issue 7's first check that the kiln can reuse the 2D solver unchanged): the same bed in the
// same turning drum, stepped with each solver's own stable time step, gives in every layer of
// the 3D grid the 2D solution (phi, bed pressure, in-plane velocity) to the linear solvers'
// tolerance, no axial velocity, and conserves the solids to round-off. The pressure is compared
// as the bed pressure (gauge-free: the two solvers fix the constant of the total pressure
// differently). The periodic drum uses the incremental projection, the closed one the plain.
#include "CfdTestUtils.hpp"
#include "TwoPhaseTestUtils.hpp"
#include "kernels/cfd/KilnGeometry.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using solver_type = TwoPhaseSolver<space>;

constexpr int cellsAcross = 24;
constexpr int layers = 4;
constexpr double diameter = 1.0;

// Apertures sampled alike in 2D and 3D (3D samples at most 32 points per face edge).
CutCellOptions sameSampling() {
  CutCellOptions o;
  o.faceSamples = 32;
  return o;
}

// Largest |a(i, j, k) - b(i, j, 0)| over the stored interior positions of staggering s in the
// x-y plane, every layer k of the 3D field a against the 2D field b.
template <class View3, class View2>
double layerDifference(View3 const& a, Grid const& g3, View2 const& b, Grid const& g2,
                       Staggering s) {
  const auto ha = test::toHost(a);
  const auto hb = test::toHost(b);
  double worst = 0.0;
  for (int k = 0; k < g3.nz; ++k) {
    for (int j = 0; j < g3.ny + isNodeCentred(s, 1); ++j) {
      for (int i = 0; i < g3.nx + isNodeCentred(s, 0); ++i) {
        const double d = ha(i + g3.ghost, j + g3.ghost, k + g3.ghostZ()) -
                         hb(i + g2.ghost, j + g2.ghost, g2.ghostZ());
        worst = std::max(worst, std::fabs(d));
      }
    }
  }
  return worst;
}

TEST(TEST_CATEGORY, drum_3d_periodic_matches_2d) {
  const Grid g2 = drumGrid(cellsAcross, diameter);
  const double h = g2.hx;
  const Grid g3 = makeGrid(g2.nx, g2.ny, layers, g2.nx * h, g2.ny * h, layers * h, g2.x0, g2.y0);
  ASSERT_TRUE(g3.is3D());
  DrumShell shell;
  shell.radius = 0.5 * diameter;
  shell.omega = 6.0 * 2.0 * hikiln::constants::pi / 60.0;
  TwoPhaseParameters params = test::drumParameters();
  // the incremental projection (its carried acceleration on the periodic axis's last node is
  // a copy of the first: a differing copy made the pressure solve stall); the two agree to the
  // momentum solve's tolerance, amplified by the flow (see below)
  params.incrementalProjection = true;
  params.viscousTolerance = 1e-11;
  solver_type flat(space{}, g2, shell, params, sameSampling());
  solver_type deep(space{}, g3, shell, params, sameSampling());
  flat.setFlatBed(-0.1);
  deep.setFlatBed(-0.1);
  const double initial = deep.solids();
  double worstSolids = 0.0, worstDt = 0.0;
  const int steps = 40;
  for (int n = 0; n < steps; ++n) {
    const TwoPhaseStepReport r2 = flat.advance();
    const TwoPhaseStepReport r3 = deep.advance();
    worstDt = std::max(worstDt, std::fabs(r3.dt - r2.dt) / r2.dt);
    worstSolids = std::max(worstSolids, std::fabs(r3.solidsAfter - r3.solidsBefore) / initial);
  }
  const double wallSpeed = shell.omega * shell.radius;
  const double phiDiff =
      layerDifference(deep.volumeFraction(), g3, flat.volumeFraction(), g2, Staggering::Cell);
  const double pDiff =
      layerDifference(deep.bedPressureField(), g3, flat.bedPressureField(), g2, Staggering::Cell);
  const double pScale = test::maxAbsInterior(flat.bedPressureField(), g2, Staggering::Cell);
  double uDiff = 0.0;
  for (int c = 0; c < 2; ++c) {
    uDiff = std::max(uDiff, layerDifference(deep.velocity().comp[c], g3, flat.velocity().comp[c],
                                            g2, faceStaggering(c)));
  }
  const double axial = test::maxAbsInterior(deep.velocity().comp[2], g3, faceStaggering(2));
  std::cout << "3D (" << layers << " layers) vs 2D after " << steps << " steps, t = " << deep.time()
            << " s: |d phi| " << phiDiff << ", |d p| / max p " << pDiff / pScale
            << ", |d u| / shell speed " << uDiff / wallSpeed << ", |w| / shell speed "
            << axial / wallSpeed << ", relative dt difference " << worstDt
            << ", worst relative solids change per step " << worstSolids << "\n";
  // The linear solves stop at relative residuals 1e-11 (pressure and, here, momentum) on
  // operators of different size, so the two agree to about those tolerances, not bitwise.
  // Measured (Serial): phi 7e-12, p_bed 2.5e-12 relative, u 1.4e-9 and w 4.8e-10 of the shell
  // speed. At the default momentum tolerance 1e-9 the differences grow with the steps (u 9e-9
  // after 10, 2.3e-7 after 40, 1.8e-6 after 80; about 1e-8 throughout with the plain
  // projection): they scale with that tolerance, 1e-7 gave 100 times more. With the 2D deviator
  // (tr(D) / 2) in the 2D strain rate the cut cells differed and phi by 3e-3, u by 8e-3 of the
  // shell speed.
  EXPECT_LT(phiDiff, 1e-10);
  EXPECT_LT(pDiff, 1e-10 * pScale);
  EXPECT_LT(uDiff, 1e-7 * wallSpeed);
  EXPECT_LT(axial, 1e-8 * wallSpeed);
  EXPECT_LT(worstDt, 1e-8);
  EXPECT_LT(worstSolids, 1e-10);
  // the bed moves (a frozen field would pass the comparisons above trivially)
  EXPECT_GT(test::maxAbsInterior(flat.velocity().comp[0], g2, faceStaggering(0)), 0.2 * wallSpeed);
}

} // namespace

namespace {

using kiln_solver_type = TwoPhaseSolver<space, KilnShell>;

// A short kiln closed at both ends (the end faces are stationary walls): the solids stay
// conserved and bounded, and the flow is mirror-symmetric about the mid-length plane (phi and
// the in-plane velocity equal, the axial velocity opposite, in layers k and nz - 1 - k).
// Measured: solids 2e-15 per step, asymmetry 1e-10 (phi) and 2e-9 of the shell speed. The end
// walls hold the bed back, and the gas near the bed surface at the shell reaches an axial
// speed of 1.7x the shell speed (reported, not asserted).
TEST(TEST_CATEGORY, drum_3d_closed_ends_symmetric) {
  const int n = 16, nz = 6;
  const double h = 1.2 / n;
  const Grid g = makeGrid(n, n, nz, n * h, n * h, nz * h, -0.6, -0.6, 0.0);
  KilnShell kiln;
  kiln.radius = 0.5;
  kiln.omega = 6.0 * 2.0 * hikiln::constants::pi / 60.0;
  kiln.zInlet = 0.0;
  kiln.zOutlet = nz * h;
  CutCellOptions options = sameSampling();
  options.periodic[2] = false;
  kiln_solver_type solver(space{}, g, kiln, test::drumParameters(), options);
  solver.setFlatBed(-0.1);
  const double initial = solver.solids();
  double worstSolids = 0.0, lo = 0.0, hi = 0.0, minPhi = 1.0, maxPhi = 0.0;
  for (int step = 0; step < 20; ++step) {
    const TwoPhaseStepReport r = solver.advance();
    worstSolids = std::max(worstSolids, std::fabs(r.solidsAfter - r.solidsBefore) / initial);
    solver.phiRange(lo, hi);
    minPhi = std::min(minPhi, lo);
    maxPhi = std::max(maxPhi, hi);
  }
  const auto phi = test::toHost(solver.volumeFraction());
  const auto u = test::toHost(solver.velocity().comp[0]);
  const auto w = test::toHost(solver.velocity().comp[2]);
  const int o = g.ghost;
  double phiAsym = 0.0, uAsym = 0.0, wAsym = 0.0, wMax = 0.0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        phiAsym = std::max(phiAsym,
                           std::fabs(phi(i + o, j + o, k + o) - phi(i + o, j + o, nz - 1 - k + o)));
        uAsym =
            std::max(uAsym, std::fabs(u(i + o, j + o, k + o) - u(i + o, j + o, nz - 1 - k + o)));
      }
    }
  }
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        wAsym = std::max(wAsym, std::fabs(w(i + o, j + o, k + o) + w(i + o, j + o, nz - k + o)));
        wMax = std::max(wMax, std::fabs(w(i + o, j + o, k + o)));
      }
    }
  }
  const double wallSpeed = kiln.omega * kiln.radius;
  std::cout << "closed 3D drum after 20 steps: worst relative solids change per step "
            << worstSolids << ", phi in [" << minPhi << ", " << maxPhi << "], mirror asymmetry phi "
            << phiAsym << ", u " << uAsym / wallSpeed << " and w " << wAsym / wallSpeed
            << " of the shell speed; max |w| " << wMax / wallSpeed << " of the shell speed\n";
  EXPECT_LT(worstSolids, 1e-10);
  EXPECT_GE(minPhi, -1e-10);
  EXPECT_LE(maxPhi, 0.6 + 1e-10);
  EXPECT_LT(phiAsym, 1e-8);
  EXPECT_LT(uAsym, 1e-6 * wallSpeed);
  EXPECT_LT(wAsym, 1e-6 * wallSpeed);
}

} // namespace
