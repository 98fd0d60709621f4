#include "drivers/compare/FieldComparison.hpp"

#include "solvers/dem/StrainRateField.hpp"

#include <cmath>
#include <limits>

namespace hikiln::compare {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
} // namespace

const std::vector<std::string>& spotFields() {
  static const std::vector<std::string> names = {"pressure", "shear_stress", "viscosity",
                                                 "strain_rate", "velocity_x"};
  return names;
}

const std::vector<std::string>& mapFields() {
  static const std::vector<std::string> names = {"volume_fraction", "pressure",    "shear_stress",
                                                 "viscosity",       "strain_rate", "velocity_x",
                                                 "velocity_y"};
  return names;
}

CellMaps continuumOnGrid(const ContinuumRun& run, const CellGrid& target, double centreX,
                         double centreY) {
  CellGrid source = run.grid; // drum axis at (0, 0): move it onto the target's axis
  source.x0 += centreX;
  source.y0 += centreY;
  const std::vector<double>& open = run.means.at("capacity");
  const OverlapSums solids = overlapSums(source, run.means.at("volume_fraction"), open, target);
  const OverlapSums momentumX = overlapSums(source, run.means.at("momentum_x"), open, target);
  const OverlapSums momentumY = overlapSums(source, run.means.at("momentum_y"), open, target);

  CellMaps maps;
  maps.grid = target;
  const std::size_t cells = static_cast<std::size_t>(target.cellCount());
  std::vector<double>& phi = maps.fields["volume_fraction"];
  phi = perCellArea(solids, target);
  const double bed = bedVolumeFraction(phi);
  std::vector<double>& ux = maps.fields["velocity_x"];
  std::vector<double>& uy = maps.fields["velocity_y"];
  ux.assign(cells, nan);
  uy.assign(cells, nan);
  std::vector<std::uint8_t> present(cells, 0);
  for (std::size_t c = 0; c < cells; ++c) {
    if (solids.weighted[c] > 0.0) {
      ux[c] = momentumX.weighted[c] / solids.weighted[c];
      uy[c] = momentumY.weighted[c] / solids.weighted[c];
    }
    present[c] = solids.weighted[c] > 0.0 && phi[c] >= solidsPresentFraction * bed ? 1 : 0;
  }
  maps.fields["pressure"] =
      perCellArea(overlapSums(source, run.means.at("bed_pressure"), open, target), target);
  maps.fields["shear_stress"] =
      perCellArea(overlapSums(source, run.means.at("shear_stress"), open, target), target);
  maps.fields["strain_rate"] = dem::cartesianStrainRate(target, ux, uy, present);
  std::vector<double>& viscosity = maps.fields["viscosity"];
  viscosity.assign(cells, nan);
  for (std::size_t c = 0; c < cells; ++c) {
    const double rate = maps.fields["strain_rate"][c];
    if (rate > 0.0)
      viscosity[c] = maps.fields["shear_stress"][c] / rate;
  }
  return maps;
}

Comparison compareRuns(const DemRun& dem, const CellMaps& continuumMaps,
                       const CompareOptions& options) {
  Comparison out;
  out.dem = dem.maps;
  out.continuum = continuumMaps;
  const CellGrid& grid = out.dem.grid;
  const std::size_t cells = static_cast<std::size_t>(grid.cellCount());
  const double diameter = dem.drum.diameter;
  out.drum = DrumCircle{dem.centreX, dem.centreY, 0.5 * diameter};

  const std::vector<double>& demPhi = out.dem.fields.at("volume_fraction");
  std::vector<double>& contPhi = out.continuum.fields.at("volume_fraction");
  out.demBedFraction = bedVolumeFraction(demPhi);
  out.continuumBedFraction = bedVolumeFraction(contPhi);
  out.validFraction = dem.minVolumeFraction / out.demBedFraction;
  out.continuum.valid.assign(cells, 0);
  for (std::size_t c = 0; c < cells; ++c)
    out.continuum.valid[c] = contPhi[c] >= out.validFraction * out.continuumBedFraction ? 1 : 0;
  // DEM-style: the viscosity exists only in valid cells
  for (std::size_t c = 0; c < cells; ++c)
    if (!out.continuum.valid[c])
      out.continuum.fields["viscosity"][c] = nan;

  std::vector<std::uint8_t> both(cells), either(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    both[c] = out.dem.valid[c] && out.continuum.valid[c] ? 1 : 0;
    either[c] = out.dem.valid[c] || out.continuum.valid[c] ? 1 : 0;
  }

  out.spotDepth = options.spotDepth >= 0.0 ? options.spotDepth : 0.05 * diameter;
  const double halfWidth = options.spotHalfWidth >= 0.0 ? options.spotHalfWidth : 0.04 * diameter;
  out.spot = SpotWindow{out.drum.cx, out.drum.cy - out.drum.radius + out.spotDepth, halfWidth};
  out.spotCells = cellsInWindow(grid, out.spot);
  for (const std::string& name : spotFields())
    out.spotValues[name] = pairedMean(grid, out.dem.fields.at(name), out.continuum.fields.at(name),
                                      both, out.spotCells);

  const double minDepth = options.minSurfaceDepthCells * grid.dy;
  out.demSurface = surfaceHeights(grid, demPhi, out.demBedFraction, out.drum, minDepth);
  out.continuumSurface =
      surfaceHeights(grid, contPhi, out.continuumBedFraction, out.drum, minDepth);
  out.demSurfaceAngleDeg =
      surfaceAngleDeg(grid, out.demSurface, out.drum, options.surfaceFitFraction);
  out.continuumSurfaceAngleDeg =
      surfaceAngleDeg(grid, out.continuumSurface, out.drum, options.surfaceFitFraction);

  for (const std::string& name : mapFields())
    out.maps[name] = mapDifference(out.dem.fields.at(name), out.continuum.fields.at(name), both);
  std::vector<double> demNormalised(cells), contNormalised(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    demNormalised[c] = demPhi[c] / out.demBedFraction;
    contNormalised[c] = contPhi[c] / out.continuumBedFraction;
  }
  out.maps["volume_fraction_normalised"] = mapDifference(demNormalised, contNormalised, either);
  return out;
}

} // namespace hikiln::compare
