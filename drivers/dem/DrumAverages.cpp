#include "drivers/dem/DrumAverages.hpp"

#include "drivers/calibrate/PlotScript.hpp"
#include "drivers/dem/AveragesFile.hpp"
#include "solvers/dem/DrumShapes.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <utility>

namespace hikiln::dem {

namespace fs = std::filesystem;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t historyColumns = 9; // AveragesConvergence, in declaration order

double relativeChange(double now, double before) {
  return std::isfinite(before) && before != 0.0 ? std::fabs(now - before) / std::fabs(before) : nan;
}

// Mean diameter summed in sorted order: the same value whatever the particle order (restarts).
// Blocky particles: the equal-area diameter (radius holds the bounding radius).
double meanDiameterOf(const ParticleArrays<Kokkos::HostSpace>& bed,
                      const ParticleShapeSpec& shape) {
  const double boundingOverEqualArea = boundingRadiusRatio(shape);
  std::vector<double> d;
  for (std::size_t i = 0; i < bed.count(); ++i)
    if (isFree(bed.kind(i))) // a rough shell's glued discs are not bed
      d.push_back(2.0 * bed.radius(i) / boundingOverEqualArea);
  std::sort(d.begin(), d.end());
  double sum = 0.0;
  for (double v : d)
    sum += v;
  return d.empty() ? 0.0 : sum / static_cast<double>(d.size());
}

} // namespace

DrumAverages::DrumAverages(const DrumRunSettings& settings, std::string outputDirectory,
                           io::RunInfo info)
    : _run(settings), _directory(std::move(outputDirectory)), _info(std::move(info)) {}

void DrumAverages::create(double thickness, double meanDiameter, double fill) {
  AveragingSettings s;
  s.drumRadius = _run.fill.drumRadius;
  s.thickness = thickness;
  _meanDiameter = meanDiameter;
  _fill = fill;
  _averager = std::make_unique<FieldAverager<Space>>(s);
}

void DrumAverages::start(const ParticleArrays<Kokkos::HostSpace>& bed, double fill) {
  const double d = meanDiameterOf(bed, _run.fill.shape);
  create(_run.fill.convention == MassConvention::Sphere ? d : _run.fill.thickness, d, fill);
  _history.clear();
}

void DrumAverages::resume(const io::Checkpoint& cp, const ParticleArrays<Kokkos::HostSpace>& bed,
                          double fill) {
  if (cp.scalars.count("averages_samples") == 0) {
    spdlog::warn("the checkpoint holds no averaged fields (an older run): the averages start now");
    start(bed, fill);
    return;
  }
  create(cp.scalars.at("averages_thickness"), cp.scalars.at("averages_mean_diameter"), fill);
  AveragingSums sums;
  sums.polar = cp.reals.at("averages_polar");
  sums.cartesian = cp.reals.at("averages_cartesian");
  sums.wall = cp.reals.at("averages_wall");
  sums.samples = static_cast<std::int64_t>(cp.scalars.at("averages_samples"));
  sums.slipSum = cp.scalars.at("averages_slip_sum");
  sums.slipSamples = static_cast<std::int64_t>(cp.scalars.at("averages_slip_samples"));
  sums.firstTime = cp.scalars.at("averages_first_time");
  sums.lastTime = cp.scalars.at("averages_last_time");
  _averager->restore(sums);
  if (cp.reals.count("averages_temperature_polar") != 0) {
    _temperaturePolar = cp.reals.at("averages_temperature_polar");
    _temperatureCartesian = cp.reals.at("averages_temperature_cartesian");
  }
  const std::vector<double>& h = cp.reals.at("averages_history");
  _history.clear();
  for (std::size_t r = 0; r + historyColumns <= h.size(); r += historyColumns) {
    AveragesConvergence c;
    c.time = h[r];
    c.samples = static_cast<std::int64_t>(h[r + 1]);
    c.pressure = h[r + 2];
    c.shearStress = h[r + 3];
    c.frictionM = h[r + 4];
    c.muWall = h[r + 5];
    c.pressureChange = h[r + 6];
    c.shearStressChange = h[r + 7];
    c.frictionMChange = h[r + 8];
    _history.push_back(c);
  }
}

void DrumAverages::sample(const DemSystem<Space>& system, double time) {
  if (!_averager)
    throw std::logic_error("hikiln::dem::DrumAverages: sample() before start()/resume()");
  _averager->sample(system, time);
}

void DrumAverages::sampleTemperature(const ParticleArrays<Kokkos::HostSpace>& particles,
                                     const std::vector<double>& temperature) {
  if (!_averager)
    throw std::logic_error("hikiln::dem::DrumAverages: sample before start()/resume()");
  const cg::PolarGrid polar = _averager->settings().polarGrid();
  const cg::CartesianGrid cartesian = _averager->settings().cartesianGrid();
  _temperaturePolar.resize(2 * static_cast<std::size_t>(polar.cellCount()), 0.0);
  _temperatureCartesian.resize(2 * static_cast<std::size_t>(cartesian.cellCount()), 0.0);
  for (std::size_t i = 0; i < particles.count(); ++i) {
    const double x = particles.position(i, 0), y = particles.position(i, 1);
    const double m = particles.mass(i);
    for (auto [sums, cell] : {std::pair{&_temperaturePolar, polar.cellOf(x, y)},
                              std::pair{&_temperatureCartesian, cartesian.cellOf(x, y)}}) {
      (*sums)[2 * cell] += m;
      (*sums)[2 * cell + 1] += m * temperature.at(i);
    }
  }
}

