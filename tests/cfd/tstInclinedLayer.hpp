// A granular layer flowing down an incline, the two-phase solver against an analytic solution.
//
// Set-up: a layer of depth H at phi_max on a no-slip base, gravity tilted by theta, periodic
// along the slope, gas above. In a steady uniform flow the shear stress is rho g sin(theta)
// (H - y) and the pressure rho g cos(theta) (H - y), so q / p = tan(theta) at every depth. The
// Drucker-Prager law q = m(gamma_dot) p with m = m0 + m1 gamma_dot then fixes one strain rate
// for the whole layer: gamma_dot = (tan(theta) - m0) / m1, a linear velocity profile
// u = gamma_dot y. (The discrete equations hold it exactly in the bed's interior: the cell
// pressures are linear in y and so are the edge viscosities.)
//
// This checks the rheology, the bed pressure and the time stepping together, and it tells the
// two projections apart. The incremental form's steady state is the steady equation itself, so
// it matches the profile at any dt. The plain form's predictor lacks gravity and the pressure
// gradient: its stresses act on u - dt g sin(theta), which the no-slip base does not follow, so
// the base slips by about that much every step and the layer runs ahead (measured below).
//
// The gas is given 0.1 Pa s so that gravity along the slope cannot accelerate it to metres per
// second between the bed and the lid (its drag on the bed surface is about 1 % of the shear
// stress one cell below it). Compared: the velocity in all bed cells but the top two, whose
// strain rate averages over the surface edge (almost no shear there); the strain rate over the
// lower half, the lowest two cells excepted (towards the surface it falls smoothly to 0.97
// gamma_dot four cells below it). Seen in this set-up and not investigated: a little solids is
// thrown into the gas just above the sheared surface, and the gas there moves up and down by a
// few cm/s; with the plain projection and a gas of 0.01 Pa s this once made a pressure solve
// fail after 0.9 s (hence the plain run's 1 s).
#include "CfdTestUtils.hpp"
#include "TwoPhaseTestUtils.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;

// walls only at the domain boundary: the base and the lid
using OpenChannel = test::Everywhere;

constexpr double depth = 0.1;        // H [m]
constexpr double cellsInLayer = 16;  // cells across H
constexpr double tanTheta = 0.4;     // slope
constexpr double m0 = 0.3, m1 = 0.1; // m = m0 + m1 gamma_dot
constexpr double shearRate = (tanTheta - m0) / m1;

struct LayerResult {
  std::vector<double> u; ///< u at the cell centres of the bed's lower cells (all but the top two)
  double maxError = 0.0; ///< max |u - gamma_dot y| over them (and over x)
  double maxRateError = 0.0; ///< max |strain rate - gamma_dot| over the lower half, base cells out
  double baseSpeed = 0.0;    ///< u of the lowest row (exact gamma_dot h / 2)
};

LayerResult flowDownIncline(bool incremental, double dtMax, double duration) {
  const double h = depth / cellsInLayer;
  const int gasCells = 4;
  const Grid g = makeGrid(4, int(cellsInLayer) + gasCells, 1, 4 * h, depth + gasCells * h, h);
  TwoPhaseParameters p;
  const double gravity = 9.81;
  const double cosTheta = 1.0 / std::sqrt(1.0 + tanTheta * tanTheta);
  p.gravity[0] = gravity * tanTheta * cosTheta;
  p.gravity[1] = -gravity * cosTheta;
  p.solidDensity = 2500.0;
  p.rheology.phiMax = 0.6;
  p.rheology.m0 = m0;
  p.rheology.m1 = m1;
  p.rheology.gasViscosity = 0.1;
  p.rheology.muWall = 1.0; // the wall layer's friction cap must not bind at the base
  p.dtMax = dtMax;
  p.coulombWall = false; // a no-slip base (the Coulomb rule would treat the grid's walls as shell)
  p.incrementalProjection = incremental;
  CutCellOptions options;
  options.periodic[0] = true;
  TwoPhaseSolver<space, OpenChannel> solver(space{}, g, OpenChannel{}, p, options);
  solver.setFlatBed(depth);
  solver.hydrostaticPressure();
  while (solver.time() < duration - 1e-12) {
    std::string reason;
    solver.step(std::min(solver.stableTimeStep(reason), duration - solver.time()));
  }
  const auto u = test::toHost(solver.velocity().comp[0]);
  const auto rate = test::toHost(solver.strainRate());
  LayerResult r;
  const int lower = int(cellsInLayer) - 2;
  for (int j = 0; j < lower; ++j) {
    const double y = g.coordinate(Staggering::Cell, 1, j);
    for (int i = 0; i < g.nx; ++i) {
      const double uij = u(i + g.ghost, j + g.ghost, 0);
      r.maxError = std::max(r.maxError, std::fabs(uij - shearRate * y));
      if (j >= 2 && 2 * j < int(cellsInLayer)) {
        const double gamma = rate(i + g.ghost, j + g.ghost, 0);
        r.maxRateError = std::max(r.maxRateError, std::fabs(gamma - shearRate));
      }
    }
    r.u.push_back(u(g.ghost, j + g.ghost, 0));
  }
  r.baseSpeed = r.u.front();
  std::cout << (incremental ? "incremental" : "plain") << " projection, dt_max " << dtMax
            << ": max velocity error " << r.maxError / (shearRate * depth)
            << " of the surface speed, max strain-rate error " << r.maxRateError / shearRate
            << ", base speed " << r.baseSpeed << " m/s (exact " << 0.5 * h * shearRate << ")\n";
  return r;
}

TEST(TEST_CATEGORY, inclined_layer_has_the_drucker_prager_shear_rate) {
  const double surface = shearRate * depth;
  const double duration = 3.0;
  const LayerResult coarse = flowDownIncline(true, 0.02, duration);
  const LayerResult fine = flowDownIncline(true, 0.005, duration);
  for (LayerResult const* r : {&coarse, &fine}) {
    EXPECT_LT(r->maxError, 0.01 * surface);       // measured 0.0040 and 0.0039
    EXPECT_LT(r->maxRateError, 0.01 * shearRate); // measured 0.0048 and 0.0043
  }
  double dtChange = 0.0;
  for (std::size_t j = 0; j < coarse.u.size(); ++j) {
    dtChange = std::max(dtChange, std::fabs(coarse.u[j] - fine.u[j]));
  }
  std::cout << "incremental: the profile moved by " << dtChange / surface
            << " of the surface speed between dt_max 0.02 and 0.005\n";
  EXPECT_LT(dtChange, 0.005 * surface); // measured 0.0018
  // the plain projection's base slips by about dt g sin(theta) per step; it has settled after
  // 1 s (run longer, its pressure solve failed once in this set-up: see the file comment)
  const LayerResult plain = flowDownIncline(false, 0.02, 1.0);
  EXPECT_GT(plain.baseSpeed, 10.0 * coarse.baseSpeed); // measured 21-22x
  EXPECT_GT(plain.maxError, 0.2 * surface);            // measured 0.84
}

} // namespace
