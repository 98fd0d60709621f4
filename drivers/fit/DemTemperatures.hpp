#pragma once
/// \file DemTemperatures.hpp
/// \brief The particle temperatures of a `hikiln dem` run with heat (its snapshots), read for
/// `hikiln fit-diffusivity`: each snapshot's centres, radii, kinds and mean temperatures at its
/// ROTATION time (heat starts with the rotation; heat_timeseries.csv gives the offset).

#include "drivers/dem/DemCase.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hikiln::fit {

/// \brief One particle snapshot of a DEM run.
struct ParticleTemperatureSnapshot {
  double rotationTime = 0.0; ///< s since the drum started turning (and the heat with it)
  std::vector<double> x, y, radius, temperature;
  std::vector<std::uint8_t> kind; ///< dem::ParticleKind (0 free)
};

/// \brief A DEM run directory with heat on: its settings and its snapshots in time order.
struct DemThermalRun {
  std::string directory;
  dem::DrumRunSettings settings;
  std::vector<ParticleTemperatureSnapshot> snapshots;
};

/// \brief Reads `directory` (case.resolved.yaml, heat_timeseries.csv, snapshots/*.h5). Throws
/// std::runtime_error naming the file and the reason: missing files, heat off, a left/right
/// initial field missing, snapshots without temperatures.
DemThermalRun readDemThermalRun(const std::string& directory);

} // namespace hikiln::fit
