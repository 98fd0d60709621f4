// Multigrid performance in numbers: residual reduction per V-cycle and iteration counts across
// grid sizes (2D, 3D, flat domains), PCG across a 1e3 density jump (a drum-like bed), the
// Neumann null space, a warm start's stopping rule, the direct single-level path and the
// coarse-size guard.
#include "CfdTestUtils.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/ShellGeometry.hpp"
#include "solvers/cfd/CellMultigrid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using field = Field<space::memory_space>;

// Unit face coefficients on every axis of g.
void unitBeta(space const& s, Grid const& g, field (&beta)[3]) {
  for (int a = 0; a < (g.is3D() ? 3 : 2); ++a) {
    beta[a] = makeField(s, g, faceStaggering(a), "hikiln::test::cfd::beta");
    Kokkos::deep_copy(s, beta[a], 1.0);
  }
}

// V-cycles on -lap x = random f from x = 0; returns the stats.
SolveStats vcycles(Grid const& g, ScalarBoundaries const& bc, int* levels = nullptr) {
  const space s{};
  field beta[3];
  unitBeta(s, g, beta);
  const field f = test::randomField(s, g, 2024);
  const field x = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x");
  MultigridOptions options;
  options.tolerance = 1e-10;
  CellMultigrid<space> mg(s, g, bc, field(), beta, options);
  if (levels != nullptr) {
    *levels = mg.numLevels();
  }
  return mg.solve(x, f);
}

TEST(TEST_CATEGORY, multigrid_2d_vcycle_rate_and_size_independent_iterations) {
  ScalarBoundaries walls; // Neumann: the singular case
  std::vector<int> iterations;
  for (const int n : {32, 64, 128, 256, 512}) {
    int levels = 0;
    const SolveStats stats = vcycles(makeGrid(n, n, 1, 1.0, 1.0, 1.0 / n), walls, &levels);
    std::cout << n << "^2: " << levels << " levels, " << stats.iterations
              << " V(2,2) to 1e-10, mean reduction " << stats.meanReduction() << ", worst "
              << stats.worstReduction() << "\n";
    EXPECT_TRUE(stats.converged);
    EXPECT_LT(stats.worstReduction(), 0.15) << "n = " << n;
    iterations.push_back(stats.iterations);
  }
  const auto [lo, hi] = std::minmax_element(iterations.begin(), iterations.end());
  EXPECT_LE(*hi - *lo, 2) << "iteration counts vary by more than +-1 across sizes";
}

TEST(TEST_CATEGORY, multigrid_3d_vcycle_rate) {
  ScalarBoundaries bc;
  bc.kind[ZLow] = bc.kind[ZHigh] = BoundaryKind::Wall;
  bc.kind[XLow] = bc.kind[XHigh] = BoundaryKind::Periodic;
  std::vector<int> iterations;
  for (const int n : {16, 32, 64}) {
    const SolveStats stats = vcycles(makeGrid(n, n, n, 1.0, 1.0, 1.0), bc);
    std::cout << n << "^3: " << stats.iterations << " V(2,2) to 1e-10, mean reduction "
              << stats.meanReduction() << ", worst " << stats.worstReduction() << "\n";
    EXPECT_TRUE(stats.converged);
    EXPECT_LT(stats.worstReduction(), 0.15) << "n = " << n;
    iterations.push_back(stats.iterations);
  }
  const auto [lo, hi] = std::minmax_element(iterations.begin(), iterations.end());
  EXPECT_LE(*hi - *lo, 2);
}

TEST(TEST_CATEGORY, multigrid_flat_domain_semicoarsens) {
  // 512 x 32 cells: y stops coarsening early, x goes on while cells stay within aspect 2
  ScalarBoundaries bc;
  bc.kind[YLow] = BoundaryKind::Value; // Dirichlet bottom, walls elsewhere
  int levels = 0;
  const SolveStats stats = vcycles(makeGrid(512, 32, 1, 16.0, 1.0, 1.0 / 32), bc, &levels);
  std::cout << "512 x 32: " << levels << " levels, " << stats.iterations
            << " V-cycles, worst reduction " << stats.worstReduction() << "\n";
  EXPECT_TRUE(stats.converged);
  EXPECT_GE(levels, 5);
  EXPECT_LT(stats.worstReduction(), 0.15);
}

