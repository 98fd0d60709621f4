#pragma once
/// \file DemCase.hpp
/// \brief The `hikiln dem` case file: its schema and the run settings read from it.

#include "drivers/case/CaseFile.hpp"
#include "drivers/case/CaseSchema.hpp"
#include "drivers/dem/HeatCase.hpp"
#include "solvers/dem/DemSystem.hpp"
#include "solvers/dem/DrumFill.hpp"

namespace hikiln::dem {

/// \brief Everything a DEM drum slice needs, in SI units.
struct DrumRunSettings {
  FillSpec fill;                    ///< drum radius, fill, particle sizes and material
  DemConfig config;                 ///< contact laws, time step, neighbours, gravity, walls
  double rpm = 3.0;                 ///< drum speed (rev/min)
  double settleTime = 1.0;          ///< s, before and again after trimming to the fill
  double settleDamping = 0.0;       ///< 1/s, motion removed while settling (0: none)
  double duration = 60.0;           ///< s of rotation
  double spinUp = 5.0;              ///< s of rotation before averages start
  double sampleInterval = 0.05;     ///< s between samples (slip, angle, averages)
  double snapshotInterval = 1.0;    ///< s between particle snapshots
  double checkpointInterval = 10.0; ///< s between checkpoints
  double averageInterval = 10.0;    ///< s between writes of the cumulative averages
  DrumHeatSettings heat;            ///< particle heat transfer (heat.*)
  /// \brief Drum angular velocity (rad/s, counter-clockwise).
  double omega() const { return rpm * 2.0 * constants::pi / 60.0; }
};

/// \brief Schema of the `hikiln dem` case file (keys, units, ranges, defaults: physics.md 1).
const cases::CaseSchema& demSchema();

/// \brief Run settings from a validated case file.
DrumRunSettings drumSettingsFromCase(const cases::CaseFile& file);

} // namespace hikiln::dem
