// Reads what `hikiln compare` needs of a continuum run: its field outputs (fields_NNNN.h5, written
// by `hikiln continuum`), time-averaged on the run's own grid, and its wall slip.
#include "drivers/compare/CompareInputs.hpp"
#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Summary.hpp"
#include "kernels/cfd/ShellGeometry.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace hikiln::compare {

namespace fs = std::filesystem;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::runtime_error fileError(const std::string& path, const std::string& what) {
  return std::runtime_error("continuum output '" + path + "': " + what);
}

std::vector<fs::path> fieldOutputs(const fs::path& dir) {
  static const std::regex name(R"(fields_[0-9]+\.h5)");
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), name))
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<double> readField(const io::H5File& file, const std::string& name,
                              const std::vector<hsize_t>& shape) {
  const std::string path = "/fields/" + name;
  if (!file.isDataset(path))
    throw fileError(file.path(), "missing dataset '" + path + "'");
  std::vector<hsize_t> dims;
  std::vector<double> values = file.readDataset<double>(path, &dims);
  if (dims != shape)
    throw fileError(file.path(), "dataset '" + path + "' does not have the grid's shape");
  return values;
}

double slipAfterOf(const std::string& yaml, const std::string& path) {
  try {
    return YAML::Load(yaml)["time"]["slip_after"].as<double>();
  } catch (const YAML::Exception&) {
    throw fileError(path, "the resolved case has no number time.slip_after");
  }
}

int cellsOf(const std::string& yaml, const std::string& path) {
  try {
    return YAML::Load(yaml)["grid"]["cells"].as<int>();
  } catch (const YAML::Exception&) {
    throw fileError(path, "the resolved case has no integer grid.cells");
  }
}

// Columns `time` and `wall_slip` of timeseries.csv, one entry per row (empty when unreadable).
void readSlipSeries(const fs::path& csv, std::vector<double>& times, std::vector<double>& slips) {
  std::ifstream in(csv);
  std::string header, line;
  if (!std::getline(in, header))
    return;
  std::vector<std::string> names;
  std::stringstream columns(header);
  for (std::string name; std::getline(columns, name, ',');)
    names.push_back(name);
  while (std::getline(in, line)) {
    std::stringstream values(line);
    double time = nan, slip = nan;
    std::string value;
    for (std::size_t k = 0; k < names.size() && std::getline(values, value, ','); ++k) {
      if (names[k] == "time")
        time = std::strtod(value.c_str(), nullptr);
      if (names[k] == "wall_slip")
        slip = std::strtod(value.c_str(), nullptr);
    }
    times.push_back(time);
    slips.push_back(slip);
  }
}

// The wall slip over the same outputs as the fields (timeseries.csv has a row per output after
// the first); summary.json's value when there is no time series.
void readSlip(ContinuumRun& run) {
  run.slipPercent = nan;
  run.slipSource = "none (no timeseries.csv rows for the averaged outputs, no summary.json value)";
  std::vector<double> times, slips;
  readSlipSeries(fs::path(run.directory) / "timeseries.csv", times, slips);
  double sum = 0.0;
  int count = 0;
  for (double t : run.averagedTimes)
    for (std::size_t k = 0; k < times.size(); ++k)
      if (std::fabs(times[k] - t) <= 1e-6 * std::max(1.0, std::fabs(t)) &&
          std::isfinite(slips[k])) {
        sum += slips[k];
        ++count;
        break;
      }
  if (count > 0) {
    run.slipPercent = sum / count;
    run.slipSource =
        fmt::format("timeseries.csv wall_slip, mean over the {} averaged outputs", count);
    return;
  }
  const fs::path summary = fs::path(run.directory) / "summary.json";
  if (fs::is_regular_file(summary)) {
    const nlohmann::json s = io::readSummaryJson(summary.string());
    if (s.contains("wall_slip_percent") && s["wall_slip_percent"].is_number()) {
      run.slipPercent = s["wall_slip_percent"].get<double>();
      run.slipSource = "summary.json wall_slip_percent (mean over the outputs after slip_after)";
    }
  }
}

} // namespace

