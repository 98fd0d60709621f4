#pragma once
/// \file Regrid.hpp
/// \brief Brings cell fields of one uniform Cartesian grid onto another by overlap areas: each
/// source cell contributes to every target cell it overlaps in proportion to the overlapping
/// area (exact for piecewise-constant cell values, conservative for any grids).

#include "kernels/dem/CoarseGrainGrid.hpp"

#include <vector>

namespace hikiln::compare {

using CellGrid = dem::cg::CartesianGrid;

/// \brief Per target cell: sum of overlap area x weight x value and sum of overlap area x weight.
struct OverlapSums {
  std::vector<double> weighted; ///< sum a w v
  std::vector<double> weight;   ///< sum a w
};

/// \brief Overlap sums of `values` weighted by `weights` (both [ny][nx] on `source`) onto
/// `target`. Source cells with a non-finite value or weight are skipped.
OverlapSums overlapSums(const CellGrid& source, const std::vector<double>& values,
                        const std::vector<double>& weights, const CellGrid& target);

/// \brief The weighted mean per target cell, sum a w v / sum a w (NaN where sum a w is 0).
std::vector<double> weightedMean(const OverlapSums& sums);

/// \brief The amount per unit area of each target cell, sum a w v / (target cell area): what a
/// DEM cell average is (a quantity summed over its particles and divided by the cell's area).
std::vector<double> perCellArea(const OverlapSums& sums, const CellGrid& target);

} // namespace hikiln::compare
