// Grid layout, ghost filling, the interior/shell split and the multigrid transfer operators:
// extents and coordinates; ghosts reproduce linear / periodic / mirrored data exactly; boundary
// nodes of the MAC velocity; every cell in exactly one of interior and shell, and the split loops
// visit it once with that part's stencil; restriction is the scaled transpose of interpolation (<R
// f, c> 2^d = <f, P c>) and preserves sums; harmonic faces.
#include "CfdTestUtils.hpp"
#include "kernels/cfd/BoxSplit.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/FieldOps.hpp"
#include "kernels/cfd/GhostFill.hpp"
#include "kernels/cfd/SplitLoop.hpp"
#include "kernels/cfd/Transfer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace hikiln::cfd;
using test::Fn3;
using space = TEST_EXECSPACE;
using field = Field<space::memory_space>;
constexpr double pi = hikiln::constants::pi;

TEST(TEST_CATEGORY, grid_extents_and_coordinates) {
  const Grid g2 = makeGrid(8, 4, 1, 2.0, 1.0, 0.25, -1.0, 0.0, 0.0, 2);
  EXPECT_FALSE(g2.is3D());
  EXPECT_EQ(g2.extent(Staggering::Cell, 0), 12);
  EXPECT_EQ(g2.extent(Staggering::FaceX, 0), 13);
  EXPECT_EQ(g2.extent(Staggering::FaceX, 1), 8);
  EXPECT_EQ(g2.extent(Staggering::Cell, 2), 1); // no ghosts along z in 2D
  EXPECT_EQ(g2.extent(Staggering::EdgeXY, 1), 9);
  EXPECT_DOUBLE_EQ(g2.coordinate(Staggering::Cell, 0, 0), -0.875);
  EXPECT_DOUBLE_EQ(g2.coordinate(Staggering::FaceX, 0, 8), 1.0);
  const Grid g3 = makeGrid(4, 4, 6, 1.0, 1.0, 3.0);
  EXPECT_TRUE(g3.is3D());
  EXPECT_EQ(g3.extent(Staggering::FaceZ, 2), 9);
  EXPECT_EQ(g3.numCells(), 96);
  EXPECT_THROW(makeGrid(0, 4, 1, 1.0, 1.0, 1.0), std::invalid_argument);
  ScalarBoundaries bad;
  bad.kind[XLow] = BoundaryKind::Periodic; // unpaired
  EXPECT_THROW(checkBoundaries(g2, bad), std::invalid_argument);
  VelocityBoundaries leaky;
  leaky.velocity[YLow][1] = 1.0; // a wall with a normal velocity
  EXPECT_THROW(checkBoundaries(g2, leaky), std::invalid_argument);
}

// Max |field - f| over every stored entry of a field (ghosts included) along axes 0, 1.
double maxErrorWithGhosts(field const& fld, Grid const& g, Staggering s, Fn3 const& f) {
  auto h = test::toHost(fld);
  double err = 0.0;
  for (int k = 0; k < static_cast<int>(h.extent(2)); ++k)
    for (int j = 0; j < static_cast<int>(h.extent(1)); ++j)
      for (int i = 0; i < static_cast<int>(h.extent(0)); ++i) {
        const double x = g.coordinate(s, 0, i - g.ghost);
        const double y = g.coordinate(s, 1, j - g.ghost);
        const double z = g.is3D() ? g.coordinate(s, 2, k - g.ghostZ()) : 0.0;
        err = std::fmax(err, std::fabs(h(i, j, k) - f(x, y, z)));
      }
  return err;
}

