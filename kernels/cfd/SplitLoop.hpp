#pragma once
/// \file SplitLoop.hpp
/// \brief Loops over the cells of a BoxSplit: the interior with the branch-free stencil, the shell
/// with the boundary closures. On the host one launch walks the box's rows (j, k), each row's
/// shell cells with the closures and its interior cells with the stencil; on devices the interior
/// is one launch index per cell and the shell a second, flat launch. A stencil kernel is written
/// once as a body with
///
///     template <unsigned Axes> KOKKOS_INLINE_FUNCTION double cell(int i, int j, int k) const;
///
/// (Axes, a mask of BoxSplit.hpp, names the axes along which no closure is needed: allAxes in the
/// interior, noAxes on the shell; on the host a shell row's middle takes xAxis and an interior
/// row's ends yzAxes); forEachSplitCell ignores the returned value, sumOverSplitCells adds it up
/// (e.g. a squared residual: on the host in row order, on devices as an interior and a shell sum),
/// forEachSplitColourCell visits one colour of a red-black sweep. Each cell gets the same
/// arithmetic on every path (a term read without its closure differs from the closure's only in
/// the sign of a zero, which the stencils' sums drop), and no cell of a launch reads what another
/// writes, so results do not depend on the path.

#include "kernels/cfd/BoxSplit.hpp"
#include "kernels/cfd/Grid.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>
#include <string>
#include <type_traits>

/// Before a host row loop over the cells of one launch: they are independent (no cell reads
/// what another writes, see the file comment), so the compiler may vectorise the row without a
/// run-time overlap test per array the stencil reads (GCC gives up beyond 10 such tests; the
/// viscous stencil reads up to 16 arrays). GCC only; nvcc and other compilers get nothing.
#if defined(__GNUC__) && !defined(__clang__) && !defined(__NVCC__) && !defined(__CUDA_ARCH__)
#define HIKILN_INDEPENDENT_CELLS _Pragma("GCC ivdep")
#else
#define HIKILN_INDEPENDENT_CELLS
#endif

namespace hikiln::cfd {

namespace detail {

template <class Body> struct InteriorCells {
  Body body;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, const int j, const int k) const {
    body.template cell<allAxes>(i, j, k);
  }
};

/// (Reductions are separate functors with a value_type: Kokkos 3.4 deduces the reduction type
/// from a functor's operator(), which must then not be overloaded.)
template <class Body> struct InteriorSum {
  using value_type = double;
  Body body;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, const int j, const int k, double& sum) const {
    sum += body.template cell<allAxes>(i, j, k);
  }
};

template <class Body> struct ShellCells {
  Body body;
  BoxSplit split;
  KOKKOS_INLINE_FUNCTION void operator()(const std::int64_t s) const {
    int i, j, k;
    split.shellCell(s, i, j, k);
    body.template cell<noAxes>(i, j, k);
  }
};

template <class Body> struct ShellSum {
  using value_type = double;
  Body body;
  BoxSplit split;
  KOKKOS_INLINE_FUNCTION void operator()(const std::int64_t s, double& sum) const {
    int i, j, k;
    split.shellCell(s, i, j, k);
    sum += body.template cell<noAxes>(i, j, k);
  }
};

/// The first index >= a with (i + j + k) % 2 == colour.
KOKKOS_INLINE_FUNCTION int firstOfColour(const int a, const int j, const int k, const int colour) {
  return a + ((colour + a + j + k) & 1);
}

/// Interior cells of one colour ((i + j + k) % 2 == colour): the x range is walked in pairs so
/// that no launch index is wasted on the other colour.
template <class Body> struct InteriorColourCells {
  Body body;
  int i0, i1, colour;
  KOKKOS_INLINE_FUNCTION void operator()(const int pair, const int j, const int k) const {
    const int i = firstOfColour(i0, j, k, colour) + 2 * pair; // (`half` is a CUDA type)
    if (i < i1) {
      body.template cell<allAxes>(i, j, k);
    }
  }
};

