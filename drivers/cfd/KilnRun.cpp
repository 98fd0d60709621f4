#include "drivers/cfd/KilnRun.hpp"

#include "drivers/app/Commands.hpp"
#include "drivers/case/CaseFile.hpp"
#include "drivers/cfd/CellFieldOutput.hpp"
#include "drivers/cfd/ContinuumCase.hpp"
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

/// The cell fields of one output, with the axial velocity (w at the cell centres) for the
/// rendered bed surface.
CellFieldOutput gatherFields(Solver const& solver) {
  CellFieldOutput out;
  out.addSolverFields(solver);
  std::vector<double>& axial = out.scalars["axial_velocity"];
  axial.resize(out.velocity.size() / 3);
  for (std::size_t n = 0; n < axial.size(); ++n) {
    axial[n] = out.velocity[3 * n + 2];
  }
  return out;
}

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
  dem::TimeSeries series((out / "timeseries.csv").string(),
                         {"time", "dt", "holdup_m3", "solids_in_m3", "solids_out_m3",
                          "dam_displaced_m3", "balance_error_m3", "outflow_rate_m3_per_s",
                          "max_speed"});
  const auto balanceError = [&] {
    return (solver.solids() - solids0 -
            (solver.solidsInTotal() - solver.solidsOutTotal() - displaced)) *
           cellVolume;
  };
  int outputIndex = 0;
  const auto record = [&](double dt, double outflowRate) {
    const CellFieldOutput f = gatherFields(solver);
    const double speed = maxSpeed(f);
    series.add({solver.time(), dt, solver.solids() * cellVolume,
                solver.solidsInTotal() * cellVolume, solver.solidsOutTotal() * cellVolume,
                displaced * cellVolume, balanceError(), outflowRate, speed});
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
    const double dt = landOn(solver.time(), solver.stableTimeStep(reason), landing, reason);
    const TwoPhaseStepReport r = solver.step(dt);
    stats.add(dt, reason, r);
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
      const double took = solver.changeShape(kilnDomain(s, true));
      displaced += took;
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
