#pragma once
/// \file CompareInputs.hpp
/// \brief What `hikiln compare` reads from a DEM run (averages.h5, summary.json) and from a
/// continuum run (fields_NNNN.h5, summary.json), and the checks that both are the same drum.

#include "drivers/compare/Regrid.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace hikiln::compare {

/// \brief The drum a run simulated, as its case requested it.
struct DrumConditions {
  double diameter = 0.0; ///< m
  double rpm = 0.0;      ///< rev/min
  double fill = 0.0;     ///< requested fill fraction
};

/// \brief Cell maps on one grid, [ny][nx] with x fastest; NaN where a value does not exist.
struct CellMaps {
  CellGrid grid;
  std::map<std::string, std::vector<double>> fields;
  std::vector<std::uint8_t> valid; ///< cells the comparison may use
};

/// \brief A DEM run's time-averaged Cartesian fields and wall slip.
struct DemRun {
  std::string directory, averagesFile;
  DrumConditions drum;                 ///< diameter and rpm from the file's drum_radius and omega
  double measuredFill = 0.0;           ///< the file's `fill` (measured)
  double centreX = 0.0, centreY = 0.0; ///< drum axis: the middle of the Cartesian grid
  double minVolumeFraction = 0.5;      ///< the `valid` filter's volume fraction threshold
  double averageStart = 0.0, averageEnd = 0.0; ///< s of rotation
  std::int64_t samples = 0;
  double slipPercent = 0.0;      ///< /wall slip_percent
  double summarySurfaceAngleDeg; ///< summary.json surface_angle_deg.mean (NaN when absent)
  /// volume_fraction, velocity_x, velocity_y, pressure, shear_stress, strain_rate, viscosity;
  /// valid = the file's `valid`
  CellMaps maps;
};

/// \brief A continuum run's outputs, time-averaged on its own grid.
struct ContinuumRun {
  std::string directory;
  DrumConditions drum;
  double slipAfter = 0.0;            ///< s, time.slip_after
  CellGrid grid;                     ///< the run's grid, drum axis at (0, 0)
  std::vector<double> outputTimes;   ///< every fields_NNNN.h5, in order
  std::vector<double> averagedTimes; ///< the outputs averaged below
  std::string averaging;             ///< which outputs were averaged and why
  /// time means of: volume_fraction (phi), phi u, phi v, bed_pressure, shear_stress, and the
  /// (constant) capacity; keys "volume_fraction", "momentum_x", "momentum_y", "bed_pressure",
  /// "shear_stress", "capacity"
  std::map<std::string, std::vector<double>> means;
  double slipPercent;     ///< NaN when the run has no slip value
  std::string slipSource; ///< where slipPercent came from
};

/// \brief Reads a DEM run directory (or its averages.h5). Throws std::runtime_error naming the
/// file and the reason (missing directory, file, group, dataset or attribute; not a DEM file).
DemRun readDemRun(const std::string& path);

/// \brief Reads a continuum run directory and time-averages its outputs after time.slip_after
/// (the outputs its summary.json averages the wall slip over), or takes the last output when
/// none is that late. Throws std::runtime_error naming the file and the reason.
ContinuumRun readContinuumRun(const std::string& path);

/// \brief Throws std::runtime_error listing every difference when the two runs are not the same
/// drum (diameter and rpm to 1e-6 relative, requested fill to 1e-6).
void requireSameDrum(const DemRun& dem, const ContinuumRun& continuum);

/// \brief `drum.diameter`, `drum.rpm` and `drum.fill` of a resolved case (YAML text); `what`
/// names its origin in errors.
DrumConditions drumOfResolvedCase(const std::string& yaml, const std::string& what);

} // namespace hikiln::compare