TEST(TEST_CATEGORY, ghost_fill_scalar_reproduces_boundary_data) {
  const space s{};
  // x: Dirichlet values of a linear profile (odd extension is exact); y: zero-gradient walls
  // (even mirror of a y-independent field); z: periodic (a periodic profile)
  const Grid g = makeGrid(10, 6, 8, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 2);
  ScalarBoundaries bc;
  bc.kind[XLow] = bc.kind[XHigh] = BoundaryKind::Value;
  bc.kind[ZLow] = bc.kind[ZHigh] = BoundaryKind::Periodic;
  const Fn3 linear = [](double x, double, double) { return 2.0 + 3.0 * x; };
  bc.value[XLow] = 2.0;
  bc.value[XHigh] = 5.0;
  const field a = test::fieldFrom(s, g, Staggering::Cell, linear);
  fillGhostsScalar(s, g, bc, a);
  EXPECT_LE(maxErrorWithGhosts(a, g, Staggering::Cell, linear), 1e-13);
  // periodic z with walls in x and y: the periodic part is reproduced in every ghost layer
  ScalarBoundaries periodicZ;
  periodicZ.kind[ZLow] = periodicZ.kind[ZHigh] = BoundaryKind::Periodic;
  const Fn3 zOnly = [](double, double, double z) { return std::sin(2 * pi * z); };
  const field b = test::fieldFrom(s, g, Staggering::Cell, zOnly);
  fillGhostsScalar(s, g, periodicZ, b);
  EXPECT_LE(maxErrorWithGhosts(b, g, Staggering::Cell, zOnly), 1e-13);
}

TEST(TEST_CATEGORY, ghost_fill_velocity_sets_boundary_nodes_and_no_slip_ghosts) {
  const space s{};
  const Grid g = makeGrid(8, 6, 1, 1.0, 1.0, 0.125);
  VelocityBoundaries bc;
  bc.kind[XLow] = BoundaryKind::Value; // inflow u = 0.3 (+ v = 0.1) at x = 0
  bc.velocity[XLow][0] = 0.3;
  bc.velocity[XLow][1] = 0.1;
  bc.kind[XHigh] = BoundaryKind::Value; // outflow at the same rate, u = 0.3 at x = 1
  bc.velocity[XHigh][0] = 0.3;
  bc.velocity[YHigh][0] = 2.0; // lid moving along x
  // the data disagree at the corners, so check what each rule defines: the boundary nodes
  // (given normal velocity) and the no-slip ghosts (2 V - u) next to the walls
  const field u =
      test::fieldFrom(s, g, Staggering::FaceX, [](double, double y, double) { return 1.0 + y; });
  fillGhostsVelocity(s, g, bc, 0, u);
  auto h = test::toHost(u);
  const int o = g.ghost;
  for (int j = 0; j < g.ny; ++j) {
    EXPECT_DOUBLE_EQ(h(0 + o, j + o, 0), 0.3);    // boundary node x = 0
    EXPECT_DOUBLE_EQ(h(g.nx + o, j + o, 0), 0.3); // boundary node x = 1
  }
  for (int i = 1; i < g.nx; ++i) {
    const double first = 1.0 + g.coordinate(Staggering::FaceX, 1, 0);
    const double last = 1.0 + g.coordinate(Staggering::FaceX, 1, g.ny - 1);
    EXPECT_DOUBLE_EQ(h(i + o, o - 1, 0), -first);        // wall at rest: 2*0 - u
    EXPECT_DOUBLE_EQ(h(i + o, g.ny + o, 0), 4.0 - last); // lid: 2*2 - u
  }
}

// check(lo, hi, split) for boxes in an 8^3 index range, split in 2D and 3D: with and without an
// interior, odd and even sizes, empty.
template <class Check> void forEachTestSplit(Check const& check) {
  const int boxes[][6] = {{0, 0, 0, 7, 5, 1}, {1, 0, 0, 8, 6, 1}, {0, 0, 0, 1, 5, 1},
                          {0, 0, 0, 2, 2, 1}, {0, 0, 0, 6, 5, 4}, {1, 0, 0, 4, 3, 2},
                          {0, 0, 0, 3, 3, 3}, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 0, 4, 4},
                          {1, 1, 0, 7, 6, 3}, {1, 2, 1, 8, 8, 8}};
  for (const auto& b : boxes) {
    const int lo[3] = {b[0], b[1], b[2]};
    const int hi[3] = {b[3], b[4], b[5]};
    for (const bool threeD : {false, true}) {
      const bool active[3] = {true, true, threeD};
      check(lo, hi, splitBox(lo, hi, active));
    }
    // a small grid's box: not split, all shell (a coarse multigrid level)
    check(lo, hi, splitUnknowns(makeGrid(8, 8, 8, 1.0, 1.0, 1.0), lo, hi));
  }
}

