// hikiln: hierarchical simulation of rotary kilns. One program, one sub-command per stage.
#include "drivers/app/Commands.hpp"
#include "drivers/log/Log.hpp"
#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

int main(int argc, char* argv[]) {
  CLI::App app{
      "hikiln " HIKILN_VERSION
      " - hierarchical rotary-kiln simulation: DEM slices -> calibration -> continuum kiln"};
  app.set_version_flag("--version", "hikiln " HIKILN_VERSION);
  std::string logLevel = "info";
  int threads = 0;
  app.add_option("--log-level", logLevel, "trace, debug, info, warn, error or off")
      ->capture_default_str();
  app.add_flag_callback(
      "-v,--verbose", [&] { logLevel = "debug"; }, "Same as --log-level debug");
  app.add_flag_callback(
      "-q,--quiet", [&] { logLevel = "warn"; }, "Same as --log-level warn");
  app.add_option("--threads", threads,
                 "CPU threads for the OpenMP backend (default: OMP_NUM_THREADS or all cores)")
      ->check(CLI::PositiveNumber);
  app.require_subcommand(1);

  hikiln::app::Action action;
  hikiln::app::addInfoCommand(app, action);
  hikiln::app::addDemCommand(app, action);
  hikiln::app::addSweepCommand(app, action);
  hikiln::app::addCalibrateCommand(app, action);
  hikiln::app::addContinuumCommand(app, action);
  hikiln::app::addKilnCommand(app, action);
  hikiln::app::addCompareCommand(app, action);
  hikiln::app::addFitDiffusivityCommand(app, action);
  hikiln::app::addSchemaCommand(app, action);

  CLI11_PARSE(app, argc, argv);

  try {
    hikiln::log::configure(logLevel);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hikiln: %s\n", e.what());
    return 2;
  }
  // Pin OpenMP threads unless the user chose otherwise (also silences Kokkos' warning about it).
  ::setenv("OMP_PROC_BIND", "spread", 0);
  ::setenv("OMP_PLACES", "threads", 0);

  // Kokkos sees only the program name plus what hikiln chose (CLI11 already parsed the rest).
  std::string threadsArgument = hikiln::kokkosThreadsArgument(threads);
  std::vector<char*> kokkosArgv{argv[0]};
  if (threads > 0)
    kokkosArgv.push_back(threadsArgument.data());
  kokkosArgv.push_back(nullptr);
  int kokkosArgc = static_cast<int>(kokkosArgv.size()) - 1;
  Kokkos::ScopeGuard kokkos(kokkosArgc, kokkosArgv.data());
  try {
    return action ? action() : 0;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}
