#pragma once
// Helpers of the continuum-solver tests: fields from analytic functions, error norms, observed
// convergence orders, and 4th-order finite differences for manufactured right-hand sides.
#include "kernels/cfd/Grid.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace hikiln::cfd::test {

using Fn3 = std::function<double(double, double, double)>;

/// Field of staggering s with f evaluated at every stored interior position (boundary nodes
/// included; ghosts 0).
template <class ExecutionSpace>
Field<typename ExecutionSpace::memory_space> fieldFrom(ExecutionSpace const& space, Grid const& g,
                                                       Staggering s, Fn3 const& f) {
  auto field = makeField(space, g, s, "hikiln::test::cfd::field");
  auto h = Kokkos::create_mirror_view(Kokkos::HostSpace{}, field);
  Kokkos::deep_copy(h, 0.0);
  const int n[3] = {g.nx + isNodeCentred(s, 0), g.ny + isNodeCentred(s, 1),
                    g.nz + (g.is3D() ? isNodeCentred(s, 2) : 0)};
  for (int k = 0; k < n[2]; ++k) {
    for (int j = 0; j < n[1]; ++j) {
      for (int i = 0; i < n[0]; ++i) {
        h(i + g.ghost, j + g.ghost, k + g.ghostZ()) =
            f(g.coordinate(s, 0, i), g.coordinate(s, 1, j), g.is3D() ? g.coordinate(s, 2, k) : 0.0);
      }
    }
  }
  Kokkos::deep_copy(space, field, h);
  space.fence();
  return field;
}

/// Host copy of a field.
template <class View> auto toHost(View const& v) {
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, v);
}

/// Index box [lo, hi) per axis of logical indices.
struct Box {
  int lo[3];
  int hi[3];
};

/// Max |field - f| over a box of logical indices (optionally after removing both means).
template <class View>
double maxError(View const& field, Grid const& g, Staggering s, Box const& box, Fn3 const& f,
                bool removeMeans = false) {
  auto h = toHost(field);
  double meanField = 0.0, meanExact = 0.0, count = 0.0;
  const auto at = [&](int i, int j, int k) { return h(i + g.ghost, j + g.ghost, k + g.ghostZ()); };
  const auto exact = [&](int i, int j, int k) {
    return f(g.coordinate(s, 0, i), g.coordinate(s, 1, j), g.is3D() ? g.coordinate(s, 2, k) : 0.0);
  };
  if (removeMeans) {
    for (int k = box.lo[2]; k < box.hi[2]; ++k)
      for (int j = box.lo[1]; j < box.hi[1]; ++j)
        for (int i = box.lo[0]; i < box.hi[0]; ++i) {
          meanField += at(i, j, k);
          meanExact += exact(i, j, k);
          count += 1.0;
        }
    meanField /= count;
    meanExact /= count;
  }
  double err = 0.0;
  for (int k = box.lo[2]; k < box.hi[2]; ++k)
    for (int j = box.lo[1]; j < box.hi[1]; ++j)
      for (int i = box.lo[0]; i < box.hi[0]; ++i) {
        err = std::fmax(err, std::fabs((at(i, j, k) - meanField) - (exact(i, j, k) - meanExact)));
      }
  return err;
}

/// Cell box of a grid.
inline Box cellBox(Grid const& g) {
  return Box{{0, 0, 0}, {g.nx, g.ny, g.nz}};
}

/// Observed orders log2(e[i] / e[i + 1]) for grids refined by 2.
inline std::vector<double> observedOrders(std::vector<double> const& errors) {
  std::vector<double> orders;
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    orders.push_back(std::log2(errors[i] / errors[i + 1]));
  }
  return orders;
}

/// d/dx_axis of f at (x, y, z), 4th-order central difference (step 1e-3: error ~1e-11 for the
/// smooth trigonometric test functions, far below every discretisation error tested).
inline double derivative(Fn3 const& f, int axis, double x, double y, double z) {
  const double h = 1e-3;
  double p[3] = {x, y, z};
  const auto at = [&](double shift) {
    double q[3] = {p[0], p[1], p[2]};
    q[axis] += shift;
    return f(q[0], q[1], q[2]);
  };
  return (8.0 * (at(h) - at(-h)) - (at(2 * h) - at(-2 * h))) / (12.0 * h);
}

/// A cell field of deterministic pseudo-random values in [-0.5, 0.5) (ghosts 0).
template <class ExecutionSpace>
Field<typename ExecutionSpace::memory_space> randomField(ExecutionSpace const& space, Grid const& g,
                                                         unsigned long long seed) {
  auto field = makeField(space, g, Staggering::Cell, "hikiln::test::cfd::random");
  auto h = Kokkos::create_mirror_view(Kokkos::HostSpace{}, field);
  Kokkos::deep_copy(h, 0.0);
  unsigned long long state = seed;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        h(i + g.ghost, j + g.ghost, k + g.ghostZ()) =
            static_cast<double>(state >> 11) / static_cast<double>(1ULL << 53) - 0.5;
      }
  Kokkos::deep_copy(space, field, h);
  space.fence();
  return field;
}

/// Drum-like two-phase density on [-1, 1]^2: a bed (rho = ratio) filling `fill` of a circle of
/// radius 0.9 below a horizontal chord, gas (rho = 1) elsewhere. Returns 1 / rho in the cells.
template <class ExecutionSpace>
Field<typename ExecutionSpace::memory_space>
drumBedInverseDensity(ExecutionSpace const& space, Grid const& g, double ratio, double fill) {
  const double radius = 0.9;
  // chord at depth t * radius below the centre: segment area fraction acos(t) - t sqrt(1 - t^2)
  double lo = -1.0, hi = 1.0;
  for (int it = 0; it < 100; ++it) {
    const double t = 0.5 * (lo + hi);
    const double fraction = (std::acos(t) - t * std::sqrt(1.0 - t * t)) / 3.14159265358979323846;
    (fraction > fill ? lo : hi) = t;
  }
  const double chord = -0.5 * (lo + hi) * radius;
  return fieldFrom(space, g, Staggering::Cell, [=](double x, double y, double) {
    const bool bed = x * x + y * y < radius * radius && y < chord;
    return bed ? 1.0 / ratio : 1.0;
  });
}

/// \brief Largest |value| of a field of staggering s over its stored interior positions
/// (boundary nodes included).
template <class View> double maxAbsInterior(View const& v, Grid const& g, Staggering s) {
  const auto h = toHost(v);
  double worst = 0.0;
  for (int k = 0; k < g.nz + isNodeCentred(s, 2); ++k) {
    for (int j = 0; j < g.ny + isNodeCentred(s, 1); ++j) {
      for (int i = 0; i < g.nx + isNodeCentred(s, 0); ++i) {
        worst = std::max(worst, std::fabs(h(i + g.ghost, j + g.ghost, k + g.ghostZ())));
      }
    }
  }
  return worst;
}

} // namespace hikiln::cfd::test
