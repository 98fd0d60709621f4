#include "drivers/compare/Regrid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hikiln::compare {

namespace {

// Length of the overlap of [a0, a1] and [b0, b1] (0 when they do not meet).
double overlap(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

// Target cells [first, last] along one axis that the interval [lo, hi] may touch.
void touchedRange(double lo, double hi, double origin, double spacing, int count, int& first,
                  int& last) {
  first = std::max(0, static_cast<int>(std::floor((lo - origin) / spacing)));
  last = std::min(count - 1, static_cast<int>(std::floor((hi - origin) / spacing)));
}

} // namespace

OverlapSums overlapSums(const CellGrid& source, const std::vector<double>& values,
                        const std::vector<double>& weights, const CellGrid& target) {
  const auto cells = static_cast<std::size_t>(source.cellCount());
  if (values.size() != cells || weights.size() != cells)
    throw std::invalid_argument("overlapSums: values and weights must have one entry per cell");
  OverlapSums sums;
  sums.weighted.assign(static_cast<std::size_t>(target.cellCount()), 0.0);
  sums.weight.assign(static_cast<std::size_t>(target.cellCount()), 0.0);
  for (int j = 0; j < source.ny; ++j) {
    const double y0 = source.y0 + j * source.dy, y1 = y0 + source.dy;
    int tj0 = 0, tj1 = -1;
    touchedRange(y0, y1, target.y0, target.dy, target.ny, tj0, tj1);
    for (int i = 0; i < source.nx; ++i) {
      const std::size_t c = static_cast<std::size_t>(j) * source.nx + i;
      if (!std::isfinite(values[c]) || !std::isfinite(weights[c]) || weights[c] == 0.0)
        continue;
      const double x0 = source.x0 + i * source.dx, x1 = x0 + source.dx;
      int ti0 = 0, ti1 = -1;
      touchedRange(x0, x1, target.x0, target.dx, target.nx, ti0, ti1);
      for (int tj = tj0; tj <= tj1; ++tj) {
        const double ty0 = target.y0 + tj * target.dy;
        const double ly = overlap(y0, y1, ty0, ty0 + target.dy);
        for (int ti = ti0; ti <= ti1; ++ti) {
          const double tx0 = target.x0 + ti * target.dx;
          const double area = overlap(x0, x1, tx0, tx0 + target.dx) * ly;
          if (area <= 0.0)
            continue;
          const std::size_t t = static_cast<std::size_t>(tj) * target.nx + ti;
          sums.weighted[t] += area * weights[c] * values[c];
          sums.weight[t] += area * weights[c];
        }
      }
    }
  }
  return sums;
}

std::vector<double> weightedMean(const OverlapSums& sums) {
  std::vector<double> mean(sums.weight.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t t = 0; t < mean.size(); ++t)
    if (sums.weight[t] != 0.0)
      mean[t] = sums.weighted[t] / sums.weight[t];
  return mean;
}

std::vector<double> perCellArea(const OverlapSums& sums, const CellGrid& target) {
  std::vector<double> density(sums.weighted.size());
  const double area = target.dx * target.dy;
  for (std::size_t t = 0; t < density.size(); ++t)
    density[t] = sums.weighted[t] / area;
  return density;
}

} // namespace hikiln::compare
