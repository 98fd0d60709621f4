#include "drivers/compare/ComparisonReport.hpp"

#include "drivers/io/Hdf5File.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hikiln::compare {

namespace {

nlohmann::json number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json numbers(const std::vector<double>& values) {
  nlohmann::json list = nlohmann::json::array();
  for (double v : values)
    list.push_back(number(v));
  return list;
}

// continuum - DEM, and that relative to |DEM|
nlohmann::json pair(double dem, double continuum) {
  return {{"dem", number(dem)},
          {"continuum", number(continuum)},
          {"difference", number(continuum - dem)},
          {"relative_difference", number((continuum - dem) / std::fabs(dem))}};
}

const char* unitOf(const std::string& field) {
  if (field == "pressure" || field == "shear_stress")
    return "Pa";
  if (field == "viscosity")
    return "Pa s";
  if (field == "strain_rate")
    return "1/s";
  if (field == "velocity_x" || field == "velocity_y")
    return "m/s";
  return "1";
}

nlohmann::json surfaceJson(const Comparison& c) {
  const CellGrid& g = c.dem.grid;
  std::vector<double> x, difference;
  double sum = 0.0, squares = 0.0, largest = 0.0;
  int columns = 0;
  for (int i = 0; i < g.nx; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    x.push_back(g.xCentre(i));
    difference.push_back(c.continuumSurface[k] - c.demSurface[k]);
    if (std::isfinite(difference.back())) {
      ++columns;
      sum += difference.back();
      squares += difference.back() * difference.back();
      largest = std::max(largest, std::fabs(difference.back()));
    }
  }
  const double nan = std::nan("");
  return {{"method", "per column of the common grid: the column's solids stacked at the bed's "
                     "volume fraction onto the shell (column mean of the shell bottom + sum of "
                     "volume fraction / bed fraction x dy); exact for a surface straight across "
                     "the column; none where less than half a cell of bed"},
          {"x", numbers(x)},
          {"dem", numbers(c.demSurface)},
          {"continuum", numbers(c.continuumSurface)},
          {"difference", numbers(difference)},
          {"columns_in_both", columns},
          {"mean_difference", number(columns > 0 ? sum / columns : nan)},
          {"rms_difference", number(columns > 0 ? std::sqrt(squares / columns) : nan)},
          {"max_abs_difference", number(columns > 0 ? largest : nan)},
          {"angle_deg", pair(c.demSurfaceAngleDeg, c.continuumSurfaceAngleDeg)},
          {"angle_method", "least-squares line through the column heights within half a radius "
                           "of the axis, positive rising towards +x"}};
}

} // namespace