TEST(TEST_CATEGORY, pcg_density_jump_drum_bed_bounded_iterations) {
  const space s{};
  std::vector<int> iterations;
  for (const int n : {64, 128, 256, 512}) {
    const Grid g = makeGrid(n, n, 1, 2.0, 2.0, 2.0 / n, -1.0, -1.0);
    ScalarBoundaries bc;
    AxisClosure axes[3];
    scalarClosures(g, bc, axes);
    const field inverseDensity = test::drumBedInverseDensity(s, g, 1000.0, 0.2);
    field beta[3];
    for (int a = 0; a < 2; ++a) {
      beta[a] = makeField(s, g, faceStaggering(a), "hikiln::test::cfd::beta");
    }
    harmonicFaceCoefficients(s, g, axes, inverseDensity, beta);
    const field f = test::randomField(s, g, 7);
    const field x = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x");
    MultigridOptions options;
    options.tolerance = 1e-10;
    CellMultigrid<space> mg(s, g, bc, field(), beta, options);
    const SolveStats stats = mg.solvePcg(x, f);
    std::cout << "drum bed, rho ratio 1e3, " << n << "^2: PCG " << stats.iterations
              << " iterations to 1e-10, true residual "
              << stats.finalResidual / stats.initialResidual << "\n";
    EXPECT_TRUE(stats.converged);
    EXPECT_LE(stats.finalResidual, 1e-8 * stats.initialResidual);
    EXPECT_LE(stats.iterations, 18) << "n = " << n;
    iterations.push_back(stats.iterations);
  }
  EXPECT_LE(iterations.back() - iterations.front(), 6) << "PCG iterations grow too fast";
}

TEST(TEST_CATEGORY, multigrid_neumann_projects_inconsistent_rhs) {
  const space s{};
  const Grid g = makeGrid(64, 64, 1, 1.0, 1.0, 1.0 / 64);
  ScalarBoundaries walls;
  field beta[3];
  unitBeta(s, g, beta);
  field f = test::randomField(s, g, 99);
  MultigridOptions options;
  options.tolerance = 1e-11;
  CellMultigrid<space> mg(s, g, walls, field(), beta, options);
  ASSERT_TRUE(mg.singular());
  const field x1 = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x1");
  EXPECT_TRUE(mg.solve(x1, f).converged);
  // the same problem with a constant added to f (inconsistent) gives the same solution
  const UnknownBox box = unknownBox(g, mg.levelOperator(0).axis);
  addToUnknowns(s, box, 3.0, f);
  const field x2 = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x2");
  EXPECT_TRUE(mg.solve(x2, f).converged);
  const double mean = sumUnknowns(s, box, x2) / static_cast<double>(box.size());
  EXPECT_NEAR(mean, 0.0, 1e-12);
  axpbyUnknowns(s, box, 1.0, x1, -1.0, x2);
  const double scale = maxAbsUnknowns(s, box, x1);
  EXPECT_LE(maxAbsUnknowns(s, box, x2), 1e-9 * scale);
}

// The pressure problem of a closed drum (TwoPhaseSolver::project) on n^2 cells: the drum bed's
// 1e3 density jump, face coefficients times the shell's apertures, alpha only on the cells with
// no open face (it decouples them). With `open` the solver gets the capacity as its mask.
struct ShellPressure {
  CutCells<space::memory_space> cut;
  field alpha, beta[3];
};

ShellPressure shellPressure(space const& s, Grid const& g) {
  ShellPressure sp;
  DrumShell shell;
  shell.radius = 0.9;
  sp.cut = buildCutCells(s, g, shell);
  AxisClosure axes[3];
  scalarClosures(g, ScalarBoundaries(), axes);
  for (int a = 0; a < 2; ++a) {
    sp.beta[a] = makeField(s, g, faceStaggering(a), "hikiln::test::cfd::beta");
  }
  harmonicFaceCoefficients(s, g, axes, test::drumBedInverseDensity(s, g, 1000.0, 0.2), sp.beta);
  sp.alpha = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::alpha");
  auto alpha = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sp.alpha);
  auto capacity = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sp.cut.capacity);
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      alpha(i + g.ghost, j + g.ghost, 0) = capacity(i + g.ghost, j + g.ghost, 0) > 0.0 ? 0.0 : 1e3;
    }
  }
  Kokkos::deep_copy(sp.alpha, alpha);
  for (int a = 0; a < 2; ++a) {
    auto beta = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sp.beta[a]);
    auto aperture = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sp.cut.aperture[a]);
    for (std::size_t q = 0; q < beta.size(); ++q) {
      beta.data()[q] *= aperture.data()[q];
    }
    Kokkos::deep_copy(sp.beta[a], beta);
  }
  return sp;
}

