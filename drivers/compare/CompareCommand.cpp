#include "drivers/compare/CompareCommand.hpp"

#include "drivers/app/Commands.hpp"
#include "drivers/calibrate/PlotScript.hpp"
#include "drivers/compare/CaseTable.hpp"
#include "drivers/compare/ComparisonReport.hpp"
#include "drivers/io/AtomicFile.hpp"
#include "drivers/io/Summary.hpp"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>

namespace hikiln::compare {

namespace fs = std::filesystem;

namespace {

// The DEM run's directory name; repeated names get "_2", "_3".
std::vector<std::string> pairLabels(const CompareCommandOptions& o, std::size_t pairs) {
  if (!o.labels.empty()) {
    if (o.labels.size() != pairs)
      throw std::runtime_error("compare: " + std::to_string(o.labels.size()) + " labels for " +
                               std::to_string(pairs) + " DEM/continuum pairs");
    return o.labels;
  }
  std::vector<std::string> labels;
  std::map<std::string, int> seen;
  for (std::size_t p = 0; p < pairs; ++p) {
    fs::path dir = fs::absolute(o.runs[2 * p]).lexically_normal();
    if (dir.filename() == "averages.h5" || dir.filename().empty())
      dir = dir.parent_path();
    const std::string name = dir.filename().string();
    const int count = ++seen[name];
    labels.push_back(count == 1 ? name : name + "_" + std::to_string(count));
  }
  return labels;
}

struct PairResult {
  std::string label;
  DemRun dem;
  ContinuumRun continuum;
  Comparison comparison;
};

PairResult comparePair(const std::string& demPath, const std::string& continuumPath,
                       const std::string& label, const CompareOptions& options) {
  PairResult r{label, readDemRun(demPath), readContinuumRun(continuumPath), {}};
  requireSameDrum(r.dem, r.continuum);
  const CellMaps continuum =
      continuumOnGrid(r.continuum, r.dem.maps.grid, r.dem.centreX, r.dem.centreY);
  r.comparison = compareRuns(r.dem, continuum, options);
  return r;
}

// A JSON number with 4 significant digits, "n/a" for null.
std::string show(const nlohmann::json& value) {
  return value.is_number() ? fmt::format("{:.4g}", value.get<double>()) : std::string("n/a");
}

void logPair(const PairResult& r, const nlohmann::json& j) {
  spdlog::info("compare {}: D = {} m, {} rpm, fill {}; continuum {}", r.label, r.dem.drum.diameter,
               r.dem.drum.rpm, r.dem.drum.fill, r.continuum.averaging);
  const auto& spot = j["spot"];
  std::string line;
  for (const std::string& name : spotFields()) {
    const auto& v = spot["values"][name];
    line += fmt::format("{}{} {} / {} {}", line.empty() ? "" : "; ", name, show(v["dem"]),
                        show(v["continuum"]), v["units"].get<std::string>());
  }
  if (spot["cells_valid_in_both"].get<std::size_t>() == 0)
    spdlog::warn("compare {}: no cell of the spot window is valid in both runs (too short a DEM "
                 "average, or an empty bottom?): the spot values are null",
                 r.label);
  spdlog::info("  spot ({} cells at {:.3g} m above the shell bottom), DEM / continuum: {}",
               spot["cells_valid_in_both"].get<std::size_t>(),
               spot["depth_above_shell_bottom"].get<double>(), line);
  spdlog::info("  wall slip DEM {} % / continuum {} %; surface angle {} / {} deg, rms surface "
               "difference {} m; relative L2 pressure {}, shear stress {}, velocity x {}",
               show(j["wall_slip_percent"]["dem"]), show(j["wall_slip_percent"]["continuum"]),
               show(j["surface"]["angle_deg"]["dem"]), show(j["surface"]["angle_deg"]["continuum"]),
               show(j["surface"]["rms_difference"]), show(j["maps"]["pressure"]["relative_l2"]),
               show(j["maps"]["shear_stress"]["relative_l2"]),
               show(j["maps"]["velocity_x"]["relative_l2"]));
}

} // namespace

int runCompare(const CompareCommandOptions& o) {
  if (o.runs.size() < 2 || o.runs.size() % 2 != 0)
    throw std::runtime_error("compare: give DEM_RUN CONTINUUM_RUN pairs, got " +
                             std::to_string(o.runs.size()) + " paths");
  if (o.output.empty())
    throw std::runtime_error("compare: no output directory given (-o DIR)");
  const std::size_t pairs = o.runs.size() / 2;
  const std::vector<std::string> labels = pairLabels(o, pairs);
  std::vector<PairResult> results;
  for (std::size_t p = 0; p < pairs; ++p)
    results.push_back(comparePair(o.runs[2 * p], o.runs[2 * p + 1], labels[p], o.compare));

  const fs::path out(o.output);
  std::vector<nlohmann::json> documents;
  for (const PairResult& r : results) {
    const fs::path dir = pairs == 1 ? out : out / r.label;
    fs::create_directories(dir);
    nlohmann::json j = comparisonJson(r.comparison, r.dem, r.continuum, r.label);
    io::writeTextAtomically((dir / "comparison.csv").string(), comparisonCsv(r.comparison));
    io::writeSummaryJson((dir / "comparison.json").string(), j); // the plot script reads both
    if (o.plots && calibrate::runPlotScript(calibrate::plotScriptPath("plot_compare.py"),
                                            "--dir " + calibrate::shellQuote(dir.string()),
                                            "matplotlib, numpy", "comparison maps")) {
      j["outputs"]["plots"] = "compare_*.png";
      io::writeSummaryJson((dir / "comparison.json").string(), j);
    }
    logPair(r, j);
    documents.push_back(j);
  }
  if (pairs > 1) {
    io::writeTextAtomically((out / "cases.csv").string(), casesCsv(documents));
    io::writeTextAtomically((out / "cases.md").string(), casesMarkdown(documents));
    if (o.plots)
      calibrate::runPlotScript(calibrate::plotScriptPath("plot_compare_cases.py"),
                               "--csv " + calibrate::shellQuote((out / "cases.csv").string()) +
                                   " --out " + calibrate::shellQuote((out / "cases.png").string()),
                               "matplotlib, numpy", "case summary plot");
    spdlog::info("compare: {} cases in {}", pairs, (out / "cases.md").string());
  }
  spdlog::info("compare: outputs in {}", out.string());
  return 0;
}

} // namespace hikiln::compare

namespace hikiln::app {

void addCompareCommand(CLI::App& app, Action& action) {
  auto options = std::make_shared<compare::CompareCommandOptions>();
  auto noPlots = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand(
      "compare", "Compare DEM slices with continuum runs of the same drums (maps, spot values, "
                 "wall slip, bed surface)");
  cmd->add_option("runs", options->runs,
                  "DEM_RUN CONTINUUM_RUN, repeated for several cases (run directories)")
      ->required();
  cmd->add_option("-o,--output", options->output, "Output directory")->required();
  cmd->add_option("--labels", options->labels, "Case names, one per pair (default: DEM run names)")
      ->delimiter(',');
  cmd->add_option("--spot-depth", options->compare.spotDepth,
                  "Height of the spot above the shell bottom [m] (default 0.05 D)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--spot-half-width", options->compare.spotHalfWidth,
                  "Half width of the square spot window [m] (default 0.04 D)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--no-plots", *noPlots, "Skip the PNG maps");
  cmd->callback([&action, options, noPlots] {
    options->plots = !*noPlots;
    action = [options] { return compare::runCompare(*options); };
  });
}

} // namespace hikiln::app
