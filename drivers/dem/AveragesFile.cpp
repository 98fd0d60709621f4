#include "drivers/dem/AveragesFile.hpp"

#include "drivers/io/Xdmf.hpp"

#include <cmath>
#include <filesystem>
#include <vector>

namespace hikiln::dem {

namespace fs = std::filesystem;

namespace {

// An alias, not `std::vector<double> CellFields::*values`: nvcc hands g++ that declarator with
// parentheses added, which -Wparentheses rejects.
using CellFieldMember = std::vector<double> CellFields::*;

/// One cell field of docs/averaged-fields.md.
struct FieldEntry {
  const char* name;
  CellFieldMember values;
  const char* units;
};

const std::vector<FieldEntry>& cellFieldTable() {
  static const std::vector<FieldEntry> table = {
      {"volume_fraction", &CellFields::volumeFraction, "1"},
      {"velocity_x", &CellFields::velocityX, "m/s"},
      {"velocity_y", &CellFields::velocityY, "m/s"},
      {"kinetic_stress_xx", &CellFields::kineticXX, "Pa"},
      {"kinetic_stress_xy", &CellFields::kineticXY, "Pa"},
      {"kinetic_stress_yy", &CellFields::kineticYY, "Pa"},
      {"contact_stress_xx", &CellFields::contactXX, "Pa"},
      {"contact_stress_xy", &CellFields::contactXY, "Pa"},
      {"contact_stress_yx", &CellFields::contactYX, "Pa"},
      {"contact_stress_yy", &CellFields::contactYY, "Pa"},
      {"granular_temperature", &CellFields::granularTemperature, "m2/s2"},
      {"strain_rate", &CellFields::strainRate, "1/s"},
      {"pressure", &CellFields::pressure, "Pa"},
      {"shear_stress", &CellFields::shearStress, "Pa"},
      {"viscosity", &CellFields::viscosity, "Pa s"},
      {"friction_m", &CellFields::frictionM, "1"},
      {"particles_per_sample", &CellFields::particlesPerSample, "1"}};
  return table;
}

void writeCellFields(io::H5File& file, const std::string& group, const CellFields& f) {
  const std::vector<hsize_t> shape = {f.slow, f.fast};
  for (const FieldEntry& e : cellFieldTable())
    file.writeDataset(group + "/" + e.name, f.*(e.values), shape, e.units);
  file.writeDataset(group + "/valid", f.valid, shape, "1");
  if (!f.temperature.empty())
    file.writeDataset(group + "/temperature", f.temperature, shape, "K");
}

void writePolar(io::H5File& file, const AveragedFields& a) {
  const cg::PolarGrid& g = a.polarGrid;
  std::vector<double> rEdges, thetaEdges, centroid;
  for (int i = 0; i <= g.nr; ++i)
    rEdges.push_back(g.rEdge(i));
  for (int i = 0; i <= g.ntheta; ++i)
    thetaEdges.push_back(g.thetaEdge(i));
  for (int i = 0; i < g.nr; ++i)
    centroid.push_back(g.centroidRadius(i));
  file.writeDataset("/polar/r_edges", rEdges, {rEdges.size()}, "m");
  file.writeDataset("/polar/theta_edges", thetaEdges, {thetaEdges.size()}, "rad");
  // where the strain rate places each ring's values (PolarGrid::centroidRadius)
  file.writeDataset("/polar/r_centroids", centroid, {centroid.size()}, "m");
  writeCellFields(file, "/polar", a.polar);
}

void writeCartesian(io::H5File& file, const AveragedFields& a) {
  const cg::CartesianGrid& g = a.cartesianGrid;
  std::vector<double> x, y;
  for (int i = 0; i < g.nx; ++i)
    x.push_back(g.xCentre(i));
  for (int i = 0; i < g.ny; ++i)
    y.push_back(g.yCentre(i));
  file.createGroup("/cartesian");
  file.setAttribute("/cartesian", "origin", std::vector<double>{g.x0, g.y0});
  file.setAttribute("/cartesian", "spacing", std::vector<double>{g.dx, g.dy});
  file.writeDataset("/cartesian/x_centres", x, {x.size()}, "m");
  file.writeDataset("/cartesian/y_centres", y, {y.size()}, "m");
  writeCellFields(file, "/cartesian", a.cartesian);
  // interleaved copy of the velocity for ParaView's vector glyphs (averages.xmf)
  const CellFields& f = a.cartesian;
  std::vector<double> velocity(2 * f.size());
  for (std::size_t c = 0; c < f.size(); ++c) {
    velocity[2 * c] = f.velocityX[c];
    velocity[2 * c + 1] = f.velocityY[c];
  }
  file.writeDataset("/cartesian/velocity", velocity, {f.slow, f.fast, 2}, "m/s");
}

void writeWall(io::H5File& file, const AveragedFields& a) {
  const WallFields& w = a.wall;
  const std::vector<hsize_t> shape = {w.thetaCentres.size()};
  file.writeDataset("/wall/theta_centres", w.thetaCentres, shape, "rad");
  file.writeDataset("/wall/normal_stress", w.normalStress, shape, "Pa");
  file.writeDataset("/wall/shear_stress", w.shearStress, shape, "Pa");
  file.writeDataset("/wall/tangential_velocity", w.tangentialVelocity, shape, "m/s");
  file.writeDataset("/wall/contacts_per_sample", w.contactsPerSample, shape, "1");
  file.setAttribute("/wall", "mu_wall", w.muWall);
  file.setAttribute("/wall", "slip_percent", w.slipPercent);
}

void writeXdmf(const std::string& xmfPath, const std::string& h5Path, const AveragedFields& a) {
  const cg::CartesianGrid& g = a.cartesianGrid;
  io::XdmfGridStep step;
  step.time = std::isfinite(a.averageEnd) ? a.averageEnd : 0.0;
  step.h5File = h5Path;
  step.group = "/cartesian";
  step.dim = 2;
  step.cells = {g.nx, g.ny, 1};
  step.origin = {g.x0, g.y0, 0.0};
  step.spacing = {g.dx, g.dy, 1.0};
  for (const FieldEntry& e : cellFieldTable())
    step.attributes.push_back({e.name, e.name});
  step.attributes.push_back({"velocity", "velocity", 2});
  step.attributes.push_back({"valid", "valid", 1, io::XdmfNumber::UInt8});
  if (!a.cartesian.temperature.empty())
    step.attributes.push_back({"temperature", "temperature"});
  io::writeXdmfGrids(xmfPath, {step});
}

} // namespace

std::string writeAveragesFile(const std::string& directory, const AveragedFields& fields,
                              const AveragesConditions& conditions, const io::RunInfo& info) {
  const std::string path = (fs::path(directory) / "averages.h5").string();
  io::H5File file = io::H5File::create(path);
  io::writeStandardAttributes(file, info);
  file.setAttribute("/", "average_start", fields.averageStart);
  file.setAttribute("/", "average_end", fields.averageEnd);
  file.setAttribute("/", "samples", static_cast<std::int64_t>(fields.samples));
  file.setAttribute("/", "drum_radius", fields.polarGrid.radius);
  file.setAttribute("/", "omega", conditions.omega);
  file.setAttribute("/", "particle_diameter", conditions.particleDiameter);
  file.setAttribute("/", "particle_density", conditions.particleDensity);
  file.setAttribute("/", "fill", conditions.fill);
  file.setAttribute("/", "slice_thickness", fields.thickness);
  file.setAttribute("/", "min_volume_fraction", fields.minVolumeFraction);
  file.setAttribute("/", "min_particle_samples",
                    static_cast<std::int64_t>(fields.minParticleSamples));
  file.setAttribute("/", "stress_sign", "compressive positive");
  writePolar(file, fields);
  writeCartesian(file, fields);
  writeWall(file, fields);
  file.commit();
  writeXdmf((fs::path(directory) / "averages.xmf").string(), path, fields);
  return path;
}

} // namespace hikiln::dem
