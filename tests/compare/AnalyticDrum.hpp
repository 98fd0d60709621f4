#pragma once
// A drum holding a bed under a straight surface y = level + slope x, with cell averages of
// analytic fields computed by integration: in y exactly (the integrands are linear in y), in x by
// the midpoint rule on strips that line up between a grid and one twice as fine, so that the fine
// grid's integrals sum to the coarse grid's to round-off.
#include "drivers/compare/Regrid.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace hikiln::compare::test {

struct AnalyticBed {
  double radius = 1.0;
  double level = -0.4; ///< surface height at x = 0
  double slope = 0.0;  ///< dy/dx of the surface
  int stripsPerMetre = 4800;

  double surface(double x) const { return level + slope * x; }

  /// \brief Per cell: the integral over the bed part of the cell of f(x, y) (linear in y),
  /// divided by the cell's area.
  std::vector<double> cellAverages(const CellGrid& g,
                                   const std::function<double(double, double)>& f) const {
    std::vector<double> out(static_cast<std::size_t>(g.cellCount()), 0.0);
    const int strips = std::max(1, static_cast<int>(std::lround(stripsPerMetre * g.dx)));
    const double w = g.dx / strips;
    for (int i = 0; i < g.nx; ++i)
      for (int s = 0; s < strips; ++s) {
        const double x = g.x0 + i * g.dx + (s + 0.5) * w;
        if (std::fabs(x) >= radius)
          continue;
        const double half = std::sqrt(radius * radius - x * x);
        const double lo = -half, hi = std::min(surface(x), half);
        for (int j = 0; j < g.ny; ++j) {
          const double a = std::max(lo, g.y0 + j * g.dy);
          const double b = std::min(hi, g.y0 + (j + 1) * g.dy);
          if (b > a)
            out[static_cast<std::size_t>(j) * g.nx + i] += f(x, 0.5 * (a + b)) * (b - a) * w;
        }
      }
    for (double& v : out)
      v /= g.dx * g.dy;
    return out;
  }
};

/// \brief n x n cells over [-R, R]^2 (the DEM's Cartesian grid of a drum of radius R).
inline CellGrid squareGrid(int n, double radius) {
  return dem::cg::drumCartesianGrid(radius, n, n);
}

} // namespace hikiln::compare::test
