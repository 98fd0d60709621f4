#pragma once
/// \file DemHeatState.hpp
/// \brief Host copy of the thermal state of a DEM heat run, keyed by particle id (for
/// checkpoints): importing it into a DemHeat attached to the same particles continues the run.

#include <cstdint>
#include <vector>

namespace hikiln::dem {

/// \brief Thermal state by particle id; per-contact layers only for touching pairs (others carry
/// nothing: a new contact's layers start from the bulk).
struct DemHeatState {
  int shells = 0;             ///< shells per particle
  double time = 0.0;          ///< heat time advanced so far (s)
  std::int64_t subSteps = 0;  ///< heat sub-steps taken so far
  double initialEnergy = 0.0; ///< heat content at initialisation (J), the drift reference
  /// Heat sub-step limit in use (s), fixed at initialisation (it depends on the temperatures and
  /// the list width then): a restart keeps it, so it splits steps as the first run did. 0: unknown.
  double stableTimeStep = 0.0;
  std::vector<std::int64_t> id;        ///< particle ids
  std::vector<double> temperature;     ///< id.size() x shells, particle-major, centre first (K)
  std::vector<double> environmentHeat; ///< J received from the environment, per particle
  std::vector<std::int64_t> contactId; ///< particle owning the layer
  std::vector<std::int64_t> contactNeighborId; ///< its neighbour
  std::vector<double> contactArea;             ///< real contact area (m^2)
  std::vector<double> contactLayer;            ///< the owner's layer temperature (K)
  std::vector<double> contactLayerOther;       ///< the neighbour's layer temperature (K)

  /// \brief Number of particles.
  std::size_t size() const { return id.size(); }
};

} // namespace hikiln::dem
