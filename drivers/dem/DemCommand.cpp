// `hikiln dem CASE -o DIR`: one DEM slice of a rotating drum.
#include "drivers/app/Commands.hpp"
#include "drivers/dem/DrumRun.hpp"

#include <memory>

namespace hikiln::app {

void addDemCommand(CLI::App& app, Action& action) {
  auto* cmd =
      app.add_subcommand("dem", "Run a 2D DEM slice of a rotating drum (fill, settle, rotate)");
  auto options = std::make_shared<dem::DrumRunOptions>();
  cmd->add_option("case", options->caseFile, "Case file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->outputDirectory, "Output directory")->required();
  cmd->add_option("--set", options->overrides,
                  "Override a case key: --set drum.rpm=6 (repeatable)");
  cmd->add_flag("--restart", options->restart,
                "Continue the run from OUTPUT/checkpoint.h5 (same case and --set options)");
  cmd->callback([&action, options] { action = [options] { return dem::runDrum(*options); }; });
}

} // namespace hikiln::app
