// Open kiln ends in the continuum solver (issue 7, OpenSides in solvers/cfd/TwoPhaseSolver.hpp):
// a short 3D kiln with the solids feed and air inlet on its inlet face and an open discharge.
// - Solids: the content changes by exactly what comes in minus what goes out (to 1e-8 of the
//   throughput, physics.md 7's mass balance), the inflow is phi_feed x feed speed x the feed
//   patch's area (4.6 % of the face in the kiln; here a larger patch to resolve it), phi stays
//   in [0, phi_max], and the bed at the discharge end pours out.
// - Volume: the mixture is incompressible, so the volume flowing out of the discharge face
//   equals what the feed and air patches bring in.
// - A gas at rest stays at rest in a kiln open at its discharge, also with gravity tilted along
//   the axis (an inclined kiln): the discharge face holds the gas's own hydrostatic pressure.
// - A dam ring put in during the run (the cut cells measured again) keeps the balance, counting
//   the solids where the ring now stands as taken by it, and phi bounded.
// - This backend (any thread count) agrees with Kokkos::Serial to the solvers' tolerance.
// - The pressure solve's iterations do not grow with the grid (16, 32 and 48 cells across, the
//   cells' shape kept): the solid cells outside the shell must not act as a sink in the coarse
//   levels of the multigrid (TwoPhaseSolver::project).
// - Bad set-ups are refused with the reason.
#include "CfdTestUtils.hpp"
#include "KilnTestUtils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace {

using namespace hikiln::cfd;
using namespace hikiln::cfd::test::small_kiln;
using space = TEST_EXECSPACE;
using solver_type = TwoPhaseSolver<space, KilnDomain>;

TEST(TEST_CATEGORY, kiln_open_ends_balance_solids_and_volume) {
  const Grid grid = kilnGrid();
  const KilnDomain domain = kiln();
  const TwoPhaseParameters params = test::drumParameters();
  solver_type solver(space{}, grid, domain, params, closedZ(), feedAndDischarge());
  solver.setFlatBed(-0.5 * radius); // a bed reaching from the inlet to the discharge face
  solver.setInflow(domain.inlet);

  const double start = solver.solids();
  double time = 0.0, worstStep = 0.0;
  const double cellVolume = grid.hx * grid.hy * grid.hz;
  for (int n = 0; n < 20; ++n) {
    const TwoPhaseStepReport r = solver.advance();
    time += r.dt;
    worstStep =
        std::max(worstStep, std::fabs(r.solidsAfter - r.solidsBefore - (r.solidsIn - r.solidsOut)) /
                                (r.solidsIn + r.solidsOut));
  }
  const double in = solver.solidsInTotal(), out = solver.solidsOutTotal();
  const double change = solver.solids() - start;
  const double misfit = std::fabs(change - (in - out)) / (in + out);
  // the feed: phi_max x feed speed x the patch area (feedFraction of the face) x time
  const double feedVolume =
      params.rheology.phiMax * feedSpeed * feedFraction * pi * radius * radius * time;
  const double airFlux = airSpeed * 0.35 * pi * radius * radius;
  const double volumeIn = -solver.volumeOutflow(ZLow);
  const double volumeOut = solver.volumeOutflow(ZHigh);
  double lo, hi;
  solver.phiRange(lo, hi);
  std::cout << "kiln open ends, " << time << " s: solids in " << in * cellVolume << " m3 (feed "
            << feedVolume << "), out " << out * cellVolume << " m3, balance misfit " << misfit
            << " of the throughput (worst step " << worstStep << "); volume in " << volumeIn
            << " m3/s (patches " << feedSpeed * feedFraction * pi * radius * radius + airFlux
            << "), out " << volumeOut << "; phi in [" << lo << ", " << hi << "]\n";
  EXPECT_LT(misfit, 1e-8);
  EXPECT_LT(worstStep, 1e-8);
  EXPECT_NEAR(in * cellVolume / feedVolume, 1.0, 0.02);
  EXPECT_GT(out, 0.1 * in); // the bed at the discharge face pours out
  EXPECT_NEAR(volumeOut / volumeIn, 1.0, 1e-6);
  EXPECT_NEAR(volumeIn / (feedSpeed * feedFraction * pi * radius * radius + airFlux), 1.0, 0.02);
  EXPECT_GE(lo, -1e-12);
  EXPECT_LE(hi, params.rheology.phiMax + 1e-12);
}

