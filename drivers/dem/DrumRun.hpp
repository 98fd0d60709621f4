#pragma once
/// \file DrumRun.hpp
/// \brief `hikiln dem`: one 2D DEM slice of a rotating drum, from filling to the averaged fields.

#include <string>
#include <vector>

namespace hikiln::dem {

/// \brief Command-line choices of a DEM slice run.
struct DrumRunOptions {
  std::string caseFile;               ///< YAML case (schema: demSchema())
  std::string outputDirectory;        ///< created if missing
  std::vector<std::string> overrides; ///< --set key=value
  bool restart = false;               ///< continue from outputDirectory/checkpoint.h5
};

/// \brief Runs the slice: fill and settle (or restart), rotate with sampling, snapshots,
/// checkpoints, summary.json. Returns the exit code; bad input throws with file/key/reason.
int runDrum(const DrumRunOptions& options);

} // namespace hikiln::dem
