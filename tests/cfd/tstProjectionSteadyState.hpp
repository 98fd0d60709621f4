// The incremental projection (kernels/cfd/CarriedAcceleration.hpp, TwoPhaseSolver.hpp step 4):
// a turning drum's steady flow does not depend on the time step. A 37 % bed with the
// Drucker-Prager rheology and the Coulomb wall in a 1 m drum at 6 rpm, 32 x 32 cells, run 5 s
// with dt_max 0.02 s and 0.01 s; the wall slip (sampled every 0.1 s over the last second) must
// agree. With the plain projection (the predictor's
// stresses act on a velocity that lacks the pressure gradient) they do not: the test asserts
// that too, so it would notice a carried acceleration that does nothing. The shell torque budget
// (ShellTorque.hpp) must close in all four runs. With the incremental form the pressure must
// exert no torque about the axis (CarriedAcceleration.hpp weights it by the apertures on the cut
// faces; before, it carried 12-18 % of the gravity torque here), so the shell can hold the bed
// only up to the Coulomb bound.
#include "CfdTestUtils.hpp"
#include "TwoPhaseTestUtils.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using solver_type = TwoPhaseSolver<space>;

struct SteadyFlow {
  double slip = 0.0;       ///< wall slip, mean of the samples
  double slipSpread = 0.0; ///< largest - smallest sample
  ShellTorque torque;      ///< after the last step
};

// Runs to `duration`, sampling the wall slip every 0.1 s over the last second.
SteadyFlow steadyFlow(bool incremental, double dtMax, double duration) {
  const Grid g = drumGrid(32, 1.0);
  TwoPhaseParameters p = test::drumParameters();
  p.dtMax = dtMax;
  p.incrementalProjection = incremental;
  DrumShell shell;
  shell.radius = 0.5;
  shell.omega = 6.0 * 2.0 * hikiln::constants::pi / 60.0;
  solver_type solver(space{}, g, shell, p);
  solver.setFlatBed(-0.1);
  SteadyFlow flow;
  double lo = 1e300, hi = -1e300;
  int samples = 0;
  for (int n = 1; n <= 10; ++n) {
    const double sampleTime = duration - 1.0 + 0.1 * n;
    while (solver.time() < sampleTime - 1e-12) {
      std::string reason;
      solver.step(std::min(solver.stableTimeStep(reason), sampleTime - solver.time()));
    }
    const double s = solver.wallSlip();
    flow.slip += s;
    lo = std::min(lo, s);
    hi = std::max(hi, s);
    ++samples;
  }
  flow.slip /= samples;
  flow.torque = solver.shellTorque();
  flow.slipSpread = hi - lo;
  std::cout << (incremental ? "incremental" : "plain") << " projection, dt_max " << dtMax
            << ": wall slip " << 100 * flow.slip << " % (spread " << 100 * flow.slipSpread
            << " points over the last second); torque N: gravity " << flow.torque.gravity
            << ", wall drag " << flow.torque.wallDrag << " (bound " << flow.torque.wallDragBound
            << "), pressure " << flow.torque.pressure << " (cut faces " << flow.torque.pressureCut
            << ")\n";
  return flow;
}

TEST(TEST_CATEGORY, steady_drum_flow_does_not_depend_on_the_time_step) {
  const double duration = 5.0;
  const SteadyFlow coarse = steadyFlow(true, 0.02, duration);
  const SteadyFlow fine = steadyFlow(true, 0.01, duration);
  const SteadyFlow plainCoarse = steadyFlow(false, 0.02, duration);
  const SteadyFlow plainFine = steadyFlow(false, 0.01, duration);
  EXPECT_LT(coarse.slipSpread, 0.03);
  EXPECT_LT(fine.slipSpread, 0.03);
  EXPECT_LT(std::fabs(coarse.slip - fine.slip), 0.01);
  EXPECT_GT(std::fabs(plainCoarse.slip - plainFine.slip), 0.03);
  // the torque budget about the axis closes near a steady state (measured within 0.6-1.5 % of
  // the gravity torque: the viscous stresses add none), and the shell's drag stays within its
  // Coulomb bound
  for (SteadyFlow const* f : {&coarse, &fine, &plainCoarse, &plainFine}) {
    const ShellTorque& t = f->torque;
    EXPECT_LT(std::fabs(t.gravity + t.wallDrag + t.pressure), 0.03 * std::fabs(t.gravity));
    EXPECT_LE(t.wallDrag, 1.001 * t.wallDragBound);
  }
  for (SteadyFlow const* f : {&coarse, &fine}) {
    const ShellTorque& t = f->torque;
    EXPECT_LT(std::fabs(t.pressure), 0.005 * std::fabs(t.gravity));
    EXPECT_LT(std::fabs(t.gravity), 1.03 * t.wallDragBound);
  }
}

} // namespace
