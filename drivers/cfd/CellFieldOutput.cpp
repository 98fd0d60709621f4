#include "drivers/cfd/CellFieldOutput.hpp"

#include <fmt/format.h>

namespace hikiln::cfd {

void writeCellFieldOutput(std::filesystem::path const& out, int index, double time, Grid const& g,
                          CellFieldOutput const& f, io::RunInfo const& info,
                          std::vector<io::XdmfGridStep>& steps) {
  const int dims = g.is3D() ? 3 : 2;
  const std::string name = fmt::format("fields_{:04d}.h5", index);
  io::H5File file = io::H5File::create((out / name).string());
  io::writeStandardAttributes(file, info);
  file.setAttribute("/", "time", time);
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    file.setAttribute("/", std::string("origin_") + axes[a],
                      a == 0 ? g.x0 : (a == 1 ? g.y0 : g.z0));
    file.setAttribute("/", std::string("spacing_") + axes[a], g.spacing(a));
  }
  std::vector<hsize_t> shape = {static_cast<hsize_t>(g.ny), static_cast<hsize_t>(g.nx)};
  if (dims == 3) {
    shape.insert(shape.begin(), static_cast<hsize_t>(g.nz));
  }
  static const std::map<std::string, std::string> units = {
      {"volume_fraction", "1"},  {"pressure", "Pa"},     {"bed_pressure", "Pa"},
      {"viscosity", "Pa s"},     {"strain_rate", "1/s"}, {"density", "kg/m^3"},
      {"capacity", "1"},         {"temperature", "K"},   {"shear_stress", "Pa"},
      {"axial_velocity", "m/s"}, {"tracer", "1"},        {"fluid_volume", "1"}};
  io::XdmfGridStep step;
  step.time = time;
  step.h5File = (out / name).string();
  step.group = "/fields";
  step.dim = dims;
  step.cells = {g.nx, g.ny, dims == 3 ? g.nz : 1};
  step.origin = {g.x0, g.y0, g.z0};
  step.spacing = {g.hx, g.hy, g.hz};
  for (auto const& [key, values] : f.scalars) {
    file.writeDataset("/fields/" + key, values, shape, units.at(key));
    step.attributes.push_back({key, key});
  }
  std::vector<hsize_t> vectorShape = shape;
  vectorShape.push_back(static_cast<hsize_t>(dims));
  file.writeDataset("/fields/velocity", f.velocity, vectorShape, "m/s");
  step.attributes.push_back({"velocity", "velocity", dims});
  file.commit();
  steps.push_back(step);
  io::writeXdmfGrids((out / "fields.xmf").string(), steps);
}

} // namespace hikiln::cfd