/// Host versions: one launch index per row (j, k), the x range walked inside the functor, so the
/// compiler sees a plain loop and keeps the body's loop-invariant reads (view strides, operator
/// flags) in registers; per cell they cost as much as the stencil itself. Rows are a flat
/// RangePolicy: a rank-2 MDRange over (j, k) was slower on two threads (perf/README.md).
struct Rows {
  int i0, i1, j0, nj, k0;
  Rows(int const (&lo)[3], int const (&hi)[3])
      : i0(lo[0]), i1(hi[0]), j0(lo[1]), nj(hi[1] - lo[1]), k0(lo[2]) {}
  KOKKOS_INLINE_FUNCTION int j(const int row) const { return j0 + row % nj; }
  KOKKOS_INLINE_FUNCTION int k(const int row) const { return k0 + row / nj; }
};

template <class Body> struct ShellColourCells {
  Body body;
  BoxSplit split;
  int colour;
  KOKKOS_INLINE_FUNCTION void operator()(const std::int64_t s) const {
    int i, j, k;
    split.shellCell(s, i, j, k);
    if (((i + j + k) & 1) == colour) {
      body.template cell<noAxes>(i, j, k);
    }
  }
};

/// Host: the rows (j, k) of a whole split box in one launch, the shell's cells with the closures
/// and the interior's with the branch-free stencil. Rows on the shell's y and z slabs are shell
/// throughout; the others are shell only where x is (their first and last cells when x is split).
/// One launch instead of an interior and a shell launch: on two threads a launch's fork and join
/// cost about 3.5 us, and a drum step makes thousands (perf/README.md, "One launch per split box").
/// A box without an interior (a coarse level's, which splitUnknowns() leaves unsplit, or one too
/// thin to have one) is walked the same way, each cell with the closures along the axes where it
/// has no interior: not as a flat list of shell cells, each decoded from its index and half of
/// them of the other colour (perf/README.md, "Unsplit boxes walked by rows").
struct SplitRows {
  Rows box;                         ///< every row of the box
  int xLo, xHi, yLo, yHi, zLo, zHi; ///< the interior's ranges
  explicit SplitRows(BoxSplit const& s)
      : box(s.lo, s.hi), xLo(s.interiorLo[0]), xHi(s.interiorHi[0]), yLo(s.interiorLo[1]),
        yHi(s.interiorHi[1]), zLo(s.interiorLo[2]), zHi(s.interiorHi[2]) {}
  KOKKOS_INLINE_FUNCTION bool shellRow(const int j, const int k) const {
    return j < yLo || j >= yHi || k < zLo || k >= zHi;
  }
};

/// Walks row (j, k) of rows.box in its pieces, each with the closures only along the axes where
/// its cells need them: walker.walk<Axes>(a, b, j, k) visits [a, b). At 64^3 the shell (9 % of
/// the cells) through the closures along every axis took about as long as the interior.
template <class Walker>
KOKKOS_FORCEINLINE_FUNCTION void walkSplitRow(SplitRows const& rows, Walker const& walker,
                                              const int j, const int k) {
  if (rows.shellRow(j, k)) {
    walker.template walk<noAxes>(rows.box.i0, rows.xLo, j, k);
    walker.template walk<xAxis>(rows.xLo, rows.xHi, j, k);
    walker.template walk<noAxes>(rows.xHi, rows.box.i1, j, k);
    return;
  }
  walker.template walk<yzAxes>(rows.box.i0, rows.xLo, j, k);
  walker.template walk<allAxes>(rows.xLo, rows.xHi, j, k);
  walker.template walk<yzAxes>(rows.xHi, rows.box.i1, j, k);
}

