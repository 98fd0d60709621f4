#include "drivers/dem/DrumHeat.hpp"

#include "drivers/calibrate/PlotScript.hpp"
#include "drivers/dem/DemCheckpoint.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <stdexcept>

namespace hikiln::dem {

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> seriesColumns = {"time",
                                                "rotation_time",
                                                "heat_time",
                                                "heat_energy_J",
                                                "energy_drift",
                                                "mean_temperature_K",
                                                "std_temperature_K",
                                                "mixing",
                                                "min_temperature_K",
                                                "max_temperature_K",
                                                "environment_heat_J"};

// Row of each id of `ids` (sorted) in `rowIds` (any order); throws if one is missing.
std::vector<std::size_t> rowsOf(const std::vector<std::int64_t>& ids,
                                const std::vector<std::int64_t>& rowIds) {
  std::vector<std::size_t> order(rowIds.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return rowIds[a] < rowIds[b]; });
  if (order.size() != ids.size())
    throw std::logic_error("hikiln::dem::DrumHeat: particle count changed");
  for (std::size_t r = 0; r < order.size(); ++r) {
    if (rowIds[order[r]] != ids[r])
      throw std::logic_error("hikiln::dem::DrumHeat: particle ids changed");
  }
  return order;
}

nlohmann::json finiteOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nullptr;
}

} // namespace

DrumHeat::DrumHeat(DrumHeatSettings settings, std::string outputDirectory)
    : _settings(std::move(settings)), _directory(std::move(outputDirectory)),
      _series((fs::path(_directory) / "heat_timeseries.csv").string(), seriesColumns) {}

std::vector<std::string> DrumHeat::snapshotFieldNames() const {
  if (!enabled())
    return {};
  return {"temperature", "surface_temperature"};
}

void DrumHeat::capacities(const DemSystem<Space>& system) {
  const auto host = system.hostParticles();
  std::vector<std::int64_t> rowIds(host.count());
  for (std::size_t i = 0; i < host.count(); ++i)
    rowIds[i] = host.id(i);
  _ids = rowIds;
  std::sort(_ids.begin(), _ids.end());
  const auto order = rowsOf(_ids, rowIds);
  _capacity.resize(order.size());
  _inBed.resize(order.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    _capacity[r] = host.mass(order[r]) * _settings.parameters.specificHeat;
    _inBed[r] = isFree(host.kind(order[r])) ? 1 : 0;
  }
}

void DrumHeat::start(const DemSystem<Space>& system, double time) {
  if (!enabled())
    return;
  _heat = std::make_unique<DemHeat<Space>>(_settings.parameters);
  _heat->initialize(system, _settings.initialField());
  capacities(system);
  _lastHeatStep = system.stepCount();
  _initialStd = 0.0;
  _initialEnergy = 0.0;
  const BedHeatMeasures m = measure(); // with zero references: energy and std only
  _initialEnergy = m.energy;
  _initialStd = m.stdTemperature;
  spdlog::info("heat: {} particles x {} shells, every {} steps (sub-step limit {:.3g} s); mean "
               "{:.1f} K, std {:.1f} K, energy {:.6g} J",
               _heat->size(), _settings.parameters.shells, _settings.stepEvery,
               _heat->stableTimeStep(), m.meanTemperature, m.stdTemperature, m.energy);
  sample(system, time);
}

void DrumHeat::resume(const io::Checkpoint& cp, const DemSystem<Space>& system) {
  if (!enabled())
    return;
  if (!hasHeatState(cp))
    throw std::runtime_error("the checkpoint holds no heat state (written with heat.enabled: "
                             "false); start the run again without --restart");
  _heat = std::make_unique<DemHeat<Space>>(_settings.parameters);
  _heat->importState(system, heatStateFromCheckpoint(cp));
  capacities(system);
  _lastHeatStep = static_cast<std::int64_t>(cp.scalars.at("heat_last_step"));
  _initialEnergy = cp.scalars.at("heat_energy_reference");
  _initialStd = cp.scalars.at("heat_std_reference");
  _equilibriumTime = cp.scalars.at("heat_equilibrium_time");
  _maxDrift = cp.scalars.at("heat_max_drift");
  _series.keepUntil(cp.time);
  _last = measure();
}

