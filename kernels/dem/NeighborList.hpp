#pragma once
/// \file NeighborList.hpp
/// \brief Full neighbour list: one row of neighbour indices per particle with the tangential
/// contact history of each slot, rebuilt in place.
///
/// Every pair closer than r_i + r_j + skin appears in the rows of both particles. A row is sorted
/// by neighbour id (looked up through the index), so the order in which a particle sums its
/// contact forces depends neither on particle indices nor on when the list was rebuilt: results
/// are bitwise reproducible across thread counts, rebuild schedules and reorderings.
///
/// Memory: a slot is an int32 index and a double shear (12 bytes). Rows are only as wide as the
/// longest row needs (DemSystem widens on demand up to its configured limit), not as wide as the
/// limit. Neighbour ids are not stored: the rebuild reads them through the index from the
/// particles' id array, which is why a reorder must remap the indices (permuteContactRows()).
///
/// Rebuild in place (rebuildNeighborList()): row i is recomputed from the cells and merged with
/// its own previous contents by neighbour id, touching no other row, so no second list is needed.
/// A row that needs more slots than the current width is left as it was and the largest count is
/// returned; the caller widens the list and runs it again (rebuilt rows are fixed points).
///
/// neighborId, normalForce and tangentialForce are optional views kept for older callers: the
/// (rows, capacity) constructor allocates them; lean() lists leave them empty. When allocated,
/// neighborId is filled by the rebuild; the forces are filled by computeContactForces()
/// (ForceKernel.hpp), never by the time step.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/CellGrid.hpp"
#include "kernels/dem/Periodic.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace hikiln::dem {

/// \brief Largest row width (slots per particle) a neighbour list may have: the rebuild sorts a
/// row in a local array of this size.
inline constexpr int maxNeighborCapacity = 64;

