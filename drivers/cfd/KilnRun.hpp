#pragma once
/// \file KilnRun.hpp
/// \brief `hikiln kiln CASE -o DIR`: the 3D two-phase continuum model of a rotary kiln with its
/// solids feed, air inlet, open discharge and dam ring (physics.md 7; solvers/cfd/TwoPhaseSolver
/// with OpenSides). Writes fields.xmf + fields_NNNN.h5 (3D cell fields), timeseries.csv (hold-up
/// and solids mass balance), case.resolved.yaml and summary.json.

#include <string>
#include <vector>

namespace hikiln::cfd {

/// \brief Command-line options of `hikiln kiln`.
struct KilnRunOptions {
  std::string caseFile;
  std::string outputDirectory;
  std::vector<std::string> overrides; ///< --set key=value
};

/// \brief Runs the case; returns the process exit code (throws on bad input).
int runKiln(KilnRunOptions const& options);

} // namespace hikiln::cfd
