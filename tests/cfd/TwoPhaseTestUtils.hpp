#pragma once
// The drum set-up shared by the two-phase solver tests: a 2500 kg/m3 bed (phi_max 0.6) with the
// Drucker-Prager rheology m = 0.5 + 0.02 gamma_dot, mu_wall 0.35, capped at 1e5 Pa s.
#include "solvers/cfd/TwoPhaseSolver.hpp"

namespace hikiln::cfd::test {

/// Everything is fluid; walls only at the domain boundary (a box or channel without a shell).
struct Everywhere {
  KOKKOS_INLINE_FUNCTION bool inside(double, double, double) const { return true; }
  KOKKOS_INLINE_FUNCTION double wallVelocity(int, double, double, double) const { return 0.0; }
};

inline TwoPhaseParameters drumParameters() {
  TwoPhaseParameters p;
  p.solidDensity = 2500.0;
  p.rheology.phiMax = 0.6;
  p.rheology.m0 = 0.5;
  p.rheology.m1 = 0.02;
  p.rheology.muWall = 0.35;
  p.rheology.viscosityMax = 1e5;
  p.dtMax = 0.02;
  return p;
}

} // namespace hikiln::cfd::test
