// Reads what `hikiln compare` needs of a DEM run: the Cartesian averaged fields of averages.h5
// (docs/averaged-fields.md), its wall slip, and the surface angle of summary.json.
#include "drivers/calibrate/AveragesReader.hpp"
#include "drivers/compare/CompareInputs.hpp"
#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Summary.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace hikiln::compare {

namespace fs = std::filesystem;

namespace {

std::runtime_error fileError(const std::string& path, const std::string& what) {
  return std::runtime_error("DEM averages file '" + path + "': " + what);
}

double requireAttribute(const io::H5File& file, const std::string& object,
                        const std::string& name) {
  if (!file.hasAttribute(object, name))
    throw fileError(file.path(), "missing attribute '" + name + "' on '" + object + "'");
  return file.readDoubleAttribute(object, name);
}

// A [ny][nx] (or [n] for an axis) dataset of exactly `shape`.
std::vector<double> readShaped(const io::H5File& file, const std::string& name,
                               const std::vector<hsize_t>& shape) {
  if (!file.isDataset(name))
    throw fileError(file.path(), "missing dataset '" + name + "'");
  std::vector<hsize_t> dims;
  std::vector<double> values = file.readDataset<double>(name, &dims);
  if (dims != shape)
    throw fileError(file.path(), "dataset '" + name + "' does not have the grid's shape");
  return values;
}

// The uniform grid whose cell centres are `x` and `y`.
CellGrid gridOfCentres(const std::string& path, const std::vector<double>& x,
                       const std::vector<double>& y) {
  if (x.size() < 2 || y.size() < 2)
    throw fileError(path, "the Cartesian grid needs at least 2 x 2 cells");
  CellGrid g;
  g.nx = static_cast<int>(x.size());
  g.ny = static_cast<int>(y.size());
  g.dx = (x.back() - x.front()) / (g.nx - 1);
  g.dy = (y.back() - y.front()) / (g.ny - 1);
  g.x0 = x.front() - 0.5 * g.dx;
  g.y0 = y.front() - 0.5 * g.dy;
  for (int i = 0; i < g.nx; ++i)
    if (!(g.dx > 0.0) || std::fabs(g.xCentre(i) - x[static_cast<std::size_t>(i)]) > 1e-9 * g.dx)
      throw fileError(path, "/cartesian/x_centres is not a uniform increasing axis");
  for (int j = 0; j < g.ny; ++j)
    if (!(g.dy > 0.0) || std::fabs(g.yCentre(j) - y[static_cast<std::size_t>(j)]) > 1e-9 * g.dy)
      throw fileError(path, "/cartesian/y_centres is not a uniform increasing axis");
  return g;
}

} // namespace

DemRun readDemRun(const std::string& path) {
  DemRun run;
  try {
    run.averagesFile = calibrate::averagesFileOf(path);
  } catch (const std::runtime_error& e) { // "run directory 'X' has no averages.h5 ..."
    throw std::runtime_error(std::string("DEM ") + e.what());
  }
  run.directory = fs::path(run.averagesFile).parent_path().string();
  const io::H5File file = io::H5File::openRead(run.averagesFile);
  if (file.hasAttribute("/", "stage") && file.readStringAttribute("/", "stage") != "dem")
    throw fileError(run.averagesFile, "written by stage '" +
                                          file.readStringAttribute("/", "stage") +
                                          "', expected 'dem'");
  if (!file.hasAttribute("/", "resolved_case"))
    throw fileError(run.averagesFile, "missing attribute 'resolved_case' on '/'");
  run.drum = drumOfResolvedCase(file.readStringAttribute("/", "resolved_case"),
                                "DEM averages file '" + run.averagesFile + "'");
  const double radius = requireAttribute(file, "/", "drum_radius");
  if (std::fabs(2.0 * radius - run.drum.diameter) > 1e-9 * run.drum.diameter)
    throw fileError(run.averagesFile, "drum_radius does not match the case's drum.diameter");
  run.measuredFill = requireAttribute(file, "/", "fill");
  run.averageStart = requireAttribute(file, "/", "average_start");
  run.averageEnd = requireAttribute(file, "/", "average_end");
  if (file.hasAttribute("/", "samples"))
    run.samples = file.readInt64Attribute("/", "samples");
  if (file.hasAttribute("/", "min_volume_fraction"))
    run.minVolumeFraction = file.readDoubleAttribute("/", "min_volume_fraction");
  if (!file.exists("/wall"))
    throw fileError(run.averagesFile, "missing group '/wall'");
  run.slipPercent = requireAttribute(file, "/wall", "slip_percent");
  if (!file.exists("/cartesian"))
    throw fileError(run.averagesFile, "missing group '/cartesian'");

  const std::vector<hsize_t> nx = file.isDataset("/cartesian/x_centres")
                                      ? file.datasetDims("/cartesian/x_centres")
                                      : std::vector<hsize_t>{};
  const std::vector<hsize_t> ny = file.isDataset("/cartesian/y_centres")
                                      ? file.datasetDims("/cartesian/y_centres")
                                      : std::vector<hsize_t>{};
  if (nx.size() != 1 || ny.size() != 1)
    throw fileError(run.averagesFile, "missing or misshapen /cartesian/x_centres, y_centres");
  CellMaps& maps = run.maps;
  maps.grid = gridOfCentres(run.averagesFile, readShaped(file, "/cartesian/x_centres", nx),
                            readShaped(file, "/cartesian/y_centres", ny));
  run.centreX = maps.grid.x0 + 0.5 * maps.grid.nx * maps.grid.dx; // the grid spans the drum
  run.centreY = maps.grid.y0 + 0.5 * maps.grid.ny * maps.grid.dy;
  const std::vector<hsize_t> shape = {ny[0], nx[0]};
  for (const char* name : {"volume_fraction", "velocity_x", "velocity_y", "pressure",
                           "shear_stress", "strain_rate", "viscosity"})
    maps.fields[name] = readShaped(file, std::string("/cartesian/") + name, shape);
  if (!file.isDataset("/cartesian/valid"))
    throw fileError(run.averagesFile, "missing dataset '/cartesian/valid'");
  std::vector<hsize_t> validShape;
  maps.valid = file.readDataset<std::uint8_t>("/cartesian/valid", &validShape);
  if (validShape != shape)
    throw fileError(run.averagesFile, "dataset '/cartesian/valid' does not have the grid's shape");

  run.summarySurfaceAngleDeg = std::numeric_limits<double>::quiet_NaN();
  const fs::path summary = fs::path(run.directory) / "summary.json";
  if (fs::is_regular_file(summary)) {
    const nlohmann::json s = io::readSummaryJson(summary.string());
    if (s.contains("surface_angle_deg") && s["surface_angle_deg"].is_number())
      run.summarySurfaceAngleDeg = s["surface_angle_deg"].get<double>();
  }
  return run;
}

} // namespace hikiln::compare
