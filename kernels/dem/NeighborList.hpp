#pragma once
/// \file NeighborList.hpp
/// \brief Full neighbour list with fixed-capacity slots per particle and per-slot contact history.
///
/// Every pair closer than r_i + r_j + skin appears in the rows of both particles. A row is sorted
/// by neighbour id, so the order in which a particle sums its contact forces depends neither on
/// particle indices nor on when the list was rebuilt: results are bitwise reproducible across
/// thread counts, rebuild schedules and reorderings. On a rebuild the history of each slot is
/// carried over from the previous list by neighbour id (a merge of two id-sorted rows).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/CellGrid.hpp"
#include "kernels/dem/Periodic.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace hikiln::dem {

/// \brief Neighbour rows (n x capacity) with their contact history and last contact forces.
template <class MemorySpace> struct NeighborList {
  using memory_space = MemorySpace;
  Kokkos::View<int*, MemorySpace> count;                ///< neighbours found (may exceed capacity)
  Kokkos::View<int**, MemorySpace> index;               ///< neighbour's current particle index
  Kokkos::View<std::int64_t**, MemorySpace> neighborId; ///< neighbour's id (rows sorted by it)
  Kokkos::View<double**, MemorySpace> shear;            ///< tangential history displacement (m)
  Kokkos::View<double**, MemorySpace> normalForce;      ///< last F_n of the slot (0: no contact)
  Kokkos::View<double**, MemorySpace> tangentialForce;  ///< last F_t of the slot along t

  NeighborList() = default;
  /// \brief Zero-filled list of `rows` rows with `capacity` slots each; props go to
  /// Kokkos::view_alloc (e.g. the execution space instance that fills the zeros).
  template <class... Props>
  NeighborList(std::size_t rows, int capacity, Props const&... props)
      : count(Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrCount")), rows),
        index(Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrIndex")), rows, capacity),
        neighborId(Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrId")), rows, capacity),
        shear(Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrShear")), rows, capacity),
        normalForce(Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrNormalForce")), rows,
                    capacity),
        tangentialForce(
            Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrTangentialForce")), rows,
            capacity) {}

  /// \brief Slots per row.
  int capacity() const { return static_cast<int>(index.extent(1)); }
  /// \brief Number of rows allocated.
  std::size_t rows() const { return count.extent(0); }
};

/// \brief Builds `list` for particles [0, n) from binned positions and carries the history (shear
/// and last forces) of persisting pairs over from `previous`, whose row i must belong to the same
/// particle as row i now (previous rows are matched by neighbour id, not index). Returns the
/// largest neighbour count found; a value above list.capacity() means overflow (the caller must
/// treat it as an error: rows were truncated).
template <class ExecutionSpace, class MemorySpace, class PositionView, class RadiusView,
          class IdView>
int buildNeighborList(ExecutionSpace const& space, CellBins<MemorySpace> const& bins,
                      PositionView const& position, RadiusView const& radius, IdView const& id,
                      std::size_t n, double skin, PeriodicX const& periodic,
                      NeighborList<MemorySpace> const& previous,
                      NeighborList<MemorySpace> const& list) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::buildNeighborList: list memory not accessible");
  const CellGrid grid = bins.grid;
  auto cellOf = bins.cellOfParticle;
  auto offset = bins.cellOffset;
  auto members = bins.cellParticles;
  auto count = list.count;
  auto index = list.index;
  auto nid = list.neighborId;
  auto shear = list.shear;
  auto fn = list.normalForce;
  auto ft = list.tangentialForce;
  auto oldCount = previous.count;
  auto oldId = previous.neighborId;
  auto oldShear = previous.shear;
  auto oldFn = previous.normalForce;
  auto oldFt = previous.tangentialForce;
  const int capacity = list.capacity();
  const int oldCapacity = previous.capacity();
  const int oldRows = static_cast<int>(previous.rows());
  int maxCount = 0;
  Kokkos::parallel_reduce(
      "hikiln::dem::buildNeighborList", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i, int& maxFound) {
        const double xi = position(i, 0);
        const double yi = position(i, 1);
        const double ri = radius(i);
        const int c = cellOf(i);
        const int cx = c % grid.nx;
        const int cy = c / grid.nx;
        int found = 0;
        for (int oy = -1; oy <= 1; ++oy) {
          const int y = cy + oy;
          if (y < 0 || y >= grid.ny) {
            continue;
          }
          for (int ox = -1; ox <= 1; ++ox) {
            int x = cx + ox;
            if (grid.periodicX) {
              x = x < 0 ? x + grid.nx : (x >= grid.nx ? x - grid.nx : x);
            } else if (x < 0 || x >= grid.nx) {
              continue;
            }
            const int cell = y * grid.nx + x;
            for (int m = offset(cell); m < offset(cell + 1); ++m) {
              const int j = members(m);
              if (j == i) {
                continue;
              }
              const double dx = periodic.minimumImage(position(j, 0) - xi);
              const double dy = position(j, 1) - yi;
              const double cut = ri + radius(j) + skin;
              if (!(dx * dx + dy * dy < cut * cut)) {
                continue;
              }
              if (found < capacity) { // insertion keeps the row sorted by id
                const std::int64_t jid = id(j);
                int k = found;
                while (k > 0 && nid(i, k - 1) > jid) {
                  nid(i, k) = nid(i, k - 1);
                  index(i, k) = index(i, k - 1);
                  --k;
                }
                nid(i, k) = jid;
                index(i, k) = j;
              }
              ++found;
            }
          }
        }
        count(i) = found;
        if (found > maxFound) {
          maxFound = found;
        }
        // carry the history over: both rows are sorted by id
        const int kept = found < capacity ? found : capacity;
        const int oldKept =
            i < oldRows ? (oldCount(i) < oldCapacity ? oldCount(i) : oldCapacity) : 0;
        int o = 0;
        for (int k = 0; k < kept; ++k) {
          const std::int64_t jid = nid(i, k);
          while (o < oldKept && oldId(i, o) < jid) {
            ++o;
          }
          if (o < oldKept && oldId(i, o) == jid) {
            shear(i, k) = oldShear(i, o);
            fn(i, k) = oldFn(i, o);
            ft(i, k) = oldFt(i, o);
          } else {
            shear(i, k) = 0.0;
            fn(i, k) = 0.0;
            ft(i, k) = 0.0;
          }
        }
      },
      Kokkos::Max<int>(maxCount));
  return n == 0 ? 0 : maxCount;
}

/// \brief Error message for a list whose largest row needed maxCount > capacity slots.
inline std::string neighborOverflowMessage(int maxCount, int capacity) {
  return "hikiln::dem: neighbour list overflow: a particle has " + std::to_string(maxCount) +
         " neighbours within the cut-off but the list holds only " + std::to_string(capacity) +
         " per particle; raise the neighbour capacity (or check for overlapping/exploding "
         "particles)";
}

} // namespace hikiln::dem