TEST(TEST_CATEGORY, kiln_dam_ring_put_in_keeps_the_balance) {
  const Grid grid = kilnGrid();
  const KilnDomain domain = kiln();
  const TwoPhaseParameters params = test::drumParameters();
  solver_type solver(space{}, grid, domain, params, closedZ(), feedAndDischarge());
  solver.setFlatBed(-0.5 * radius);
  solver.setInflow(domain.inlet);
  const double start = solver.solids();
  for (int n = 0; n < 5; ++n) {
    solver.advance();
  }
  KilnDomain dammed = domain;
  dammed.shell.damHeight = 0.3 * radius;
  dammed.shell.damWidth = 2.0 * grid.hz;
  const double took = solver.changeShape(dammed);
  double worstDivergence = 0.0;
  for (int n = 0; n < 10; ++n) {
    worstDivergence = std::max(worstDivergence, solver.advance().maxDivergence);
  }
  const double in = solver.solidsInTotal(), out = solver.solidsOutTotal();
  const double misfit = std::fabs(solver.solids() - start - (in - out - took)) / (in + out);
  double lo, hi;
  solver.phiRange(lo, hi);
  std::cout << "dam ring put in after 5 steps: it took " << took << " cell volumes of solids; "
            << "balance misfit " << misfit << " of the throughput after 10 more steps, max "
            << "divergence " << worstDivergence << " 1/s, phi in [" << lo << ", " << hi << "]\n";
  EXPECT_GT(took, 0.0);
  EXPECT_LT(misfit, 1e-8);
  EXPECT_LT(worstDivergence, 1e-8);
  EXPECT_GE(lo, -1e-12);
  EXPECT_LE(hi, params.rheology.phiMax + 1e-12);
}

TEST(TEST_CATEGORY, kiln_open_discharge_keeps_gas_at_rest) {
  const Grid grid = kilnGrid();
  KilnDomain domain = kiln();
  domain.shell.omega = 0.0;
  TwoPhaseParameters params = test::drumParameters();
  // an inclined kiln: gravity with a component along the axis, towards the discharge
  const double slope = 3.0 * pi / 180.0;
  params.gravity[1] = -9.81 * std::cos(slope);
  params.gravity[2] = 9.81 * std::sin(slope);
  OpenSides discharge;
  discharge.kind[ZHigh] = BoundaryKind::Outflow;
  solver_type solver(space{}, grid, domain, params, closedZ(), discharge);
  double worst = 0.0;
  for (int n = 0; n < 5; ++n) {
    solver.step(0.01);
    for (int c = 0; c < 3; ++c) {
      worst =
          std::max(worst, test::maxAbsInterior(solver.velocity().comp[c], grid, faceStaggering(c)));
    }
  }
  std::cout << "gas in a kiln open at its discharge, gravity tilted 3 deg: |u| <= " << worst
            << " m/s after 5 steps\n";
  EXPECT_LT(worst, 1e-9);
}

// phi, u, v, w (host copies) after `steps` steps of the fed, discharging kiln on Space.
template <class Space> std::vector<std::vector<double>> kilnRunOn(int steps) {
  const Grid grid = kilnGrid();
  const KilnDomain domain = kiln();
  TwoPhaseSolver<Space, KilnDomain> solver(
      Space{}, grid, domain, hikiln::cfd::test::drumParameters(), closedZ(), feedAndDischarge());
  solver.setFlatBed(-0.5 * radius);
  solver.setInflow(domain.inlet);
  for (int n = 0; n < steps; ++n) {
    solver.step(0.02);
  }
  std::vector<std::vector<double>> out;
  const auto flatten = [&](auto const& field) {
    const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, field);
    out.emplace_back(h.data(), h.data() + h.size());
  };
  flatten(solver.volumeFraction());
  for (int c = 0; c < 3; ++c) {
    flatten(solver.velocity().comp[c]);
  }
  return out;
}