void DrumHeat::advance(DemSystem<Space>& system, std::int64_t steps) {
  if (!_heat) {
    system.advance(steps);
    return;
  }
  const std::int64_t every = _settings.stepEvery;
  while (steps > 0) {
    const std::int64_t n = std::min(steps, every - system.stepCount() % every);
    system.advance(n);
    steps -= n;
    if (system.stepCount() % every == 0) {
      const auto t0 = std::chrono::steady_clock::now();
      _heat->step(system,
                  static_cast<double>(system.stepCount() - _lastHeatStep) * system.timeStep());
      _lastHeatStep = system.stepCount();
      _wallSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
  }
}

BedHeatMeasures DrumHeat::measure() const {
  const ParticleTemperatures t = _heat->hostTemperatures();
  const auto order = rowsOf(_ids, t.id);
  BedHeatMeasures m;
  double bedEnergy = 0.0, bedCapacity = 0.0, sum = 0.0, n = 0.0;
  m.minTemperature = std::numeric_limits<double>::infinity();
  m.maxTemperature = -m.minTemperature;
  for (std::size_t r = 0; r < order.size(); ++r) {
    const double ti = t.mean[order[r]];
    m.energy += _capacity[r] * ti;
    if (!_inBed[r])
      continue;
    bedEnergy += _capacity[r] * ti;
    bedCapacity += _capacity[r];
    sum += ti;
    n += 1.0;
    m.minTemperature = std::min(m.minTemperature, ti);
    m.maxTemperature = std::max(m.maxTemperature, ti);
  }
  double square = 0.0;
  for (std::size_t r = 0; r < order.size(); ++r) {
    const double d = t.mean[order[r]] - sum / n;
    square += _inBed[r] ? d * d : 0.0;
  }
  m.meanTemperature = bedEnergy / bedCapacity;
  m.stdTemperature = std::sqrt(square / n);
  m.environmentHeat = _settings.parameters.environmentExchange ? _heat->environmentHeat() : 0.0;
  if (_initialEnergy > 0.0)
    m.drift = (m.energy - m.environmentHeat - _initialEnergy) / _initialEnergy;
  if (_initialStd > 0.0)
    m.mixing = m.stdTemperature / _initialStd;
  return m;
}

void DrumHeat::sample(const DemSystem<Space>& system, double time) {
  if (!_heat)
    return;
  _last = measure();
  _maxDrift = std::max(_maxDrift, std::fabs(_last.drift));
  if (!std::isfinite(_equilibriumTime) && _last.mixing < _settings.equilibriumThreshold) {
    _equilibriumTime = time;
    spdlog::info("heat: thermal equilibrium (mixing {:.3g} < {}) at {:.2f} s of rotation",
                 _last.mixing, _settings.equilibriumThreshold, time);
  }
  _series.add({system.time(), time, _heat->time(), _last.energy, _last.drift, _last.meanTemperature,
               _last.stdTemperature, _last.mixing, _last.minTemperature, _last.maxTemperature,
               _last.environmentHeat});
}

ParticleTemperatures
DrumHeat::inParticleOrder(const ParticleArrays<Kokkos::HostSpace>& particles) const {
  const ParticleTemperatures t = _heat->hostTemperatures();
  ParticleTemperatures out;
  for (std::size_t i = 0; i < particles.count(); ++i)
    out.id.push_back(particles.id(i));
  // rank of each particle row and of each temperature row in id order
  const auto particleOrder = rowsOf(_ids, out.id);
  const auto heatOrder = rowsOf(_ids, t.id);
  out.mean.resize(out.id.size());
  out.surface.resize(out.id.size());
  out.centre.resize(out.id.size());
  for (std::size_t r = 0; r < particleOrder.size(); ++r) {
    out.mean[particleOrder[r]] = t.mean[heatOrder[r]];
    out.surface[particleOrder[r]] = t.surface[heatOrder[r]];
    out.centre[particleOrder[r]] = t.centre[heatOrder[r]];
  }
  return out;
}

std::vector<double>
DrumHeat::meanTemperatures(const ParticleArrays<Kokkos::HostSpace>& particles) const {
  return _heat ? inParticleOrder(particles).mean : std::vector<double>();
}

std::vector<ParticleField>
DrumHeat::snapshotFields(const ParticleArrays<Kokkos::HostSpace>& particles) const {
  if (!_heat)
    return {};
  ParticleTemperatures t = inParticleOrder(particles);
  return {{"temperature", "K", std::move(t.mean)},
          {"surface_temperature", "K", std::move(t.surface)}};
}

void DrumHeat::save(io::Checkpoint& cp) const {
  if (!_heat)
    return;
  addHeatState(cp, _heat->exportState());
  cp.scalars["heat_last_step"] = static_cast<double>(_lastHeatStep);
  cp.scalars["heat_energy_reference"] = _initialEnergy;
  cp.scalars["heat_std_reference"] = _initialStd;
  cp.scalars["heat_equilibrium_time"] = _equilibriumTime;
  cp.scalars["heat_max_drift"] = _maxDrift;
}

void DrumHeat::flush() const {
  if (_heat)
    _series.flush();
}

nlohmann::json DrumHeat::summary() const {
  nlohmann::json j;
  j["enabled"] = enabled();
  if (!_heat)
    return j;
  const HeatParameters& p = _settings.parameters;
  j["shells"] = p.shells;
  j["step_every"] = _settings.stepEvery;
  j["mechanisms"] = {{"internal_conduction", p.shells > 1},
                     {"contact_conduction", p.contactConduction},
                     {"radiation", p.radiation},
                     {"environment_exchange", p.environmentExchange}};
  j["heat_energy_initial_J"] = _initialEnergy;
  j["heat_energy_J"] = _last.energy;
  j["heat_energy_drift_relative"] = _last.drift;
  j["heat_energy_drift_max_relative"] = _maxDrift;
  if (p.environmentExchange)
    j["environment_heat_J"] = _last.environmentHeat;
  j["mean_temperature_K"] = _last.meanTemperature;
  j["min_temperature_K"] = _last.minTemperature;
  j["max_temperature_K"] = _last.maxTemperature;
  j["std_temperature_initial_K"] = _initialStd;
  j["std_temperature_K"] = _last.stdTemperature;
  j["mixing_measure"] = finiteOrNull(_last.mixing);
  j["equilibrium_threshold"] = _settings.equilibriumThreshold;
  j["time_to_equilibrium_s"] = finiteOrNull(_equilibriumTime);
  j["heat_time_s"] = _heat->time();
  j["heat_sub_steps"] = _heat->subStepCount();
  j["heat_sub_step_limit_s"] = _heat->stableTimeStep();
  j["heat_wall_time_s"] = _wallSeconds;
  j["timeseries"] = "heat_timeseries.csv";
  return j;
}

bool DrumHeat::plot(double drumRadius) const {
  if (!_heat)
    return false;
  const fs::path dir(_directory);
  return calibrate::runPlotScript(calibrate::plotScriptPath("plot_temperature.py"),
                                  "--run " + calibrate::shellQuote(dir.string()) + " --out " +
                                      calibrate::shellQuote((dir / "plots").string()) +
                                      fmt::format(" --drum-radius {}", drumRadius),
                                  "matplotlib, numpy, h5py", "temperature maps");
}

} // namespace hikiln::dem
