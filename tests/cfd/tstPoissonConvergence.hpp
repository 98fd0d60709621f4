// Second-order convergence of the cell-centred operator -div(beta grad p) against manufactured
// solutions (2D: Neumann walls, constant beta; periodic x + Dirichlet y with variable beta; 3D:
// Neumann), each solved by multigrid to a residual far below the discretisation error.
#include "CfdTestUtils.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/GhostFill.hpp"
#include "solvers/cfd/CellMultigrid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

namespace {

using namespace hikiln::cfd;
using test::Fn3;
using space = TEST_EXECSPACE;
using field = Field<space::memory_space>;
constexpr double pi = hikiln::constants::pi;

struct Problem {
  Fn3 exact;
  Fn3 beta;
  ScalarBoundaries bc;
  bool singular = false;
};

// f = -div(beta grad p) from the analytic p and beta (fluxes differenced at 4th order).
Fn3 rhsOf(Problem const& p) {
  return [p](double x, double y, double z) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) {
      const Fn3 flux = [p, a](double u, double v, double w) {
        return p.beta(u, v, w) * test::derivative(p.exact, a, u, v, w);
      };
      sum += test::derivative(flux, a, x, y, z);
    }
    return -sum;
  };
}

// Max error of the multigrid solution on an n^d grid of the unit square/cube.
double solveError(Problem const& p, int n, bool threeD) {
  const space s{};
  const Grid g = makeGrid(n, n, threeD ? n : 1, 1.0, 1.0, threeD ? 1.0 : 1.0 / n);
  field beta[3];
  for (int a = 0; a < (threeD ? 3 : 2); ++a) {
    beta[a] = test::fieldFrom(s, g, faceStaggering(a), p.beta);
  }
  const Fn3 f = rhsOf(p);
  const field rhs = test::fieldFrom(s, g, Staggering::Cell, f);
  const field x = makeField(s, g, Staggering::Cell, "hikiln::test::cfd::x");
  MultigridOptions options;
  options.tolerance = 1e-12;
  CellMultigrid<space> mg(s, g, p.bc, field(), beta, options);
  EXPECT_EQ(mg.singular(), p.singular);
  const SolveStats stats = mg.solve(x, rhs);
  EXPECT_TRUE(stats.converged) << "n = " << n << " residual " << stats.finalResidual;
  const double error =
      test::maxError(x, g, Staggering::Cell, test::cellBox(g), p.exact, p.singular);
  std::cout << "n = " << n << (threeD ? "^3" : "^2") << ": max error " << error << ", "
            << stats.iterations << " V-cycles, mean reduction " << stats.meanReduction()
            << ", levels " << mg.numLevels() << "\n";
  return error;
}

void expectSecondOrder(Problem const& p, std::vector<int> const& sizes, bool threeD) {
  std::vector<double> errors;
  for (const int n : sizes) {
    errors.push_back(solveError(p, n, threeD));
  }
  const auto orders = test::observedOrders(errors);
  for (std::size_t i = 0; i < orders.size(); ++i) {
    EXPECT_GE(orders[i], 1.8) << "n " << sizes[i] << " -> " << sizes[i + 1] << " errors "
                              << errors[i] << " " << errors[i + 1];
    EXPECT_LE(orders[i], 2.2) << "n " << sizes[i] << " -> " << sizes[i + 1] << " errors "
                              << errors[i] << " " << errors[i + 1];
  }
}

TEST(TEST_CATEGORY, poisson_2d_neumann_second_order) {
  Problem p;
  p.exact = [](double x, double y, double) { return std::cos(pi * x) * std::cos(pi * y); };
  p.beta = [](double, double, double) { return 1.0; };
  p.singular = true;
  expectSecondOrder(p, {32, 64, 128, 256}, false);
}

TEST(TEST_CATEGORY, poisson_2d_variable_beta_periodic_dirichlet_second_order) {
  Problem p;
  // p(x, 0) = 0 and p(x, 1) = 0.5 for every x: constant Dirichlet values on the y sides
  p.exact = [](double x, double y, double) {
    return std::cos(2.0 * pi * x) * std::sin(pi * y) + 0.5 * y;
  };
  p.beta = [](double x, double y, double) {
    return 1.0 + 0.5 * std::sin(2.0 * pi * x) * std::cos(pi * y);
  };
  p.bc.kind[XLow] = p.bc.kind[XHigh] = BoundaryKind::Periodic;
  p.bc.kind[YLow] = p.bc.kind[YHigh] = BoundaryKind::Value;
  p.bc.value[YLow] = 0.0;
  p.bc.value[YHigh] = 0.5;
  expectSecondOrder(p, {32, 64, 128, 256}, false);
}

TEST(TEST_CATEGORY, poisson_3d_neumann_second_order) {
  Problem p;
  p.exact = [](double x, double y, double z) {
    return std::cos(pi * x) * std::cos(pi * y) * std::cos(pi * z);
  };
  p.beta = [](double, double, double) { return 1.0; };
  p.bc.kind[ZLow] = p.bc.kind[ZHigh] = BoundaryKind::Wall;
  p.singular = true;
  expectSecondOrder(p, {16, 32, 64}, true);
}

} // namespace
