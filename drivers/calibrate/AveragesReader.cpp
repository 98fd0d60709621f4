#include "drivers/calibrate/AveragesReader.hpp"

#include "drivers/io/Hdf5File.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace hikiln::calibrate {

namespace fs = std::filesystem;
using calibration::CellSamples;
using calibration::GridFields;

std::string gridName(AveragesGrid grid) {
  return grid == AveragesGrid::Polar ? "polar" : "cartesian";
}

std::string averagesFileOf(const std::string& runPath) {
  const fs::path given(runPath);
  if (fs::is_regular_file(given))
    return given.string();
  if (!fs::exists(given))
    throw std::runtime_error("run '" + runPath + "' does not exist");
  const fs::path file = given / "averages.h5";
  if (!fs::is_regular_file(file))
    throw std::runtime_error("run directory '" + runPath + "' has no averages.h5 (expected '" +
                             file.string() + "', written by `hikiln dem`)");
  return file.string();
}

namespace {

std::runtime_error fileError(const io::H5File& file, const std::string& what) {
  return std::runtime_error("averages file '" + file.path() + "': " + what);
}

// A dataset that must exist with exactly `count` values (1D) or `shape` (2D).
std::vector<double> readExact(const io::H5File& file, const std::string& name,
                              const std::vector<hsize_t>& shape) {
  if (!file.isDataset(name))
    throw fileError(file, "missing dataset '" + name + "'");
  std::vector<hsize_t> dims;
  std::vector<double> values = file.readDataset<double>(name, &dims);
  if (dims != shape) {
    std::string expected, found;
    for (hsize_t d : shape)
      expected += (expected.empty() ? "" : " x ") + std::to_string(d);
    for (hsize_t d : dims)
      found += (found.empty() ? "" : " x ") + std::to_string(d);
    throw fileError(file, "dataset '" + name + "' has shape " + found + ", expected " + expected);
  }
  return values;
}

std::vector<hsize_t> shapeOf(const io::H5File& file, const std::string& name) {
  if (!file.isDataset(name))
    throw fileError(file, "missing dataset '" + name + "'");
  return file.datasetDims(name);
}

std::vector<double> centres(const std::vector<double>& edges) {
  std::vector<double> mid(edges.size() - 1);
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    mid[i] = 0.5 * (edges[i] + edges[i + 1]);
  return mid;
}

// Cell coordinates (r, theta) of a [slow][fast] grid, from its group's axis datasets.
std::vector<hsize_t> readCoordinates(const io::H5File& file, AveragesGrid grid, CellSamples& c) {
  if (grid == AveragesGrid::Polar) {
    const std::vector<hsize_t> nr = shapeOf(file, "/polar/r_edges");
    const std::vector<hsize_t> nt = shapeOf(file, "/polar/theta_edges");
    if (nr.size() != 1 || nt.size() != 1 || nr[0] < 2 || nt[0] < 2)
      throw fileError(file, "/polar/r_edges and /polar/theta_edges must be 1D with >= 2 edges");
    const std::vector<double> r = centres(readExact(file, "/polar/r_edges", nr));
    const std::vector<double> theta = centres(readExact(file, "/polar/theta_edges", nt));
    for (double t : theta)
      for (double radius : r) {
        c.r.push_back(radius);
        c.theta.push_back(t);
      }
    return {theta.size(), r.size()};
  }
  const std::vector<hsize_t> nx = shapeOf(file, "/cartesian/x_centres");
  const std::vector<hsize_t> ny = shapeOf(file, "/cartesian/y_centres");
  if (nx.size() != 1 || ny.size() != 1 || nx[0] < 1 || ny[0] < 1)
    throw fileError(file, "/cartesian/x_centres and /cartesian/y_centres must be 1D, non-empty");
  const std::vector<double> x = readExact(file, "/cartesian/x_centres", nx);
  const std::vector<double> y = readExact(file, "/cartesian/y_centres", ny);
  // The grid covers the drum's bounding square, so its middle is the drum centre.
  const double x0 = 0.5 * (x.front() + x.back());
  const double y0 = 0.5 * (y.front() + y.back());
  for (double yc : y)
    for (double xc : x) {
      c.r.push_back(std::hypot(xc - x0, yc - y0));
      c.theta.push_back(std::atan2(yc - y0, xc - x0));
    }
  return {y.size(), x.size()};
}

double requireDouble(const io::H5File& file, const std::string& object, const std::string& name) {
  if (!file.hasAttribute(object, name))
    throw fileError(file, "missing attribute '" + name + "' on '" + object + "'");
  return file.readDoubleAttribute(object, name);
}

} // namespace

