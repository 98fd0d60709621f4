#include "drivers/calibrate/CalibrateCommand.hpp"

#include "drivers/app/Commands.hpp"
#include "drivers/calibrate/CalibrationCsv.hpp"
#include "drivers/calibrate/PlotScript.hpp"
#include "drivers/io/AtomicFile.hpp"
#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Summary.hpp"
#include "solvers/calibration/CalibrationJson.hpp"
#include "solvers/calibration/RheologyFile.hpp"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

namespace hikiln::calibrate {

namespace fs = std::filesystem;
using calibration::CalibrationRun;

namespace {

// The run's directory: the argument itself, or the folder holding a given averages.h5.
fs::path runDirectory(const std::string& runArgument) {
  const fs::path given(runArgument);
  return fs::is_regular_file(given) ? given.parent_path() : given;
}

std::string describe(const calibration::SelectionCounts& n) {
  return std::to_string(n.total) + " cells: " + std::to_string(n.invalid) + " not valid, " +
         std::to_string(n.nonFinite) + " non-finite, " + std::to_string(n.belowStrainRate) +
         " at or below the strain-rate floor, " + std::to_string(n.nonPositivePressure) +
         " with p <= 0";
}

CalibrationRun loadRun(const std::string& runArgument, const CalibrateOptions& options) {
  const std::string file = averagesFileOf(runArgument);
  CalibrationRun run = readRunHeader(file);
  const calibration::GridFields fields = readGridFields(file, options.grid);
  calibration::SelectionOptions selection;
  selection.minStrainRate = options.minStrainRate;
  run.cells = calibration::selectCells(fields, selection, &run.counts);
  if (run.counts.selected < options.minCells)
    throw std::runtime_error("averages file '" + file + "': only " +
                             std::to_string(run.counts.selected) + " usable cells on the " +
                             gridName(options.grid) + " grid, need at least " +
                             std::to_string(options.minCells) + " (" + describe(run.counts) + ")");
  spdlog::info("{}: {} of {} cells selected", file, run.counts.selected, run.counts.total);
  return run;
}

// Directory names make the labels; repeated names get "#2", "#3".
void assignLabels(std::vector<CalibrationRun>& runs, const std::vector<std::string>& arguments) {
  std::map<std::string, int> seen;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::string name = fs::absolute(runDirectory(arguments[i])).lexically_normal().filename();
    if (name.empty())
      name = fs::absolute(runDirectory(arguments[i])).lexically_normal().parent_path().filename();
    const int count = ++seen[name];
    runs[i].label = count == 1 ? name : name + "#" + std::to_string(count);
  }
}

// summary.json in the output directory would overwrite a run's own summary.json.
void refuseRunDirectoryAsOutput(const fs::path& outputDir, const std::vector<std::string>& runs) {
  for (const std::string& run : runs) {
    std::error_code ec;
    if (fs::equivalent(outputDir, runDirectory(run), ec))
      throw std::runtime_error("output '" + outputDir.string() + "' is the run directory '" + run +
                               "'; calibration outputs (summary.json) would overwrite the run's");
  }
}

nlohmann::json summaryOf(const calibration::CalibrationResult& result,
                         const std::vector<CalibrationRun>& runs, const CalibrateOptions& options,
                         const std::string& created) {
  nlohmann::json s;
  s["stage"] = "calibrate";
  s["hikiln_version"] = HIKILN_VERSION;
  s["created"] = created;
  s["grid"] = gridName(options.grid);
  s["min_strain_rate"] = options.minStrainRate;
  s["outputs"] = {{"rheology", fs::path(options.output).filename().string()},
                  {"csv", "calibration.csv"},
                  {"wall_profile", "wall_profile.csv"},
                  {"fits", "calibration.json"}};
  nlohmann::json inputs = nlohmann::json::array();
  for (const CalibrationRun& run : runs) {
    const fs::path demSummary = fs::path(run.path).parent_path() / "summary.json";
    inputs.push_back({{"label", run.label},
                      {"averages", run.path},
                      {"dem_summary", fs::exists(demSummary) ? nlohmann::json(demSummary.string())
                                                             : nlohmann::json(nullptr)},
                      {"cells", run.counts.selected},
                      {"cells_total", run.counts.total}});
  }
  s["inputs"] = inputs;
  s["cells"] = result.cellCount;
  s["m0"] = result.frictionLine.intercept;
  s["m1"] = result.frictionLine.slope;
  s["m_line_r_squared"] = result.frictionLine.quality.rSquared;
  s["mu_fr"] = result.coulomb.frictionCoefficient;
  s["phi_deg"] = result.coulomb.frictionAngleDeg;
  s["cohesion"] = result.coulomb.cohesion;
  s["coulomb_r_squared"] = result.coulomb.quality.rSquared;
  s["newtonian_exponent"] = result.newtonian.fit.exponent;
  s["newtonian"] = result.newtonian.newtonian;
  s["mu_wall"] = result.wall.muWall;
  s["mu_wall_std"] = result.wall.muWallStd;
  s["mu_i_status"] = result.muIStatus;
  if (result.muI)
    s["mu_i"] = {{"m_s", result.muI->parameters.staticFriction},
                 {"m_2", result.muI->parameters.limitFriction},
                 {"I0", result.muI->parameters.inertialScale},
                 {"r_squared", result.muI->quality.rSquared}};
  return s;
}

} // namespace

