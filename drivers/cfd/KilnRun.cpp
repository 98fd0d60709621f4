#include "drivers/cfd/KilnRun.hpp"

#include "drivers/app/Commands.hpp"
#include "drivers/case/CaseFile.hpp"
#include "drivers/cfd/CellFieldOutput.hpp"
#include "drivers/cfd/ContinuumCase.hpp"
#include "drivers/cfd/KilnBedProfile.hpp"
#include "drivers/cfd/KilnCase.hpp"
#include "drivers/cfd/StepStatistics.hpp"
#include "drivers/dem/TimeSeries.hpp"
#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Summary.hpp"
#include "drivers/io/Xdmf.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <Kokkos_Core.hpp>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace hikiln::cfd {

namespace {

namespace fs = std::filesystem;
using Space = Kokkos::DefaultExecutionSpace;
using Solver = TwoPhaseSolver<Space, KilnDomain>;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Peak resident memory of this process (bytes; 0 where /proc is not there).
double peakResidentBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) {
      std::istringstream in(line.substr(6));
      double kib = 0.0;
      in >> kib;
      return kib * 1024.0;
    }
  }
  return 0.0;
}

/// The cell fields of one output, with the cells' true open volume, the axial velocity (w at the
/// cell centres) for the rendered bed surface, the temperature (heat on) and the tracer (tracer <
/// 0: none).
CellFieldOutput gatherFields(Solver const& solver, int tracer) {
  CellFieldOutput out;
  out.addSolverFields(solver);
  out.add("fluid_volume", solver.cutCells().volume, solver.grid());
  out.add("temperature", solver.temperature(), solver.grid());
  if (tracer >= 0) {
    out.add("tracer", solver.tracerTemperature(tracer), solver.grid());
  }
  std::vector<double>& axial = out.scalars["axial_velocity"];
  axial.resize(out.velocity.size() / 3);
  for (std::size_t n = 0; n < axial.size(); ++n) {
    axial[n] = out.velocity[3 * n + 2];
  }
  return out;
}

/// Solids-weighted mean temperature of an output (sum capacity phi T / sum capacity phi; 0
/// without temperature).
double bedMeanTemperature(CellFieldOutput const& f) {
  const auto T = f.scalars.find("temperature");
  if (T == f.scalars.end()) {
    return 0.0;
  }
  std::vector<double> const& phi = f.scalars.at("volume_fraction");
  std::vector<double> const& cap = f.scalars.at("capacity");
  double weighted = 0.0, weight = 0.0;
  for (std::size_t n = 0; n < phi.size(); ++n) {
    weighted += cap[n] * phi[n] * T->second[n];
    weight += cap[n] * phi[n];
  }
  return weight > 0.0 ? weighted / weight : 0.0;
}

/// A passive tracer pulse in the feed and the residence time it gives: the mean time between
/// entering and leaving over the tagged solids that have left (the first moment of the
/// discharge rate less the pulse's mid-time), and the fraction that has left.
struct ResidenceTracer {
  int index = -1; ///< the solver's tracer; -1: none
  double start = 0.0, end = 0.0;
  double injected = 0.0, recovered = 0.0, firstMoment = 0.0;

  bool tagging(double t) const { return t >= start - 1e-12 && t < end - 1e-12; }
  void add(double t0, double dt, double in, double out) {
    injected += in;
    recovered += out;
    firstMoment += (t0 + 0.5 * dt) * out;
  }
  double meanResidenceTime() const {
    return recovered > 0.0 ? firstMoment / recovered - 0.5 * (start + end) : 0.0;
  }
};

/// Largest speed over the cells of an output.
double maxSpeed(CellFieldOutput const& f) {
  double speed = 0.0;
  for (std::size_t n = 0; n + 2 < f.velocity.size(); n += 3) {
    const double* v = &f.velocity[n];
    speed = std::max(speed, std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  }
  return speed;
}

/// The output times: every interval, and the snapshot times, up to the duration, sorted.
std::vector<double> outputTimes(KilnSettings const& s) {
  std::vector<double> times;
  for (int n = 1; n * s.outputInterval <= s.duration * (1.0 + 1e-12); ++n) {
    times.push_back(n * s.outputInterval);
  }
  for (double t : s.snapshots) {
    if (t > 0.0 && t <= s.duration) {
      times.push_back(t);
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end(),
                          [](double a, double b) { return std::fabs(a - b) < 1e-9; }),
              times.end());
  return times;
}

} // namespace

