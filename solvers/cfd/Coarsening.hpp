#pragma once
/// \file Coarsening.hpp
/// \brief The grid hierarchy of a geometric multigrid: which axes are halved from one level to
/// the next, and where the hierarchy stops.

#include "kernels/cfd/Grid.hpp"

#include <cstdint>
#include <vector>

namespace hikiln::cfd {

/// \brief When to coarsen an axis and when to stop.
struct CoarseningOptions {
  std::int64_t maxCoarseCells = 64; ///< stop once a level has at most this many cells
  int minCells = 2;                 ///< never coarsen an axis below this many cells
  double maxAspect = 2.0;           ///< coarsen an axis only while h_axis * 2 <= maxAspect * min h
};

/// \brief One level of the hierarchy: its grid and the factor (1 or 2) per axis from the next
/// finer level (all 1 on the finest).
struct LevelGeometry {
  Grid grid;
  int ratio[3] = {1, 1, 1};
};

/// \brief The grids of a hierarchy, finest first. An active axis is halved when its cell count
/// is even, stays >= minCells, and its cell stays within maxAspect of the smallest spacing (so
/// flat domains semi-coarsen). A periodic axis with an odd cell count cannot be red-black
/// smoothed, so such a level ends the hierarchy (its equations are solved directly).
std::vector<LevelGeometry> coarsenGrids(Grid const& fine, bool const (&periodic)[3],
                                        CoarseningOptions const& options);

} // namespace hikiln::cfd
