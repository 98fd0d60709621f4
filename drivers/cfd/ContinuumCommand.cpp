// `hikiln continuum CASE -o DIR`: the 2D two-phase continuum model of a rotating drum.
#include "drivers/app/Commands.hpp"
#include "drivers/cfd/ContinuumRun.hpp"

#include <memory>

namespace hikiln::app {

void addContinuumCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "continuum", "Run the 2D two-phase continuum model of a rotating drum (granular rheology)");
  auto options = std::make_shared<cfd::ContinuumRunOptions>();
  cmd->add_option("case", options->caseFile, "Case file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->outputDirectory, "Output directory")->required();
  cmd->add_option("--set", options->overrides,
                  "Override a case key: --set drum.rpm=6 (repeatable)");
  cmd->callback([&action, options] { action = [options] { return cfd::runContinuum(*options); }; });
}

} // namespace hikiln::app
