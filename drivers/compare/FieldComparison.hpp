#pragma once
/// \file FieldComparison.hpp
/// \brief A DEM run and a continuum run of the same drum on one grid (the DEM's Cartesian cells)
/// and what `hikiln compare` reports of them: spot values near the bottom of the drum, wall slip,
/// bed surface shapes and map differences.

#include "drivers/compare/BedSurface.hpp"
#include "drivers/compare/CellStatistics.hpp"
#include "drivers/compare/CompareInputs.hpp"

#include <map>
#include <string>
#include <vector>

namespace hikiln::compare {

/// \brief Fields of the spot values (physics.md 5: near the bottom of the kiln).
const std::vector<std::string>& spotFields();

/// \brief Fields of the maps, in the order the CSV and the plots use.
const std::vector<std::string>& mapFields();

/// \brief Where the spot is and how surfaces are measured; negative lengths take the defaults.
struct CompareOptions {
  double spotDepth = -1.0;           ///< m above the shell bottom; default 0.05 D
  double spotHalfWidth = -1.0;       ///< m; default 0.04 D (with 30 cells across: 2 x 3 cells)
  double surfaceFitFraction = 0.5;   ///< surface angle from the columns within this x R of the axis
  double minSurfaceDepthCells = 0.5; ///< columns with less stacked bed (in cells) have no surface
};

/// \brief Fraction of the bed's volume fraction above which the continuum's solids velocity
/// enters the strain rate (as particles' velocities do in the DEM wherever any were seen).
inline constexpr double solidsPresentFraction = 0.01;

/// \brief The continuum's time-averaged fields on `target` (the DEM's grid, whose drum axis is
/// at (centreX, centreY)), made comparable with the DEM's averages: overlap-area averages of the
/// continuum cells weighted by their open (fluid) area; volume fraction, pressure (the bed
/// pressure) and shear stress per whole target cell area, as the DEM divides its sums by the cell
/// area; velocity solids-mass weighted (sum a phi u / sum a phi), as the DEM's; strain rate from
/// that velocity by the DEM's own finite differences (dem::cartesianStrainRate); viscosity = shear
/// stress / strain rate. `valid` is left empty (it needs the DEM's bed scale, see compareRuns).
CellMaps continuumOnGrid(const ContinuumRun& run, const CellGrid& target, double centreX,
                         double centreY);

/// \brief Everything `hikiln compare` reports of one pair of runs.
struct Comparison {
  CellMaps dem, continuum; ///< same grid; continuum.valid set from the bed scale
  DrumCircle drum;
  double demBedFraction, continuumBedFraction; ///< bedVolumeFraction of each map
  double validFraction; ///< continuum cells are valid at or above this x its bed fraction
  SpotWindow spot;
  double spotDepth;
  std::vector<std::size_t> spotCells;
  std::map<std::string, PairedMean> spotValues;     ///< reference = DEM, model = continuum
  std::vector<double> demSurface, continuumSurface; ///< heights per column (NaN: no bed)
  double demSurfaceAngleDeg, continuumSurfaceAngleDeg;
  std::map<std::string, MapDifference> maps; ///< mapFields(), plus "volume_fraction_normalised"
};

/// \brief Compares `continuumMaps` (continuumOnGrid of the run) with the DEM run. Continuum cells
/// are valid where their volume fraction over the continuum's bed fraction reaches the DEM's
/// `min_volume_fraction` over the DEM's bed fraction (the same filter on the same relative
/// scale); spot values and map differences use the cells valid in both, the normalised volume
/// fraction the cells valid in either (so that a different bed shape counts).
Comparison compareRuns(const DemRun& dem, const CellMaps& continuumMaps,
                       const CompareOptions& options);

} // namespace hikiln::compare
