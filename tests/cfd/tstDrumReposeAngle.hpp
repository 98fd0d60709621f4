// A turning drum's bed stands near its friction angle.
//
// Set-up: the cross-section of the Kramers validation kilns (cases/kiln/kramers-*.yaml): a 0.4 m
// drum at 10 rpm, a bed of about 22 % of it, a rate-independent Drucker-Prager bed with m = 0.6
// (tan 31 deg) on a rough shell (mu_wall 0.7, so the bed turns with the shell and cascades),
// 32 x 32 cells, the incremental projection, 8 s. A bed whose yield surface is q = m p cannot
// hold a surface much steeper than atan(m) once it flows: the surface angle (the least-squares
// line through the half-phi_max heights of the columns within R / 2 of the axis, as
// tests/validation/drum_surface_angle.py measures it) must lie within -3 / +5 deg of 31 deg.
//
// This is what the harmonic edge viscosity (ViscousOperator.hpp, EdgeViscosity) is for, and the
// test runs with it: with the arithmetic mean of the four cells (still the default), an edge
// between the flowing layer and the plug below it (the 1e5 Pa s cap) takes half the plug's
// viscosity and holds the layer, and this bed stood at 44.9 deg; with the harmonic mean at 33.6.
#include "CfdTestUtils.hpp"
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

// The bed surface angle [deg]: per column within R / 2 of the axis, the height where phi falls
// through half its largest value (the highest such crossing, linear between the two cells),
// then the slope of the least-squares line through those heights.
template <class Solver> double surfaceAngleDeg(Solver const& solver, double radius) {
  const Grid& g = solver.grid();
  const auto phi = test::toHost(solver.volumeFraction());
  const int gh = g.ghost, gz = g.ghostZ();
  double top = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      top = std::max(top, phi(i + gh, j + gh, gz));
  const double half = 0.5 * top;
  std::vector<double> xs, ys;
  for (int i = 0; i < g.nx; ++i) {
    const double x = g.coordinate(Staggering::Cell, 0, i);
    if (std::fabs(x) > 0.5 * radius)
      continue;
    for (int j = g.ny - 2; j >= 0; --j) {
      const double below = phi(i + gh, j + gh, gz), above = phi(i + gh, j + 1 + gh, gz);
      if (below > half) {
        xs.push_back(x);
        ys.push_back(g.coordinate(Staggering::Cell, 1, j) +
                     (below - half) / (below - above) * g.hy);
        break;
      }
    }
  }
  const double n = static_cast<double>(xs.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t c = 0; c < xs.size(); ++c) {
    sx += xs[c];
    sy += ys[c];
    sxx += xs[c] * xs[c];
    sxy += xs[c] * ys[c];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return std::atan(std::fabs(slope)) * 180.0 / hikiln::constants::pi;
}

TEST(TEST_CATEGORY, turning_bed_stands_near_its_friction_angle) {
  const double radius = 0.2;
  TwoPhaseParameters p;
  p.solidDensity = 2700.0;
  p.rheology.phiMax = 0.57;
  p.rheology.m0 = 0.6;
  p.rheology.m1 = 0.0;
  p.rheology.muWall = 0.7;
  p.dtMax = 0.01;
  p.incrementalProjection = true;
  p.harmonicEdgeViscosity = true;
  DrumShell shell;
  shell.radius = radius;
  shell.omega = 10.0 * 2.0 * hikiln::constants::pi / 60.0;
  TwoPhaseSolver<space> solver(space{}, drumGrid(32, 2.0 * radius), shell, p);
  solver.setFlatBed(-0.45 * radius);

  double lo = 1e300, hi = -1e300, mean = 0.0;
  const int samples = 5;
  for (int n = 0; n < samples; ++n) {
    const double sampleTime = 6.0 + 0.5 * n;
    while (solver.time() < sampleTime - 1e-12) {
      std::string reason;
      solver.step(std::min(solver.stableTimeStep(reason), sampleTime - solver.time()));
    }
    const double angle = surfaceAngleDeg(solver, radius);
    lo = std::min(lo, angle);
    hi = std::max(hi, angle);
    mean += angle / samples;
  }
  const double friction = std::atan(p.rheology.m0) * 180.0 / hikiln::constants::pi;
  std::cout << "surface angle " << mean << " deg (" << lo << "-" << hi
            << " over 6-8 s); friction angle " << friction << " deg\n";
  EXPECT_GT(mean, friction - 3.0);
  EXPECT_LT(mean, friction + 5.0);
}

} // namespace
