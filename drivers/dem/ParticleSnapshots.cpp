#include "drivers/dem/ParticleSnapshots.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>

namespace hikiln::dem {

namespace fs = std::filesystem;

namespace {
std::vector<io::XdmfAttribute> snapshotAttributes() {
  return {{"velocity", "velocity", 2},
          {"angular_velocity", "angular_velocity", 1},
          {"radius", "radius", 1},
          {"id", "id", 1, io::XdmfNumber::Int64},
          {"kind", "kind", 1, io::XdmfNumber::UInt8}};
}
} // namespace

std::vector<ParticleField> shapeFields(const BlockyArrays<Kokkos::HostSpace>& shapes,
                                       std::size_t count) {
  if (shapes.capacity() == 0)
    return {};
  const std::vector<std::string> names = shapeFieldNames();
  const char* units[] = {"rad", "m", "m", "1"};
  std::vector<ParticleField> f(names.size());
  for (std::size_t k = 0; k < names.size(); ++k)
    f[k].name = names[k], f[k].unit = units[k];
  for (std::size_t i = 0; i < count; ++i) {
    f[0].values.push_back(shapes.orientation(i));
    f[1].values.push_back(shapes.shape(i).a);
    f[2].values.push_back(shapes.shape(i).b);
    f[3].values.push_back(shapes.shape(i).n);
  }
  return f;
}

std::vector<std::string> shapeFieldNames() {
  return {"orientation", "semi_axis_a", "semi_axis_b", "blockiness"};
}

ParticleSnapshots::ParticleSnapshots(std::string directory, io::RunInfo info, double keepUntil,
                                     const std::vector<std::string>& extraFields)
    : _directory(std::move(directory)), _info(std::move(info)) {
  const fs::path dir = fs::path(_directory) / "snapshots";
  fs::create_directories(dir);
  if (keepUntil < 0)
    return;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".h5" && e.path().filename().string().rfind("particles_", 0) == 0)
      files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    auto h5 = io::H5File::openRead(f.string());
    const double time = h5.readDoubleAttribute("/", "time");
    const auto step = h5.readInt64Attribute("/", "step");
    if (time > keepUntil)
      continue;
    io::XdmfParticleStep s;
    s.time = time;
    s.h5File = f.string();
    s.group = io::stepGroupName(step);
    s.count = static_cast<std::int64_t>(h5.datasetDims(s.group + "/position").at(0));
    s.attributes = snapshotAttributes();
    for (const std::string& name : extraFields) {
      if (h5.isDataset(s.group + "/" + name))
        s.attributes.push_back({name, name, 1});
    }
    _steps.push_back(s);
  }
}

void ParticleSnapshots::write(std::int64_t step, double time,
                              const ParticleArrays<Kokkos::HostSpace>& p,
                              const std::vector<ParticleField>& extra) {
  const std::size_t n = p.count();
  const std::string path =
      (fs::path(_directory) / "snapshots" / fmt::format("particles_{:09d}.h5", step)).string();
  const std::string g = io::stepGroupName(step);
  auto h5 = io::H5File::create(path);
  io::writeStandardAttributes(h5, _info);
  h5.setAttribute("/", "time", time);
  h5.setAttribute("/", "step", static_cast<std::int64_t>(step));
  std::vector<double> pos(2 * n), vel(2 * n), omega(n), radius(n);
  std::vector<std::int64_t> id(n);
  std::vector<std::uint8_t> kind(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int d = 0; d < 2; ++d) {
      pos[2 * i + d] = p.position(i, d);
      vel[2 * i + d] = p.velocity(i, d);
    }
    omega[i] = p.angularVelocity(i);
    radius[i] = p.radius(i);
    id[i] = p.id(i);
    kind[i] = p.kind(i);
  }
  h5.writeDataset(g + "/position", pos, {n, 2}, "m");
  h5.writeDataset(g + "/velocity", vel, {n, 2}, "m/s");
  h5.writeDataset(g + "/angular_velocity", omega, {n}, "rad/s");
  h5.writeDataset(g + "/radius", radius, {n}, "m");
  h5.writeDataset(g + "/id", id, {n}, "1");
  h5.writeDataset(g + "/kind", kind, {n}, "1"); // ParticleKind: 0 free, 1 fixed, 2 shell
  for (const ParticleField& f : extra)
    h5.writeDataset(g + "/" + f.name, f.values, {n}, f.unit);
  h5.commit();

  io::XdmfParticleStep s;
  s.time = time;
  s.h5File = path;
  s.group = g;
  s.count = static_cast<std::int64_t>(n);
  s.attributes = snapshotAttributes();
  for (const ParticleField& f : extra)
    s.attributes.push_back({f.name, f.name, 1});
  _steps.push_back(s);
  io::writeXdmfParticles((fs::path(_directory) / "particles.xmf").string(), _steps);
}

} // namespace hikiln::dem
