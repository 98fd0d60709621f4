#pragma once
/// \file HeatArrays.hpp
/// \brief Thermal state of the DEM particles: shell temperatures per particle and boundary-layer
/// state per neighbour slot, with rows in the particle order of the DEM system.
///
/// Slot (i, k) belongs to the pair (particle i, its k-th neighbour in the DEM neighbour list) and
/// keeps both layers of the contact: layerSelf (i's side) and layerOther (the neighbour's side).
/// The neighbour's row holds the mirror copy; while the slot has a layer (area > 0) both copies
/// evolve bitwise identically because every pair quantity is computed from the lower-id side (like
/// the DEM's shear history).

#include "kernels/dem/heat/HeatParameters.hpp"
#include "kernels/dem/heat/ShellModel.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>
#include <string>

namespace hikiln::dem {

/// \brief Per-slot boundary-layer state, rows aligned with a NeighborList (sorted by neighbour id).
template <class MemorySpace> struct HeatSlots {
  using memory_space = MemorySpace;
  Kokkos::View<int*, MemorySpace> count;                ///< slots in use per row
  Kokkos::View<std::int64_t**, MemorySpace> neighborId; ///< neighbour id of the slot
  Kokkos::View<double**, MemorySpace> layerSelf;        ///< this particle's layer temperature (K)
  Kokkos::View<double**, MemorySpace> layerOther;       ///< the neighbour's layer temperature (K)
  Kokkos::View<double**, MemorySpace> area; ///< real contact area of the last sub-step (m^2)

  HeatSlots() = default;
  /// \brief Zero-filled slots: `rows` rows of `capacity`; props go to Kokkos::view_alloc.
  template <class... Props>
  HeatSlots(std::size_t rows, int capacity, Props const&... props)
      : count(Kokkos::view_alloc(props..., std::string("hikiln::dem::heat::slotCount")), rows),
        neighborId(Kokkos::view_alloc(props..., std::string("hikiln::dem::heat::slotId")), rows,
                   capacity),
        layerSelf(Kokkos::view_alloc(props..., std::string("hikiln::dem::heat::layerSelf")), rows,
                  capacity),
        layerOther(Kokkos::view_alloc(props..., std::string("hikiln::dem::heat::layerOther")), rows,
                   capacity),
        area(Kokkos::view_alloc(props..., std::string("hikiln::dem::heat::contactArea")), rows,
             capacity) {}

  /// \brief Slots per row.
  KOKKOS_INLINE_FUNCTION int capacity() const { return static_cast<int>(area.extent(1)); }
  /// \brief Rows allocated.
  KOKKOS_INLINE_FUNCTION std::size_t rows() const { return count.extent(0); }
};

/// \brief Per-particle thermal state: shell temperatures (row i: shells from the centre out) and
/// the heat received from the environment so far.
template <class MemorySpace> struct HeatParticles {
  using memory_space = MemorySpace;
  Kokkos::View<double**, MemorySpace> temperature;    ///< n x shells (K)
  Kokkos::View<double*, MemorySpace> environmentHeat; ///< J received from the environment

  HeatParticles() = default;
  /// \brief Zero-filled state of n particles with `shells` shells; props go to view_alloc.
  template <class... Props>
  HeatParticles(std::size_t n, int shells, Props const&... props)
      : temperature(Kokkos::view_alloc(props..., std::string("hikiln::dem::heat::temperature")), n,
                    shells),
        environmentHeat(
            Kokkos::view_alloc(props..., std::string("hikiln::dem::heat::environmentHeat")), n) {}

  /// \brief Shells per particle.
  KOKKOS_INLINE_FUNCTION int shells() const { return static_cast<int>(temperature.extent(1)); }
  /// \brief Rows allocated.
  KOKKOS_INLINE_FUNCTION std::size_t rows() const { return temperature.extent(0); }
};

/// \brief Constants the heat kernels read instead of recomputing them: per-particle constants
/// (rows aligned with the thermal state) and the shell tables shared by all particles.
template <class MemorySpace> struct HeatModelViews {
  using memory_space = MemorySpace;
  Kokkos::View<ParticleHeat*, MemorySpace> particle;  ///< per row, from radius and mass
  Kokkos::View<double*, MemorySpace> inverseFraction; ///< 1 / volume fraction of shell m
  Kokkos::View<double*, MemorySpace> faceConductance; ///< k shellFaceFactor(f); entry 0 unused
};

/// \brief Allocates the model views for `rows` particles and fills the shell tables (host work,
/// copied to MemorySpace); the particle constants are filled by computeParticleHeat().
template <class MemorySpace, class ExecutionSpace>
HeatModelViews<MemorySpace> makeHeatModelViews(ExecutionSpace const& space,
                                               HeatCoefficients const& c, std::size_t rows) {
  HeatModelViews<MemorySpace> v;
  v.particle = Kokkos::View<ParticleHeat*, MemorySpace>(
      Kokkos::view_alloc(space, std::string("hikiln::dem::heat::particleConstants")), rows);
  Kokkos::View<double*, Kokkos::HostSpace> fraction("hikiln::dem::heat::inverseFractionHost",
                                                    c.shells);
  Kokkos::View<double*, Kokkos::HostSpace> face("hikiln::dem::heat::faceConductanceHost", c.shells);
  for (int m = 0; m < c.shells; ++m) {
    fraction(m) = 1.0 / shellVolumeFraction(c.geometry, c.shells, m);
    face(m) = m > 0 ? c.conductivity * shellFaceFactor(c.geometry, c.shells, m, c.thickness) : 0.0;
  }
  v.inverseFraction = Kokkos::create_mirror_view_and_copy(MemorySpace{}, fraction);
  v.faceConductance = Kokkos::create_mirror_view_and_copy(MemorySpace{}, face);
  return v;
}

/// \brief particle(i) = particleHeat(radius(i), mass(i)) for rows [0, n).
template <class ExecutionSpace, class MemorySpace>
void computeParticleHeat(ExecutionSpace const& space,
                         Kokkos::View<double*, MemorySpace> const& radius,
                         Kokkos::View<double*, MemorySpace> const& mass, std::size_t n,
                         HeatCoefficients const& c,
                         Kokkos::View<ParticleHeat*, MemorySpace> const& particle) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::computeParticleHeat: memory not accessible");
  Kokkos::parallel_for(
      "hikiln::dem::heat::particleConstants", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) { particle(i) = particleHeat(c, radius(i), mass(i)); });
}

} // namespace hikiln::dem
