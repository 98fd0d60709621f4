// `hikiln sweep STUDY -o DIR`: a DEM parameter study, one slice per case, resumable.
#include "drivers/app/Commands.hpp"
#include "drivers/dem/DrumRun.hpp"
#include "drivers/dem/SweepStudy.hpp"
#include "drivers/io/AtomicFile.hpp"
#include "drivers/io/Summary.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <memory>

namespace hikiln::app {

namespace {
namespace fs = std::filesystem;

struct SweepOptions {
  std::string study;
  std::string output;
  std::vector<std::string> overrides;
  std::vector<std::string> only;
  bool batch = false;
};

bool finished(const fs::path& dir) {
  return fs::exists(dir / "summary.json");
}

/// One CSV row per finished case with the figures a study compares.
void writeTable(const fs::path& out, const dem::SweepStudy& study) {
  const char* columns[] = {
      "particles",         "fill_measured",         "wall_slip_percent",    "wall_slip_std_percent",
      "surface_angle_deg", "surface_angle_std_deg", "particle_steps_per_s", "wall_time_s"};
  std::string csv = "case";
  for (const char* c : columns)
    csv += std::string(",") + c;
  csv += "\n";
  nlohmann::json all = nlohmann::json::object();
  for (const auto& c : study.cases) {
    const fs::path dir = out / c.name;
    if (!finished(dir))
      continue;
    const auto s = io::readSummaryJson((dir / "summary.json").string());
    all[c.name] = s;
    csv += c.name;
    for (const char* col : columns) {
      csv += ",";
      if (s.contains(col) && s[col].is_number())
        csv += fmt::format("{:.6g}", s[col].get<double>());
    }
    csv += "\n";
  }
  io::writeTextAtomically((out / "sweep.csv").string(), csv);
  io::writeSummaryJson((out / "summary.json").string(),
                       {{"stage", "sweep"}, {"study", study.source}, {"cases", all}});
}

int runSweep(const SweepOptions& o) {
  const auto study = dem::loadSweepStudy(o.study, o.overrides);
  const fs::path out(o.output);
  fs::create_directories(out);
  int done = 0, ran = 0;
  std::vector<dem::DrumRunOptions> pending; // --batch: run together at the end
  for (const auto& c : study.cases) {
    if (!o.only.empty() && std::find(o.only.begin(), o.only.end(), c.name) == o.only.end())
      continue;
    const fs::path dir = out / c.name;
    if (finished(dir)) {
      spdlog::info("sweep: case '{}' already finished ({}), skipped", c.name, dir.string());
      ++done;
      continue;
    }
    dem::DrumRunOptions run;
    run.caseFile = study.baseCase;
    run.outputDirectory = dir.string();
    run.overrides = c.overrides;
    run.restart = fs::exists(dir / "checkpoint.h5");
    spdlog::info("sweep: case '{}' ({}){}", c.name, fmt::join(c.overrides, " "),
                 run.restart ? ", resuming from its checkpoint" : "");
    ++ran;
    if (o.batch) {
      pending.push_back(run);
      continue;
    }
    dem::runDrum(run);
    writeTable(out, study);
  }
  if (!pending.empty())
    dem::runDrumBatch(pending);
  writeTable(out, study);
  spdlog::info("sweep: {} cases run, {} already done; table in {}", ran, done,
               (out / "sweep.csv").string());
  return 0;
}
} // namespace

void addSweepCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "sweep", "Run a DEM parameter study: one slice per case, each in its own folder; resumable");
  auto o = std::make_shared<SweepOptions>();
  cmd->add_option("study", o->study, "Study file (YAML: base, defaults, cases)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", o->output, "Output directory (one sub-folder per case)")
      ->required();
  cmd->add_option("--set", o->overrides, "Override a key in every case (repeatable)");
  cmd->add_option("--only", o->only, "Run only these cases (repeatable)");
  cmd->add_flag("--batch", o->batch,
                "Rotate the cases together as one batch (one set of kernel launches for all "
                "slices; disc cases without heat or rough drum, sharing one time step; the others "
                "run alone). Each case's trajectory is the same as run alone");
  cmd->callback([&action, o] { action = [o] { return runSweep(*o); }; });
}

} // namespace hikiln::app
