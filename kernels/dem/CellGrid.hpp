#pragma once
/// \file CellGrid.hpp
/// \brief Uniform cell grid over a bounding box and the binning of particles into its cells, with a
/// deterministic order of particles inside each cell (sorted by index after an atomic fill).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/Periodic.hpp"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace hikiln::dem {

/// \brief A uniform grid of nx * ny cells of size hx * hy starting at (xlo, ylo). Positions outside
/// are clamped to the edge cells, which keeps neighbour search correct (clamping never separates
/// two particles closer than a cell by more than one cell). With periodicX the x cells tile one
/// period and wrap around. `layers` copies of the grid stack the slices of a batch (DemBatch.hpp):
/// particles of different layers share coordinates but never share a cell, so they never meet.
struct CellGrid {
  double xlo = 0.0, ylo = 0.0;
  double hx = 1.0, hy = 1.0;
  int nx = 1, ny = 1;
  int layers = 1;
  bool periodicX = false;

  /// \brief Number of cells (all layers).
  KOKKOS_INLINE_FUNCTION int numCells() const { return nx * ny * layers; }
  /// \brief Column of x, clamped to [0, nx).
  KOKKOS_INLINE_FUNCTION int cellX(double x) const {
    const double c = math::floor((x - xlo) / hx);
    return c < 0.0 ? 0 : (c >= nx ? nx - 1 : static_cast<int>(c));
  }
  /// \brief Row of y, clamped to [0, ny).
  KOKKOS_INLINE_FUNCTION int cellY(double y) const {
    const double c = math::floor((y - ylo) / hy);
    return c < 0.0 ? 0 : (c >= ny ? ny - 1 : static_cast<int>(c));
  }
  /// \brief Linear index of the cell holding (x, y) in layer `layer`.
  KOKKOS_INLINE_FUNCTION int cellOf(double x, double y, int layer = 0) const {
    return (layer * ny + cellY(y)) * nx + cellX(x);
  }
};

/// \brief Builds a grid with cells no smaller than minCellSize covering [xmin, xmax] x [ymin, ymax]
/// (x replaced by the period when periodic is enabled), `layers` deep. maxCells bounds the cell
/// count: beyond it the cells grow (still correct, only slower), which protects against a runaway
/// particle.
inline CellGrid makeCellGrid(double xmin, double xmax, double ymin, double ymax, double minCellSize,
                             const PeriodicX& periodic, std::size_t maxCells, int layers = 1) {
  if (!(minCellSize > 0.0) || !std::isfinite(xmin) || !std::isfinite(xmax) ||
      !std::isfinite(ymin) || !std::isfinite(ymax)) {
    throw std::runtime_error("hikiln::dem::makeCellGrid: non-finite particle bounds or cell size "
                             "(a particle position is NaN/inf: the run has blown up)");
  }
  CellGrid g;
  double h = minCellSize;
  const auto countAlong = [](double extent, double size) {
    return static_cast<long long>(std::floor(extent / size)) + 1;
  };
  long long nx = 0, ny = 0;
  for (;;) {
    if (periodic.enabled) {
      nx = static_cast<long long>(std::floor(periodic.length / h));
    } else {
      nx = countAlong(xmax - xmin, h);
    }
    ny = countAlong(ymax - ymin, h);
    if (static_cast<double>(nx) * static_cast<double>(ny) * layers <=
        static_cast<double>(maxCells)) {
      break;
    }
    h *= 2.0;
  }
  if (periodic.enabled) {
    if (nx < 3) {
      throw std::runtime_error("hikiln::dem::makeCellGrid: the periodic length " +
                               std::to_string(periodic.length) +
                               " must hold at least 3 cells of size " + std::to_string(h));
    }
    g.periodicX = true;
    g.xlo = periodic.xlo;
    g.hx = periodic.length / static_cast<double>(nx);
  } else {
    g.xlo = xmin;
    g.hx = h;
  }
  g.ylo = ymin;
  g.hy = h;
  g.nx = static_cast<int>(nx);
  g.ny = static_cast<int>(ny);
  g.layers = layers;
  return g;
}

/// \brief Axis-aligned bounds of a set of positions.
struct Bounds {
  double xmin = 0.0, xmax = 0.0, ymin = 0.0, ymax = 0.0;
};

namespace detail {
/// \brief One reduction for the bounds and the count of non-finite positions.
template <class PositionView> struct BoundsFunctor {
  struct value_type {
    double xmin, xmax, ymin, ymax;
    int bad;
  };
  PositionView position;

  KOKKOS_INLINE_FUNCTION void init(value_type& v) const {
    v.xmin = v.ymin = 1.0e308;
    v.xmax = v.ymax = -1.0e308;
    v.bad = 0;
  }
  KOKKOS_INLINE_FUNCTION void join(volatile value_type& a, const volatile value_type& b) const {
    a.xmin = b.xmin < a.xmin ? b.xmin : a.xmin;
    a.xmax = b.xmax > a.xmax ? b.xmax : a.xmax;
    a.ymin = b.ymin < a.ymin ? b.ymin : a.ymin;
    a.ymax = b.ymax > a.ymax ? b.ymax : a.ymax;
    a.bad += b.bad;
  }
  KOKKOS_INLINE_FUNCTION void operator()(int i, value_type& v) const {
    const double x = position(i, 0);
    const double y = position(i, 1);
    // a NaN never wins a comparison: count it explicitly so makeCellGrid can report it
    if (!math::isfinite(x) || !math::isfinite(y)) {
      v.bad += 1;
      return;
    }
    v.xmin = x < v.xmin ? x : v.xmin;
    v.xmax = x > v.xmax ? x : v.xmax;
    v.ymin = y < v.ymin ? y : v.ymin;
    v.ymax = y > v.ymax ? y : v.ymax;
  }
};
} // namespace detail

