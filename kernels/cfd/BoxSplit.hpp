#pragma once
/// \file BoxSplit.hpp
/// \brief Splits an index box into its interior (every neighbour along every active axis is
/// inside the box) and a shell of at most 6 slabs. Stencil kernels run the interior with a
/// branch-free point function and only the shell with the boundary closures: with the closures
/// everywhere a 5-point apply measured 1.6 GB/s, the split 13-22 GB/s (one core).

#include "kernels/cfd/Grid.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>

namespace hikiln::cfd {

/// \brief The axes along which a cell lies in a split's interior, as bits (1 << axis): a stencil
/// reads its neighbours along those axes without closures or wrap-around. The stencil bodies'
/// template argument (cell<Axes>(), SplitLoop.hpp); along the other axes they take the closures,
/// which are right everywhere, so a mask may leave out axes, never add one.
inline constexpr unsigned noAxes = 0u;  ///< every read through the closures
inline constexpr unsigned xAxis = 1u;   ///< a row's middle on a y or z shell slab
inline constexpr unsigned yzAxes = 6u;  ///< the first and last cells of an interior row
inline constexpr unsigned allAxes = 7u; ///< the interior

/// \brief True when the mask `axes` holds axis a.
KOKKOS_INLINE_FUNCTION constexpr bool interiorAlong(unsigned axes, int a) {
  return ((axes >> a) & 1u) != 0u;
}

/// \brief A box [lo, hi), its interior [lo + 1, hi - 1) along active axes (full along inactive
/// ones) and the shell between them as slabs.
struct BoxSplit {
  int lo[3] = {0, 0, 0};
  int hi[3] = {0, 0, 0};
  int interiorLo[3] = {0, 0, 0};
  int interiorHi[3] = {0, 0, 0};
  int numSlabs = 0;
  int slabLo[6][3] = {};
  int slabHi[6][3] = {};
  std::int64_t slabStart[7] = {0, 0, 0, 0, 0, 0, 0};

  /// \brief Number of interior cells.
  KOKKOS_INLINE_FUNCTION std::int64_t interiorSize() const {
    return static_cast<std::int64_t>(interiorHi[0] - interiorLo[0]) *
           (interiorHi[1] - interiorLo[1]) * (interiorHi[2] - interiorLo[2]);
  }
  /// \brief Number of shell cells.
  KOKKOS_INLINE_FUNCTION std::int64_t shellSize() const { return slabStart[numSlabs]; }
  /// \brief Number of cells of the box: interior and shell.
  KOKKOS_INLINE_FUNCTION std::int64_t size() const { return interiorSize() + shellSize(); }
  /// \brief Cell s of the shell, s in [0, shellSize()).
  KOKKOS_INLINE_FUNCTION void shellCell(std::int64_t s, int& i, int& j, int& k) const {
    int slab = 0;
    // (slab < 5 states the bound numSlabs <= 6 for the compiler's array-bounds analysis)
    while (slab < 5 && slab + 1 < numSlabs && s >= slabStart[slab + 1]) {
      ++slab;
    }
    std::int64_t r = s - slabStart[slab];
    const std::int64_t nx = slabHi[slab][0] - slabLo[slab][0];
    const std::int64_t ny = slabHi[slab][1] - slabLo[slab][1];
    i = slabLo[slab][0] + static_cast<int>(r % nx);
    r /= nx;
    j = slabLo[slab][1] + static_cast<int>(r % ny);
    k = slabLo[slab][2] + static_cast<int>(r / ny);
  }
};

/// \brief Interior and shell of the box [lo, hi); axes with active[a] == false have no shell.
inline BoxSplit splitBox(int const (&lo)[3], int const (&hi)[3], bool const (&active)[3]) {
  BoxSplit b;
  int cur[2][3];
  for (int a = 0; a < 3; ++a) {
    b.lo[a] = lo[a];
    b.hi[a] = hi[a] > lo[a] ? hi[a] : lo[a];
    cur[0][a] = b.lo[a];
    cur[1][a] = b.hi[a];
    b.interiorLo[a] = active[a] ? b.lo[a] + 1 : b.lo[a];
    b.interiorHi[a] = active[a] ? b.hi[a] - 1 : b.hi[a];
    if (b.interiorHi[a] < b.interiorLo[a]) {
      b.interiorHi[a] = b.interiorLo[a];
    }
  }
  bool empty = false;
  for (int a = 0; a < 3; ++a) {
    empty = empty || b.hi[a] == b.lo[a];
  }
  if (empty) {
    return b;
  }
  // peel the active axes from z to x: each slab spans the still-unpeeled axes fully
  for (int a = 2; a >= 0; --a) {
    if (!active[a]) {
      continue;
    }
    const int extent = cur[1][a] - cur[0][a];
    const int sides = extent >= 2 ? 2 : 1;
    for (int side = 0; side < sides; ++side) {
      int& n = b.numSlabs;
      for (int e = 0; e < 3; ++e) {
        b.slabLo[n][e] = cur[0][e];
        b.slabHi[n][e] = cur[1][e];
      }
      b.slabLo[n][a] = side == 0 ? cur[0][a] : cur[1][a] - 1;
      b.slabHi[n][a] = b.slabLo[n][a] + 1;
      std::int64_t size = 1;
      for (int e = 0; e < 3; ++e) {
        size *= b.slabHi[n][e] - b.slabLo[n][e];
      }
      b.slabStart[n + 1] = b.slabStart[n] + size;
      ++n;
    }
    cur[0][a] += 1;
    cur[1][a] = cur[1][a] - 1 > cur[0][a] ? cur[1][a] - 1 : cur[0][a];
    if (cur[1][a] <= cur[0][a]) {
      break; // nothing left to peel: the shell is the whole box
    }
  }
  return b;
}

/// \brief Boxes with fewer cells than this are not split: on coarse multigrid levels one
/// launch costs more than the closures (fork/join dominates).
inline constexpr std::int64_t minCellsToSplit = 4096;

/// \brief The split of the unknown box of a field whose axes are active as in `grid`; a box on a
/// small grid is all shell (one launch). The size test is on the grid's cells, not the box: a
/// face-centred component of a 64^2 grid has 63 x 64 unknowns and must split like the cells
/// (unsplit, its viscous stencil ran every unknown through the closures: 1.5x slower drum steps).
inline BoxSplit splitUnknowns(Grid const& grid, int const (&lo)[3], int const (&hi)[3]) {
  std::int64_t cells = 1;
  for (int a = 0; a < 3; ++a) {
    cells *= hi[a] > lo[a] ? hi[a] - lo[a] : 0;
  }
  const bool large = static_cast<std::int64_t>(grid.nx) * grid.ny * grid.nz >= minCellsToSplit;
  const bool active[3] = {large, large, large && grid.is3D()};
  BoxSplit split = splitBox(lo, hi, active);
  if (!large && cells > 0) {
    // no active axis: the interior is the whole box; make it the single shell slab instead
    split.numSlabs = 1;
    for (int a = 0; a < 3; ++a) {
      split.slabLo[0][a] = split.lo[a];
      split.slabHi[0][a] = split.hi[a];
      split.interiorLo[a] = split.interiorHi[a] = split.lo[a];
    }
    split.slabStart[1] = cells;
  }
  return split;
}

} // namespace hikiln::cfd
