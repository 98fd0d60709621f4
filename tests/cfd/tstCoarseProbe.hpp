// The coarsest multigrid level's matrix probed many columns per operator application
// (DenseCoarseSolver, MultigridOptions::colouredProbe) is the matrix probed one column at a
// time, bitwise: solves with either take the same iterations to the same bits. Covered: the
// closed drum's masked pressure problem, a 3D pressure problem periodic along z with 3 and
// 5 coarse cells there (the colour spacing wraps), and the coupled viscous operator with
// walls and a periodic axis in 2D and 3D (6 coarse cells along the periodic z).
#include "CfdTestUtils.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/ShellGeometry.hpp"
#include "solvers/cfd/CellMultigrid.hpp"
#include "solvers/cfd/ViscousMultigrid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <iostream>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using field = Field<space::memory_space>;
using velocity = VelocityFields<space::memory_space>;
constexpr double pi = hikiln::constants::pi;

// Number of entries whose bits differ.
int differingBits(field const& a, field const& b) {
  const auto ha = test::toHost(a);
  const auto hb = test::toHost(b);
  int differ = 0;
  for (std::size_t q = 0; q < ha.size(); ++q) {
    differ += std::memcmp(&ha.data()[q], &hb.data()[q], sizeof(double)) != 0;
  }
  return differ;
}

struct ProbeRun {
  SolveStats stats;
  field x;
  int probes = 0, unknowns = 0;
};

// PCG on the cell operator with face coefficients 1 / rho(x) and alpha (may be empty).
ProbeRun pressureSolve(Grid const& g, ScalarBoundaries const& bc, field const& alpha,
                       field const (&beta)[3], field const& open, bool coloured) {
  const space s{};
  MultigridOptions options;
  options.tolerance = 1e-11;
  options.colouredProbe = coloured;
  CellMultigrid<space> mg(s, g, bc, alpha, beta, options, open);
  ProbeRun run;
  run.x = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x");
  run.stats = mg.solvePcg(run.x, test::randomField(s, g, 7));
  run.probes = mg.coarseProbes();
  run.unknowns = mg.coarseUnknowns();
  return run;
}

void expectSameSolve(ProbeRun const& coloured, ProbeRun const& columns, const char* what) {
  std::cout << what << ": coarse level " << columns.unknowns << " unknowns, " << columns.probes
            << " probes one column at a time, " << coloured.probes << " coloured; PCG "
            << coloured.stats.iterations << " / " << columns.stats.iterations << " iterations\n";
  EXPECT_TRUE(coloured.stats.converged) << what;
  EXPECT_EQ(coloured.stats.iterations, columns.stats.iterations) << what;
  EXPECT_EQ(differingBits(coloured.x, columns.x), 0) << what;
  EXPECT_EQ(columns.probes, columns.unknowns) << what;
  EXPECT_LT(coloured.probes, columns.probes) << what;
}

TEST(TEST_CATEGORY, coarse_probe_coloured_equals_columns_closed_drum_pressure) {
  const space s{};
  const Grid g = makeGrid(64, 64, 1, 2.0, 2.0, 2.0 / 64, -1.0, -1.0);
  DrumShell shell;
  shell.radius = 0.9;
  const CutCells<space::memory_space> cut = buildCutCells(s, g, shell);
  AxisClosure axes[3];
  scalarClosures(g, ScalarBoundaries(), axes);
  field beta[3];
  for (int a = 0; a < 2; ++a) {
    beta[a] = makeField(s, g, faceStaggering(a), "hikiln::test::cfd::beta");
  }
  harmonicFaceCoefficients(s, g, axes, test::drumBedInverseDensity(s, g, 1000.0, 0.2), beta);
  // alpha decouples the cells with no fluid, as in TwoPhaseSolver::project
  field alpha = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::alpha");
  auto hAlpha = test::toHost(alpha);
  const auto capacity = test::toHost(cut.capacity);
  for (std::size_t q = 0; q < hAlpha.size(); ++q) {
    hAlpha.data()[q] = capacity.data()[q] > 0.0 ? 0.0 : 1e3;
  }
  Kokkos::deep_copy(alpha, hAlpha);
  const ProbeRun coloured = pressureSolve(g, ScalarBoundaries(), alpha, beta, cut.capacity, true);
  const ProbeRun columns = pressureSolve(g, ScalarBoundaries(), alpha, beta, cut.capacity, false);
  expectSameSolve(coloured, columns, "closed drum pressure, 64^2");
}

