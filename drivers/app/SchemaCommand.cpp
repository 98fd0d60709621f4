// `hikiln schema STAGE`: the case-file reference of a stage (Markdown), generated from its schema
// so the documentation can never drift from what the program accepts.
#include "drivers/app/Commands.hpp"
#include "drivers/cfd/ContinuumCase.hpp"
#include "drivers/cfd/KilnCase.hpp"
#include "drivers/dem/DemCase.hpp"

#include <iostream>
#include <memory>

namespace hikiln::app {

void addSchemaCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("schema", "Print the case-file reference of a stage (Markdown)");
  auto stage = std::make_shared<std::string>();
  cmd->add_option("stage", *stage, "Stage")
      ->required()
      ->check(CLI::IsMember({"dem", "continuum", "kiln"}));
  cmd->callback([&action, stage] {
    action = [stage] {
      const cases::CaseSchema& schema = *stage == "continuum" ? cfd::continuumSchema()
                                        : *stage == "kiln"    ? cfd::kilnSchema()
                                                              : dem::demSchema();
      std::cout << schema.markdownReference();
      return 0;
    };
  });
}

} // namespace hikiln::app
