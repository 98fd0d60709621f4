// The two-phase projection step in a rotating drum (solvers/cfd/TwoPhaseSolver.hpp):
// - a bed of 30 % fill in a turning drum with the Drucker-Prager rheology: the solids content is
//   conserved to 1e-10 relative per step and phi stays in [0, phiMax];
// - a full drum with a very viscous (Newtonian) bed spins up to a rigid rotation;
// - the Coulomb wall friction controls the wall slip: a frictionless shell lets the bed slip,
//   mu_wall = 1 drags it along;
// - the shell holds the gas on its cut faces (shell_gas no_slip), and without that it does not;
// - the momentum solve's iterations hardly grow from 64 to 128 cells with the bed sliding on the
//   shell (the multigrid's coarse faces are not held by the shell's penalty);
// - warm starts of the solves save iterations and leave the flow as the cold starts' to the
//   solvers' tolerances;
// - a flat bed at rest in a still drum stays at rest (spurious velocities) and carries the
//   hydrostatic granular pressure, whether the pressure starts hydrostatic or at 0 (gravity and
//   the pressure gradient meet on the same faces: the balance is exact to the solver tolerance).
#include "CfdTestUtils.hpp"
#include "TwoPhaseTestUtils.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using solver_type = TwoPhaseSolver<space>;

constexpr double diameter = 1.0;

DrumShell drum(double rpm) {
  DrumShell s;
  s.radius = 0.5 * diameter;
  s.omega = rpm * 2.0 * hikiln::constants::pi / 60.0;
  return s;
}

// Largest |u - omega x r| over open faces (aperture > 0) and over fully open faces (interior),
// and the largest |u| there.
void velocityError(solver_type const& solver, double& error, double& speed,
                   double* interiorError = nullptr) {
  const Grid g = solver.grid();
  error = speed = 0.0;
  double interior = 0.0;
  for (int c = 0; c < 2; ++c) {
    const auto u = test::toHost(solver.velocity().comp[c]);
    const auto ap = test::toHost(solver.cutCells().aperture[c]);
    for (int j = 0; j < g.ny + (c == 1); ++j) {
      for (int i = 0; i < g.nx + (c == 0); ++i) {
        if (ap(i + g.ghost, j + g.ghost, 0) <= 0.0) {
          continue;
        }
        const double x = g.coordinate(faceStaggering(c), 0, i);
        const double y = g.coordinate(faceStaggering(c), 1, j);
        const double value = u(i + g.ghost, j + g.ghost, 0);
        const double e = std::fabs(value - solver.shape().wallVelocity(c, x, y, 0.0));
        error = std::max(error, e);
        interior = ap(i + g.ghost, j + g.ghost, 0) >= 1.0 ? std::max(interior, e) : interior;
        speed = std::max(speed, std::fabs(value));
      }
    }
  }
  if (interiorError) {
    *interiorError = interior;
  }
}

TEST(TEST_CATEGORY, two_phase_drum_conserves_solids) {
  const Grid g = drumGrid(32, diameter);
  solver_type solver(space{}, g, drum(6.0), test::drumParameters());
  solver.setFlatBed(-0.1); // about 37 % of the drum area
  const double initial = solver.solids();
  double worst = 0.0, lo = 0.0, hi = 0.0, minPhi = 1.0, maxPhi = 0.0, divergence = 0.0;
  for (int n = 0; n < 30; ++n) {
    const TwoPhaseStepReport r = solver.advance();
    worst = std::max(worst, std::fabs(r.solidsAfter - r.solidsBefore) / initial);
    divergence = std::max(divergence, r.maxDivergence);
    solver.phiRange(lo, hi);
    minPhi = std::min(minPhi, lo);
    maxPhi = std::max(maxPhi, hi);
    if (n % 10 == 0) {
      std::cout << "step " << n << " t " << solver.time() << " dt " << r.dt << " (" << r.limitedBy
                << "), viscous " << r.viscous.iterations << " pressure " << r.pressure.iterations
                << " div " << r.maxDivergence << "\n";
    }
  }
  double error, speed;
  velocityError(solver, error, speed);
  std::cout << "worst relative solids change per step " << worst << ", phi in [" << minPhi << ", "
            << maxPhi << "], max |u| " << speed << ", max div " << divergence << "\n";
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(std::fabs(solver.solids() - initial) / initial, 1e-10 * 30);
  EXPECT_GE(minPhi, -1e-10);
  EXPECT_LE(maxPhi, 0.6 + 1e-10);
  // the bed is moving with the drum (not a frozen field): some face moves at >= 20 % of the
  // shell speed
  EXPECT_GT(speed, 0.2 * solver.shape().omega * solver.shape().radius);
}

