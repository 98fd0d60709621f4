/// \file Coarsening.cpp
/// \brief Grid hierarchy of the geometric multigrid (see Coarsening.hpp).
#include "solvers/cfd/Coarsening.hpp"

#include <algorithm>

namespace hikiln::cfd {

namespace {

/// \brief True when a periodic active axis of grid has an odd cell count (no red-black colouring).
bool hasOddPeriodicAxis(Grid const& grid, bool const (&periodic)[3]) {
  for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
    if (periodic[a] && grid.cells(a) % 2 != 0) {
      return true;
    }
  }
  return false;
}

} // namespace

std::vector<LevelGeometry> coarsenGrids(Grid const& fine, bool const (&periodic)[3],
                                        CoarseningOptions const& options) {
  std::vector<LevelGeometry> levels;
  LevelGeometry level;
  level.grid = fine;
  levels.push_back(level);
  const int numAxes = fine.is3D() ? 3 : 2;
  for (;;) {
    Grid const& g = levels.back().grid;
    if (g.numCells() <= options.maxCoarseCells || hasOddPeriodicAxis(g, periodic)) {
      break;
    }
    double hmin = g.spacing(0);
    for (int a = 1; a < numAxes; ++a) {
      hmin = std::min(hmin, g.spacing(a));
    }
    LevelGeometry next;
    next.grid = g;
    bool any = false;
    for (int a = 0; a < numAxes; ++a) {
      const int n = g.cells(a);
      const bool even = n % 2 == 0;
      const bool bigEnough = n / 2 >= options.minCells;
      const bool shapely = 2.0 * g.spacing(a) <= options.maxAspect * hmin * (1.0 + 1e-12);
      if (even && bigEnough && shapely) {
        next.ratio[a] = 2;
        any = true;
      }
    }
    if (!any) {
      break;
    }
    next.grid.nx = g.nx / next.ratio[0];
    next.grid.ny = g.ny / next.ratio[1];
    next.grid.nz = g.nz / next.ratio[2];
    next.grid.hx = g.hx * next.ratio[0];
    next.grid.hy = g.hy * next.ratio[1];
    next.grid.hz = g.hz * next.ratio[2];
    next.grid.ghost = 1;
    levels.push_back(next);
  }
  return levels;
}

} // namespace hikiln::cfd