/// One launch's functor (SplitRows): every cell of each row, or (Coloured) those of one colour.
template <class Body, bool Coloured> struct SplitBoxRows {
  Body body;
  SplitRows rows;
  int colour = 0;

  /// Visits [a, b) of row (j, k) with cell<Axes>.
  template <unsigned Axes>
  KOKKOS_FORCEINLINE_FUNCTION void walk(const int a, const int b, const int j, const int k) const {
    HIKILN_INDEPENDENT_CELLS
    for (int i = Coloured ? firstOfColour(a, j, k, colour) : a; i < b; i += Coloured ? 2 : 1) {
      body.template cell<Axes>(i, j, k);
    }
  }

  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int row) const {
    walkSplitRow(rows, *this, rows.box.j(row), rows.box.k(row));
  }
};

/// Adds body.cell<Axes> over pieces of rows to `partial` (a local of SplitBoxRowSum).
template <class Body> struct RowPieceSum {
  Body const& body;
  double& partial;
  template <unsigned Axes>
  KOKKOS_FORCEINLINE_FUNCTION void walk(const int a, const int b, const int j, const int k) const {
    double s = partial; // a register: the same additions in the same order
    HIKILN_INDEPENDENT_CELLS
    for (int i = a; i < b; ++i) {
      s += body.template cell<Axes>(i, j, k);
    }
    partial = s;
  }
};

/// One launch's reduction (SplitRows): the sum of body.cell over every cell of the box, row by
/// row, each row's cells in order.
template <class Body> struct SplitBoxRowSum {
  using value_type = double;
  Body body;
  SplitRows rows;
  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int row, double& sum) const {
    double partial = sum;
    walkSplitRow(rows, RowPieceSum<Body>{body, partial}, rows.box.j(row), rows.box.k(row));
    sum = partial;
  }
};

/// Host: a whole red-black sweep (colour `first`, then the other) in one pass over the box
/// instead of two. The box's planes (the rows of one k; in a box one cell deep, single rows) are
/// split into one chunk per launch index; a chunk takes the first colour on plane p and the
/// second on plane p - 1 right after, while plane p - 1's data is still in cache, so the arrays
/// stream from memory once per sweep. The stencils couple neighbouring planes only, so plane p -
/// 1's second colour sees the first colour's new values on p - 2 .. p, and plane p's first colour
/// the second colour's old values on p - 1 .. p + 1: the cells get the values of two colour
/// passes, bit for bit. A chunk's first and last planes border another chunk (or, along a
/// periodic axis, each other), so their second colour waits for a second launch (Edges).
template <class Body> struct SplitBoxRedBlack {
  SplitBoxRows<Body, true> first, second; ///< the coloured row walks of the two colours
  int rowsPerPlane, planes, chunks;
  bool edges = false; ///< the second launch: the chunks' first and last planes' second colour

  /// maxChunks > 0; a chunk has one plane at least.
  SplitBoxRedBlack(Body const& body, BoxSplit const& split, int firstColour, int maxChunks)
      : first{body, SplitRows(split), firstColour}, second{body, SplitRows(split), 1 - firstColour},
        rowsPerPlane(split.hi[2] - split.lo[2] > 1 ? first.rows.box.nj : 1),
        planes(split.hi[2] - split.lo[2] > 1 ? split.hi[2] - split.lo[2] : first.rows.box.nj),
        chunks(math::min(maxChunks, planes)) {}

  KOKKOS_FORCEINLINE_FUNCTION void plane(SplitBoxRows<Body, true> const& walk, int p) const {
    for (int row = p * rowsPerPlane; row < (p + 1) * rowsPerPlane; ++row) {
      walk(row);
    }
  }

  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int chunk) const {
    const int p0 = static_cast<int>(static_cast<std::int64_t>(planes) * chunk / chunks);
    const int p1 = static_cast<int>(static_cast<std::int64_t>(planes) * (chunk + 1) / chunks);
    if (edges) {
      plane(second, p0);
      if (p1 - 1 > p0) {
        plane(second, p1 - 1);
      }
      return;
    }
    for (int p = p0; p < p1; ++p) {
      plane(first, p);
      if (p - 1 > p0) {
        plane(second, p - 1);
      }
    }
  }
};

