#include "drivers/cfd/ContinuumRun.hpp"

#include "drivers/app/Commands.hpp"
#include "drivers/case/CaseFile.hpp"
#include "drivers/cfd/CellFieldOutput.hpp"
#include "drivers/cfd/ContinuumCase.hpp"
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
#include <map>
#include <stdexcept>
#include <vector>

namespace hikiln::cfd {

namespace {

namespace fs = std::filesystem;
using Space = Kokkos::DefaultExecutionSpace;
using Solver = TwoPhaseSolver<Space>;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The cell fields of one output, with the shear stress invariant q = mu gamma_dot (physics.md
/// 3) for the DEM comparison.
CellFieldOutput gatherFields(Solver const& solver) {
  const Grid g = solver.grid();
  CellFieldOutput out;
  out.addSolverFields(solver);
  out.add("density", solver.density(), g);
  out.add("temperature", solver.temperature(), g);
  std::vector<double>& q = out.scalars["shear_stress"];
  q.resize(out.scalars["viscosity"].size());
  for (std::size_t c = 0; c < q.size(); ++c) {
    q[c] = out.scalars["viscosity"][c] * out.scalars["strain_rate"][c];
  }
  return out;
}

} // namespace

int runContinuum(ContinuumRunOptions const& o) {
  const auto wallStart = Clock::now();
  const auto file = cases::CaseFile::load(o.caseFile, continuumSchema(), o.overrides);
  const ContinuumSettings s = continuumSettingsFromCase(file);
  const fs::path out(o.outputDirectory);
  fs::create_directories(out);
  file.writeResolved((out / "case.resolved.yaml").string());
  const io::RunInfo info{"continuum", app::defaultBackend(), file.resolvedYaml()};

  const Grid grid = drumGrid(s.cells, s.diameter);
  DrumShell shell;
  shell.radius = 0.5 * s.diameter;
  shell.omega = s.omega();
  Solver solver(Space{}, grid, shell, s.params);
  solver.setFlatBed(flatBedLevel(shell.radius, s.fill));
  if (s.params.energy) {
    auto T = Kokkos::create_mirror_view(Kokkos::HostSpace{}, solver.temperature());
    Kokkos::deep_copy(T, 0.5 * (s.initialLeft + s.initialRight));
    for (int j = 0; j < grid.ny; ++j) {
      for (int i = 0; i < grid.nx; ++i) {
        T(i + grid.ghost, j + grid.ghost, 0) =
            grid.coordinate(Staggering::Cell, 0, i) < 0.0 ? s.initialLeft : s.initialRight;
      }
    }
    Kokkos::deep_copy(solver.temperature(), T);
  }
  spdlog::info("continuum: {} x {} cells (h = {:.4g} m), drum D = {} m at {} rpm, fill {}, "
               "rheology from {}",
               grid.nx, grid.ny, grid.hx, s.diameter, s.rpm, s.fill, s.rheologySource);

  const double solids0 = solver.solids();
  const double heat0 = solver.heat();
  double worstSolids = 0.0, worstHeat = 0.0, phiLo = 0.0, phiHi = 0.0, slipSum = 0.0;
  int mostHeatSubsteps = 0;
  std::int64_t slipSamples = 0;
  ShellTorque torque; // sums over the outputs after slip_after
  int torqueSamples = 0;
  StepStatistics stats;
  std::vector<io::XdmfGridStep> outputs;
  dem::TimeSeries series((out / "timeseries.csv").string(),
                         {"time", "dt", "wall_slip", "solids_change", "max_speed"});
  int outputIndex = 0;
  {
    const CellFieldOutput f = gatherFields(solver);
    writeCellFieldOutput(out, outputIndex++, solver.time(), grid, f, info, outputs);
  }
  const auto loopStart = Clock::now();
  double nextOutput = s.outputInterval;
  while (solver.time() < s.duration * (1.0 - 1e-12)) {
    std::string reason;
    const double dt = landOn(solver.time(), solver.stableTimeStep(reason), nextOutput, reason);
    const TwoPhaseStepReport r = solver.step(dt);
    stats.add(dt, reason, r);
    worstSolids = std::max(worstSolids, std::fabs(r.solidsAfter - r.solidsBefore) / solids0);
    if (s.params.energy && r.heatBefore != 0.0) {
      worstHeat = std::max(worstHeat, std::fabs(r.heatAfter - r.heatBefore) / r.heatBefore);
      mostHeatSubsteps = std::max(mostHeatSubsteps, r.heatSubsteps);
    }
    spdlog::debug("t {:.4f} s, dt {:.3g} s ({}), iterations viscous {} pressure {}", solver.time(),
                  dt, reason, r.viscous.iterations, r.pressure.iterations);
    if (solver.time() >= nextOutput * (1.0 - 1e-12)) {
      nextOutput += s.outputInterval;
      const CellFieldOutput f = gatherFields(solver);
      const double slip = solver.wallSlip();
      if (std::isfinite(slip) && solver.time() > s.slipAfter) {
        slipSum += slip;
        ++slipSamples;
      }
      if (solver.time() > s.slipAfter) {
        torque += solver.shellTorque();
        ++torqueSamples;
      }
      double speed = 0.0;
      for (double v : f.velocity) {
        speed = std::max(speed, std::fabs(v));
      }
      series.add({solver.time(), dt, 100.0 * slip, (solver.solids() - solids0) / solids0, speed});
      series.flush();
      writeCellFieldOutput(out, outputIndex++, solver.time(), grid, f, info, outputs);
      solver.phiRange(phiLo, phiHi);
      spdlog::info("t = {:.2f} s: step {} (dt {:.3g} s, {}), wall slip {:.1f} %, max speed "
                   "{:.3f} m/s, phi in [{:.3g}, {:.4g}], solids change {:.2e}",
                   solver.time(), stats.steps, dt, reason, 100.0 * slip, speed, phiLo, phiHi,
                   (solver.solids() - solids0) / solids0);
    }
  }
  const double loopSeconds = secondsSince(loopStart);
  solver.phiRange(phiLo, phiHi);

  nlohmann::json summary;
  summary["stage"] = "continuum";
  summary["case"] = o.caseFile;
  summary["backend"] = app::defaultBackend();
  summary["cells"] = {grid.nx, grid.ny};
  summary["cell_size"] = grid.hx;
  summary["rheology_source"] = s.rheologySource;
  summary["simulated_time"] = solver.time();
  stats.writeTo(summary, loopSeconds, grid.numCells());
  summary["wall_slip_percent"] =
      slipSamples > 0 ? nlohmann::json(100.0 * slipSum / slipSamples) : nlohmann::json(nullptr);
  summary["wall_slip_samples"] = slipSamples;
  if (torqueSamples > 0) {
    const double n = torqueSamples;
    summary["shell_torque_N"] = {
        {"note", "about the drum axis per metre, mean of the outputs after slip_after; "
                 "counter-clockwise positive (kernels/cfd/ShellTorque.hpp)"},
        {"gravity", torque.gravity / n},
        {"wall_drag", torque.wallDrag / n},
        {"wall_drag_coulomb_bound", torque.wallDragBound / n},
        {"pressure", torque.pressure / n},
        {"pressure_on_cut_faces", torque.pressureCut / n},
        {"pressure_share_of_gravity",
         torque.gravity != 0.0 ? -torque.pressure / torque.gravity : 0.0}};
    spdlog::info("shell torque (N m/m, mean after {} s): gravity {:.4g}, wall drag {:.4g} "
                 "(Coulomb bound {:.4g}), pressure {:.4g} ({:.4g} on the cut faces)",
                 s.slipAfter, torque.gravity / n, torque.wallDrag / n, torque.wallDragBound / n,
                 torque.pressure / n, torque.pressureCut / n);
  }
  summary["solids_relative_change_total"] = (solver.solids() - solids0) / solids0;
  summary["solids_relative_change_worst_step"] = worstSolids;
  summary["phi_min"] = phiLo;
  summary["phi_max"] = phiHi;
  if (s.params.energy) {
    summary["heat_relative_change_total"] = (solver.heat() - heat0) / heat0;
    summary["heat_relative_change_worst_step"] = worstHeat;
    summary["heat_advection_substeps_max"] = mostHeatSubsteps;
  }
  summary["wall_seconds"] = secondsSince(wallStart);
  summary["outputs"] = {{"fields", "fields.xmf"}, {"timeseries", "timeseries.csv"}};
  io::writeSummaryJson((out / "summary.json").string(), summary);
  spdlog::info("continuum: {} steps to t = {:.2f} s in {:.1f} s ({:.3g} cell-updates/s); wall "
               "slip {} %; solids change {:.2e}; outputs in {}",
               stats.steps, solver.time(), loopSeconds,
               summary["cell_updates_per_second"].get<double>(),
               slipSamples > 0 ? fmt::format("{:.1f}", 100.0 * slipSum / slipSamples) : "n/a",
               (solver.solids() - solids0) / solids0, o.outputDirectory);
  return 0;
}

} // namespace hikiln::cfd
