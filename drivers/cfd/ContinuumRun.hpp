#pragma once
/// \file ContinuumRun.hpp
/// \brief `hikiln continuum CASE -o DIR`: the 2D two-phase continuum model of a rotating drum
/// (solvers/cfd/TwoPhaseSolver.hpp) from a flat bed at rest; writes fields.xmf + fields_NNNN.h5
/// (cell fields), timeseries.csv, case.resolved.yaml and summary.json (wall slip, solids
/// conservation, time-step limits, timing).

#include <string>
#include <vector>

namespace hikiln::cfd {

/// \brief Command-line options of `hikiln continuum`.
struct ContinuumRunOptions {
  std::string caseFile;
  std::string outputDirectory;
  std::vector<std::string> overrides; ///< --set key=value
};

/// \brief Runs the case; returns the process exit code (throws on bad input).
int runContinuum(ContinuumRunOptions const& options);

} // namespace hikiln::cfd