/// \brief Bounds of positions [0, n) (one device reduction). Empty sets give zero bounds; a
/// non-finite position gives NaN bounds (makeCellGrid() reports it).
template <class ExecutionSpace, class PositionView>
Bounds particleBounds(ExecutionSpace const& space, PositionView const& position, std::size_t n) {
  static_assert(
      Kokkos::SpaceAccessibility<ExecutionSpace, typename PositionView::memory_space>::accessible,
      "hikiln::dem::particleBounds: positions not accessible");
  Bounds b;
  if (n == 0) {
    return b;
  }
  using Functor = detail::BoundsFunctor<PositionView>;
  typename Functor::value_type v;
  Kokkos::parallel_reduce("hikiln::dem::bounds", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
                          Functor{position}, v);
  b.xmin = v.xmin;
  b.xmax = v.xmax;
  b.ymin = v.ymin;
  b.ymax = v.ymax;
  if (v.bad != 0) {
    b.xmin = std::nan("");
  }
  return b;
}

/// \brief Particles binned per cell: cellParticles[cellOffset[c] .. cellOffset[c + 1]) are the
/// indices of the particles in cell c in increasing order; cellOfParticle[i] is i's cell.
template <class MemorySpace> struct CellBins {
  using memory_space = MemorySpace;
  using layer_view = Kokkos::View<const int*, MemorySpace>; ///< each particle's layer
  CellGrid grid;
  Kokkos::View<int*, MemorySpace> cellOfParticle;
  Kokkos::View<int*, MemorySpace> cellCount;
  Kokkos::View<int*, MemorySpace> cellOffset;
  Kokkos::View<int*, MemorySpace> cellParticles;

  /// \brief Makes sure the Views hold n particles and numCells cells (grows only; contents are
  /// left uninitialised, binParticles() fills them).
  void reserve(std::size_t n, std::size_t numCells) {
    const auto make = [](const char* label, std::size_t size) {
      return Kokkos::View<int*, MemorySpace>(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string(label)), size);
    };
    if (cellOfParticle.extent(0) < n) {
      cellOfParticle = make("hikiln::dem::cellOfParticle", n);
      cellParticles = make("hikiln::dem::cellParticles", n);
    }
    if (cellCount.extent(0) < numCells) {
      cellCount = make("hikiln::dem::cellCount", numCells);
      cellOffset = make("hikiln::dem::cellOffset", numCells + 1);
    }
  }
};

/// \brief Bins positions [0, n) into grid: counts (atomic), offsets (scan), fill (atomic) and a
/// per-cell insertion sort that makes the order inside a cell independent of thread timing.
/// `layer` gives each particle's layer (grid.layers > 1; empty: all in layer 0).
template <class ExecutionSpace, class MemorySpace, class PositionView>
void binParticles(ExecutionSpace const& space, CellGrid const& grid, PositionView const& position,
                  std::size_t n, CellBins<MemorySpace>& bins,
                  typename CellBins<MemorySpace>::layer_view const& layer = {}) {
  if (grid.layers > 1 && layer.extent(0) < n) {
    throw std::invalid_argument("hikiln::dem::binParticles: a layered grid needs every "
                                "particle's layer");
  }
  const bool layered = grid.layers > 1;
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::binParticles: bins not accessible");
  const int numCells = grid.numCells();
  bins.reserve(n, static_cast<std::size_t>(numCells));
  bins.grid = grid;
  auto cellOf = bins.cellOfParticle;
  auto count = bins.cellCount;
  auto offset = bins.cellOffset;
  auto sorted = bins.cellParticles;
  Kokkos::deep_copy(space, count, 0);
  Kokkos::parallel_for(
      "hikiln::dem::binCount", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        const int c = grid.cellOf(position(i, 0), position(i, 1), layered ? layer(i) : 0);
        cellOf(i) = c;
        Kokkos::atomic_fetch_add(&count(c), 1);
      });
  Kokkos::parallel_scan(
      "hikiln::dem::binOffsets", Kokkos::RangePolicy<ExecutionSpace>(space, 0, numCells),
      KOKKOS_LAMBDA(int c, int& partial, bool final) {
        if (final) {
          offset(c) = partial;
        }
        partial += count(c);
        if (final && c == numCells - 1) {
          offset(numCells) = partial;
        }
      });
  Kokkos::deep_copy(space, count, 0);
  Kokkos::parallel_for(
      "hikiln::dem::binFill", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        const int c = cellOf(i);
        sorted(offset(c) + Kokkos::atomic_fetch_add(&count(c), 1)) = i;
      });
  Kokkos::parallel_for(
      "hikiln::dem::binSort", Kokkos::RangePolicy<ExecutionSpace>(space, 0, numCells),
      KOKKOS_LAMBDA(int c) {
        const int begin = offset(c);
        const int end = offset(c + 1);
        for (int a = begin + 1; a < end; ++a) {
          const int v = sorted(a);
          int b = a - 1;
          while (b >= begin && sorted(b) > v) {
            sorted(b + 1) = sorted(b);
            --b;
          }
          sorted(b + 1) = v;
        }
      });
}

} // namespace hikiln::dem
