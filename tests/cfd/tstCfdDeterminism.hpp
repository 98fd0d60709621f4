// Backend agreement: a fixed number of V-cycles (red-black Gauss-Seidel, no atomics, no
// reductions in the iterate) of the pressure and of the viscous multigrid is bitwise identical on
// TEST_EXECSPACE (any thread count) and on Kokkos::Serial; a PCG solve (dot products are parallel
// reductions) agrees to round-off.
#include "CfdTestUtils.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "solvers/cfd/CellMultigrid.hpp"
#include "solvers/cfd/ViscousMultigrid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using namespace hikiln::cfd;
// on a device the compiler may contract a*b+c into FMA: compare with the host to round-off only
constexpr bool bitwiseVsHost =
    Kokkos::SpaceAccessibility<Kokkos::HostSpace, TEST_EXECSPACE::memory_space>::accessible;

// Solution (host copy, cells in i-fastest order) after `cycles` V-cycles, or after a PCG solve
// when cycles == 0, of a variable-coefficient problem on space.
template <class Space> std::vector<double> solveOn(Grid const& g, int cycles) {
  using field = Field<typename Space::memory_space>;
  const Space s{};
  ScalarBoundaries bc;
  bc.kind[XLow] = bc.kind[XHigh] = BoundaryKind::Periodic;
  bc.kind[YHigh] = BoundaryKind::Value;
  bc.value[YHigh] = 0.7;
  if (g.is3D()) {
    bc.kind[ZLow] = bc.kind[ZHigh] = BoundaryKind::Wall;
  }
  AxisClosure axes[3];
  scalarClosures(g, bc, axes);
  const field c = test::fieldFrom(s, g, Staggering::Cell, [](double x, double y, double z) {
    return (x - 0.3) * (x - 0.3) + (y - 0.6) * (y - 0.6) + z * z < 0.1 ? 1e-3 : 1.0;
  });
  field beta[3];
  for (int a = 0; a < (g.is3D() ? 3 : 2); ++a) {
    beta[a] = makeField(s, g, faceStaggering(a), "hikiln::test::cfd::beta");
  }
  harmonicFaceCoefficients(s, g, axes, c, beta);
  const field f = test::randomField(s, g, 11);
  const field x = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x");
  MultigridOptions options;
  options.tolerance = 1e-10;
  CellMultigrid<Space> mg(s, g, bc, field(), beta, options);
  if (cycles > 0) {
    for (int i = 0; i < cycles; ++i) {
      mg.vcycle(x, f, true);
    }
  } else {
    EXPECT_TRUE(mg.solvePcg(x, f).converged);
  }
  auto h = test::toHost(x);
  std::vector<double> out;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        out.push_back(h(i + g.ghost, j + g.ghost, k + g.ghostZ()));
      }
  return out;
}

// Velocity (host copy, all components) after `cycles` V-cycles of the viscous multigrid with a
// moving wall, variable viscosity and alpha, on space.
template <class Space> std::vector<double> viscousOn(Grid const& g, int cycles) {
  using field = Field<typename Space::memory_space>;
  const Space s{};
  VelocityBoundaries bc;
  bc.kind[XLow] = bc.kind[XHigh] = BoundaryKind::Periodic;
  bc.velocity[YHigh][0] = 1.0;
  if (g.is3D()) {
    bc.kind[ZLow] = bc.kind[ZHigh] = BoundaryKind::Wall;
    bc.velocity[YHigh][2] = 0.5;
  }
  const int dims = g.is3D() ? 3 : 2;
  field alpha[3];
  VelocityFields<typename Space::memory_space> u, f;
  for (int c = 0; c < dims; ++c) {
    alpha[c] = test::fieldFrom(s, g, faceStaggering(c),
                               [](double x, double y, double) { return 1.0 + x * y; });
    f.comp[c] = test::fieldFrom(s, g, faceStaggering(c), [c](double x, double y, double z) {
      return std::sin(3.0 * x + c) * std::cos(2.0 * y - z);
    });
    u.comp[c] = makeField(s, g, faceStaggering(c), "hikiln::test::cfd::u");
  }
  const field mu = test::fieldFrom(s, g, Staggering::Cell, [](double x, double y, double z) {
    return std::exp(2.0 * std::sin(4.0 * x) * y + z);
  });
  ViscousMultigrid<Space> mg(s, g, bc, alpha, mu);
  mg.fillBoundaries(u);
  for (int i = 0; i < cycles; ++i) {
    mg.vcycle(u, f, true);
  }
  std::vector<double> out;
  for (int c = 0; c < dims; ++c) {
    auto h = test::toHost(u.comp[c]);
    for (std::size_t i = 0; i < h.size(); ++i) {
      out.push_back(h.data()[i]);
    }
  }
  return out;
}

double maxAbs(std::vector<double> const& v) {
  double m = 0.0;
  for (const double x : v) {
    m = std::fmax(m, std::fabs(x));
  }
  return m;
}

void expectSame(Grid const& g, int cycles, double relativeTolerance, bool viscous = false) {
#if defined(KOKKOS_ENABLE_SERIAL)
  const auto reference =
      viscous ? viscousOn<Kokkos::Serial>(g, cycles) : solveOn<Kokkos::Serial>(g, cycles);
  const auto result =
      viscous ? viscousOn<TEST_EXECSPACE>(g, cycles) : solveOn<TEST_EXECSPACE>(g, cycles);
  ASSERT_EQ(reference.size(), result.size());
  const double scale = maxAbs(reference);
  ASSERT_GT(scale, 0.0);
  std::size_t differing = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < result.size(); ++i) {
    differing += result[i] != reference[i] ? 1 : 0;
    worst = std::fmax(worst, std::fabs(result[i] - reference[i]));
  }
  if (relativeTolerance == 0.0) {
    EXPECT_EQ(differing, 0u) << "largest difference " << worst;
  } else {
    EXPECT_LE(worst, relativeTolerance * scale);
  }
#else
  GTEST_SKIP() << "Kokkos::Serial not enabled";
#endif
}

TEST(TEST_CATEGORY, vcycles_bitwise_identical_to_serial_2d) {
  expectSame(makeGrid(96, 64, 1, 1.5, 1.0, 1.0 / 64), 4, bitwiseVsHost ? 0.0 : 1e-13);
}

TEST(TEST_CATEGORY, vcycles_bitwise_identical_to_serial_3d) {
  expectSame(makeGrid(32, 32, 16, 1.0, 1.0, 0.5), 3, bitwiseVsHost ? 0.0 : 1e-13);
}

TEST(TEST_CATEGORY, pcg_matches_serial_to_round_off) {
  expectSame(makeGrid(128, 128, 1, 1.0, 1.0, 1.0 / 128), 0, 1e-12);
}

TEST(TEST_CATEGORY, viscous_vcycles_bitwise_identical_to_serial_2d) {
  expectSame(makeGrid(64, 48, 1, 1.0, 0.75, 1.0 / 64), 3, bitwiseVsHost ? 0.0 : 1e-13, true);
}

TEST(TEST_CATEGORY, viscous_vcycles_bitwise_identical_to_serial_3d) {
  expectSame(makeGrid(16, 16, 16, 1.0, 1.0, 1.0), 2, bitwiseVsHost ? 0.0 : 1e-13, true);
}

} // namespace