TEST(TEST_CATEGORY, box_split_covers_every_cell_once) {
  forEachTestSplit([](int const(&lo)[3], int const(&hi)[3], BoxSplit const& split) {
    std::vector<int> count(static_cast<std::size_t>(8 * 8 * 8), 0);
    for (int k = split.interiorLo[2]; k < split.interiorHi[2]; ++k)
      for (int j = split.interiorLo[1]; j < split.interiorHi[1]; ++j)
        for (int i = split.interiorLo[0]; i < split.interiorHi[0]; ++i) {
          ++count[static_cast<std::size_t>(i + 8 * (j + 8 * k))];
        }
    for (std::int64_t sIdx = 0; sIdx < split.shellSize(); ++sIdx) {
      int i, j, k;
      split.shellCell(sIdx, i, j, k);
      ASSERT_TRUE(i >= lo[0] && i < hi[0] && j >= lo[1] && j < hi[1] && k >= lo[2] && k < hi[2]);
      ++count[static_cast<std::size_t>(i + 8 * (j + 8 * k))];
    }
    for (int k = 0; k < 8; ++k)
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
          const bool inside =
              i >= lo[0] && i < hi[0] && j >= lo[1] && j < hi[1] && k >= lo[2] && k < hi[2];
          EXPECT_EQ(count[static_cast<std::size_t>(i + 8 * (j + 8 * k))], inside ? 1 : 0)
              << "box " << lo[0] << lo[1] << lo[2] << "-" << hi[0] << hi[1] << hi[2] << " cell "
              << i << j << k;
        }
  });
}

// Marks each visit of a split loop with 1000 + the mask of axes it was given (BoxSplit.hpp).
struct VisitMarks {
  Kokkos::View<int***, space::memory_space> marks;
  template <unsigned Axes> KOKKOS_INLINE_FUNCTION double cell(int i, int j, int k) const {
    marks(i, j, k) += 1000 + static_cast<int>(Axes);
    return 1.0; // sumOverSplitCells counts the visits
  }
};

// forEachSplitCell, sumOverSplitCells and forEachSplitColourCell (on the host one launch over the
// box's rows) visit each cell of the box once, one colour only where asked; a visit skips the
// closures only along axes where the cell is in the interior, and the interior's cells skip them
// along every axis.
TEST(TEST_CATEGORY, split_loops_visit_each_cell_once_with_its_stencil) {
  forEachTestSplit([](int const(&lo)[3], int const(&hi)[3], BoxSplit const& split) {
    for (int colour = -2; colour < 2; ++colour) { // -2: forEachSplitCell, -1: the sum
      const VisitMarks body{Kokkos::View<int***, space::memory_space>("marks", 8, 8, 8)};
      if (colour == -2) {
        forEachSplitCell(space{}, "test::splitCells", split, body);
      } else if (colour == -1) {
        const double visits = sumOverSplitCells(space{}, "test::sumOverSplitCells", split, body);
        const double boxCells = double(hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
        EXPECT_EQ(visits, boxCells);
        EXPECT_EQ(static_cast<double>(split.size()), boxCells);
      } else {
        forEachSplitColourCell(space{}, "test::splitColourCells", split, colour, body);
      }
      const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, body.marks);
      for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
          for (int i = 0; i < 8; ++i) {
            const int idx[3] = {i, j, k};
            const bool inBox =
                i >= lo[0] && i < hi[0] && j >= lo[1] && j < hi[1] && k >= lo[2] && k < hi[2];
            unsigned insideAxes = 0u; // the axes along which the cell is in the interior
            for (int a = 0; a < 3; ++a) {
              if (idx[a] >= split.interiorLo[a] && idx[a] < split.interiorHi[a]) {
                insideAxes |= 1u << a;
              }
            }
            const bool visited = inBox && (colour < 0 || ((i + j + k) & 1) == colour);
            const std::string where = "box " + std::to_string(lo[0]) + std::to_string(lo[1]) +
                                      std::to_string(lo[2]) + "-" + std::to_string(hi[0]) +
                                      std::to_string(hi[1]) + std::to_string(hi[2]) + " colour " +
                                      std::to_string(colour) + " cell " + std::to_string(i) +
                                      std::to_string(j) + std::to_string(k);
            if (!visited) {
              EXPECT_EQ(h(i, j, k), 0) << where;
              continue;
            }
            ASSERT_GE(h(i, j, k), 1000) << where;
            ASSERT_LE(h(i, j, k), 1007) << where; // once
            const auto given = static_cast<unsigned>(h(i, j, k) - 1000);
            EXPECT_EQ(given & ~insideAxes, 0u) << where << ": closures skipped where needed";
            if (insideAxes == allAxes) {
              EXPECT_EQ(given, allAxes) << where;
            }
          }
    }
  });
}

