// The MAC viscous operator alpha u - div(mu (grad u + grad u^T)) and its multigrid:
// - plane Couette (2D, and 3D with a wall moving along x and z): the discrete solution is the
//   exact linear profile, to round-off;
// - plane Poiseuille: the discrete solution is the exact parabola plus G h^2 / (8 mu) (the
//   no-slip ghost closure), so the error is known exactly and converges at second order;
// - Couette with viscosity varying across the gap: second order;
// - manufactured, coupled u-v(-w) fields with variable mu and alpha (2D with moving walls, 3D
//   periodic): second order, and the V-cycle rate and PCG iteration counts.
#include "CfdTestUtils.hpp"
#include "kernels/cfd/ViscousOperator.hpp"
#include "solvers/cfd/ViscousMultigrid.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace {

using namespace hikiln::cfd;
using test::Fn3;
using space = TEST_EXECSPACE;
using field = Field<space::memory_space>;
using velocity = VelocityFields<space::memory_space>;
constexpr double pi = hikiln::constants::pi;

struct Flow {
  std::array<Fn3, 3> u;     // exact velocity components
  Fn3 mu;                   // viscosity
  Fn3 alpha;                // rho / dt (nullptr: none)
  std::array<Fn3, 3> force; // right-hand side (nullptr: computed from u, mu, alpha)
  VelocityBoundaries bc;
};

// f_c = alpha u_c - sum_a d/dx_a (mu (du_c/dx_a + du_a/dx_c)), 4th-order differences.
Fn3 manufacturedForce(Flow const& flow, int c, int dims) {
  return [flow, c, dims](double x, double y, double z) {
    double sum = flow.alpha ? flow.alpha(x, y, z) * flow.u[c](x, y, z) : 0.0;
    for (int a = 0; a < dims; ++a) {
      const Fn3 stress = [flow, a, c](double p, double q, double r) {
        return flow.mu(p, q, r) *
               (test::derivative(flow.u[c], a, p, q, r) + test::derivative(flow.u[a], c, p, q, r));
      };
      sum -= test::derivative(stress, a, x, y, z);
    }
    return sum;
  };
}

struct Result {
  double error = 0.0;
  SolveStats stats;
  int levels = 0;
};

// Solves on grid g; error = max over components and unknowns of |u - exact - offset[c]|.
Result solveFlow(Flow const& flow, Grid const& g, bool pcg = false,
                 std::array<double, 3> offset = {0.0, 0.0, 0.0}, double tolerance = 1e-11) {
  const space s{};
  const int dims = g.is3D() ? 3 : 2;
  field alpha[3];
  velocity f, u;
  for (int c = 0; c < dims; ++c) {
    if (flow.alpha) {
      alpha[c] = test::fieldFrom(s, g, faceStaggering(c), flow.alpha);
    }
    f.comp[c] = test::fieldFrom(s, g, faceStaggering(c),
                                flow.force[c] ? flow.force[c] : manufacturedForce(flow, c, dims));
    u.comp[c] = makeField(s, g, faceStaggering(c), "hikiln::test::cfd::u");
  }
  const field mu = test::fieldFrom(s, g, Staggering::Cell, flow.mu);
  MultigridOptions options;
  options.tolerance = tolerance;
  ViscousMultigrid<space> mg(s, g, flow.bc, alpha, mu, options);
  Result result;
  result.levels = mg.numLevels();
  result.stats = pcg ? mg.solvePcg(u, f) : mg.solve(u, f);
  EXPECT_TRUE(result.stats.converged) << "residual " << result.stats.finalResidual;
  for (int c = 0; c < dims; ++c) {
    AxisClosure axes[3];
    velocityClosures(g, flow.bc, c, axes);
    test::Box box{{axes[0].begin(), axes[1].begin(), axes[2].begin()},
                  {axes[0].end(), axes[1].end(), axes[2].end()}};
    const double shift = offset[c];
    const Fn3 exact = [&flow, c, shift](double x, double y, double z) {
      return flow.u[c](x, y, z) + shift;
    };
    result.error =
        std::fmax(result.error, test::maxError(u.comp[c], g, faceStaggering(c), box, exact));
  }
  return result;
}

// Channel 0 <= y <= 1, periodic in x (and z), no-slip walls at y = 0 and 1.
VelocityBoundaries channel(bool threeD) {
  VelocityBoundaries bc;
  bc.kind[XLow] = bc.kind[XHigh] = BoundaryKind::Periodic;
  bc.kind[YLow] = bc.kind[YHigh] = BoundaryKind::Wall;
  bc.kind[ZLow] = bc.kind[ZHigh] = BoundaryKind::Periodic;
  (void)threeD;
  return bc;
}

