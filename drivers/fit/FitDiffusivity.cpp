#include "drivers/fit/FitDiffusivity.hpp"

#include "drivers/app/Commands.hpp"
#include "drivers/calibrate/PlotScript.hpp"
#include "drivers/case/CaseFile.hpp"
#include "drivers/cfd/ContinuumCase.hpp"
#include "drivers/fit/DemTemperatures.hpp"
#include "drivers/fit/TemperatureMaps.hpp"
#include "drivers/io/AtomicFile.hpp"
#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Summary.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <Kokkos_Core.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hikiln::fit {

namespace {

namespace fs = std::filesystem;
using Space = Kokkos::DefaultExecutionSpace;
using Solver = cfd::TwoPhaseSolver<Space>;

constexpr double demBedThreshold = 0.4;       ///< particle area / block area (dense bed ~0.8)
constexpr double continuumBedThreshold = 0.5; ///< capacity x phi / phi_max (bed: 1)

std::vector<double> defaultAlphas() {
  std::vector<double> a;
  for (int k = 0; k < 9; ++k)
    a.push_back(std::pow(10.0, -7.0 + 0.5 * k));
  return a;
}

/// The continuum case: the DEM run's drum and material first, then the user's --set.
cases::CaseFile continuumCase(const FitOptions& o, const DemThermalRun& dem) {
  const dem::DrumRunSettings& d = dem.settings;
  std::vector<std::string> sets = {
      fmt::format("drum.diameter={:.17g}", 2.0 * d.fill.drumRadius),
      fmt::format("drum.rpm={:.17g}", d.rpm),
      fmt::format("drum.fill={:.17g}", d.fill.fill),
      fmt::format("material.solid_density={:.17g}", d.fill.density),
      fmt::format("heat.solid_heat_capacity={:.17g}", d.heat.parameters.specificHeat),
      fmt::format("heat.initial_left={:.17g}", d.heat.leftTemperature),
      fmt::format("heat.initial_right={:.17g}", d.heat.rightTemperature),
      fmt::format("time.duration={:.17g}", o.duration),
      "heat.enabled=false"}; // the candidates are tracers; the energy equation is not needed
  sets.insert(sets.end(), o.overrides.begin(), o.overrides.end());
  if (o.caseFile.empty())
    return cases::CaseFile::fromString("{}", "hikiln fit-diffusivity (continuum defaults)",
                                       cfd::continuumSchema(), sets);
  return cases::CaseFile::load(o.caseFile, cfd::continuumSchema(), sets);
}

std::vector<double> hostCells(const cfd::Grid& g, const cfd::Field<Space::memory_space>& f) {
  const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, f);
  std::vector<double> v;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      v.push_back(h(i + g.ghost, j + g.ghost, 0));
  return v;
}

/// Minimum of y(log10 x) refined by the parabola through the smallest sample and its neighbours.
double refinedMinimum(const std::vector<double>& x, const std::vector<double>& y) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < y.size(); ++i)
    if (y[i] < y[k])
      k = i;
  if (k == 0 || k + 1 >= y.size())
    return x[k];
  const double a = std::log10(x[k - 1]), b = std::log10(x[k]), c = std::log10(x[k + 1]);
  const double fa = y[k - 1], fb = y[k], fc = y[k + 1];
  const double den = (b - a) * (fb - fc) - (b - c) * (fb - fa);
  if (!(std::fabs(den) > 0.0))
    return x[k];
  const double vertex =
      b - 0.5 * ((b - a) * (b - a) * (fb - fc) - (b - c) * (b - c) * (fb - fa)) / den;
  return std::pow(10.0, std::clamp(vertex, a, c));
}

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v)
    s += x * x;
  return v.empty() ? std::numeric_limits<double>::quiet_NaN()
                   : std::sqrt(s / static_cast<double>(v.size()));
}

nlohmann::json finiteOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nullptr;
}

} // namespace