// A Gauss-Seidel-like update of one cell of an 8^3 torus from its six neighbours (indices wrap,
// so a box spanning an axis couples its first and last planes, as a periodic axis does).
struct TorusGaussSeidel {
  Kokkos::View<double***, space::memory_space> x;
  template <unsigned> KOKKOS_INLINE_FUNCTION double cell(int i, int j, int k) const {
    const double around = x((i + 1) & 7, j, k) + x((i + 7) & 7, j, k) + x(i, (j + 1) & 7, k) +
                          x(i, (j + 7) & 7, k) + x(i, j, (k + 1) & 7) + x(i, j, (k + 7) & 7);
    x(i, j, k) = 0.3 * x(i, j, k) + 0.1 * around + 0.01 * (i - 2 * j + 3 * k);
    return 0.0;
  }
};

// forEachSplitRedBlackCell (on the host one pass over the box's planes, shared out in chunks)
// gives bit for bit what two colour passes give, whichever colour goes first and however many
// chunks the planes are split into.
TEST(TEST_CATEGORY, split_red_black_sweep_equals_two_colour_passes) {
  forEachTestSplit([](int const(&lo)[3], int const(&hi)[3], BoxSplit const& split) {
    using view = Kokkos::View<double***, space::memory_space>;
    const auto start = Kokkos::create_mirror_view(view("start", 8, 8, 8));
    for (int k = 0; k < 8; ++k)
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
          start(i, j, k) = std::sin(1.0 + i + 3.1 * j - 1.7 * k * k);
        }
    for (int first = 0; first < 2; ++first) {
      const view twoPasses("twoPasses", 8, 8, 8);
      Kokkos::deep_copy(twoPasses, start);
      forEachSplitColourCell(space{}, "test::colour", split, first, TorusGaussSeidel{twoPasses});
      forEachSplitColourCell(space{}, "test::colour", split, 1 - first,
                             TorusGaussSeidel{twoPasses});
      const auto expected = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, twoPasses);
      for (int chunks : {0, 1, 2, 3, 5, 8}) {
        const view onePass("onePass", 8, 8, 8);
        Kokkos::deep_copy(onePass, start);
        forEachSplitRedBlackCell(space{}, "test::redBlack", split, first, TorusGaussSeidel{onePass},
                                 chunks);
        const auto got = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, onePass);
        int differ = 0, changed = 0;
        for (int k = 0; k < 8; ++k)
          for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
              differ += got(i, j, k) != expected(i, j, k) ? 1 : 0;
              changed += got(i, j, k) != start(i, j, k) ? 1 : 0;
            }
        EXPECT_EQ(differ, 0) << "box " << lo[0] << lo[1] << lo[2] << "-" << hi[0] << hi[1] << hi[2]
                             << " first colour " << first << " chunks " << chunks;
        EXPECT_EQ(static_cast<std::int64_t>(changed), split.size()); // every cell swept
      }
    }
  });
}

// Transfer of a field of staggering s between g and its coarsening by `ratio`.
Transfer makeTestTransfer(Grid const& fine, Grid const& coarse, ScalarBoundaries const& sbc,
                          VelocityBoundaries const& vbc, Staggering s, int const (&ratio)[3],
                          bool linear, bool transpose) {
  Transfer t;
  AxisClosure f[3], c[3];
  if (s == Staggering::Cell) {
    scalarClosures(fine, sbc, f);
    scalarClosures(coarse, sbc, c);
  } else {
    const int comp = s == Staggering::FaceX ? 0 : (s == Staggering::FaceY ? 1 : 2);
    velocityClosures(fine, vbc, comp, f);
    velocityClosures(coarse, vbc, comp, c);
  }
  for (int a = 0; a < 3; ++a) {
    t.axis[a] = TransferAxis{f[a], c[a], ratio[a], linear, transpose};
  }
  t.fineOffsets = ghostOffsets(fine);
  t.coarseOffsets = ghostOffsets(coarse);
  return t;
}