void DrumAverages::write(double time) {
  if (!_averager || _averager->samples() == 0)
    return;
  if (_written && _last.samples == _averager->samples())
    return; // nothing new since the last write (the end of the run fell on an interval)
  _last = _averager->result();
  _written = true;
  for (auto [sums, fields] : {std::pair{&_temperaturePolar, &_last.polar},
                              std::pair{&_temperatureCartesian, &_last.cartesian}}) {
    for (std::size_t c = 0; 2 * c < sums->size(); ++c)
      fields->temperature.push_back((*sums)[2 * c] > 0 ? (*sums)[2 * c + 1] / (*sums)[2 * c] : nan);
  }
  const AveragesConditions conditions{_run.omega(), _meanDiameter, _run.fill.density, _fill};
  writeAveragesFile(_directory, _last, conditions, _info);
  const BedAverage bed = bedAverage(_last.cartesian);
  AveragesConvergence c;
  c.time = time;
  c.samples = _last.samples;
  c.pressure = bed.pressure;
  c.shearStress = bed.shearStress;
  c.frictionM = bed.frictionM;
  c.muWall = _last.wall.muWall;
  const AveragesConvergence before =
      _history.empty() ? AveragesConvergence{0, 0, nan, nan, nan, nan, nan, nan, nan}
                       : _history.back();
  c.pressureChange = relativeChange(c.pressure, before.pressure);
  c.shearStressChange = relativeChange(c.shearStress, before.shearStress);
  c.frictionMChange = relativeChange(c.frictionM, before.frictionM);
  _history.push_back(c);
  spdlog::info("averages: {} samples to {:.1f} s, {} valid cells; bed p {:.4g} Pa, q {:.4g} Pa, "
               "m {:.3f} (changes {:.1f} / {:.1f} / {:.1f} %), mu_wall {:.3f}, slip {:.1f} %",
               c.samples, time, bed.validCells, c.pressure, c.shearStress, c.frictionM,
               100 * c.pressureChange, 100 * c.shearStressChange, 100 * c.frictionMChange, c.muWall,
               _last.wall.slipPercent);
}

void DrumAverages::save(io::Checkpoint& cp) const {
  if (!_averager)
    return;
  const AveragingSums sums = _averager->sums();
  cp.reals["averages_polar"] = sums.polar;
  cp.reals["averages_cartesian"] = sums.cartesian;
  cp.reals["averages_wall"] = sums.wall;
  cp.scalars["averages_samples"] = static_cast<double>(sums.samples);
  cp.scalars["averages_slip_sum"] = sums.slipSum;
  cp.scalars["averages_slip_samples"] = static_cast<double>(sums.slipSamples);
  cp.scalars["averages_first_time"] = sums.firstTime;
  cp.scalars["averages_last_time"] = sums.lastTime;
  cp.scalars["averages_thickness"] = _averager->settings().thickness;
  cp.scalars["averages_mean_diameter"] = _meanDiameter;
  std::vector<double> h;
  for (const AveragesConvergence& c : _history) {
    for (double v : {c.time, static_cast<double>(c.samples), c.pressure, c.shearStress, c.frictionM,
                     c.muWall, c.pressureChange, c.shearStressChange, c.frictionMChange})
      h.push_back(v);
  }
  cp.reals["averages_history"] = h;
  if (!_temperaturePolar.empty()) {
    cp.reals["averages_temperature_polar"] = _temperaturePolar;
    cp.reals["averages_temperature_cartesian"] = _temperatureCartesian;
  }
}

nlohmann::json DrumAverages::summary() const {
  nlohmann::json j;
  j["samples"] = _averager ? _averager->samples() : 0;
  if (!_written) {
    j["file"] = nullptr;
    return j;
  }
  const BedAverage polar = bedAverage(_last.polar), cartesian = bedAverage(_last.cartesian);
  j["file"] = "averages.h5";
  j["average_start_s"] = _last.averageStart;
  j["average_end_s"] = _last.averageEnd;
  j["slice_thickness_m"] = _last.thickness;
  j["mu_wall"] = _last.wall.muWall;
  j["slip_percent"] = _last.wall.slipPercent;
  j["valid_cells"] = {{"polar", polar.validCells}, {"cartesian", cartesian.validCells}};
  j["bed_pressure_pa"] = cartesian.pressure;
  j["bed_shear_stress_pa"] = cartesian.shearStress;
  j["bed_friction_m"] = cartesian.frictionM;
  nlohmann::json history = nlohmann::json::array();
  for (const AveragesConvergence& c : _history) {
    history.push_back({{"time_s", c.time},
                       {"samples", c.samples},
                       {"pressure_pa", c.pressure},
                       {"shear_stress_pa", c.shearStress},
                       {"friction_m", c.frictionM},
                       {"mu_wall", c.muWall},
                       {"relative_change_pressure", c.pressureChange},
                       {"relative_change_shear_stress", c.shearStressChange},
                       {"relative_change_friction_m", c.frictionMChange}});
  }
  j["convergence"] = history;
  return j;
}

bool DrumAverages::plot() const {
  if (!_written)
    return false;
  const fs::path dir(_directory);
  return calibrate::runPlotScript(calibrate::plotScriptPath("plot_fields.py"),
                                  "--h5 " + calibrate::shellQuote((dir / "averages.h5").string()) +
                                      " --out " + calibrate::shellQuote((dir / "plots").string()),
                                  "matplotlib, numpy, h5py", "field maps");
}

} // namespace hikiln::dem