nlohmann::json comparisonJson(const Comparison& c, const DemRun& dem, const ContinuumRun& cont,
                              const std::string& label) {
  const CellGrid& g = c.dem.grid;
  nlohmann::json j;
  j["stage"] = "compare";
  j["hikiln_version"] = HIKILN_VERSION;
  j["created"] = io::utcTimestamp();
  j["label"] = label;
  j["dem_run"] = dem.directory;
  j["continuum_run"] = cont.directory;
  j["drum"] = {{"diameter", dem.drum.diameter},
               {"rpm", dem.drum.rpm},
               {"fill", dem.drum.fill},
               {"dem_fill_measured", dem.measuredFill}};
  j["grid"] = {
      {"nx", g.nx},
      {"ny", g.ny},
      {"x0", g.x0},
      {"y0", g.y0},
      {"dx", g.dx},
      {"dy", g.dy},
      {"axis", {c.drum.cx, c.drum.cy}},
      {"continuum_cells", {cont.grid.nx, cont.grid.ny}},
      {"method",
       "the DEM's Cartesian cells; the continuum cells (axes aligned on the drum axis) averaged "
       "into them by overlap area x open (fluid) area: volume fraction, bed pressure and shear "
       "stress per whole cell area (as the DEM's sums over a cell's particles / cell area), "
       "velocity solids-mass weighted, strain rate from that velocity by the DEM's finite "
       "differences, viscosity = shear stress / strain rate"}};
  j["dem_average"] = {{"from_s", dem.averageStart},
                      {"to_s", dem.averageEnd},
                      {"samples", dem.samples},
                      {"file", dem.averagesFile}};
  j["continuum_average"] = {{"outputs", cont.averagedTimes.size()},
                            {"from_s", cont.averagedTimes.front()},
                            {"to_s", cont.averagedTimes.back()},
                            {"slip_after_s", cont.slipAfter},
                            {"rule", cont.averaging}};
  j["bed_volume_fraction"] = {
      {"dem", number(c.demBedFraction)},
      {"continuum", number(c.continuumBedFraction)},
      {"valid_fraction_of_bed", number(c.validFraction)},
      {"method", "median over the cells with at least half the largest volume fraction; maps "
                 "of volume fraction are compared divided by it (the DEM's is an area fraction "
                 "of discs, the continuum's a volume fraction)"}};
  nlohmann::json spotValues;
  for (const auto& [name, mean] : c.spotValues) {
    spotValues[name] = pair(mean.reference, mean.model);
    spotValues[name]["units"] = unitOf(name);
    spotValues[name]["cells"] = mean.cells;
  }
  std::size_t spotCells = 0;
  double cx = std::nan(""), cy = std::nan("");
  for (const auto& [name, mean] : c.spotValues)
    if (mean.cells > spotCells) {
      spotCells = mean.cells;
      cx = mean.centroidX;
      cy = mean.centroidY;
    }
  j["spot"] = {{"x", c.spot.x},
               {"y", c.spot.y},
               {"depth_above_shell_bottom", c.spotDepth},
               {"half_width", c.spot.halfWidth},
               {"window_cells", c.spotCells.size()},
               {"cells_valid_in_both", spotCells},
               {"centroid", {number(cx), number(cy)}},
               {"method", "mean over the cells of the common grid whose centres lie in the "
                          "square window around (x, y) and that are valid in both runs"},
               {"values", spotValues}};
  j["wall_slip_percent"] = pair(dem.slipPercent, cont.slipPercent);
  j["wall_slip_percent"]["dem_source"] = "averages.h5 /wall slip_percent";
  j["wall_slip_percent"]["continuum_source"] = cont.slipSource;
  j["surface"] = surfaceJson(c);
  j["surface"]["dem_summary_angle_deg"] = number(dem.summarySurfaceAngleDeg);
  nlohmann::json maps;
  for (const auto& [name, d] : c.maps)
    maps[name] = {{"cells", d.cells},
                  {"dem_mean", number(d.referenceMean)},
                  {"continuum_mean", number(d.modelMean)},
                  {"relative_l2", number(d.relativeL2)},
                  {"rms_log10_ratio", number(d.rmsLog10Ratio)},
                  {"units", name == "volume_fraction_normalised" ? "1" : unitOf(name)}};
  j["maps"] = maps;
  j["maps_method"] = "relative L2 = ||continuum - DEM|| / ||DEM|| over the cells valid in both "
                     "(volume_fraction_normalised: valid in either); rms_log10_ratio over those "
                     "where both are positive";
  j["outputs"] = {{"csv", "comparison.csv"}};
  return j;
}

std::string comparisonCsv(const Comparison& c) {
  const CellGrid& g = c.dem.grid;
  std::string csv = "i,j,x,y,dem_valid,continuum_valid";
  for (const std::string& name : mapFields())
    csv += ",dem_" + name + ",continuum_" + name;
  csv += "\n";
  for (int jy = 0; jy < g.ny; ++jy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t k = static_cast<std::size_t>(jy) * g.nx + ix;
      csv += fmt::format("{},{},{:.9g},{:.9g},{},{}", ix, jy, g.xCentre(ix), g.yCentre(jy),
                         int(c.dem.valid[k]), int(c.continuum.valid[k]));
      for (const std::string& name : mapFields())
        csv +=
            fmt::format(",{:.9g},{:.9g}", c.dem.fields.at(name)[k], c.continuum.fields.at(name)[k]);
      csv += "\n";
    }
  return csv;
}

} // namespace hikiln::compare
