#pragma once
/// \file HeatCarryOver.hpp
/// \brief Keeps the thermal state aligned with the DEM system when it rebuilds its neighbour list
/// or reorders its particles: rows follow their particle (matched by id), slot state follows its
/// neighbour (rows of both lists are sorted by neighbour id, so a merge matches them). Only the
/// list's count and index are read (neighbour ids as id(index)).
///
/// A slot whose pair left the list returns its layer (capacity and heat) to the outer shell's
/// bulk, so the carry-over conserves energy. (A touching pair is always in the list, so this only
/// happens when the heat model is stepped less often than the list is rebuilt.)

#include "kernels/common/Compat.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/heat/HeatArrays.hpp"
#include "kernels/dem/heat/HeatParameters.hpp"
#include "kernels/dem/heat/ShellModel.hpp"

#include <Kokkos_Core.hpp>
#include <Kokkos_Sort.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace hikiln::dem {

/// \brief First position in sorted[0, n) whose value is not below key.
template <class View>
KOKKOS_INLINE_FUNCTION int lowerBound(View const& sorted, int n, std::int64_t key) {
  int lo = 0, hi = n;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (sorted(mid) < key) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo;
}

/// \brief origin(i) = the index that particle ids(i) had in previousIds, for i in [0, n) (both
/// hold the same n unique ids in some order). Sorts a copy of previousIds (Kokkos::sort, rare:
/// only after a reorder). Throws when an id is missing.
template <class ExecutionSpace, class MemorySpace>
void matchRowsById(ExecutionSpace const& space,
                   Kokkos::View<std::int64_t*, MemorySpace> const& previousIds,
                   Kokkos::View<std::int64_t*, MemorySpace> const& ids, std::size_t n,
                   Kokkos::View<int*, MemorySpace> const& origin) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::matchRowsById: id memory not accessible");
  using range = Kokkos::RangePolicy<ExecutionSpace>;
  Kokkos::View<std::int64_t*, MemorySpace> sorted(
      Kokkos::view_alloc(space, Kokkos::WithoutInitializing,
                         std::string("hikiln::dem::heat::sortedIds")),
      n);
  Kokkos::View<int*, MemorySpace> rankToRow(
      Kokkos::view_alloc(space, Kokkos::WithoutInitializing,
                         std::string("hikiln::dem::heat::rankToRow")),
      n);
  Kokkos::parallel_for(
      "hikiln::dem::heat::copyIds", range(space, 0, n),
      KOKKOS_LAMBDA(int o) { sorted(o) = previousIds(o); });
  space.fence(); // Kokkos::sort runs on the memory space's default instance
  Kokkos::sort(sorted);
  Kokkos::fence();
  const int count = static_cast<int>(n);
  Kokkos::parallel_for(
      "hikiln::dem::heat::rankRows", range(space, 0, n),
      KOKKOS_LAMBDA(int o) { rankToRow(lowerBound(sorted, count, previousIds(o))) = o; });
  int missing = 0;
  Kokkos::parallel_reduce(
      "hikiln::dem::heat::matchRows", range(space, 0, n),
      KOKKOS_LAMBDA(int i, int& miss) {
        const int r = lowerBound(sorted, count, ids(i));
        if (r < count && sorted(r) == ids(i)) {
          origin(i) = rankToRow(r);
        } else {
          origin(i) = 0;
          ++miss;
        }
      },
      missing);
  if (missing > 0) {
    throw std::runtime_error("hikiln::dem::DemHeat: " + std::to_string(missing) +
                             " particles of the DEM system are unknown to the heat state "
                             "(particles were replaced: initialise the heat model again)");
  }
}