TEST(TEST_CATEGORY, kiln_open_ends_backend_agrees_with_serial) {
  const auto here = kilnRunOn<space>(6);
  const auto serial = kilnRunOn<Kokkos::Serial>(6);
  double worst[4] = {0.0, 0.0, 0.0, 0.0}, scale[4] = {0.0, 0.0, 0.0, 0.0};
  for (int f = 0; f < 4; ++f) {
    ASSERT_EQ(here[f].size(), serial[f].size());
    for (std::size_t n = 0; n < here[f].size(); ++n) {
      worst[f] = std::max(worst[f], std::fabs(here[f][n] - serial[f][n]));
      scale[f] = std::max(scale[f], std::fabs(serial[f][n]));
    }
  }
  std::cout << "kiln, 6 steps, this backend vs Serial: |d phi| " << worst[0] << ", |d u| "
            << worst[1] << ", |d v| " << worst[2] << ", |d w| " << worst[3] << " (max |w| "
            << scale[3] << " m/s)\n";
  EXPECT_LT(worst[0], 1e-9);
  for (int f = 1; f < 4; ++f) {
    EXPECT_LT(worst[f], 1e-7 * scale[3]) << "velocity component " << f - 1;
  }
}

TEST(TEST_CATEGORY, kiln_pressure_iterations_do_not_grow_with_the_grid) {
  const KilnDomain domain = kiln();
  const TwoPhaseParameters params = test::drumParameters();
  std::vector<double> iterations;
  for (const int across : {16, 32, 48}) {
    const Grid grid = kilnGrid(across / 2, across);
    solver_type solver(space{}, grid, domain, params, closedZ(), feedAndDischarge());
    solver.setFlatBed(-0.5 * radius);
    solver.setInflow(domain.inlet);
    double sum = 0.0;
    const int steps = 4;
    for (int n = 0; n < steps; ++n) {
      const TwoPhaseStepReport r = solver.advance();
      ASSERT_TRUE(r.pressure.converged) << across << " cells across, step " << n;
      sum += r.pressure.iterations;
    }
    iterations.push_back(sum / steps);
    std::cout << "kiln " << across << " x " << across << " x " << grid.nz
              << ": mean pressure iterations " << iterations.back() << "\n";
  }
  const auto [least, most] = std::minmax_element(iterations.begin(), iterations.end());
  EXPECT_LE(*most - *least, 2.0) << "pressure iterations grow with the grid";
}

TEST(TEST_CATEGORY, kiln_open_ends_refuse_bad_setups) {
  const Grid grid = kilnGrid();
  const KilnDomain domain = kiln();
  const TwoPhaseParameters params = test::drumParameters();
  const auto message = [&](auto&& make) {
    try {
      make();
    } catch (std::invalid_argument const& e) {
      return std::string(e.what());
    }
    return std::string("(nothing thrown)");
  };
  OpenSides feedOnly;
  feedOnly.kind[ZLow] = BoundaryKind::Inflow;
  EXPECT_NE(message([&] {
              solver_type(space{}, grid, domain, params, closedZ(), feedOnly);
            }).find("needs an outflow"),
            std::string::npos);
  OpenSides sideways;
  sideways.kind[XHigh] = BoundaryKind::Outflow;
  EXPECT_NE(message([&] {
              solver_type(space{}, grid, domain, params, closedZ(), sideways);
            }).find("only the z ends"),
            std::string::npos);
  solver_type solver(space{}, grid, domain, params, closedZ(), feedAndDischarge());
  KilnInlet tooDense = domain.inlet;
  tooDense.feedPhi = 0.9;
  EXPECT_NE(message([&] { solver.setInflow(tooDense); }).find("phi_max"), std::string::npos);
}

} // namespace
