#pragma once
/// \file CompareCommand.hpp
/// \brief `hikiln compare DEM_RUN CONTINUUM_RUN [DEM_RUN CONTINUUM_RUN ...] -o OUT`: the
/// physics.md section 5 comparison of DEM slices with continuum runs of the same drums.

#include "drivers/compare/FieldComparison.hpp"

#include <string>
#include <vector>

namespace hikiln::compare {

/// \brief The command's options.
struct CompareCommandOptions {
  std::vector<std::string> runs;   ///< DEM run, continuum run, DEM run, continuum run, ...
  std::string output;              ///< output directory
  std::vector<std::string> labels; ///< one per pair; default: the DEM run's directory name
  CompareOptions compare;
  bool plots = true;
};

/// \brief Reads and checks every pair first (nothing is written when one is bad), then writes
/// comparison.json, comparison.csv and the PNG maps: into OUT for one pair, into OUT/LABEL per
/// pair plus cases.csv, cases.md and cases.png in OUT for several. Returns 0; throws
/// std::runtime_error naming the file and the reason for bad input.
int runCompare(const CompareCommandOptions& options);

} // namespace hikiln::compare