/// \brief Neighbour rows (rows x width) with their contact history; see the file comment.
template <class MemorySpace> struct NeighborList {
  using memory_space = MemorySpace;
  Kokkos::View<int*, MemorySpace> count;     ///< neighbours in the row (<= capacity())
  Kokkos::View<int**, MemorySpace> index;    ///< neighbour's current particle index
  Kokkos::View<double**, MemorySpace> shear; ///< tangential history displacement (m)
  /// Optional (empty in lean lists): neighbour's id, filled by the rebuild when allocated.
  Kokkos::View<std::int64_t**, MemorySpace> neighborId;
  /// Optional (empty in lean lists): F_n of the slot from computeContactForces() (0: no contact).
  Kokkos::View<double**, MemorySpace> normalForce;
  /// Optional (empty in lean lists): F_t of the slot along t from computeContactForces().
  Kokkos::View<double**, MemorySpace> tangentialForce;
  /// Optional (empty unless allocateNormalAngle()): a second per-slot history, the last contact
  /// normal or separating axis of a blocky pair (encoded as BlockyForceKernel.hpp says; 0: none),
  /// carried over by the rebuild and copyNeighborRows() like shear; not by permuteContactRows().
  Kokkos::View<double**, MemorySpace> normalAngle;

  NeighborList() = default;
  /// \brief Zero-filled list of `rows` rows with `capacity` slots each, including the optional
  /// views; props go to Kokkos::view_alloc (e.g. the execution space instance that fills zeros).
  template <class... Props>
  NeighborList(std::size_t rows, int capacity, Props const&... props)
      : NeighborList(lean(rows, capacity, props...)) {
    allocateOptional(props...);
  }

  /// \brief Zero-filled list of `rows` rows of `width` slots without the optional views.
  template <class... Props>
  static NeighborList lean(std::size_t rows, int width, Props const&... props) {
    checkWidth(width);
    NeighborList list;
    list.count = Kokkos::View<int*, MemorySpace>(
        Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrCount")), rows);
    list.index = Kokkos::View<int**, MemorySpace>(
        Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrIndex")), rows, width);
    list.shear = Kokkos::View<double**, MemorySpace>(
        Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrShear")), rows, width);
    return list;
  }

  /// \brief Allocates the optional views (zero-filled) to the list's shape.
  template <class... Props> void allocateOptional(Props const&... props) {
    neighborId = Kokkos::View<std::int64_t**, MemorySpace>(
        Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrId")), rows(), capacity());
    normalForce = Kokkos::View<double**, MemorySpace>(
        Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrNormalForce")), rows(),
        capacity());
    tangentialForce = Kokkos::View<double**, MemorySpace>(
        Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrTangentialForce")), rows(),
        capacity());
  }

  /// \brief Allocates normalAngle (zero-filled) to the list's shape.
  template <class... Props> void allocateNormalAngle(Props const&... props) {
    normalAngle = Kokkos::View<double**, MemorySpace>(
        Kokkos::view_alloc(props..., std::string("hikiln::dem::nbrNormalAngle")), rows(),
        capacity());
  }

  /// \brief Slots per row (the row width).
  int capacity() const { return static_cast<int>(index.extent(1)); }
  /// \brief Number of rows allocated.
  std::size_t rows() const { return count.extent(0); }
  /// \brief Bytes held by all allocated views.
  std::size_t bytes() const {
    return count.span() * sizeof(int) + index.span() * sizeof(int) + shear.span() * sizeof(double) +
           neighborId.span() * sizeof(std::int64_t) + normalForce.span() * sizeof(double) +
           tangentialForce.span() * sizeof(double) + normalAngle.span() * sizeof(double);
  }

  /// \brief Throws unless 1 <= width <= maxNeighborCapacity.
  static void checkWidth(int width) {
    if (width < 1 || width > maxNeighborCapacity) {
      throw std::invalid_argument("hikiln::dem::NeighborList: row width " + std::to_string(width) +
                                  " outside [1, " + std::to_string(maxNeighborCapacity) + "]");
    }
  }
};

/// \brief Rebuilds rows [0, n) of `list` in place from binned positions, carrying each slot's
/// history over by neighbour id (the rows' indices must refer to the current particle order).
/// Rows that need more than list.capacity() slots are left unchanged. Returns the largest number
/// of neighbours any row needs; above list.capacity() the caller must widen the list and call
/// again (or report an overflow).
template <class ExecutionSpace, class MemorySpace, class PositionView, class RadiusView,
          class IdView>
int rebuildNeighborList(ExecutionSpace const& space, CellBins<MemorySpace> const& bins,
                        PositionView const& position, RadiusView const& radius, IdView const& id,
                        std::size_t n, double skin, PeriodicX const& periodic,
                        NeighborList<MemorySpace> const& list) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::rebuildNeighborList: list memory not accessible");
  const CellGrid grid = bins.grid;
  auto cellOf = bins.cellOfParticle;
  auto offset = bins.cellOffset;
  auto members = bins.cellParticles;
  auto count = list.count;
  auto index = list.index;
  auto shear = list.shear;
  auto nid = list.neighborId;
  const bool storeIds = nid.extent(0) >= n && nid.extent(1) == index.extent(1);
  auto angle = list.normalAngle;
  const bool carryAngle = angle.extent(0) >= n && angle.extent(1) == index.extent(1);
  const int width = list.capacity();
  int maxCount = 0;
  Kokkos::parallel_reduce(
      "hikiln::dem::rebuildNeighborList",
      Kokkos::RangePolicy<ExecutionSpace, Kokkos::Schedule<Kokkos::Dynamic>>(space, 0, n)
          .set_chunk_size(64),
      KOKKOS_LAMBDA(int i, int& maxFound) {
        int slotIndex[maxNeighborCapacity];
        std::int64_t slotId[maxNeighborCapacity];
        double slotShear[maxNeighborCapacity];
        double slotAngle[maxNeighborCapacity];
        const double xi = position(i, 0);
        const double yi = position(i, 1);
        const double ri = radius(i);
        const int c = cellOf(i);
        const int layerSize = grid.nx * grid.ny;
        const int layerStart = c - c % layerSize; // neighbours only within i's layer
        const int cx = c % grid.nx;
        const int cy = (c % layerSize) / grid.nx;
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
            const int cell = layerStart + y * grid.nx + x;
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
              if (found < width) { // insertion keeps the row sorted by id
                const std::int64_t jid = id(j);
                int k = found;
                while (k > 0 && slotId[k - 1] > jid) {
                  slotId[k] = slotId[k - 1];
                  slotIndex[k] = slotIndex[k - 1];
                  --k;
                }
                slotId[k] = jid;
                slotIndex[k] = j;
              }
              ++found;
            }
          }
        }
        if (found > maxFound) {
          maxFound = found;
        }
        if (found > width) {
          return; // left as it was: the caller widens the list and repeats
        }
        // carry the history over from the old row (also sorted by id) before overwriting it
        const int oldCount = count(i);
        int o = 0;
        for (int k = 0; k < found; ++k) {
          const std::int64_t jid = slotId[k];
          while (o < oldCount && id(index(i, o)) < jid) {
            ++o;
          }
          const bool kept = o < oldCount && index(i, o) == slotIndex[k];
          slotShear[k] = kept ? shear(i, o) : 0.0;
          if (carryAngle) {
            slotAngle[k] = kept ? angle(i, o) : 0.0;
          }
        }
        for (int k = 0; k < found; ++k) {
          index(i, k) = slotIndex[k];
          shear(i, k) = slotShear[k];
          if (storeIds) {
            nid(i, k) = slotId[k];
          }
          if (carryAngle) {
            angle(i, k) = slotAngle[k];
          }
        }
        count(i) = found;
      },
      Kokkos::Max<int>(maxCount));
  return n == 0 ? 0 : maxCount;
}