Fn3 constant(double value) {
  return [value](double, double, double) { return value; };
}

TEST(TEST_CATEGORY, viscous_couette_exact_to_round_off) {
  Flow flow;
  flow.bc = channel(false);
  flow.bc.velocity[YHigh][0] = 1.0; // top wall moves along x at 1 m/s
  flow.u = {[](double, double y, double) { return y; }, constant(0.0), constant(0.0)};
  flow.mu = constant(0.7);
  flow.force = {constant(0.0), constant(0.0), constant(0.0)};
  const Result r =
      solveFlow(flow, makeGrid(32, 64, 1, 0.5, 1.0, 1.0 / 64), false, {0, 0, 0}, 1e-13);
  std::cout << "Couette 32 x 64: max error " << r.error << " after " << r.stats.iterations
            << " V-cycles\n";
  EXPECT_LE(r.error, 1e-12);
}

TEST(TEST_CATEGORY, viscous_couette_3d_exact_to_round_off) {
  Flow flow;
  flow.bc = channel(true);
  flow.bc.velocity[YHigh][0] = 1.0;
  flow.bc.velocity[YHigh][2] = -0.5;
  flow.u = {[](double, double y, double) { return y; }, constant(0.0),
            [](double, double y, double) { return -0.5 * y; }};
  flow.mu = constant(2.0);
  flow.alpha = constant(10.0); // one implicit step from the steady state stays there
  flow.force = {[](double, double y, double) { return 10.0 * y; }, constant(0.0),
                [](double, double y, double) { return -5.0 * y; }};
  const Result r = solveFlow(flow, makeGrid(16, 32, 16, 0.5, 1.0, 0.5), false, {0, 0, 0}, 1e-13);
  std::cout << "Couette 3D 16 x 32 x 16: max error " << r.error << "\n";
  EXPECT_LE(r.error, 1e-12);
}

TEST(TEST_CATEGORY, viscous_poiseuille_known_discrete_error_second_order) {
  const double mu = 0.5, gradient = 3.0; // body force G = -dp/dx
  Flow flow;
  flow.bc = channel(false);
  flow.u = {[=](double, double y, double) { return gradient / (2.0 * mu) * y * (1.0 - y); },
            constant(0.0), constant(0.0)};
  flow.mu = constant(mu);
  flow.force = {constant(gradient), constant(0.0), constant(0.0)};
  std::vector<double> errors;
  for (const int ny : {16, 32, 64, 128}) {
    const double h = 1.0 / ny;
    const Grid g = makeGrid(8, ny, 1, 8.0 * h, 1.0, h);
    const Result r = solveFlow(flow, g);
    errors.push_back(r.error);
    // the discrete solution is the parabola shifted by G h^2 / (8 mu), to solver tolerance
    const double shift = gradient * h * h / (8.0 * mu);
    const Result shifted = solveFlow(flow, g, false, {shift, 0.0, 0.0});
    std::cout << "Poiseuille ny = " << ny << ": max error " << r.error
              << " (G h^2 / 8 mu = " << shift << "), |u - parabola - shift| " << shifted.error
              << "\n";
    EXPECT_LE(shifted.error, 1e-9);
    EXPECT_NEAR(r.error, shift, 1e-9);
  }
  for (const double order : test::observedOrders(errors)) {
    EXPECT_NEAR(order, 2.0, 0.01);
  }
}

TEST(TEST_CATEGORY, viscous_variable_viscosity_couette_second_order) {
  // mu = mu0 (1 + a y): uniform shear stress, u = U ln(1 + a y) / ln(1 + a)
  const double a = 3.0;
  Flow flow;
  flow.bc = channel(false);
  flow.bc.velocity[YHigh][0] = 1.0;
  flow.u = {[=](double, double y, double) { return std::log(1.0 + a * y) / std::log(1.0 + a); },
            constant(0.0), constant(0.0)};
  flow.mu = [=](double, double y, double) { return 0.2 * (1.0 + a * y); };
  flow.force = {constant(0.0), constant(0.0), constant(0.0)};
  std::vector<double> errors;
  for (const int ny : {32, 64, 128, 256}) {
    const double h = 1.0 / ny;
    const Result r = solveFlow(flow, makeGrid(8, ny, 1, 8.0 * h, 1.0, h));
    std::cout << "variable-mu Couette ny = " << ny << ": max error " << r.error << "\n";
    errors.push_back(r.error);
  }
  for (const double order : test::observedOrders(errors)) {
    EXPECT_GE(order, 1.8);
    EXPECT_LE(order, 2.2);
  }
}

