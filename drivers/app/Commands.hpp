#pragma once
/// \file Commands.hpp
/// \brief Sub-commands of the `hikiln` program. Each stage adds one with add*Command(app, action):
/// it declares its options on a CLI11 sub-command and, when chosen, stores in `action` the work to
/// do once Kokkos is initialised.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace hikiln::app {

/// \brief The work a chosen sub-command runs; returns the process exit code.
using Action = std::function<int()>;

/// \brief `hikiln info`: versions, enabled backends, threads, GPU.
void addInfoCommand(CLI::App& app, Action& action);

/// \brief `hikiln calibrate`: fit the continuum rheology to DEM averaged fields.
void addCalibrateCommand(CLI::App& app, Action& action);

/// \brief `hikiln dem CASE -o DIR`: one 2D DEM slice of a rotating drum.
void addDemCommand(CLI::App& app, Action& action);

/// \brief `hikiln sweep STUDY -o DIR`: a resumable DEM parameter study.
void addSweepCommand(CLI::App& app, Action& action);

/// \brief `hikiln continuum CASE -o DIR`: the 2D two-phase continuum model of a drum.
void addContinuumCommand(CLI::App& app, Action& action);

/// \brief `hikiln kiln CASE -o DIR`: the 3D two-phase continuum model of a rotary kiln.
void addKilnCommand(CLI::App& app, Action& action);

/// \brief `hikiln compare DEM_RUN CONTINUUM_RUN... -o DIR`: DEM vs continuum (physics.md 5).
void addCompareCommand(CLI::App& app, Action& action);

/// \brief `hikiln fit-diffusivity DEM_RUN -o DIR` (drivers/fit/FitDiffusivity.hpp).
void addFitDiffusivityCommand(CLI::App& app, Action& action);

/// \brief `hikiln schema STAGE`: the case-file reference of a stage.
void addSchemaCommand(CLI::App& app, Action& action);

/// \brief Names of the Kokkos backends compiled in ("Serial", "OpenMP", "Cuda").
std::vector<std::string> enabledBackends();

/// \brief Name of the execution space hikiln runs its kernels on by default.
std::string defaultBackend();

} // namespace hikiln::app