TEST(TEST_CATEGORY, two_phase_full_drum_rotates_rigidly) {
  const Grid g = drumGrid(32, diameter);
  TwoPhaseParameters p = test::drumParameters();
  p.constantBedViscosity = 1e4;
  p.dtMax = 0.01;
  solver_type solver(space{}, g, drum(3.0), p);
  solver.setFull();
  for (int n = 0; n < 20; ++n) {
    solver.advance();
  }
  double error, speed, interior;
  velocityError(solver, error, speed, &interior);
  const double wallSpeed = solver.shape().omega * solver.shape().radius;
  std::cout << "rigid rotation: max error " << error / wallSpeed << " (cut faces), "
            << interior / wallSpeed << " (fully open faces) of the shell speed\n";
  // measured 0.033 (on a face 8 % open) and 0.013 at 32 cells per diameter
  EXPECT_LT(error, 0.05 * wallSpeed);
  EXPECT_LT(interior, 0.02 * wallSpeed);
}

double slipAfter(double muWall, int steps) {
  const Grid g = drumGrid(32, diameter);
  TwoPhaseParameters p = test::drumParameters();
  p.rheology.muWall = muWall;
  solver_type solver(space{}, g, drum(6.0), p);
  solver.setFlatBed(-0.1);
  for (int n = 0; n < steps; ++n) {
    solver.advance();
  }
  return solver.wallSlip();
}

TEST(TEST_CATEGORY, two_phase_wall_friction_controls_slip) {
  const double frictionless = slipAfter(0.0, 20);
  const double rough = slipAfter(1.0, 20);
  std::cout << "wall slip after 20 steps: " << 100 * frictionless << " % (mu_wall = 0), "
            << 100 * rough << " % (mu_wall = 1)\n";
  // measured 99.85 % and 11.7 % after 0.27 s. A frictionless shell must not drag the bed at all:
  // 76 % before the viscous stencil, the advection and the slip measure stopped reading the
  // closed (shell-held) faces (88 % with the advection still reading them)
  EXPECT_GT(frictionless, 0.99);
  EXPECT_LT(rough, 0.25);
}

// The mean |u - u_wall| over the cut faces with gas (phi < 1e-3) on both sides, over the shell
// speed, after `steps` in the turning drum of slipAfter.
double gasSlipAtShell(bool shellHoldsGas, int steps) {
  const Grid g = drumGrid(32, diameter);
  TwoPhaseParameters p = test::drumParameters();
  p.shellHoldsGas = shellHoldsGas;
  solver_type solver(space{}, g, drum(6.0), p);
  solver.setFlatBed(-0.1);
  for (int n = 0; n < steps; ++n) {
    solver.advance();
  }
  const auto phi = test::toHost(solver.volumeFraction());
  double sum = 0.0;
  int faces = 0;
  for (int c = 0; c < 2; ++c) {
    const auto u = test::toHost(solver.velocity().comp[c]);
    const auto ap = test::toHost(solver.cutCells().aperture[c]);
    const auto cx = test::toHost(solver.cutCells().centroid[c][0]);
    const auto cy = test::toHost(solver.cutCells().centroid[c][1]);
    for (int j = 1; j < g.ny + (c == 1) - 1; ++j) {
      for (int i = 1; i < g.nx + (c == 0) - 1; ++i) {
        const int I = i + g.ghost, J = j + g.ghost;
        const double open = ap(I, J, 0);
        const double phiBelow = c == 0 ? phi(I - 1, J, 0) : phi(I, J - 1, 0);
        if (!(open > 0.0 && open < 1.0) || std::max(phi(I, J, 0), phiBelow) >= 1e-3) {
          continue;
        }
        const double wall = solver.shape().wallVelocity(c, cx(I, J, 0), cy(I, J, 0), 0.0);
        sum += std::fabs(u(I, J, 0) - wall);
        ++faces;
      }
    }
  }
  return sum / (faces * solver.shape().omega * solver.shape().radius);
}

