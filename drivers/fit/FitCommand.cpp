// `hikiln fit-diffusivity DEM_RUN -o DIR`: fits the continuum bed diffusivity to a DEM mixing run.
#include "drivers/app/Commands.hpp"
#include "drivers/fit/FitDiffusivity.hpp"

#include <memory>

namespace hikiln::app {

void addFitDiffusivityCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "fit-diffusivity",
      "Fit the continuum bed diffusivity alpha_eff to a DEM thermal mixing run (physics.md 6.3)");
  auto o = std::make_shared<fit::FitOptions>();
  cmd->add_option("dem_run", o->demRun, "Run directory of `hikiln dem` with heat.enabled: true")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", o->outputDirectory, "Output directory")->required();
  cmd->add_option("--case", o->caseFile,
                  "Continuum case file for numerics and rheology (drum and material come from "
                  "the DEM run)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", o->overrides, "Override a continuum case key (repeatable)");
  cmd->add_option("--alphas", o->alphas,
                  "Candidate alpha_eff values in m^2/s (default 9 values, 1e-7 .. 1e-3)")
      ->delimiter(',');
  cmd->add_option("--duration", o->duration, "Seconds of rotation compared (default 30)");
  cmd->add_option("--block", o->blockFactor,
                  "Continuum cells per comparison block side (default 2)")
      ->check(CLI::PositiveNumber);
  cmd->callback([&action, o] { action = [o] { return fit::runFitDiffusivity(*o); }; });
}

} // namespace hikiln::app