int runKiln(KilnRunOptions const& o) {
  const auto wallStart = Clock::now();
  const auto file = cases::CaseFile::load(o.caseFile, kilnSchema(), o.overrides);
  const KilnSettings s = kilnSettingsFromCase(file);
  const fs::path out(o.outputDirectory);
  fs::create_directories(out);
  file.writeResolved((out / "case.resolved.yaml").string());
  const io::RunInfo info{"kiln", app::defaultBackend(), file.resolvedYaml()};

  const Grid grid = kilnGrid(s);
  const bool damFromStart = s.damHeight > 0.0 && s.damOnAt <= 0.0;
  bool damPending = s.damHeight > 0.0 && !damFromStart;
  const KilnDomain domain = kilnDomain(s, damFromStart);
  CutCellOptions cut;
  cut.periodic[2] = false;
  OpenSides ends;
  ends.kind[ZLow] = BoundaryKind::Inflow;
  ends.kind[ZHigh] = BoundaryKind::Outflow;
  Solver solver(Space{}, grid, domain, s.params, cut, ends);
  solver.setFlatBed(flatBedLevel(0.5 * s.diameter, s.fill));
  solver.setInflow(domain.inlet);
  const bool heatOn = s.params.energy;
  if (heatOn) {
    Kokkos::deep_copy(solver.temperature(), s.initialTemperature);
    solver.setInflowTemperature(InflowTemperature{s.feedTemperature, s.airTemperature});
  }
  ResidenceTracer tracer;
  if (s.tracerDuration > 0.0) {
    // content = solids volume x concentration, carried, never diffused. The gas holds a trace
    // of it, in the heat's ratio of gas to solids heat capacity per volume (4.5e-4 with the
    // defaults): with none, a cell the bed has left holds no content and an undefined
    // concentration, and solids passing through it were tagged from nothing (a 1.2 m kiln
    // discharged 9x the tracer it was fed).
    ThermalParameters tagged;
    tagged.solidHeatCapacity = 1.0 / s.params.solidDensity;
    tagged.gasHeatCapacity = s.params.thermal.gasHeatCapacity /
                             (s.params.thermal.solidHeatCapacity * s.params.solidDensity);
    tagged.alphaEff = 0.0;
    tagged.gasConductivity = 0.0;
    tracer.index = solver.addTemperatureTracer(tagged);
    tracer.start = s.tracerStart;
    tracer.end = s.tracerStart + s.tracerDuration;
  }
  const double cellVolume = grid.hx * grid.hy * grid.hz;
  spdlog::info("kiln: {} x {} x {} cells (h = {:.3g} m across, {:.3g} m along), L = {} m, D = {} "
               "m, {} rpm, slope {} deg, fill {}, feed {:.3g} m3/s of solids, rheology from {}",
               grid.nx, grid.ny, grid.nz, grid.hx, grid.hz, s.length, s.diameter, s.rpm,
               s.slopeDegrees, s.fill,
               s.feedPacking * s.params.rheology.phiMax * s.feedVelocity * s.feedFraction *
                   constants::pi * 0.25 * s.diameter * s.diameter,
               s.rheologySource);

  const double solids0 = solver.solids();
  double displaced = 0.0, phiLo = 0.0, phiHi = 0.0, worstStep = 0.0;
  StepStatistics stats;
  std::vector<io::XdmfGridStep> outputs;
  std::vector<std::string> columns = {"time",
                                      "dt",
                                      "holdup_m3",
                                      "solids_in_m3",
                                      "solids_out_m3",
                                      "dam_displaced_m3",
                                      "balance_error_m3",
                                      "outflow_rate_m3_per_s",
                                      "max_speed"};
  if (heatOn) {
    for (char const* c : {"heat_J", "heat_in_J", "heat_out_J", "heat_from_shell_J",
                          "heat_balance_error_J", "bed_mean_temperature_K"}) {
      columns.emplace_back(c);
    }
  }
  if (tracer.index >= 0) {
    columns.emplace_back("tracer_in_m3");
    columns.emplace_back("tracer_out_m3");
  }
  dem::TimeSeries series((out / "timeseries.csv").string(), columns);
  const auto balanceError = [&] {
    return (solver.solids() - solids0 -
            (solver.solidsInTotal() - solver.solidsOutTotal() - displaced)) *
           cellVolume;
  };
  // heat (heat() units): in and out at the ends, from the shell, taken by the dam ring
  const double heat0 = solver.heat();
  double heatIn = 0.0, heatOut = 0.0, heatShell = 0.0, heatDisplaced = 0.0, worstHeatStep = 0.0;
  const auto heatBalanceError = [&] {
    return (solver.heat() - heat0 - (heatIn - heatOut + heatShell - heatDisplaced)) * cellVolume;
  };
  KramersSetup kramersSetup;
  kramersSetup.length = s.length;
  kramersSetup.radius = 0.5 * s.diameter;
  kramersSetup.revolutionsPerSecond = s.rpm / 60.0;
  kramersSetup.slope = s.slopeDegrees * constants::pi / 180.0;
  kramersSetup.damWidth = s.damHeight > 0.0 ? s.damWidth : 0.0;
  kramersSetup.phiMax = s.params.rheology.phiMax;
  kramersSetup.averageFrom = s.kramersFrom;
  KramersComparison kramers(kramersSetup);
  int outputIndex = 0;
  const auto record = [&](double dt, double outflowRate) {
    const CellFieldOutput f = gatherFields(solver, tracer.index);
    if (s.kramersFrom > 0.0) {
      kramers.add(solver.time(),
                  bedSections(grid, f.scalars.at("volume_fraction"), f.scalars.at("fluid_volume"),
                              kramersSetup.phiMax, kramersSetup.radius),
                  solver.solidsInTotal() * cellVolume, solver.solidsOutTotal() * cellVolume);
    }
    const double speed = maxSpeed(f);
    std::vector<double> row = {solver.time(),
                               dt,
                               solver.solids() * cellVolume,
                               solver.solidsInTotal() * cellVolume,
                               solver.solidsOutTotal() * cellVolume,
                               displaced * cellVolume,
                               balanceError(),
                               outflowRate,
                               speed};
    if (heatOn) {
      for (double v : {solver.heat() * cellVolume, heatIn * cellVolume, heatOut * cellVolume,
                       heatShell * cellVolume, heatBalanceError(), bedMeanTemperature(f)}) {
        row.push_back(v);
      }
    }
    if (tracer.index >= 0) {
      row.push_back(tracer.injected * cellVolume);
      row.push_back(tracer.recovered * cellVolume);
    }
    series.add(row);
    series.flush();
    writeCellFieldOutput(out, outputIndex++, solver.time(), grid, f, info, outputs);
    return speed;
  };
  record(0.0, 0.0);
  const std::vector<double> times = outputTimes(s);
  std::size_t nextOutput = 0;
  const auto loopStart = Clock::now();
  while (solver.time() < s.duration * (1.0 - 1e-12)) {
    std::string reason;
    // land on the next output time and on the dam's time
    double landing = nextOutput < times.size() ? times[nextOutput] : s.duration;
    if (damPending) {
      landing = std::min(landing, s.damOnAt);
    }
    for (double edge : {tracer.start, tracer.end}) { // the pulse's edges
      if (tracer.index >= 0 && edge > solver.time() + 1e-12) {
        landing = std::min(landing, edge);
      }
    }
    const double dt = landOn(solver.time(), solver.stableTimeStep(reason), landing, reason);
    const double t0 = solver.time();
    if (tracer.index >= 0) {
      solver.setTracerInflow(tracer.index, InflowTemperature{tracer.tagging(t0) ? 1.0 : 0.0, 0.0});
    }
    const TwoPhaseStepReport r = solver.step(dt);
    stats.add(dt, reason, r);
    if (heatOn) {
      heatIn += r.heatIn;
      heatOut += r.heatOut;
      heatShell += r.heatFromShell;
      const double exchanged =
          std::fabs(r.heatIn) + std::fabs(r.heatOut) + std::fabs(r.heatFromShell);
      if (exchanged > 0.0) {
        worstHeatStep =
            std::max(worstHeatStep, std::fabs(r.heatAfter - r.heatBefore -
                                              (r.heatIn - r.heatOut + r.heatFromShell)) /
                                        exchanged);
      }
    }
    if (tracer.index >= 0) {
      tracer.add(t0, dt, solver.tracerInLastStep(tracer.index),
                 solver.tracerOutLastStep(tracer.index));
    }
    const double throughput = r.solidsIn + r.solidsOut;
    if (throughput > 0.0) {
      worstStep = std::max(worstStep,
                           std::fabs(r.solidsAfter - r.solidsBefore - (r.solidsIn - r.solidsOut)) /
                               throughput);
    }
    if (!std::isfinite(r.solidsAfter)) {
      throw std::runtime_error(fmt::format("kiln: the solution is no longer finite at t = {:.4f} s "
                                           "(step {}); outputs so far are in {}",
                                           solver.time(), stats.steps, o.outputDirectory));
    }
    if (damPending && solver.time() >= s.damOnAt * (1.0 - 1e-12)) {
      const double heatBefore = solver.heat();
      const double took = solver.changeShape(kilnDomain(s, true));
      displaced += took;
      heatDisplaced += heatBefore - solver.heat();
      damPending = false;
      spdlog::info("kiln: dam ring in at t = {:.2f} s (height {} m, width {} m); it displaced "
                   "{:.4g} m3 of solids",
                   solver.time(), s.damHeight, s.damWidth, took * cellVolume);
    }
    if (nextOutput < times.size() && solver.time() >= times[nextOutput] * (1.0 - 1e-12)) {
      ++nextOutput;
      const double rate = r.solidsOut * cellVolume / dt;
      const double speed = record(dt, rate);
      solver.phiRange(phiLo, phiHi);
      spdlog::info("t = {:.2f} s: step {} (dt {:.3g} s, {}), hold-up {:.4g} m3, in {:.4g} m3, "
                   "out {:.4g} m3 ({:.3g} m3/s), balance error {:.2e} m3, max speed {:.3f} m/s, "
                   "phi in [{:.3g}, {:.4g}], {:.0f} s elapsed",
                   solver.time(), stats.steps, dt, reason, solver.solids() * cellVolume,
                   solver.solidsInTotal() * cellVolume, solver.solidsOutTotal() * cellVolume, rate,
                   balanceError(), speed, phiLo, phiHi, secondsSince(wallStart));
      if (heatOn) {
        spdlog::info("  heat: in {:.4g} J, out {:.4g} J, from the shell {:.4g} J, balance error "
                     "{:.2e} J",
                     heatIn * cellVolume, heatOut * cellVolume, heatShell * cellVolume,
                     heatBalanceError());
      }
    }
  }
  const double loopSeconds = secondsSince(loopStart);
  solver.phiRange(phiLo, phiHi);
  const double throughputTotal = (solver.solidsInTotal() + solver.solidsOutTotal()) * cellVolume;

  nlohmann::json summary;
  summary["stage"] = "kiln";
  summary["case"] = o.caseFile;
  summary["backend"] = app::defaultBackend();
  summary["cells"] = {grid.nx, grid.ny, grid.nz};
  summary["cell_size"] = {grid.hx, grid.hy, grid.hz};
  summary["rheology_source"] = s.rheologySource;
  summary["simulated_time"] = solver.time();
  stats.writeTo(summary, loopSeconds, grid.numCells());
  summary["holdup_initial_m3"] = solids0 * cellVolume;
  summary["holdup_final_m3"] = solver.solids() * cellVolume;
  summary["solids_in_m3"] = solver.solidsInTotal() * cellVolume;
  summary["solids_out_m3"] = solver.solidsOutTotal() * cellVolume;
  summary["dam_displaced_m3"] = displaced * cellVolume;
  summary["balance_error_m3"] = balanceError();
  summary["balance_error_of_throughput"] =
      throughputTotal > 0.0 ? std::fabs(balanceError()) / throughputTotal : 0.0;
  summary["balance_error_worst_step_of_throughput"] = worstStep;
  summary["phi_min"] = phiLo;
  summary["phi_max"] = phiHi;
  summary["wall_seconds"] = secondsSince(wallStart);
  summary["peak_resident_bytes"] = peakResidentBytes();
  summary["peak_resident_bytes_per_cell"] = peakResidentBytes() / double(grid.numCells());
  if (heatOn) {
    const double exchanged =
        (std::fabs(heatIn) + std::fabs(heatOut) + std::fabs(heatShell)) * cellVolume;
    summary["heat"] = {
        {"initial_J", heat0 * cellVolume},
        {"final_J", solver.heat() * cellVolume},
        {"in_J", heatIn * cellVolume},
        {"out_J", heatOut * cellVolume},
        {"from_shell_J", heatShell * cellVolume},
        {"dam_displaced_J", heatDisplaced * cellVolume},
        {"balance_error_J", heatBalanceError()},
        {"balance_error_of_exchanged",
         exchanged > 0.0 ? std::fabs(heatBalanceError()) / exchanged : 0.0},
        {"balance_error_worst_step_of_exchanged", worstHeatStep},
        {"bed_mean_temperature_K", bedMeanTemperature(gatherFields(solver, tracer.index))}};
  }
  if (tracer.index >= 0) {
    // hold-up over the feed rate: the mean residence time of a steady kiln
    const double feedRate = solver.solidsInTotal() / solver.time();
    const double inKiln = solver.tracerHeat(tracer.index);
    summary["tracer"] = {
        {"pulse_start_s", tracer.start},
        {"pulse_end_s", tracer.end},
        {"injected_m3", tracer.injected * cellVolume},
        {"recovered_m3", tracer.recovered * cellVolume},
        {"recovered_fraction", tracer.injected > 0.0 ? tracer.recovered / tracer.injected : 0.0},
        {"in_kiln_m3", inKiln * cellVolume},
        // tagged content now against fed - discharged (conservation of the tracer)
        {"balance_error_of_injected",
         tracer.injected > 0.0
             ? std::fabs(inKiln - (tracer.injected - tracer.recovered)) / tracer.injected
             : 0.0},
        {"mean_residence_time_of_recovered_s", tracer.meanResidenceTime()},
        // the mean residence time only once (nearly) all the tagged solids have left
        {"mean_residence_time_s", tracer.recovered >= 0.99 * tracer.injected
                                      ? nlohmann::json(tracer.meanResidenceTime())
                                      : nlohmann::json(nullptr)},
        {"holdup_over_feed_s", feedRate > 0.0 ? solver.solids() / feedRate : 0.0}};
  }
  if (s.kramersFrom > 0.0) {
    const nlohmann::json k = kramers.report(out);
    summary["kramers_croockewit"] = k;
    if (k.contains("max_rel_deviation") && k["max_rel_deviation"].is_number()) {
      spdlog::info("kiln: Kramers-Croockewit over {} outputs from t = {} s: repose angle {:.1f} "
                   "deg, depth within {:.1f} % (rms {:.1f} %) of the theory, discharge / feed "
                   "{:.4f}; kramers_croockewit.csv",
                   kramers.samples(), s.kramersFrom, k["repose_angle_deg"].get<double>(),
                   100.0 * k["max_rel_deviation"].get<double>(),
                   100.0 * k["rms_rel_deviation"].get<double>(),
                   k["outflow_over_feed"].get<double>());
    } else {
      spdlog::warn("kiln: Kramers-Croockewit: {}", k.value("note", std::string("no comparison")));
    }
  }
  summary["outputs"] = {{"fields", "fields.xmf"}, {"timeseries", "timeseries.csv"}};
  io::writeSummaryJson((out / "summary.json").string(), summary);
  spdlog::info("kiln: {} steps to t = {:.2f} s in {:.1f} s ({:.3g} cell-updates/s); hold-up {:.4g} "
               "-> {:.4g} m3, in {:.4g} m3, out {:.4g} m3, balance error {:.2e} of the "
               "throughput; outputs in {}",
               stats.steps, solver.time(), loopSeconds,
               summary["cell_updates_per_second"].get<double>(), solids0 * cellVolume,
               solver.solids() * cellVolume, solver.solidsInTotal() * cellVolume,
               solver.solidsOutTotal() * cellVolume,
               summary["balance_error_of_throughput"].get<double>(), o.outputDirectory);
  return 0;
}

} // namespace hikiln::cfd