TEST(TEST_CATEGORY, coarse_probe_coloured_equals_columns_periodic_3d_pressure) {
  const space s{};
  ScalarBoundaries bc;
  bc.kind[ZLow] = bc.kind[ZHigh] = BoundaryKind::Periodic;
  bc.kind[XLow] = BoundaryKind::Value; // not singular
  for (const int nz : {12, 20}) {      // 3 and 5 cells along z on the coarsest level
    const Grid g = makeGrid(16, 16, nz, 1.0, 1.0, nz / 16.0);
    field beta[3];
    for (int a = 0; a < 3; ++a) {
      beta[a] = test::fieldFrom(s, g, faceStaggering(a), [](double x, double y, double z) {
        return 1.0 + 0.5 * std::sin(2 * pi * x) * std::cos(2 * pi * y) * std::cos(pi * z);
      });
    }
    const ProbeRun coloured = pressureSolve(g, bc, field(), beta, field(), true);
    const ProbeRun columns = pressureSolve(g, bc, field(), beta, field(), false);
    expectSameSolve(coloured, columns,
                    nz == 12 ? "3D pressure, 16 x 16 x 12, periodic z"
                             : "3D pressure, 16 x 16 x 20, periodic z");
  }
}

// PCG on the viscous operator with alpha = 30, variable mu and a smooth right-hand side;
// x = component c of the solution.
ProbeRun viscousSolve(Grid const& g, VelocityBoundaries const& bc, bool coloured, int c,
                      std::int64_t maxCoarseCells = 64) {
  const space s{};
  const int dims = g.is3D() ? 3 : 2;
  field alpha[3];
  velocity f, u;
  for (int a = 0; a < dims; ++a) {
    alpha[a] =
        test::fieldFrom(s, g, faceStaggering(a), [](double, double, double) { return 30.0; });
    f.comp[a] = test::fieldFrom(s, g, faceStaggering(a), [a](double x, double y, double z) {
      return std::sin(3.0 * x + a) * std::cos(5.0 * y - z) + 0.1 * a;
    });
    u.comp[a] = makeField(s, g, faceStaggering(a), "hikiln::test::cfd::u");
  }
  const field mu = test::fieldFrom(s, g, Staggering::Cell, [](double x, double y, double z) {
    return 1.0 + 50.0 * (y < 0.4 + 0.1 * std::sin(2 * pi * (x + z)));
  });
  MultigridOptions options;
  options.tolerance = 1e-11;
  options.colouredProbe = coloured;
  options.coarsening.maxCoarseCells = maxCoarseCells;
  ViscousMultigrid<space> mg(s, g, bc, alpha, mu, options);
  ProbeRun run;
  run.stats = mg.solvePcg(u, f);
  run.x = u.comp[c];
  run.probes = mg.coarseProbes();
  run.unknowns = mg.coarseUnknowns();
  return run;
}

TEST(TEST_CATEGORY, coarse_probe_coloured_equals_columns_viscous) {
  VelocityBoundaries walls2d;
  walls2d.kind[XLow] = walls2d.kind[XHigh] = BoundaryKind::Periodic;
  walls2d.velocity[YHigh][0] = 1.0;
  const Grid g2 = makeGrid(32, 32, 1, 1.0, 1.0, 1.0);
  for (int c = 0; c < 2; ++c) {
    expectSameSolve(viscousSolve(g2, walls2d, true, c), viscousSolve(g2, walls2d, false, c),
                    c == 0 ? "viscous 2D, walls in y, u" : "viscous 2D, walls in y, v");
  }
  // walls in x and y, periodic in z; the coarsest level 4 x 4 x 6 (6 wraps with spacing 3)
  VelocityBoundaries walls3d;
  walls3d.velocity[YHigh][2] = 1.0;
  const Grid g3 = makeGrid(16, 16, 24, 1.0, 1.0, 1.5);
  for (int c = 0; c < 3; ++c) {
    expectSameSolve(viscousSolve(g3, walls3d, true, c, 256),
                    viscousSolve(g3, walls3d, false, c, 256),
                    c == 0   ? "viscous 3D, periodic z, u"
                    : c == 1 ? "viscous 3D, periodic z, v"
                             : "viscous 3D, periodic z, w");
  }
}

} // namespace