/// True when grid kernels on ExecutionSpace walk whole rows per launch index (host spaces);
/// device spaces keep one cell per index.
template <class ExecutionSpace>
constexpr bool walksRows =
    std::is_same<typename ExecutionSpace::memory_space, Kokkos::HostSpace>::value;

/// One index per (j, k) row of the box [lo, hi).
template <class ExecutionSpace>
Kokkos::RangePolicy<ExecutionSpace> rowPolicy(ExecutionSpace const& space, int const (&lo)[3],
                                              int const (&hi)[3]) {
  return Kokkos::RangePolicy<ExecutionSpace>(space, 0, (hi[1] - lo[1]) * (hi[2] - lo[2]));
}

template <class F> struct BoxRows {
  F f;
  Rows rows;
  KOKKOS_INLINE_FUNCTION void operator()(const int row) const {
    const int j = rows.j(row), k = rows.k(row);
    HIKILN_INDEPENDENT_CELLS
    for (int i = rows.i0; i < rows.i1; ++i) {
      f(i, j, k);
    }
  }
};

} // namespace detail

/// \brief f(i, j, k) on every cell of the box [lo, hi), for element-wise kernels (f must not
/// depend on the visiting order): on host spaces one launch index per row, as the stencils.
template <class ExecutionSpace, class F>
void forEachBoxCell(ExecutionSpace const& space, std::string const& label, int const (&lo)[3],
                    int const (&hi)[3], F const& f) {
  if (!(hi[0] > lo[0] && hi[1] > lo[1] && hi[2] > lo[2])) {
    return;
  }
  if constexpr (detail::walksRows<ExecutionSpace>) {
    Kokkos::parallel_for(label, detail::rowPolicy(space, lo, hi),
                         detail::BoxRows<F>{f, detail::Rows(lo, hi)});
  } else {
    Kokkos::parallel_for(label, gridPolicy(space, lo, hi), f);
  }
}

/// \brief body.cell<Axes>(i, j, k) on every cell of split (labels "<label>::interior/shell").
template <class ExecutionSpace, class Body>
void forEachSplitCell(ExecutionSpace const& space, std::string const& label, BoxSplit const& split,
                      Body const& body) {
  if constexpr (detail::walksRows<ExecutionSpace>) {
    if (split.size() > 0) {
      Kokkos::parallel_for(label, detail::rowPolicy(space, split.lo, split.hi),
                           detail::SplitBoxRows<Body, false>{body, detail::SplitRows(split)});
    }
    return;
  } else if (split.interiorSize() > 0) {
    Kokkos::parallel_for(label + "::interior",
                         gridPolicy(space, split.interiorLo, split.interiorHi),
                         detail::InteriorCells<Body>{body});
  }
  if (split.shellSize() > 0) {
    Kokkos::parallel_for(label + "::shell",
                         Kokkos::RangePolicy<ExecutionSpace>(space, 0, split.shellSize()),
                         detail::ShellCells<Body>{body, split});
  }
}

/// \brief As forEachSplitCell; returns the sum of the values body.cell returns (e.g. a squared
/// residual). On the host one reduction over the box's rows, each row's cells added in order; on
/// devices the interior sum plus the shell sum, each a parallel reduction.
template <class ExecutionSpace, class Body>
double sumOverSplitCells(ExecutionSpace const& space, std::string const& label,
                         BoxSplit const& split, Body const& body) {
  if constexpr (detail::walksRows<ExecutionSpace>) {
    double sum = 0.0;
    if (split.size() > 0) {
      Kokkos::parallel_reduce(label, detail::rowPolicy(space, split.lo, split.hi),
                              detail::SplitBoxRowSum<Body>{body, detail::SplitRows(split)}, sum);
    }
    return sum;
  } else {
    double interior = 0.0, shell = 0.0;
    if (split.interiorSize() > 0) {
      Kokkos::parallel_reduce(label + "::interior",
                              gridPolicy(space, split.interiorLo, split.interiorHi),
                              detail::InteriorSum<Body>{body}, interior);
    }
    if (split.shellSize() > 0) {
      Kokkos::parallel_reduce(label + "::shell",
                              Kokkos::RangePolicy<ExecutionSpace>(space, 0, split.shellSize()),
                              detail::ShellSum<Body>{body, split}, shell);
    }
    return interior + shell;
  }
}

