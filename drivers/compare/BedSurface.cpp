#include "drivers/compare/BedSurface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hikiln::compare {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double degreesPerRadian = 57.29577951308232;

// Integral of sqrt(R^2 - s^2) ds from 0 to s (|s| <= R).
double halfDiscArea(double s, double R) {
  return 0.5 * (s * std::sqrt(std::max(R * R - s * s, 0.0)) + R * R * std::asin(s / R));
}

} // namespace

double bedVolumeFraction(const std::vector<double>& volumeFraction) {
  double largest = 0.0;
  for (double v : volumeFraction)
    if (std::isfinite(v))
      largest = std::max(largest, v);
  if (!(largest > 0.0))
    return nan;
  std::vector<double> dense;
  for (double v : volumeFraction)
    if (std::isfinite(v) && v >= 0.5 * largest)
      dense.push_back(v);
  const auto middle = dense.begin() + static_cast<std::ptrdiff_t>(dense.size() / 2);
  std::nth_element(dense.begin(), middle, dense.end());
  if (dense.size() % 2 == 1)
    return *middle;
  const double upper = *middle;
  return 0.5 * (upper + *std::max_element(dense.begin(), middle));
}

std::vector<double> surfaceHeights(const CellGrid& grid, const std::vector<double>& volumeFraction,
                                   double bedValue, const DrumCircle& drum, double minDepth) {
  std::vector<double> heights(static_cast<std::size_t>(grid.nx), nan);
  const double R = drum.radius;
  for (int i = 0; i < grid.nx; ++i) {
    // the column's part inside the drum, relative to the axis
    const double a = std::max(grid.x0 + i * grid.dx - drum.cx, -R);
    const double b = std::min(grid.x0 + (i + 1) * grid.dx - drum.cx, R);
    if (b <= a || !(bedValue > 0.0))
      continue;
    double depth = 0.0; // solids area of the column over its width, at the bed's density
    for (int j = 0; j < grid.ny; ++j) {
      const double v = volumeFraction[static_cast<std::size_t>(j) * grid.nx + i];
      if (std::isfinite(v))
        depth += v / bedValue * grid.dy;
    }
    if (depth < minDepth)
      continue;
    const double shellBottom = drum.cy - (halfDiscArea(b, R) - halfDiscArea(a, R)) / (b - a);
    heights[static_cast<std::size_t>(i)] = shellBottom + depth * grid.dx / (b - a);
  }
  return heights;
}

double surfaceAngleDeg(const CellGrid& grid, const std::vector<double>& heights,
                       const DrumCircle& drum, double fraction) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (int i = 0; i < grid.nx; ++i) {
    const double x = grid.xCentre(i) - drum.cx;
    const double y = heights[static_cast<std::size_t>(i)];
    if (!std::isfinite(y) || std::fabs(x) > fraction * drum.radius)
      continue;
    n += 1.0;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double spread = n * sxx - sx * sx;
  if (n < 2.0 || spread <= 0.0)
    return nan;
  return std::atan((n * sxy - sx * sy) / spread) * degreesPerRadian;
}

} // namespace hikiln::compare
