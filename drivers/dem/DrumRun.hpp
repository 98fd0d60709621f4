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

/// \brief Runs several slices (the cases of a sweep) with their rotation batched: each is set up
/// (or restored) as runDrum() does, then the slices that can (disc particles, no heat, no rough
/// drum, the first batchable slice's time step) rotate together as one DemBatch
/// (solvers/dem/DemBatch.hpp), each writing its own outputs, bitwise the same trajectories as
/// alone; the others then run alone. Returns the exit code.
int runDrumBatch(const std::vector<DrumRunOptions>& runs);

} // namespace hikiln::dem