/// \brief body.cell<Axes>(i, j, k) on the cells of split with (i + j + k) % 2 == colour.
template <class ExecutionSpace, class Body>
void forEachSplitColourCell(ExecutionSpace const& space, std::string const& label,
                            BoxSplit const& split, int colour, Body const& body) {
  if constexpr (detail::walksRows<ExecutionSpace>) {
    if (split.size() > 0) {
      Kokkos::parallel_for(
          label, detail::rowPolicy(space, split.lo, split.hi),
          detail::SplitBoxRows<Body, true>{body, detail::SplitRows(split), colour});
    }
    return;
  } else if (split.interiorSize() > 0) {
    const int i0 = split.interiorLo[0];
    const int i1 = split.interiorHi[0];
    Kokkos::parallel_for(label + "::interior",
                         gridPolicy(space, {0, split.interiorLo[1], split.interiorLo[2]},
                                    {(i1 - i0 + 1) / 2, split.interiorHi[1], split.interiorHi[2]}),
                         detail::InteriorColourCells<Body>{body, i0, i1, colour});
  }
  if (split.shellSize() > 0) {
    Kokkos::parallel_for(label + "::shell",
                         Kokkos::RangePolicy<ExecutionSpace>(space, 0, split.shellSize()),
                         detail::ShellColourCells<Body>{body, split, colour});
  }
}

/// \brief A red-black sweep: forEachSplitColourCell with colour `first`, then with the other
/// colour, with the same results bit for bit. On the host one pass over the box (two launches:
/// SplitBoxRedBlack), so that a grid larger than the caches streams from memory once per sweep;
/// chunks (default: the space's concurrency, at most one per plane) sets how the planes are
/// shared out (tests vary it). Devices take the two colour launches.
template <class ExecutionSpace, class Body>
void forEachSplitRedBlackCell(ExecutionSpace const& space, std::string const& label,
                              BoxSplit const& split, int first, Body const& body, int chunks = 0) {
  if constexpr (detail::walksRows<ExecutionSpace>) {
    if (split.size() == 0) {
      return;
    }
    detail::SplitBoxRedBlack<Body> sweep(
        body, split, first, chunks > 0 ? chunks : static_cast<int>(space.concurrency()));
    const Kokkos::RangePolicy<ExecutionSpace> policy(space, 0, sweep.chunks);
    Kokkos::parallel_for(label, policy, sweep);
    sweep.edges = true;
    Kokkos::parallel_for(label, policy, sweep);
  } else {
    (void)chunks;
    forEachSplitColourCell(space, label, split, first, body);
    forEachSplitColourCell(space, label, split, 1 - first, body);
  }
}

/// \brief The smoothers' sweep: forEachSplitRedBlackCell from `colour` (both) or
/// forEachSplitColourCell of `colour` alone, labelled "<label>RedBlack" or "<label>Colour".
template <class ExecutionSpace, class Body>
void forEachSplitSweepCell(ExecutionSpace const& space, std::string const& label,
                           BoxSplit const& split, int colour, bool both, Body const& body) {
  if (both) {
    forEachSplitRedBlackCell(space, label + "RedBlack", split, colour, body);
  } else {
    forEachSplitColourCell(space, label + "Colour", split, colour, body);
  }
}

} // namespace hikiln::cfd