TEST(TEST_CATEGORY, pcg_shell_masked_singular_converges) {
  // With the capacity as its mask the multigrid keeps the outside cells' alpha out of the coarse
  // cells that straddle the shell, so the problem is singular on the fluid cells on every level.
  // The solver removes their mean from the right-hand side (random here, so not zero) and from
  // every residual; without that the iteration cannot converge.
  const space s{};
  for (const int n : {64, 128, 256}) {
    const Grid g = makeGrid(n, n, 1, 2.0, 2.0, 2.0 / n, -1.0, -1.0);
    const ShellPressure sp = shellPressure(s, g);
    const field f = test::randomField(s, g, 11);
    MultigridOptions options;
    options.tolerance = 1e-11; // the drums' pressure tolerance
    CellMultigrid<space> mg(s, g, ScalarBoundaries(), sp.alpha, sp.beta, options, sp.cut.capacity);
    const field x = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x");
    const SolveStats stats = mg.solvePcg(x, f);
    std::cout << "closed shell, rho ratio 1e3, " << n << "^2: PCG " << stats.iterations
              << " iterations to 1e-11, true residual "
              << stats.finalResidual / stats.initialResidual << "\n";
    EXPECT_TRUE(stats.converged) << "n = " << n;
    EXPECT_LE(stats.finalResidual, 1e-10 * stats.initialResidual) << "n = " << n;
    EXPECT_LE(stats.iterations, 30) << "n = " << n; // measured 19 / 27 / 18
  }
}

TEST(TEST_CATEGORY, pcg_warm_start_stops_at_the_cold_target) {
  // A warm start (x from a neighbouring problem's solution) given the cold start's residual as
  // its reference stops at the cold start's target in fewer iterations; referred to its own,
  // smaller residual it would iterate on to a tighter target.
  const space s{};
  const Grid g = makeGrid(64, 64, 1, 2.0, 2.0, 2.0 / 64, -1.0, -1.0);
  const ShellPressure sp = shellPressure(s, g);
  MultigridOptions options;
  options.tolerance = 1e-11;
  CellMultigrid<space> mg(s, g, ScalarBoundaries(), sp.alpha, sp.beta, options, sp.cut.capacity);
  const field f = test::randomField(s, g, 11);
  const field x0 = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x0");
  ASSERT_TRUE(mg.solvePcg(x0, f).converged);
  // the next problem: f moved by 1e-3 of a second random field
  const field next = test::randomField(s, g, 12);
  axpbyUnknowns(s, unknownBox(g, mg.levelOperator(0).axis), 1.0, f, 1e-3, next);
  const field cold = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::cold");
  const double reference = mg.residualNorm(cold, next);
  const SolveStats fromCold = mg.solvePcg(cold, next);
  const auto warmFrom = [&](double ref) {
    const field x = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::warm");
    Kokkos::deep_copy(s, x, x0);
    return mg.solvePcg(x, next, ref);
  };
  const SolveStats warm = warmFrom(reference);
  const SolveStats ownTarget = warmFrom(0.0);
  std::cout << "closed shell 64^2, next problem: PCG iterations cold " << fromCold.iterations
            << ", warm " << warm.iterations << " (start at " << warm.initialResidual / reference
            << " of the cold residual), warm to its own target " << ownTarget.iterations << "\n";
  EXPECT_DOUBLE_EQ(fromCold.referenceResidual, reference);
  EXPECT_DOUBLE_EQ(warm.referenceResidual, reference);
  EXPECT_LT(warm.initialResidual, 1e-2 * reference);
  EXPECT_TRUE(warm.converged);
  EXPECT_LE(warm.finalResidual, 10.0 * options.tolerance * reference);
  EXPECT_LT(warm.iterations, fromCold.iterations);
  EXPECT_LT(warm.iterations, ownTarget.iterations);
}

TEST(TEST_CATEGORY, multigrid_single_level_direct_solve_is_exact) {
  // 5 x 6 cells periodic in x (odd: no red-black colouring) -> one level, solved densely
  const space s{};
  const Grid g = makeGrid(5, 6, 1, 1.0, 1.2, 0.2);
  ScalarBoundaries bc;
  bc.kind[XLow] = bc.kind[XHigh] = BoundaryKind::Periodic;
  bc.kind[YHigh] = BoundaryKind::Value;
  bc.value[YHigh] = 2.5;
  field beta[3];
  unitBeta(s, g, beta);
  const field f = test::randomField(s, g, 5);
  const field x = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x");
  CellMultigrid<space> mg(s, g, bc, field(), beta);
  EXPECT_EQ(mg.numLevels(), 1);
  EXPECT_FALSE(mg.singular());
  const SolveStats stats = mg.solve(x, f);
  EXPECT_EQ(stats.iterations, 1);
  EXPECT_LE(stats.finalResidual, 1e-12 * stats.initialResidual);
}

TEST(TEST_CATEGORY, multigrid_rejects_large_coarsest_level) {
  // 70 -> 35 (odd) leaves 35^2 = 1225 cells for the dense solve (limit 1024)
  const space s{};
  const Grid g = makeGrid(70, 70, 1, 1.0, 1.0, 1.0 / 70);
  field beta[3];
  unitBeta(s, g, beta);
  EXPECT_THROW(CellMultigrid<space>(s, g, ScalarBoundaries(), field(), beta), std::runtime_error);
}

} // namespace