int runFitDiffusivity(const FitOptions& o) {
  const auto wallStart = std::chrono::steady_clock::now();
  const DemThermalRun dem = readDemThermalRun(o.demRun);
  std::vector<double> alphas = o.alphas.empty() ? defaultAlphas() : o.alphas;
  std::sort(alphas.begin(), alphas.end());
  for (double a : alphas)
    if (!(a > 0.0) || !std::isfinite(a))
      throw std::invalid_argument("--alphas: every candidate must be a positive number");
  if (!(o.duration > 0.0))
    throw std::invalid_argument("--duration must be > 0");
  const fs::path out(o.outputDirectory);
  fs::create_directories(out);

  const cases::CaseFile file = continuumCase(o, dem);
  file.writeResolved((out / "continuum.resolved.yaml").string());
  const cfd::ContinuumSettings s = cfd::continuumSettingsFromCase(file);
  const cfd::Grid grid = cfd::drumGrid(s.cells, s.diameter);
  if (grid.nx % o.blockFactor != 0)
    throw std::invalid_argument(
        fmt::format("--block {} does not divide grid.cells = {}", o.blockFactor, grid.nx));
  BlockGrid blocks;
  blocks.n = grid.nx / o.blockFactor;
  blocks.h = grid.hx * o.blockFactor;
  blocks.x0 = grid.x0;
  blocks.y0 = grid.y0;

  const double cold = dem.settings.heat.leftTemperature, hot = dem.settings.heat.rightTemperature;
  if (!(std::fabs(hot - cold) > 0.0))
    throw std::runtime_error(o.demRun + ": heat.left_temperature equals heat.right_temperature: "
                                        "there is no mixing layer to fit");
  const double splitX = dem.settings.heat.splitX;
  std::vector<const ParticleTemperatureSnapshot*> samples;
  for (const auto& snap : dem.snapshots)
    if (snap.rotationTime <= o.duration * 1.01) // snapshots land a few steps after round times
      samples.push_back(&snap);
  if (samples.size() < 2)
    throw std::runtime_error(o.demRun + ": fewer than two snapshots within --duration " +
                             fmt::format("{} s", o.duration));

  cfd::DrumShell shell;
  shell.radius = 0.5 * s.diameter;
  shell.omega = s.omega();
  Solver solver(Space{}, grid, shell, s.params);
  solver.setFlatBed(cfd::flatBedLevel(shell.radius, s.fill));
  {
    // a new host field shaped like the cell fields (create_mirror_view would alias phi on a
    // host backend)
    auto T = Kokkos::create_mirror(Kokkos::HostSpace{}, solver.volumeFraction());
    Kokkos::deep_copy(T, 0.5 * (cold + hot));
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i)
        T(i + grid.ghost, j + grid.ghost, 0) =
            grid.coordinate(cfd::Staggering::Cell, 0, i) < splitX ? cold : hot;
    for (double a : alphas)
      Kokkos::deep_copy(solver.tracerTemperature(solver.addTemperatureTracer(a)), T);
  }
  spdlog::info("fit-diffusivity: DEM run {} ({} snapshots to {:.1f} s); continuum {} x {} cells, "
               "{} candidates alpha_eff in [{:.3g}, {:.3g}] m^2/s",
               o.demRun, samples.size(), samples.back()->rotationTime, grid.nx, grid.ny,
               alphas.size(), alphas.front(), alphas.back());

  const std::size_t nA = alphas.size(), nT = samples.size();
  std::vector<double> times, demMixed;
  std::vector<std::vector<double>> mixed(nA), mapRms(nA);
  std::vector<TemperatureMap> demMaps;
  std::vector<std::vector<TemperatureMap>> contMaps(nA);
  std::int64_t steps = 0;
  for (const ParticleTemperatureSnapshot* snap : samples) {
    while (solver.time() < snap->rotationTime * (1.0 - 1e-12)) {
      std::string reason;
      const double dt = std::min(solver.stableTimeStep(reason), snap->rotationTime - solver.time());
      solver.step(dt);
      ++steps;
    }
    const std::vector<double> capacity = hostCells(grid, solver.cutCells().capacity);
    std::vector<double> relPhi = hostCells(grid, solver.volumeFraction());
    for (double& v : relPhi)
      v /= s.params.rheology.phiMax;
    demMaps.push_back(binParticles(blocks, *snap));
    times.push_back(snap->rotationTime);
    demMixed.push_back(mixedFraction(demMaps.back(), cold, hot, demBedThreshold));
    for (std::size_t k = 0; k < nA; ++k) {
      contMaps[k].push_back(coarsenCells(grid.nx, grid.ny, o.blockFactor,
                                         hostCells(grid, solver.tracerTemperature(int(k))),
                                         capacity, relPhi));
      mixed[k].push_back(mixedFraction(contMaps[k].back(), cold, hot, continuumBedThreshold));
      mapRms[k].push_back(thetaRms(contMaps[k].back(), continuumBedThreshold, demMaps.back(),
                                   demBedThreshold, cold, hot));
    }
    spdlog::info("fit-diffusivity: t = {:.2f} s, DEM mixed fraction {:.3f}, continuum {:.3f} .. "
                 "{:.3f}",
                 snap->rotationTime, demMixed.back(), mixed.front().back(), mixed.back().back());
  }

  // misfits over the times after the start (at t = 0 both are the initial split)
  std::vector<double> misfitWidth(nA), misfitMap(nA);
  for (std::size_t k = 0; k < nA; ++k) {
    std::vector<double> dw, dm;
    for (std::size_t t = 0; t < nT; ++t) {
      if (times[t] <= 1e-9)
        continue;
      dw.push_back(mixed[k][t] - demMixed[t]);
      dm.push_back(mapRms[k][t]);
    }
    misfitWidth[k] = rms(dw);
    misfitMap[k] = rms(dm);
  }
  const std::size_t best =
      std::min_element(misfitWidth.begin(), misfitWidth.end()) - misfitWidth.begin();
  const double refined = refinedMinimum(alphas, misfitWidth);

  std::ostringstream fitCsv, layerCsv;
  fitCsv << "alpha_eff,misfit_mixed_fraction,misfit_theta_rms\n";
  for (std::size_t k = 0; k < nA; ++k)
    fitCsv << fmt::format("{:.6g},{:.6g},{:.6g}\n", alphas[k], misfitWidth[k], misfitMap[k]);
  layerCsv << "time,dem";
  for (double a : alphas)
    layerCsv << fmt::format(",alpha_{:.3g}", a);
  layerCsv << "\n";
  for (std::size_t t = 0; t < nT; ++t) {
    layerCsv << fmt::format("{:.6g},{:.6g}", times[t], demMixed[t]);
    for (std::size_t k = 0; k < nA; ++k)
      layerCsv << fmt::format(",{:.6g}", mixed[k][t]);
    layerCsv << "\n";
  }
  io::writeTextAtomically((out / "fit.csv").string(), fitCsv.str());
  io::writeTextAtomically((out / "mixing_layer.csv").string(), layerCsv.str());

  {
    auto h5 = io::H5File::create((out / "maps.h5").string());
    const auto n = static_cast<hsize_t>(blocks.n);
    std::vector<double> xc, yc, demT, demBed, contT, contBed;
    for (int i = 0; i < blocks.n; ++i) {
      xc.push_back(blocks.centreX(i));
      yc.push_back(blocks.centreY(i * blocks.n));
    }
    for (std::size_t t = 0; t < nT; ++t) {
      demT.insert(demT.end(), demMaps[t].temperature.begin(), demMaps[t].temperature.end());
      demBed.insert(demBed.end(), demMaps[t].bedFraction.begin(), demMaps[t].bedFraction.end());
    }
    for (std::size_t k = 0; k < nA; ++k) {
      for (std::size_t t = 0; t < nT; ++t) {
        const TemperatureMap& m = contMaps[k][t];
        contT.insert(contT.end(), m.temperature.begin(), m.temperature.end());
        contBed.insert(contBed.end(), m.bedFraction.begin(), m.bedFraction.end());
      }
    }
    h5.writeDataset("x_centres", xc, {n}, "m");
    h5.writeDataset("y_centres", yc, {n}, "m");
    h5.writeDataset("times", times, {nT}, "s");
    h5.writeDataset("alpha_eff", alphas, {nA}, "m^2/s");
    h5.writeDataset("dem_temperature", demT, {nT, n, n}, "K");
    h5.writeDataset("dem_bed_fraction", demBed, {nT, n, n}, "1");
    h5.writeDataset("continuum_temperature", contT, {nA, nT, n, n}, "K");
    h5.writeDataset("continuum_bed_fraction", contBed, {nA, nT, n, n}, "1");
    h5.setAttribute("/", "cold_K", cold);
    h5.setAttribute("/", "hot_K", hot);
    h5.setAttribute("/", "best_index", static_cast<std::int64_t>(best));
    h5.setAttribute("/", "dem_bed_threshold", demBedThreshold);
    h5.setAttribute("/", "continuum_bed_threshold", continuumBedThreshold);
    h5.setAttribute("/", "drum_radius", shell.radius);
    h5.commit();
  }

  nlohmann::json j;
  j["stage"] = "fit-diffusivity";
  j["dem_run"] = o.demRun;
  j["continuum_case"] = o.caseFile.empty() ? "defaults" : o.caseFile;
  j["backend"] = app::defaultBackend();
  j["cells"] = grid.nx;
  j["block_cells"] = o.blockFactor;
  j["block_size_m"] = blocks.h;
  j["duration_s"] = samples.back()->rotationTime;
  j["times_s"] = times;
  j["alpha_eff_candidates"] = alphas;
  j["misfit_mixed_fraction"] = nlohmann::json::array();
  j["misfit_theta_rms"] = nlohmann::json::array();
  for (std::size_t k = 0; k < nA; ++k) {
    j["misfit_mixed_fraction"].push_back(finiteOrNull(misfitWidth[k]));
    j["misfit_theta_rms"].push_back(finiteOrNull(misfitMap[k]));
  }
  j["dem_mixed_fraction"] = demMixed;
  j["best_alpha_eff"] = alphas[best];
  j["best_alpha_eff_refined"] = refined;
  j["best_misfit_mixed_fraction"] = finiteOrNull(misfitWidth[best]);
  j["best_misfit_theta_rms"] = finiteOrNull(misfitMap[best]);
  j["at_candidate_range_edge"] = best == 0 || best + 1 == nA;
  j["measure"] = "rms over DEM snapshot times t > 0 of (continuum - DEM) mixed fraction: share "
                 "of bed blocks with 0.1 < theta < 0.9, theta = (T - T_left) / (T_right - T_left)";
  j["continuum_steps"] = steps;
  j["wall_time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  io::writeSummaryJson((out / "fit.json").string(), j);
  spdlog::info("fit-diffusivity: best alpha_eff {:.3g} m^2/s (refined {:.3g}), misfit {:.3g} "
               "(mixed fraction), theta rms {:.3g}{}; outputs in {}",
               alphas[best], refined, misfitWidth[best], misfitMap[best],
               best == 0 || best + 1 == nA ? " -- at the edge of the candidates, widen --alphas"
                                           : "",
               out.string());

  calibrate::runPlotScript(calibrate::plotScriptPath("plot_fit_diffusivity.py"),
                           "--run " + calibrate::shellQuote(out.string()), "matplotlib,h5py,numpy",
                           "fit-diffusivity plots");
  return 0;
}

} // namespace hikiln::fit