void expectAdjoint(Grid const& fine, int const (&ratio)[3], ScalarBoundaries const& sbc,
                   VelocityBoundaries const& vbc, Staggering s, bool linear, bool transpose) {
  const space sp{};
  Grid coarse = fine;
  coarse.nx /= ratio[0];
  coarse.ny /= ratio[1];
  coarse.nz /= ratio[2];
  coarse.hx *= ratio[0];
  coarse.hy *= ratio[1];
  coarse.hz *= ratio[2];
  const Transfer t = makeTestTransfer(fine, coarse, sbc, vbc, s, ratio, linear, transpose);
  AxisClosure fa[3] = {t.axis[0].fine, t.axis[1].fine, t.axis[2].fine};
  AxisClosure ca[3] = {t.axis[0].coarse, t.axis[1].coarse, t.axis[2].coarse};
  const UnknownBox fbox = unknownBox(fine, fa);
  const UnknownBox cbox = unknownBox(coarse, ca);
  const Fn3 rough = [](double x, double y, double z) {
    return std::sin(7.1 * x + 1.3) * std::cos(5.3 * y - 0.4) + 0.3 * z * z + x * y;
  };
  const field ffine = test::fieldFrom(sp, fine, s, rough);
  const field cval = test::fieldFrom(
      sp, coarse, s, [](double x, double y, double z) { return std::cos(3.7 * x * y + z) + y; });
  // zero the boundary nodes of the coarse field: a correction has none
  const field cc = makeField(sp, coarse, s, "hikiln::test::cfd::cc");
  axpbyUnknowns(sp, cbox, 1.0, cval, 0.0, cc);
  const field rc = makeField(sp, coarse, s, "hikiln::test::cfd::rc");
  restrictField(sp, t, ffine, rc);
  const field pc = makeField(sp, fine, s, "hikiln::test::cfd::pc");
  prolongateAdd(sp, t, cc, pc);
  int d = 0;
  for (int a = 0; a < 3; ++a) {
    d += ratio[a] == 2 ? 1 : 0;
  }
  const double left = dotUnknowns(sp, cbox, rc, cc) * static_cast<double>(1 << d);
  const double right = dotUnknowns(sp, fbox, ffine, pc);
  const bool symmetric = transpose || !linear;
  if (symmetric) {
    EXPECT_NEAR(left, right, 1e-12 * std::fabs(right) + 1e-12)
        << "staggering " << static_cast<int>(s) << " linear " << linear;
  }
  // restriction of a constant (interpolation of a constant) is that constant away from
  // Dirichlet boundaries: sums are preserved for the Neumann / periodic scalar
  if (s == Staggering::Cell) {
    const field one = makeField(sp, fine, s, "hikiln::test::cfd::one");
    fillUnknowns(sp, fbox, 1.0, one);
    const field r1 = makeField(sp, coarse, s, "hikiln::test::cfd::r1");
    restrictField(sp, t, one, r1);
    EXPECT_NEAR(sumUnknowns(sp, cbox, r1) * (1 << d), sumUnknowns(sp, fbox, one), 1e-10);
  }
}

