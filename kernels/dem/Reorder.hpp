#pragma once
/// \file Reorder.hpp
/// \brief Reordering of particles (e.g. by cell, for memory locality) together with their contact
/// history rows. History rows store neighbour ids, so they stay valid; the neighbour indices do
/// not, and the list must be rebuilt after a reorder (buildNeighborList() carries the history
/// over).

#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem {

/// \brief dst(k) = src(permutation(k)) for every particle field, k in [0, src.count()); dst must
/// have at least that capacity and must not alias src. dst's count is set to src's.
template <class ExecutionSpace, class MemorySpace, class PermutationView>
void permuteParticles(ExecutionSpace const& space, PermutationView const& permutation,
                      ParticleArrays<MemorySpace> const& src, ParticleArrays<MemorySpace>& dst) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::permuteParticles: particle memory not accessible");
  dst.setCount(src.count());
  const ParticleArrays<MemorySpace> s = src;
  const ParticleArrays<MemorySpace> d = dst;
  Kokkos::parallel_for(
      "hikiln::dem::permuteParticles", Kokkos::RangePolicy<ExecutionSpace>(space, 0, src.count()),
      KOKKOS_LAMBDA(int k) {
        const int o = permutation(k);
        for (int c = 0; c < 2; ++c) {
          d.position(k, c) = s.position(o, c);
          d.velocity(k, c) = s.velocity(o, c);
          d.force(k, c) = s.force(o, c);
        }
        d.angularVelocity(k) = s.angularVelocity(o);
        d.torque(k) = s.torque(o);
        d.radius(k) = s.radius(o);
        d.mass(k) = s.mass(o);
        d.inertia(k) = s.inertia(o);
        d.inverseMass(k) = s.inverseMass(o);
        d.inverseInertia(k) = s.inverseInertia(o);
        d.id(k) = s.id(o);
      });
}

/// \brief Row k of the destination history = row permutation(k) of the source, for the neighbour
/// list (count, ids, shear, last forces; not the stale indices) and the wall contact state.
template <class ExecutionSpace, class MemorySpace, class PermutationView>
void permuteContactRows(ExecutionSpace const& space, PermutationView const& permutation,
                        std::size_t n, NeighborList<MemorySpace> const& src,
                        NeighborList<MemorySpace> const& dst,
                        WallContactState<MemorySpace> const& wallSrc,
                        WallContactState<MemorySpace> const& wallDst) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::permuteContactRows: list memory not accessible");
  const int capacity = src.capacity() < dst.capacity() ? src.capacity() : dst.capacity();
  Kokkos::parallel_for(
      "hikiln::dem::permuteContactRows", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int k) {
        const int o = permutation(k);
        dst.count(k) = src.count(o);
        for (int m = 0; m < capacity; ++m) {
          dst.neighborId(k, m) = src.neighborId(o, m);
          dst.shear(k, m) = src.shear(o, m);
          dst.normalForce(k, m) = src.normalForce(o, m);
          dst.tangentialForce(k, m) = src.tangentialForce(o, m);
        }
        for (int m = 0; m < wallSlotCount; ++m) {
          wallDst.shear(k, m) = wallSrc.shear(o, m);
          wallDst.normalForce(k, m) = wallSrc.normalForce(o, m);
          wallDst.tangentialForce(k, m) = wallSrc.tangentialForce(o, m);
        }
      });
}

} // namespace hikiln::dem