GridFields readGridFields(const std::string& path, AveragesGrid grid) {
  const io::H5File file = io::H5File::openRead(path);
  const std::string group = "/" + gridName(grid);
  if (!file.exists(group))
    throw fileError(file, "missing group '" + group + "'");
  GridFields fields;
  CellSamples& c = fields.cells;
  const std::vector<hsize_t> shape = readCoordinates(file, grid, c);
  c.volumeFraction = readExact(file, group + "/volume_fraction", shape);
  c.pressure = readExact(file, group + "/pressure", shape);
  c.shearStress = readExact(file, group + "/shear_stress", shape);
  c.strainRate = readExact(file, group + "/strain_rate", shape);
  c.viscosity = readExact(file, group + "/viscosity", shape);
  c.frictionM = readExact(file, group + "/friction_m", shape);
  const std::string validName = group + "/valid";
  if (!file.isDataset(validName))
    throw fileError(file, "missing dataset '" + validName + "'");
  std::vector<hsize_t> validShape;
  fields.valid = file.readDataset<std::uint8_t>(validName, &validShape);
  if (validShape != shape)
    throw fileError(file, "dataset '" + validName + "' does not match the grid's shape");
  return fields;
}

WallProfile readWallProfile(const std::string& path, double omega, double drumRadius) {
  const io::H5File file = io::H5File::openRead(path);
  const auto read = [&](const std::string& name) {
    const std::string dataset = "/wall/" + name;
    if (!file.isDataset(dataset))
      throw fileError(file, "missing dataset '" + dataset + "'");
    return file.readDataset<double>(dataset);
  };
  const std::vector<double> theta = read("theta_centres");
  WallProfile w;
  w.normalStress = read("normal_stress");
  w.shearStress = read("shear_stress");
  const std::vector<double> speed = read("tangential_velocity");
  if (w.normalStress.size() != theta.size() || w.shearStress.size() != theta.size() ||
      speed.size() != theta.size())
    throw fileError(file, "the /wall datasets differ in length from '/wall/theta_centres'");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double degreesPerRadian = 180.0 / std::acos(-1.0);
  const double shellSpeed = omega * drumRadius;
  for (std::size_t i = 0; i < theta.size(); ++i) {
    w.thetaDeg.push_back(theta[i] * degreesPerRadian);
    w.ratio.push_back(w.normalStress[i] > 0.0 ? w.shearStress[i] / w.normalStress[i] : nan);
    w.slipPercent.push_back(shellSpeed != 0.0 ? 100.0 * (1.0 - speed[i] / shellSpeed) : nan);
  }
  return w;
}

calibration::CalibrationRun readRunHeader(const std::string& path) {
  const io::H5File file = io::H5File::openRead(path);
  calibration::CalibrationRun run;
  run.path = path;
  calibration::RunConditions& c = run.conditions;
  c.omega = requireDouble(file, "/", "omega");
  c.drumRadius = requireDouble(file, "/", "drum_radius");
  c.particleDiameter = requireDouble(file, "/", "particle_diameter");
  c.particleDensity = requireDouble(file, "/", "particle_density");
  c.fill = requireDouble(file, "/", "fill");
  // Provenance only: absent values stay NaN / 0 rather than failing the calibration.
  if (file.hasAttribute("/", "average_start"))
    c.averageStart = file.readDoubleAttribute("/", "average_start");
  if (file.hasAttribute("/", "average_end"))
    c.averageEnd = file.readDoubleAttribute("/", "average_end");
  if (file.hasAttribute("/", "samples"))
    c.samples = file.readInt64Attribute("/", "samples");
  if (!file.exists("/wall"))
    throw fileError(file, "missing group '/wall'");
  run.muWall = requireDouble(file, "/wall", "mu_wall");
  run.slipPercent = requireDouble(file, "/wall", "slip_percent");
  return run;
}

} // namespace hikiln::calibrate
