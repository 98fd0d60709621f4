#pragma once
// The short test kiln of the open-end tests (tstKilnOpenEnds.hpp, tstKilnHeat.hpp): 1 m across,
// 1 m long, 3 rpm, a feed patch over the lowest 10 % of the inlet face (resolvable on 14 x 14
// cells), air over the top 35 %, an open discharge.
#include "TwoPhaseTestUtils.hpp"
#include "kernels/cfd/KilnGeometry.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

namespace hikiln::cfd::test::small_kiln {

constexpr double pi = hikiln::constants::pi;
constexpr double radius = 0.5;
constexpr double length = 1.0;
constexpr double feedFraction = 0.1;
constexpr double feedSpeed = 0.05; // m/s
constexpr double airSpeed = 0.5;   // m/s

inline KilnDomain kiln() {
  KilnDomain d;
  d.shell.radius = radius;
  d.shell.omega = 3.0 * 2.0 * pi / 60.0;
  d.shell.zInlet = 0.0;
  d.shell.zOutlet = length;
  const double phiMax = drumParameters().rheology.phiMax;
  d.inlet = makeKilnInlet(d.shell, feedFraction, 0.35, feedSpeed, airSpeed, phiMax, "test");
  return d;
}

// `across` x `across` cells across the kiln (14: the feed patch resolved), nz along it.
inline Grid kilnGrid(int nz = 8, int across = 14) {
  const double width = 2.2 * radius;
  return makeGrid(across, across, nz, width, width, length, -0.5 * width, -0.5 * width, 0.0);
}

inline CutCellOptions closedZ() {
  CutCellOptions o;
  o.periodic[2] = false;
  return o;
}

inline OpenSides feedAndDischarge() {
  OpenSides s;
  s.kind[ZLow] = BoundaryKind::Inflow;
  s.kind[ZHigh] = BoundaryKind::Outflow;
  return s;
}

} // namespace hikiln::cfd::test::small_kiln