/// \brief Copies rows [0, n) of `from` into `to` (count and the first count slots of index and
/// shear, and of normalAngle where both have it; rows wider than `to` are truncated). For widening
/// a list before a rebuild.
template <class ExecutionSpace, class MemorySpace>
void copyNeighborRows(ExecutionSpace const& space, std::size_t n,
                      NeighborList<MemorySpace> const& from, NeighborList<MemorySpace> const& to) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::copyNeighborRows: list memory not accessible");
  const int fromWidth = from.capacity();
  const int toWidth = to.capacity();
  const std::size_t fromRows = from.rows();
  const bool copyAngle = from.normalAngle.extent(0) == fromRows &&
                         from.normalAngle.extent(1) == from.index.extent(1) &&
                         to.normalAngle.extent(0) == to.rows() &&
                         to.normalAngle.extent(1) == to.index.extent(1);
  Kokkos::parallel_for(
      "hikiln::dem::copyNeighborRows", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        int c = static_cast<std::size_t>(i) < fromRows ? from.count(i) : 0;
        c = c < fromWidth ? c : fromWidth;
        c = c < toWidth ? c : toWidth;
        for (int k = 0; k < c; ++k) {
          to.index(i, k) = from.index(i, k);
          to.shear(i, k) = from.shear(i, k);
          if (copyAngle) {
            to.normalAngle(i, k) = from.normalAngle(i, k);
          }
        }
        to.count(i) = c;
      });
}

/// \brief neighborId(i, k) = id(index(i, k)) for the filled slots of rows [0, n) of `rows`: the
/// stable ids of the neighbours, written into `neighborId` (at least n rows, as wide as `rows`).
template <class ExecutionSpace, class MemorySpace, class IdView>
void fillNeighborIds(ExecutionSpace const& space, std::size_t n,
                     NeighborList<MemorySpace> const& rows, IdView const& id,
                     Kokkos::View<std::int64_t**, MemorySpace> const& neighborId) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::fillNeighborIds: list memory not accessible");
  const auto count = rows.count;
  const auto index = rows.index;
  Kokkos::parallel_for(
      "hikiln::dem::fillNeighborIds", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        for (int k = 0; k < count(i); ++k) {
          neighborId(i, k) = id(index(i, k));
        }
      });
}

/// \brief Builds `list` for particles [0, n) and carries the history over from `previous`, whose
/// row i belongs to the same particle as row i now and whose indices refer to the current
/// particle order (as after permuteContactRows()). Returns the largest neighbour count; a value
/// above list.capacity() means overflow (those rows hold previous's contents).
template <class ExecutionSpace, class MemorySpace, class PositionView, class RadiusView,
          class IdView>
int buildNeighborList(ExecutionSpace const& space, CellBins<MemorySpace> const& bins,
                      PositionView const& position, RadiusView const& radius, IdView const& id,
                      std::size_t n, double skin, PeriodicX const& periodic,
                      NeighborList<MemorySpace> const& previous,
                      NeighborList<MemorySpace> const& list) {
  copyNeighborRows(space, n, previous, list);
  return rebuildNeighborList(space, bins, position, radius, id, n, skin, periodic, list);
}

/// \brief Error message for a list whose largest row needed maxCount > capacity slots.
inline std::string neighborOverflowMessage(int maxCount, int capacity) {
  return "hikiln::dem: neighbour list overflow: a particle has " + std::to_string(maxCount) +
         " neighbours within the cut-off but the list holds only " + std::to_string(capacity) +
         " per particle; raise the neighbour capacity (or check for overlapping/exploding "
         "particles)";
}

} // namespace hikiln::dem