TEST(TEST_CATEGORY, two_phase_shell_holds_gas) {
  const double held = gasSlipAtShell(true, 20);
  const double free = gasSlipAtShell(false, 20);
  std::cout << "gas at the shell's cut faces after 20 steps: mean |u - u_wall| " << held
            << " (shell_gas no_slip), " << free << " (slip) of the shell speed\n";
  // measured 0.017 and 0.42 (32 x 32, 6 rpm, 20 steps): the shell holds the gas with the
  // penalty forcing (the projection moves the faces next to the bed a little); without it only
  // the gas's viscosity turns the gas there. That the bed's faces keep the Coulomb cap is
  // two_phase_wall_friction_controls_slip's frictionless shell.
  EXPECT_LT(held, 0.05);
  EXPECT_GT(free, 0.3);
}

// The turning drum of slipAfter on a grid of `cells` across with parameters p over `steps`
// steps: the mean iterations of the momentum and pressure solves (multigrid-preconditioned CG)
// from step 6 on, and the velocity at the end.
struct SolveIterations {
  double momentum = 0.0, pressure = 0.0;
};
struct TurningDrum {
  SolveIterations mean;
  std::vector<double> u;
};
TurningDrum turningDrum(int cells, TwoPhaseParameters const& p, int steps) {
  const Grid g = drumGrid(cells, diameter);
  solver_type solver(space{}, g, drum(6.0), p);
  solver.setFlatBed(-0.1);
  TurningDrum run;
  for (int n = 0; n < steps; ++n) {
    const TwoPhaseStepReport report = solver.advance();
    if (n >= 5) {
      run.mean.momentum += report.viscous.iterations / double(steps - 5);
      run.mean.pressure += report.pressure.iterations / double(steps - 5);
    }
  }
  for (int c = 0; c < 2; ++c) {
    const auto u = test::toHost(solver.velocity().comp[c]);
    run.u.insert(run.u.end(), u.data(), u.data() + u.size());
  }
  return run;
}
SolveIterations solveIterations(int cells) {
  return turningDrum(cells, test::drumParameters(), 15).mean;
}

TEST(TEST_CATEGORY, two_phase_solve_iterations_independent_of_grid) {
  const SolveIterations medium = solveIterations(64);
  const SolveIterations fine = solveIterations(128);
  std::cout << "mean iterations per step, 64 / 128 cells: momentum " << medium.momentum << " / "
            << fine.momentum << ", pressure " << medium.pressure << " / " << fine.pressure << "\n";
  // momentum measured 20.1 and 21.0 (15.3 at 32 cells; 19.2 and 20.1 with the warm starts). With
  // the shell's penalty averaged into the coarse faces (the code before 829196c) 36.4 and 45.4, and
  // 57 at 256 cells in the shipped 2 m drum: the coarse levels held the sliding bed (averageDown in
  // Transfer.hpp)
  EXPECT_LT(fine.momentum - medium.momentum, 3.0);
  EXPECT_LT(fine.momentum, 30.0);
  // pressure measured 10.0 and 10.5 (9.6 and 10.5 warm). With the outside cells' alpha averaged
  // into the coarse cells that straddle the shell (the code before this test's pressure part) 16.8
  // and 23.9: a sink the fine problem does not have (TwoPhaseSolver::project)
  EXPECT_LT(fine.pressure - medium.pressure, 2.0);
  EXPECT_LT(fine.pressure, 15.0);
}