TEST(TEST_CATEGORY, transfer_restriction_is_scaled_transpose_of_interpolation) {
  ScalarBoundaries walls;
  ScalarBoundaries periodic;
  periodic.kind[XLow] = periodic.kind[XHigh] = BoundaryKind::Periodic;
  periodic.kind[YLow] = periodic.kind[YHigh] = BoundaryKind::Periodic;
  VelocityBoundaries channel;
  channel.kind[XLow] = channel.kind[XHigh] = BoundaryKind::Periodic;
  VelocityBoundaries box;
  const int r2[3] = {2, 2, 1};
  const int semi[3] = {2, 1, 1};
  const int r3[3] = {2, 2, 2};
  const Grid g2 = makeGrid(16, 12, 1, 1.0, 0.75, 1.0 / 16);
  const Grid g3 = makeGrid(8, 8, 4, 1.0, 1.0, 0.5);
  ScalarBoundaries walls3 = walls;
  walls3.kind[ZLow] = walls3.kind[ZHigh] = BoundaryKind::Wall;
  VelocityBoundaries box3 = box;
  box3.kind[ZLow] = box3.kind[ZHigh] = BoundaryKind::Wall;
  for (const bool linear : {false, true}) {
    for (const bool transpose : {false, true}) {
      expectAdjoint(g2, r2, walls, box, Staggering::Cell, linear, transpose);
      expectAdjoint(g2, r2, periodic, box, Staggering::Cell, linear, transpose);
      expectAdjoint(g2, semi, walls, box, Staggering::Cell, linear, transpose);
      expectAdjoint(g3, r3, walls3, box3, Staggering::Cell, linear, transpose);
      for (const Staggering s : {Staggering::FaceX, Staggering::FaceY}) {
        expectAdjoint(g2, r2, walls, box, s, linear, transpose);
        expectAdjoint(g2, r2, walls, channel, s, linear, transpose);
        expectAdjoint(g2, semi, walls, channel, s, linear, transpose);
      }
      expectAdjoint(g3, r3, walls3, box3, Staggering::FaceZ, linear, transpose);
    }
  }
}

TEST(TEST_CATEGORY, transfer_linear_interpolation_is_exact_for_linear_data) {
  // interior fine cells of a linearly varying coarse field get the linear value
  const space sp{};
  const Grid fine = makeGrid(16, 16, 1, 1.0, 1.0, 1.0 / 16);
  Grid coarse = fine;
  coarse.nx = coarse.ny = 8;
  coarse.hx = coarse.hy = 1.0 / 8;
  const int r2[3] = {2, 2, 1};
  const Transfer t = makeTestTransfer(fine, coarse, ScalarBoundaries(), VelocityBoundaries(),
                                      Staggering::Cell, r2, true, false);
  const Fn3 linear = [](double x, double y, double) { return 1.0 + 2.0 * x - 3.0 * y; };
  const field c = test::fieldFrom(sp, coarse, Staggering::Cell, linear);
  const field f = makeField(sp, fine, Staggering::Cell, "hikiln::test::cfd::f");
  prolongateAdd(sp, t, c, f);
  const test::Box interior{{1, 1, 0}, {15, 15, 1}};
  EXPECT_LE(test::maxError(f, fine, Staggering::Cell, interior, linear), 1e-13);
}

TEST(TEST_CATEGORY, harmonic_face_coefficients) {
  const space sp{};
  const Grid g = makeGrid(4, 2, 1, 1.0, 0.5, 0.25);
  ScalarBoundaries bc;
  bc.kind[XLow] = bc.kind[XHigh] = BoundaryKind::Periodic;
  AxisClosure axes[3];
  scalarClosures(g, bc, axes);
  // cells: 1, 1000, 1, 1000 along x
  const field c = test::fieldFrom(sp, g, Staggering::Cell, [](double x, double, double) {
    return static_cast<int>(x * 4) % 2 == 0 ? 1.0 : 1000.0;
  });
  field beta[3] = {makeField(sp, g, Staggering::FaceX, "hikiln::test::cfd::bx"),
                   makeField(sp, g, Staggering::FaceY, "hikiln::test::cfd::by"), field()};
  harmonicFaceCoefficients(sp, g, axes, c, beta);
  auto bx = test::toHost(beta[0]);
  auto by = test::toHost(beta[1]);
  const int o = g.ghost;
  for (int i = 0; i <= 4; ++i) { // periodic: the boundary faces see cells 3 and 0
    EXPECT_NEAR(bx(i + o, o, 0), 2.0 * 1000.0 / 1001.0, 1e-12);
  }
  EXPECT_DOUBLE_EQ(by(1 + o, 0 + o, 0), 1000.0); // wall face: the inside cell's value
  EXPECT_DOUBLE_EQ(by(1 + o, 1 + o, 0), 1000.0);
}

} // namespace
