// The assembled Kokkos Kernels baseline (CrsMatrix + Jacobi-PCG) against the matrix-free
// operator and the multigrid solution: same matrix-vector product, same solution to solver
// tolerance (Dirichlet + variable coefficients; Neumann with a density jump; 3D with alpha).
#include "CfdTestUtils.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "solvers/cfd/CellMultigrid.hpp"
#include "solvers/cfd/CrsBaseline.hpp"

#include <gtest/gtest.h>

#include <KokkosSparse_spmv.hpp>

#include <cmath>
#include <iostream>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using field = Field<space::memory_space>;

struct Case {
  Grid grid;
  ScalarBoundaries bc;
  field alpha;
  field beta[3];
};

Case makeCase(int n, bool threeD, bool jump) {
  const space s{};
  Case c;
  c.grid = threeD ? makeGrid(n, n, n, 2.0, 2.0, 2.0, -1.0, -1.0, -1.0)
                  : makeGrid(n, n, 1, 2.0, 2.0, 2.0 / n, -1.0, -1.0);
  if (!jump) {
    c.bc.kind[XLow] = c.bc.kind[XHigh] = BoundaryKind::Periodic;
    c.bc.kind[YLow] = BoundaryKind::Value;
    c.bc.value[YLow] = 1.5;
  }
  if (threeD) {
    c.bc.kind[ZLow] = c.bc.kind[ZHigh] = BoundaryKind::Wall;
    c.alpha = test::fieldFrom(s, c.grid, Staggering::Cell,
                              [](double x, double, double z) { return 2.0 + x * z; });
  }
  AxisClosure axes[3];
  scalarClosures(c.grid, c.bc, axes);
  const field cellCoefficient =
      jump ? test::drumBedInverseDensity(s, c.grid, 1000.0, 0.3)
           : test::fieldFrom(s, c.grid, Staggering::Cell, [](double x, double y, double z) {
               return 1.0 + 0.5 * std::sin(3.0 * x) * std::cos(2.0 * y) + 0.2 * z;
             });
  for (int a = 0; a < (threeD ? 3 : 2); ++a) {
    c.beta[a] = makeField(s, c.grid, faceStaggering(a), "hikiln::test::cfd::beta");
  }
  harmonicFaceCoefficients(s, c.grid, axes, cellCoefficient, c.beta);
  return c;
}

void compareWithMultigrid(Case const& c) {
  const space s{};
  MultigridOptions options;
  options.tolerance = 1e-12;
  CellMultigrid<space> mg(s, c.grid, c.bc, c.alpha, c.beta, options);
  const field f = test::randomField(s, c.grid, 31);
  const field xMg = makeField(s, c.grid, Staggering::Cell, "hikiln::test::cfd::xMg");
  const SolveStats mgStats = mg.solvePcg(xMg, f);
  ASSERT_TRUE(mgStats.converged);

  CrsBaseline<space> crs(s, mg.levelOperator(0));
  // same operator: A y for a random y, matrix-free vs CrsMatrix
  const UnknownBox box = unknownBox(c.grid, mg.levelOperator(0).axis);
  const field y = test::randomField(s, c.grid, 77);
  const field ay = makeField(s, c.grid, Staggering::Cell, "hikiln::test::cfd::ay");
  applyCellOperator(s, mg.levelOperator(0), y, ay, false);
  typename CrsBaseline<space>::vector_type yv("hikiln::test::cfd::yv", crs.size()),
      ayv("hikiln::test::cfd::ayv", crs.size());
  packUnknowns(s, box, y, yv, 0);
  KokkosSparse::spmv("N", 1.0, crs.matrix(), yv, 0.0, ayv);
  const field ayCrs = makeField(s, c.grid, Staggering::Cell, "hikiln::test::cfd::ayCrs");
  unpackUnknowns(s, box, ayv, 0, ayCrs);
  axpbyUnknowns(s, box, 1.0, ay, -1.0, ayCrs);
  EXPECT_LE(maxAbsUnknowns(s, box, ayCrs), 1e-12 * maxAbsUnknowns(s, box, ay));

  const field xCrs = makeField(s, c.grid, Staggering::Cell, "hikiln::test::cfd::xCrs");
  const SolveStats crsStats = crs.solve(xCrs, f, 1e-12, 20000);
  ASSERT_TRUE(crsStats.converged);
  std::cout << c.grid.nx << (c.grid.is3D() ? "^3" : "^2") << ": " << crs.numEntries()
            << " matrix entries; Jacobi-CG " << crsStats.iterations << " iterations, MG-PCG "
            << mgStats.iterations << " iterations (to 1e-12)\n";
  const double scale = maxAbsUnknowns(s, box, xMg);
  axpbyUnknowns(s, box, 1.0, xMg, -1.0, xCrs);
  EXPECT_LE(maxAbsUnknowns(s, box, xCrs), 1e-8 * scale);
  EXPECT_GT(crsStats.iterations, 3 * mgStats.iterations);
}

TEST(TEST_CATEGORY, crs_baseline_matches_multigrid_2d_dirichlet_variable_beta) {
  compareWithMultigrid(makeCase(64, false, false));
}

TEST(TEST_CATEGORY, crs_baseline_matches_multigrid_2d_density_jump) {
  compareWithMultigrid(makeCase(64, false, true));
}

TEST(TEST_CATEGORY, crs_baseline_matches_multigrid_3d_helmholtz) {
  compareWithMultigrid(makeCase(16, true, false));
}

} // namespace
