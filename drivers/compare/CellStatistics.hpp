#pragma once
/// \file CellStatistics.hpp
/// \brief Statistics of two maps on the same grid: means over a spot window and differences over
/// the cells both maps hold.

#include "drivers/compare/Regrid.hpp"

#include <cstdint>
#include <vector>

namespace hikiln::compare {

/// \brief A square window around a point: the cells whose centres lie within halfWidth of (x, y)
/// along both axes.
struct SpotWindow {
  double x = 0.0, y = 0.0, halfWidth = 0.0;
};

/// \brief Indices of the cells whose centres lie in `window` (edges included, to round-off).
std::vector<std::size_t> cellsInWindow(const CellGrid& grid, const SpotWindow& window);

/// \brief Means of a reference and a model map over the same cells.
struct PairedMean {
  double reference, model;     ///< NaN when no cell qualifies
  std::size_t cells = 0;       ///< cells that entered the means
  double centroidX, centroidY; ///< mean of their centres: where a linear field's mean is exact
};

/// \brief Means of `reference` and `model` over the cells of `cells` where `mask` is set and
/// both values are finite.
PairedMean pairedMean(const CellGrid& grid, const std::vector<double>& reference,
                      const std::vector<double>& model, const std::vector<std::uint8_t>& mask,
                      const std::vector<std::size_t>& cells);

/// \brief How far a model map is from a reference map over the cells both hold.
struct MapDifference {
  std::size_t cells = 0;           ///< cells with `mask` set and both values finite
  double referenceMean, modelMean; ///< means over those cells (NaN when none)
  double relativeL2;               ///< ||model - reference||_2 / ||reference||_2
  double rmsLog10Ratio;            ///< rms of log10(model / reference) where both are > 0
  std::size_t positiveCells = 0;   ///< cells in rmsLog10Ratio
};

/// \brief The difference of `model` from `reference` over the cells where `mask` is set and
/// both values are finite.
MapDifference mapDifference(const std::vector<double>& reference, const std::vector<double>& model,
                            const std::vector<std::uint8_t>& mask);

} // namespace hikiln::compare