int runCalibrate(const CalibrateOptions& options) {
  if (options.runs.empty())
    throw std::runtime_error("calibrate: no runs given");
  if (options.output.empty())
    throw std::runtime_error("calibrate: no output file given (-o rheology.yaml)");
  const fs::path output = fs::absolute(options.output);
  const fs::path outputDir = output.parent_path();
  refuseRunDirectoryAsOutput(outputDir, options.runs);

  std::vector<CalibrationRun> runs;
  std::vector<WallProfile> walls;
  for (const std::string& argument : options.runs) {
    runs.push_back(loadRun(argument, options));
    const calibration::RunConditions& c = runs.back().conditions;
    walls.push_back(readWallProfile(runs.back().path, c.omega, c.drumRadius));
  }
  assignLabels(runs, options.runs);
  fs::create_directories(outputDir); // only once the inputs are known to be good

  calibration::CalibrationOptions fitOptions;
  fitOptions.selection.minStrainRate = options.minStrainRate;
  fitOptions.fitMuI = options.fitMuI;
  const calibration::CalibrationResult result = calibration::calibrate(runs, fitOptions);

  const std::string created = io::utcTimestamp();
  const calibration::RheologyProvenance provenance{HIKILN_VERSION, created, gridName(options.grid)};
  io::writeTextAtomically(output.string(),
                          calibration::formatRheologyYaml(result, runs, fitOptions, provenance));
  io::writeTextAtomically((outputDir / "calibration.csv").string(), formatCalibrationCsv(runs));
  io::writeTextAtomically((outputDir / "wall_profile.csv").string(),
                          formatWallProfileCsv(runs, walls));
  nlohmann::json fits = calibration::calibrationToJson(result, runs, fitOptions);
  fits["hikiln_version"] = HIKILN_VERSION;
  fits["created"] = created;
  fits["grid"] = gridName(options.grid);
  io::writeSummaryJson((outputDir / "calibration.json").string(), fits);
  io::writeSummaryJson((outputDir / "summary.json").string(),
                       summaryOf(result, runs, options, created));

  spdlog::info("m(gamma_dot) = {:.4g} + {:.4g} gamma_dot (R^2 {:.3f}, {} cells, {} runs)",
               result.frictionLine.intercept, result.frictionLine.slope,
               result.frictionLine.quality.rSquared, result.cellCount, runs.size());
  spdlog::info("Coulomb: mu_fr {:.4g} (phi {:.2f} deg), cohesion {:.4g} Pa; shear stress ~ "
               "gamma_dot^{:.3f} ({}Newtonian); mu_wall {:.4g} +- {:.2g}",
               result.coulomb.frictionCoefficient, result.coulomb.frictionAngleDeg,
               result.coulomb.cohesion, result.newtonian.fit.exponent,
               result.newtonian.newtonian ? "" : "not ", result.wall.muWall, result.wall.muWallStd);
  if (result.muI)
    spdlog::info("mu(I): m_s {:.4g}, m_2 {:.4g}, I0 {:.4g} (R^2 {:.3f})",
                 result.muI->parameters.staticFriction, result.muI->parameters.limitFriction,
                 result.muI->parameters.inertialScale, result.muI->quality.rSquared);
  else
    spdlog::warn("mu(I) fit: {}", result.muIStatus);
  spdlog::info("wrote {}", output.string());

  if (!options.plotDir.empty())
    drawCalibrationPlots(outputDir.string(), options.plotDir); // the script creates plotDir
  return 0;
}

} // namespace hikiln::calibrate

namespace hikiln::app {

void addCalibrateCommand(CLI::App& app, Action& action) {
  auto options = std::make_shared<calibrate::CalibrateOptions>();
  auto grid = std::make_shared<std::string>("polar");
  auto noMuI = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand(
      "calibrate", "Fit the continuum rheology (m(strain rate), Coulomb, mu_wall) to DEM averages");
  cmd->add_option("runs", options->runs, "DEM run directories holding averages.h5")->required();
  cmd->add_option("-o,--output", options->output, "Rheology file to write (e.g. rheology.yaml)")
      ->required();
  cmd->add_option("--grid", *grid, "Averaging grid to calibrate from")
      ->check(CLI::IsMember({"polar", "cartesian"}))
      ->capture_default_str();
  cmd->add_option("--min-strain-rate", options->minStrainRate,
                  "Cells at or below this strain rate [1/s] are not fitted")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--min-cells", options->minCells, "Fewest usable cells per run")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--plots", options->plotDir,
                  "Directory for PNG plots (needs python3-matplotlib)");
  cmd->add_flag("--no-mu-i", *noMuI, "Skip the mu(I) fit");
  cmd->callback([&action, options, grid, noMuI] {
    options->grid =
        *grid == "cartesian" ? calibrate::AveragesGrid::Cartesian : calibrate::AveragesGrid::Polar;
    options->fitMuI = !*noMuI;
    action = [options] { return calibrate::runCalibrate(*options); };
  });
}

} // namespace hikiln::app