// The turning drum at 64 cells with or without warm starts.
TurningDrum warmOrCold(bool warmStart, int steps) {
  TwoPhaseParameters p = test::drumParameters();
  p.warmStart = warmStart;
  return turningDrum(64, p, steps);
}

TEST(TEST_CATEGORY, two_phase_warm_start_saves_iterations_not_accuracy) {
  // The warm starts (TwoPhaseParameters::warmStart) stop where the cold ones would: the
  // momentum solve at tolerance x the residual of u^n, the pressure solve at tolerance x that
  // of p = 0. So the flow is the same to the solvers' tolerances, in fewer iterations.
  const int steps = 40;
  const TurningDrum cold = warmOrCold(false, steps);
  const TurningDrum warm = warmOrCold(true, steps);
  double difference = 0.0, speed = 0.0;
  for (std::size_t q = 0; q < cold.u.size(); ++q) {
    difference = std::max(difference, std::fabs(warm.u[q] - cold.u[q]));
    speed = std::max(speed, std::fabs(cold.u[q]));
  }
  std::cout << "mean iterations per step, cold / warm: momentum " << cold.mean.momentum << " / "
            << warm.mean.momentum << ", pressure " << cold.mean.pressure << " / "
            << warm.mean.pressure << "; largest velocity difference after " << steps << " steps "
            << difference << " m/s (largest speed " << speed << " m/s)\n";
  // measured 8.2e-9 m/s of 0.54 m/s (the solves' tolerances 1e-9 and 1e-11)
  EXPECT_GT(speed, 0.1);
  EXPECT_LT(difference, 1e-6 * speed);
  // measured momentum 19.1 / 16.5, pressure 10.0 / 9.4 in this spin-up (the shipped 2 m drum at
  // 128 cells over 30 s: 13.2 / 5.4 and 10.8 / 8.5 at its momentum tolerance 1e-6)
  EXPECT_LT(warm.mean.momentum, cold.mean.momentum - 1.5);
  EXPECT_LT(warm.mean.pressure, cold.mean.pressure - 0.3);
}

// p_bed = phiMax (rhoS - rhoG) g (level - y) in the bed; spurious velocities after `steps`.
void stillBed(bool hydrostaticStart, double& spurious, double& pressureError) {
  const Grid g = drumGrid(32, diameter);
  TwoPhaseParameters p = test::drumParameters();
  solver_type solver(space{}, g, drum(0.0), p);
  const double level = -0.1 + 0.3 * g.hy;
  solver.setFlatBed(level);
  if (!hydrostaticStart) {
    Kokkos::deep_copy(solver.pressure(), 0.0);
  }
  for (int n = 0; n < 10; ++n) {
    solver.advance();
  }
  double error;
  velocityError(solver, error, spurious);
  const auto pBed = test::toHost(solver.bedPressureField());
  const auto vol = test::toHost(solver.cutCells().volume);
  const double weight = p.rheology.phiMax * (p.solidDensity - p.gasDensity) * 9.81;
  pressureError = 0.0;
  for (int j = 0; j < g.ny; ++j) {
    const double y = g.coordinate(Staggering::Cell, 1, j);
    if (y > level - g.hy) {
      continue; // the surface cell and above
    }
    for (int i = 0; i < g.nx; ++i) {
      if (vol(i + g.ghost, j + g.ghost, 0) > 0.0) {
        pressureError = std::max(
            pressureError, std::fabs(pBed(i + g.ghost, j + g.ghost, 0) - weight * (level - y)));
      }
    }
  }
  pressureError /= weight * (level + 0.5 * diameter);
}

TEST(TEST_CATEGORY, two_phase_bed_at_rest_is_hydrostatic) {
  for (bool hydrostaticStart : {true, false}) {
    double spurious, pressureError;
    stillBed(hydrostaticStart, spurious, pressureError);
    std::cout << (hydrostaticStart ? "hydrostatic" : "zero") << " start: spurious |u| " << spurious
              << " m/s, bed pressure error " << pressureError << " of the bottom pressure\n";
    EXPECT_LT(spurious, 1e-9);
    EXPECT_LT(pressureError, 1e-8);
  }
}

} // namespace
