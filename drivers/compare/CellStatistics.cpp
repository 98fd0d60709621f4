#include "drivers/compare/CellStatistics.hpp"

#include <cmath>
#include <limits>

namespace hikiln::compare {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
} // namespace

std::vector<std::size_t> cellsInWindow(const CellGrid& grid, const SpotWindow& window) {
  const double reach = window.halfWidth * (1.0 + 1e-9) + 1e-12 * (grid.dx + grid.dy);
  std::vector<std::size_t> cells;
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i)
      if (std::fabs(grid.xCentre(i) - window.x) <= reach &&
          std::fabs(grid.yCentre(j) - window.y) <= reach)
        cells.push_back(static_cast<std::size_t>(j) * grid.nx + i);
  return cells;
}

PairedMean pairedMean(const CellGrid& grid, const std::vector<double>& reference,
                      const std::vector<double>& model, const std::vector<std::uint8_t>& mask,
                      const std::vector<std::size_t>& cells) {
  double sumReference = 0.0, sumModel = 0.0, sumX = 0.0, sumY = 0.0;
  PairedMean mean{nan, nan, 0, nan, nan};
  for (std::size_t c : cells) {
    if (!mask[c] || !std::isfinite(reference[c]) || !std::isfinite(model[c]))
      continue;
    ++mean.cells;
    sumReference += reference[c];
    sumModel += model[c];
    sumX += grid.xCentre(static_cast<int>(c % static_cast<std::size_t>(grid.nx)));
    sumY += grid.yCentre(static_cast<int>(c / static_cast<std::size_t>(grid.nx)));
  }
  if (mean.cells > 0) {
    const double n = static_cast<double>(mean.cells);
    mean.reference = sumReference / n;
    mean.model = sumModel / n;
    mean.centroidX = sumX / n;
    mean.centroidY = sumY / n;
  }
  return mean;
}

MapDifference mapDifference(const std::vector<double>& reference, const std::vector<double>& model,
                            const std::vector<std::uint8_t>& mask) {
  MapDifference d{0, nan, nan, nan, nan, 0};
  double sumReference = 0.0, sumModel = 0.0, squaredDifference = 0.0, squaredReference = 0.0;
  double squaredLogRatio = 0.0;
  for (std::size_t c = 0; c < reference.size(); ++c) {
    if (!mask[c] || !std::isfinite(reference[c]) || !std::isfinite(model[c]))
      continue;
    ++d.cells;
    sumReference += reference[c];
    sumModel += model[c];
    squaredDifference += (model[c] - reference[c]) * (model[c] - reference[c]);
    squaredReference += reference[c] * reference[c];
    if (reference[c] > 0.0 && model[c] > 0.0) {
      ++d.positiveCells;
      const double r = std::log10(model[c] / reference[c]);
      squaredLogRatio += r * r;
    }
  }
  if (d.cells > 0) {
    d.referenceMean = sumReference / static_cast<double>(d.cells);
    d.modelMean = sumModel / static_cast<double>(d.cells);
    if (squaredReference > 0.0)
      d.relativeL2 = std::sqrt(squaredDifference / squaredReference);
  }
  if (d.positiveCells > 0)
    d.rmsLog10Ratio = std::sqrt(squaredLogRatio / static_cast<double>(d.positiveCells));
  return d;
}

} // namespace hikiln::compare
