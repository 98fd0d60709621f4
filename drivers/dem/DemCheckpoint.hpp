#pragma once
/// \file DemCheckpoint.hpp
/// \brief DemState <-> hikiln::io::Checkpoint, so a DEM run can stop and continue bitwise
/// identically.

#include "drivers/io/Checkpoint.hpp"
#include "solvers/dem/DemState.hpp"
#include "solvers/dem/heat/DemHeatState.hpp"

namespace hikiln::dem {

/// \brief Packs a DEM state (and the caller's extra scalars) into a checkpoint.
io::Checkpoint toCheckpoint(const DemState& state, const std::string& stage);

/// \brief Unpacks the DEM state of a checkpoint; throws std::runtime_error naming a missing array.
DemState fromCheckpoint(const io::Checkpoint& checkpoint);

/// \brief Adds a heat state to a checkpoint (arrays and scalars named heat_*).
void addHeatState(io::Checkpoint& checkpoint, const DemHeatState& state);

/// \brief Whether a checkpoint holds a heat state.
bool hasHeatState(const io::Checkpoint& checkpoint);

/// \brief Unpacks the heat state of a checkpoint; throws std::runtime_error naming a missing entry.
DemHeatState heatStateFromCheckpoint(const io::Checkpoint& checkpoint);

} // namespace hikiln::dem
