#pragma once
/// \file BedSurface.hpp
/// \brief The bed's volume fraction scale and its surface shape on a Cartesian map of a drum.

#include "drivers/compare/Regrid.hpp"

#include <vector>

namespace hikiln::compare {

/// \brief The drum's circle in the map's coordinates.
struct DrumCircle {
  double cx = 0.0, cy = 0.0, radius = 1.0;
};

/// \brief The volume fraction of the bulk of the bed: the median over the cells holding at least
/// half the largest value (the dense core; thin surface, cut and airborne cells are left out).
/// NaN when no value is finite and positive.
double bedVolumeFraction(const std::vector<double>& volumeFraction);

/// \brief Bed surface height per column of `grid` (y of the surface, same length as the
/// columns). Each column's solids are stacked into a dense layer on the shell: height = the
/// column mean of the shell bottom + (sum over the column of volumeFraction / bedValue x dy)
/// scaled from the column width to its part inside the drum. A volume fraction per whole cell
/// area (as the DEM's) makes this exact for any surface that is straight across a column and
/// lies above the shell there. NaN where the stacked depth is below `minDepth` (no bed).
std::vector<double> surfaceHeights(const CellGrid& grid, const std::vector<double>& volumeFraction,
                                   double bedValue, const DrumCircle& drum, double minDepth);

/// \brief Inclination (degrees, positive when the surface rises towards +x) of the
/// least-squares line through the finite heights of the columns within `fraction` x radius of
/// the drum axis. NaN with fewer than two such columns.
double surfaceAngleDeg(const CellGrid& grid, const std::vector<double>& heights,
                       const DrumCircle& drum, double fraction);

} // namespace hikiln::compare
