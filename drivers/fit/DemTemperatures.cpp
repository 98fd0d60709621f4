#include "drivers/fit/DemTemperatures.hpp"

#include "drivers/io/Hdf5File.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hikiln::fit {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& file, const std::string& reason) {
  throw std::runtime_error(file.string() + ": " + reason);
}

/// time - rotation_time of the first row of heat_timeseries.csv: when the rotation started.
double rotationStart(const fs::path& csv) {
  std::ifstream in(csv);
  if (!in)
    fail(csv, "cannot be read (is this a `hikiln dem` run with heat.enabled: true?)");
  std::string header, row;
  std::getline(in, header);
  if (header.rfind("time,rotation_time,", 0) != 0)
    fail(csv, "does not start with the columns time,rotation_time");
  if (!std::getline(in, row))
    fail(csv, "has no rows");
  std::istringstream fields(row);
  std::string time, rotation;
  std::getline(fields, time, ',');
  std::getline(fields, rotation, ',');
  return std::stod(time) - std::stod(rotation);
}

ParticleTemperatureSnapshot readSnapshot(const fs::path& file, double offset) {
  const auto h5 = io::H5File::openRead(file.string());
  const auto groups = h5.children("/");
  if (groups.size() != 1)
    fail(file, "expected one step group");
  const std::string g = "/" + groups.front();
  ParticleTemperatureSnapshot s;
  s.rotationTime = h5.readDoubleAttribute("/", "time") - offset;
  if (s.rotationTime < -1e-9)
    return s; // before the rotation (and the heat) started: not used
  if (!h5.isDataset(g + "/temperature"))
    fail(file, "has no temperature dataset (written without heat)");
  const auto position = h5.readDataset<double>(g + "/position");
  s.radius = h5.readDataset<double>(g + "/radius");
  s.temperature = h5.readDataset<double>(g + "/temperature");
  const std::size_t n = s.radius.size();
  if (position.size() != 2 * n || s.temperature.size() != n)
    fail(file, "position, radius and temperature have different particle counts");
  s.kind = h5.isDataset(g + "/kind") ? h5.readDataset<std::uint8_t>(g + "/kind")
                                     : std::vector<std::uint8_t>(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    s.x.push_back(position[2 * i]);
    s.y.push_back(position[2 * i + 1]);
  }
  return s;
}

} // namespace

DemThermalRun readDemThermalRun(const std::string& directory) {
  const fs::path dir(directory);
  if (!fs::is_directory(dir))
    fail(dir, "is not a directory (expected a `hikiln dem` run directory)");
  DemThermalRun run;
  run.directory = directory;
  const fs::path resolved = dir / "case.resolved.yaml";
  if (!fs::exists(resolved))
    fail(resolved, "missing (expected a `hikiln dem` run directory)");
  run.settings =
      dem::drumSettingsFromCase(cases::CaseFile::load(resolved.string(), dem::demSchema()));
  if (!run.settings.heat.enabled)
    fail(resolved, "heat.enabled is false: the run has no temperatures to fit against");
  if (run.settings.heat.initial != dem::InitialTemperatureKind::LeftRight)
    fail(resolved, "heat.initial must be left_right (physics.md 6.2 mixing runs)");
  const double offset = rotationStart(dir / "heat_timeseries.csv");
  std::vector<fs::path> files;
  if (fs::is_directory(dir / "snapshots")) {
    for (const auto& e : fs::directory_iterator(dir / "snapshots")) {
      if (e.path().extension() == ".h5")
        files.push_back(e.path());
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    ParticleTemperatureSnapshot s = readSnapshot(f, offset);
    if (s.rotationTime >= -1e-9)
      run.snapshots.push_back(std::move(s));
  }
  if (run.snapshots.size() < 2)
    fail(dir / "snapshots", "needs at least two snapshots taken during the rotation");
  return run;
}

} // namespace hikiln::fit
