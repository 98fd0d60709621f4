#pragma once
/// \file CalibrateCommand.hpp
/// \brief `hikiln calibrate RUN_DIR... -o rheology.yaml`: fits the continuum rheology to the
/// averaged fields of DEM calibration runs (physics.md section 4).

#include "drivers/calibrate/AveragesReader.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace hikiln::calibrate {

/// \brief Everything the calibrate command needs (its command-line options).
struct CalibrateOptions {
  std::vector<std::string> runs; ///< run directories (or averages.h5 files)
  std::string output;            ///< the rheology file to write; other outputs go next to it
  AveragesGrid grid = AveragesGrid::Polar;
  double minStrainRate = 1e-2; ///< [1/s] selection floor, also the law's regularisation floor
  std::size_t minCells = 10;   ///< fewest selected cells a run may contribute
  std::string plotDir;         ///< where PNG plots go; empty: no plots
  bool fitMuI = true;          ///< also fit the mu(I) form
};

/// \brief Reads the runs, fits, and writes rheology.yaml (at options.output), calibration.csv,
/// calibration.json and summary.json (next to it), then the plots if asked. Returns 0; throws
/// std::runtime_error naming the file and the reason for bad input (missing averages.h5, dataset
/// or attribute, too few valid cells) or an output directory that is one of the runs.
int runCalibrate(const CalibrateOptions& options);

} // namespace hikiln::calibrate