TEST(TEST_CATEGORY, viscous_coupled_2d_moving_walls_second_order) {
  // u(x, 0) = 0, u(x, 1) = 1 (moving lid), v = 0 on both walls; mu and alpha vary
  Flow flow;
  flow.bc = channel(false);
  flow.bc.velocity[YHigh][0] = 1.0;
  flow.u = {[](double x, double y, double) { return y + std::sin(2 * pi * x) * std::sin(pi * y); },
            [](double x, double y, double) {
              return std::cos(2 * pi * x) * std::sin(pi * y) * std::sin(pi * y);
            },
            constant(0.0)};
  flow.mu = [](double x, double y, double) {
    return 1.0 + 0.5 * std::sin(2 * pi * x) * std::cos(pi * y);
  };
  flow.alpha = [](double x, double y, double) { return 5.0 + 2.0 * std::cos(2 * pi * x) * y; };
  std::vector<double> errors;
  for (const int n : {32, 64, 128}) {
    const Result r = solveFlow(flow, makeGrid(n, n, 1, 1.0, 1.0, 1.0 / n));
    std::cout << "coupled 2D n = " << n << ": max error " << r.error << ", " << r.levels
              << " levels, " << r.stats.iterations << " V-cycles, worst reduction "
              << r.stats.worstReduction() << "\n";
    EXPECT_LT(r.stats.worstReduction(), 0.2);
    errors.push_back(r.error);
  }
  for (const double order : test::observedOrders(errors)) {
    EXPECT_GE(order, 1.8);
    EXPECT_LE(order, 2.2);
  }
}

TEST(TEST_CATEGORY, viscous_coupled_3d_periodic_second_order) {
  Flow flow;
  flow.bc.kind[YLow] = flow.bc.kind[YHigh] = BoundaryKind::Periodic;
  flow.bc.kind[XLow] = flow.bc.kind[XHigh] = BoundaryKind::Periodic;
  flow.u = {[](double x, double y, double z) {
              return std::sin(2 * pi * x) * std::cos(2 * pi * (y + z));
            },
            [](double x, double y, double z) {
              return std::cos(2 * pi * (x - z)) * std::sin(2 * pi * y);
            },
            [](double x, double y, double z) {
              return std::sin(2 * pi * (x + y)) * std::cos(2 * pi * z);
            }};
  flow.mu = [](double x, double y, double z) {
    return 1.0 + 0.4 * std::sin(2 * pi * x) * std::sin(2 * pi * y) * std::cos(2 * pi * z);
  };
  flow.alpha = constant(20.0);
  std::vector<double> errors;
  for (const int n : {16, 32}) {
    const Result r = solveFlow(flow, makeGrid(n, n, n, 1.0, 1.0, 1.0), true);
    std::cout << "coupled 3D n = " << n << ": max error " << r.error << ", PCG "
              << r.stats.iterations << " iterations\n";
    errors.push_back(r.error);
    EXPECT_LE(r.stats.iterations, 20);
  }
  for (const double order : test::observedOrders(errors)) {
    EXPECT_GE(order, 1.8);
    EXPECT_LE(order, 2.2);
  }
}

TEST(TEST_CATEGORY, viscous_steady_stokes_rates_size_independent) {
  // no alpha (steady), walls: the hardest case for the smoother; V-cycles and PCG
  Flow flow;
  flow.bc = channel(false);
  flow.bc.velocity[YHigh][0] = 1.0;
  flow.u = {[](double x, double y, double) { return y + std::sin(2 * pi * x) * std::sin(pi * y); },
            [](double x, double y, double) {
              return std::cos(2 * pi * x) * std::sin(pi * y) * std::sin(pi * y);
            },
            constant(0.0)};
  flow.mu = [](double x, double y, double) { return std::exp(std::sin(2 * pi * x) * y); };
  std::vector<int> iterations;
  for (const int n : {32, 64, 128, 256}) {
    const Grid g = makeGrid(n, n, 1, 1.0, 1.0, 1.0 / n);
    const Result mgResult = solveFlow(flow, g, false, {0, 0, 0}, 1e-10);
    const Result pcgResult = solveFlow(flow, g, true, {0, 0, 0}, 1e-10);
    std::cout << "steady Stokes-like n = " << n << ": " << mgResult.stats.iterations
              << " V-cycles (worst reduction " << mgResult.stats.worstReduction() << "), PCG "
              << pcgResult.stats.iterations << "\n";
    iterations.push_back(pcgResult.stats.iterations);
    EXPECT_LE(pcgResult.stats.iterations, 25);
  }
  EXPECT_LE(iterations.back() - iterations.front(), 4);
}

} // namespace