ContinuumRun readContinuumRun(const std::string& path) {
  ContinuumRun run;
  run.directory = path;
  const fs::path dir(path);
  if (!fs::is_directory(dir))
    throw std::runtime_error("continuum run '" + path + "' does not exist or is not a directory");
  const std::vector<fs::path> files = fieldOutputs(dir);
  if (files.empty())
    throw std::runtime_error(
        "continuum run directory '" + path + "' has no fields_NNNN.h5 (written by `hikiln " +
        "continuum`)" +
        (fs::exists(dir / "averages.h5")
             ? "; it holds averages.h5, a DEM run: the order is DEM_RUN CONTINUUM_RUN"
             : ""));

  std::string resolved;
  for (const fs::path& f : files) {
    const io::H5File file = io::H5File::openRead(f.string());
    if (!file.hasAttribute("/", "stage") || file.readStringAttribute("/", "stage") != "continuum")
      throw fileError(f.string(), "not written by `hikiln continuum` (root attribute stage)");
    if (!file.hasAttribute("/", "time"))
      throw fileError(f.string(), "missing attribute 'time' on '/'");
    run.outputTimes.push_back(file.readDoubleAttribute("/", "time"));
    if (resolved.empty() && file.hasAttribute("/", "resolved_case"))
      resolved = file.readStringAttribute("/", "resolved_case");
  }
  const std::string first = files.front().string();
  if (resolved.empty())
    throw fileError(first, "missing attribute 'resolved_case' on '/'");
  run.drum = drumOfResolvedCase(resolved, "continuum output '" + first + "'");
  run.slipAfter = slipAfterOf(resolved, first);
  const cfd::Grid g = cfd::drumGrid(cellsOf(resolved, first), run.drum.diameter);
  run.grid.nx = g.nx;
  run.grid.ny = g.ny;
  run.grid.dx = g.hx;
  run.grid.dy = g.hy;
  run.grid.x0 = g.x0;
  run.grid.y0 = g.y0;

  // The outputs after slip_after (as summary.json's wall slip; an output time that the step
  // sum lands a rounding error past slip_after counts as at it, not after it).
  std::vector<std::size_t> chosen;
  const double after = run.slipAfter + 1e-9 * std::max(1.0, run.slipAfter);
  for (std::size_t k = 0; k < files.size(); ++k)
    if (run.outputTimes[k] > after)
      chosen.push_back(k);
  if (!chosen.empty()) {
    run.averaging = fmt::format("mean of the {} outputs after time.slip_after = {:g} s (t = {:g} "
                                "to {:g} s): the developed flow, as the DEM averages after spin-up",
                                chosen.size(), run.slipAfter, run.outputTimes[chosen.front()],
                                run.outputTimes[chosen.back()]);
  } else {
    chosen.push_back(files.size() - 1);
    run.averaging = fmt::format("the last output only (t = {:g} s): no output is later than "
                                "time.slip_after = {:g} s",
                                run.outputTimes.back(), run.slipAfter);
  }

  const std::vector<hsize_t> shape = {static_cast<hsize_t>(g.ny), static_cast<hsize_t>(g.nx)};
  const std::size_t cells = static_cast<std::size_t>(g.nx) * g.ny;
  for (const char* key :
       {"volume_fraction", "momentum_x", "momentum_y", "bed_pressure", "shear_stress", "capacity"})
    run.means[key].assign(cells, 0.0);
  const double share = 1.0 / static_cast<double>(chosen.size());
  for (std::size_t k : chosen) {
    run.averagedTimes.push_back(run.outputTimes[k]);
    const io::H5File file = io::H5File::openRead(files[k].string());
    const std::vector<double> phi = readField(file, "volume_fraction", shape);
    const std::vector<double> pressure = readField(file, "bed_pressure", shape);
    const std::vector<double> shear = readField(file, "shear_stress", shape);
    const std::vector<double> capacity = readField(file, "capacity", shape);
    if (!file.isDataset("/fields/velocity"))
      throw fileError(file.path(), "missing dataset '/fields/velocity'");
    std::vector<hsize_t> dims;
    const std::vector<double> velocity = file.readDataset<double>("/fields/velocity", &dims);
    if (dims != std::vector<hsize_t>{shape[0], shape[1], 2})
      throw fileError(file.path(), "dataset '/fields/velocity' is not [ny][nx][2]");
    for (std::size_t c = 0; c < cells; ++c) {
      run.means["volume_fraction"][c] += share * phi[c];
      run.means["momentum_x"][c] += share * phi[c] * velocity[2 * c];
      run.means["momentum_y"][c] += share * phi[c] * velocity[2 * c + 1];
      run.means["bed_pressure"][c] += share * pressure[c];
      run.means["shear_stress"][c] += share * shear[c];
      run.means["capacity"][c] += share * capacity[c];
    }
  }
  readSlip(run);
  return run;
}

DrumConditions drumOfResolvedCase(const std::string& yaml, const std::string& what) {
  DrumConditions drum;
  try {
    const YAML::Node node = YAML::Load(yaml)["drum"];
    drum.diameter = node["diameter"].as<double>();
    drum.rpm = node["rpm"].as<double>();
    drum.fill = node["fill"].as<double>();
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(what +
                             ": the resolved case lacks drum.diameter, drum.rpm or "
                             "drum.fill (" +
                             e.what() + ")");
  }
  return drum;
}

void requireSameDrum(const DemRun& dem, const ContinuumRun& continuum) {
  const auto differs = [](double a, double b, double relative, double absolute) {
    return std::fabs(a - b) > relative * std::max(std::fabs(a), std::fabs(b)) + absolute;
  };
  std::string problems;
  const auto note = [&](const char* key, double a, double b, const char* unit) {
    problems += fmt::format("{}{} {:g}{} (DEM) vs {:g}{} (continuum)", problems.empty() ? "" : "; ",
                            key, a, unit, b, unit);
  };
  if (differs(dem.drum.diameter, continuum.drum.diameter, 1e-6, 0.0))
    note("drum.diameter", dem.drum.diameter, continuum.drum.diameter, " m");
  if (differs(dem.drum.rpm, continuum.drum.rpm, 1e-6, 0.0))
    note("drum.rpm", dem.drum.rpm, continuum.drum.rpm, " rpm");
  if (differs(dem.drum.fill, continuum.drum.fill, 0.0, 1e-6))
    note("drum.fill", dem.drum.fill, continuum.drum.fill, "");
  if (!problems.empty())
    throw std::runtime_error("DEM run '" + dem.directory + "' and continuum run '" +
                             continuum.directory + "' are not the same drum: " + problems);
}

} // namespace hikiln::compare