namespace detail {

/// \brief Per-particle body of the carry-over.
template <class MemorySpace> struct HeatCarryFunctor {
  Kokkos::View<int*, MemorySpace> origin; ///< empty: identity
  Kokkos::View<double*, MemorySpace> radius, mass;
  Kokkos::View<std::int64_t*, MemorySpace> id;
  Kokkos::View<int*, MemorySpace> listCount;
  Kokkos::View<int**, MemorySpace> listIndex;
  HeatParticles<MemorySpace> from, to;
  HeatSlots<MemorySpace> oldSlots, newSlots;
  HeatCoefficients c;

  KOKKOS_INLINE_FUNCTION void operator()(int i) const {
    const int o = origin.extent(0) > 0 ? origin(i) : i;
    const int ns = c.shells;
    for (int s = 0; s < ns; ++s) {
      to.temperature(i, s) = from.temperature(o, s);
    }
    to.environmentHeat(i) = from.environmentHeat(o);
    const double bulkTemperature = from.temperature(o, ns - 1);
    const ParticleHeat ph = particleHeat(c, radius(i), mass(i));
    const int newCapacity = newSlots.capacity(), oldCapacity = oldSlots.capacity();
    const int kept = listCount(i) < newCapacity ? listCount(i) : newCapacity;
    const int oldKept = oldSlots.count(o) < oldCapacity ? oldSlots.count(o) : oldCapacity;
    double layerCapacity = 0.0, droppedCapacity = 0.0, droppedHeat = 0.0;
    for (int q = 0; q < oldKept; ++q) {
      layerCapacity += ph.layerCapacityPerArea * oldSlots.area(o, q);
    }
    int q = 0;
    for (int k = 0; k < kept; ++k) {
      const std::int64_t jid = id(listIndex(i, k));
      for (; q < oldKept && oldSlots.neighborId(o, q) < jid; ++q) { // pair left the list
        const double cl = ph.layerCapacityPerArea * oldSlots.area(o, q);
        droppedCapacity += cl;
        droppedHeat += cl * oldSlots.layerSelf(o, q);
      }
      newSlots.neighborId(i, k) = jid;
      if (q < oldKept && oldSlots.neighborId(o, q) == jid) {
        newSlots.layerSelf(i, k) = oldSlots.layerSelf(o, q);
        newSlots.layerOther(i, k) = oldSlots.layerOther(o, q);
        newSlots.area(i, k) = oldSlots.area(o, q);
        ++q;
      } else { // a new pair: no layer yet
        newSlots.layerSelf(i, k) = bulkTemperature;
        newSlots.layerOther(i, k) = bulkTemperature;
        newSlots.area(i, k) = 0.0;
      }
    }
    for (; q < oldKept; ++q) {
      const double cl = ph.layerCapacityPerArea * oldSlots.area(o, q);
      droppedCapacity += cl;
      droppedHeat += cl * oldSlots.layerSelf(o, q);
    }
    newSlots.count(i) = kept;
    if (droppedCapacity > 0.0) { // dissolve the dropped layers into the bulk
      const double bulk = ph.outerCapacity - layerCapacity;
      to.temperature(i, ns - 1) = (bulk * bulkTemperature + droppedHeat) / (bulk + droppedCapacity);
    }
  }
};

} // namespace detail

/// \brief Carries the thermal state over to the DEM system's current order and neighbour list:
/// row i of `to`/`newSlots` receives row origin(i) of `from`/`oldSlots` (origin empty: the same
/// row), its slots matched to list row i by neighbour id. `to`/`newSlots` must not alias the
/// sources; newSlots needs at least list.rows() rows.
template <class ExecutionSpace, class MemorySpace>
void carryHeatState(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                    NeighborList<MemorySpace> const& list, HeatCoefficients const& coefficients,
                    Kokkos::View<int*, MemorySpace> const& origin,
                    HeatParticles<MemorySpace> const& from, HeatSlots<MemorySpace> const& oldSlots,
                    HeatParticles<MemorySpace> const& to, HeatSlots<MemorySpace> const& newSlots) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::carryHeatState: heat memory not accessible");
  detail::HeatCarryFunctor<MemorySpace> f;
  f.origin = origin;
  f.radius = p.radius;
  f.mass = p.mass;
  f.id = p.id;
  f.listCount = list.count;
  f.listIndex = list.index;
  f.from = from;
  f.to = to;
  f.oldSlots = oldSlots;
  f.newSlots = newSlots;
  f.c = coefficients;
  Kokkos::parallel_for("hikiln::dem::heat::carryOver",
                       Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()), f);
}

} // namespace hikiln::dem
