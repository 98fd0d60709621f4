// `hikiln kiln CASE -o DIR`: the 3D two-phase continuum model of a rotary kiln.
#include "drivers/app/Commands.hpp"
#include "drivers/cfd/KilnRun.hpp"

#include <memory>

namespace hikiln::app {

void addKilnCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "kiln", "Run the 3D two-phase continuum model of a rotary kiln (feed, air, discharge, dam)");
  auto options = std::make_shared<cfd::KilnRunOptions>();
  cmd->add_option("case", options->caseFile, "Case file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->outputDirectory, "Output directory")->required();
  cmd->add_option("--set", options->overrides,
                  "Override a case key: --set kiln.rpm=2 (repeatable)");
  cmd->callback([&action, options] { action = [options] { return cfd::runKiln(*options); }; });
}

} // namespace hikiln::app
