// The viscous operator with the stresses that read closed faces left out (ViscousOperator.hpp,
// "Closed faces"), on the cut cells of a drum shell (2D, and 3D periodic along the axis):
// - it stays symmetric and positive semi-definite: <A x, y> = <x, A y> and <A x, x> >= 0;
// - changing the velocity on closed faces only leaves A x unchanged on every open face (the
//   shell does not pull on the fluid through the viscous stencil), whereas the operator without
//   the mask does change there (so the check can fail);
// - the strain rate with the same apertures is blind to closed faces as well (every cell).
#include "CfdTestUtils.hpp"
#include "kernels/cfd/GranularRheology.hpp"
#include "kernels/cfd/ShellGeometry.hpp"
#include "kernels/cfd/ViscousOperator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace {

using namespace hikiln::cfd;
using space = TEST_EXECSPACE;
using memory = space::memory_space;
using field = Field<memory>;
using velocity = VelocityFields<memory>;

struct Case {
  Grid grid;
  CutCells<memory> cut;
  field mu;
  AxisClosure axis[3][3];
  int dims = 2;
};

Case drumCase(bool threeD) {
  Case c;
  c.grid = makeGrid(24, 24, threeD ? 4 : 1, 1.0, 1.0, 0.25, -0.5, -0.5, 0.0);
  c.dims = threeD ? 3 : 2;
  DrumShell shell;
  shell.radius = 0.45;
  c.cut = buildCutCells(space{}, c.grid, shell);
  // a positive viscosity that varies from cell to cell
  c.mu = test::fieldFrom(space{}, c.grid, Staggering::Cell, [](double x, double y, double z) {
    return 1.5 + std::sin(7.0 * x + 3.0 * y) * std::cos(5.0 * z + 2.0 * x);
  });
  const VelocityBoundaries bc; // walls on x and y, periodic along z
  for (int comp = 0; comp < 3; ++comp) {
    velocityClosures(c.grid, bc, comp, c.axis[comp]);
  }
  return c;
}

ViscousOperator<memory> makeOperator(Case const& c, bool masked) {
  ViscousOperator<memory> op;
  op.grid = c.grid;
  op.mu = c.mu;
  for (int comp = 0; comp < 3; ++comp) {
    for (int a = 0; a < 3; ++a) {
      op.axis[comp][a] = c.axis[comp][a];
    }
  }
  velocity open;
  for (int comp = 0; comp < c.dims; ++comp) {
    open.comp[comp] = masked ? c.cut.aperture[comp] : field();
  }
  op.open = open;
  for (int s = 0; s < (c.dims == 3 ? 3 : 1); ++s) {
    op.muEdge[s] = makeField(space{}, c.grid, edgeStaggering(s), "hikiln::test::muEdge");
  }
  const bool periodic[3] = {false, false, true};
  edgeViscosities(space{}, c.grid, periodic, op.mu, op.muEdge, op.open);
  return op;
}

// Calls f(comp, I, J, K) for every unknown (ghost-offset indices) of every component.
template <class F> void forEachUnknown(Case const& c, F&& f) {
  const Grid& g = c.grid;
  const int off[3] = {g.ghost, g.ghost, g.ghostZ()};
  for (int comp = 0; comp < c.dims; ++comp) {
    AxisClosure const(&ax)[3] = c.axis[comp];
    for (int k = ax[2].begin(); k < ax[2].end(); ++k)
      for (int j = ax[1].begin(); j < ax[1].end(); ++j)
        for (int i = ax[0].begin(); i < ax[0].end(); ++i)
          f(comp, i + off[0], j + off[1], k + off[2]);
  }
}

// Pseudo-random values in [-0.5, 0.5) on the unknowns (0 elsewhere, boundary nodes included);
// `closedOnly`: only on the closed faces.
velocity randomVelocity(Case const& c, unsigned long long seed, bool closedOnly) {
  velocity v;
  decltype(test::toHost(c.mu)) host[3], open[3];
  for (int comp = 0; comp < c.dims; ++comp) {
    v.comp[comp] = makeField(space{}, c.grid, faceStaggering(comp), "hikiln::test::x");
    host[comp] = test::toHost(v.comp[comp]);
    open[comp] = test::toHost(c.cut.aperture[comp]);
  }
  unsigned long long state = seed;
  forEachUnknown(c, [&](int comp, int I, int J, int K) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double value = static_cast<double>(state >> 11) / static_cast<double>(1ULL << 53) - 0.5;
    if (!closedOnly || open[comp](I, J, K) <= 0.0) {
      host[comp](I, J, K) = value;
    }
  });
  for (int comp = 0; comp < c.dims; ++comp) {
    Kokkos::deep_copy(v.comp[comp], host[comp]);
  }
  return v;
}

velocity apply(Case const& c, ViscousOperator<memory> const& op, velocity const& x) {
  velocity out;
  for (int comp = 0; comp < c.dims; ++comp) {
    out.comp[comp] = makeField(space{}, c.grid, faceStaggering(comp), "hikiln::test::Ax");
  }
  applyViscousOperator(space{}, op, x, out, false);
  space().fence();
  return out;
}

velocity sum(Case const& c, velocity const& a, velocity const& b) {
  velocity out;
  for (int comp = 0; comp < c.dims; ++comp) {
    out.comp[comp] = makeField(space{}, c.grid, faceStaggering(comp), "hikiln::test::sum");
    const auto ha = test::toHost(a.comp[comp]);
    const auto hb = test::toHost(b.comp[comp]);
    auto ho = test::toHost(out.comp[comp]);
    for (std::size_t n = 0; n < ha.span(); ++n) {
      ho.data()[n] = ha.data()[n] + hb.data()[n];
    }
    Kokkos::deep_copy(out.comp[comp], ho);
  }
  return out;
}

double dot(Case const& c, velocity const& a, velocity const& b) {
  decltype(test::toHost(c.mu)) ha[3], hb[3];
  for (int comp = 0; comp < c.dims; ++comp) {
    ha[comp] = test::toHost(a.comp[comp]);
    hb[comp] = test::toHost(b.comp[comp]);
  }
  double sum = 0.0;
  forEachUnknown(
      c, [&](int comp, int I, int J, int K) { sum += ha[comp](I, J, K) * hb[comp](I, J, K); });
  return sum;
}

// Largest |A x - A y| on the open faces, relative to the largest |A x| there.
double openFaceChange(Case const& c, velocity const& ax, velocity const& ay) {
  double change = 0.0, scale = 0.0;
  for (int comp = 0; comp < c.dims; ++comp) {
    const auto hx = test::toHost(ax.comp[comp]);
    const auto hy = test::toHost(ay.comp[comp]);
    const auto open = test::toHost(c.cut.aperture[comp]);
    forEachUnknown(c, [&](int q, int I, int J, int K) {
      if (q == comp && open(I, J, K) > 0.0) {
        change = std::max(change, std::fabs(hx(I, J, K) - hy(I, J, K)));
        scale = std::max(scale, std::fabs(hx(I, J, K)));
      }
    });
  }
  return change / scale;
}

void checkClosedFaces(bool threeD) {
  const Case c = drumCase(threeD);
  const auto masked = makeOperator(c, true);
  const velocity x = randomVelocity(c, 11, false);
  const velocity y = randomVelocity(c, 29, false);
  const velocity ax = apply(c, masked, x), ay = apply(c, masked, y);
  const double xAy = dot(c, x, ay), yAx = dot(c, y, ax);
  const double xAx = dot(c, x, ax), yAy = dot(c, y, ay);
  // a sum of squares: also non-negative on x - y
  const double mixed = xAx - xAy - yAx + yAy;
  std::cout << (threeD ? "3D" : "2D") << ": <x, Ay> " << xAy << " <y, Ax> " << yAx << ", <x, Ax> "
            << xAx << ", <x-y, A(x-y)> " << mixed << "\n";
  EXPECT_LT(std::fabs(xAy - yAx), 1e-12 * (std::fabs(xAx) + std::fabs(yAy)));
  EXPECT_GT(xAx, 0.0);
  EXPECT_GT(yAy, 0.0);
  EXPECT_GT(mixed, 0.0);

  // x plus a change on the closed faces only
  const velocity kick = randomVelocity(c, 47, true);
  const velocity xk = sum(c, x, kick);
  const double maskedChange = openFaceChange(c, ax, apply(c, masked, xk));
  const auto plain = makeOperator(c, false);
  const double plainChange = openFaceChange(c, apply(c, plain, x), apply(c, plain, xk));
  std::cout << "  change of A x on open faces after a change on closed faces: " << maskedChange
            << " (masked), " << plainChange << " (unmasked)\n";
  EXPECT_LT(maskedChange, 1e-14);
  EXPECT_GT(plainChange, 1e-2);
}

// Largest change of gamma_dot over all cells after a change on closed faces only, relative to
// the largest gamma_dot; with or without the apertures.
double strainRateChange(Case const& c, bool masked) {
  const velocity x = randomVelocity(c, 11, false);
  const velocity xk = sum(c, x, randomVelocity(c, 47, true));
  velocity open;
  for (int comp = 0; comp < c.dims; ++comp) {
    open.comp[comp] = masked ? c.cut.aperture[comp] : field();
  }
  const field before = makeField(space{}, c.grid, Staggering::Cell, "hikiln::test::rate");
  const field after = makeField(space{}, c.grid, Staggering::Cell, "hikiln::test::rate");
  strainRateInvariant(space{}, c.grid, x, before, open);
  strainRateInvariant(space{}, c.grid, xk, after, open);
  const auto hb = test::toHost(before);
  const auto ha = test::toHost(after);
  double change = 0.0, scale = 0.0;
  for (std::size_t n = 0; n < hb.span(); ++n) {
    change = std::max(change, std::fabs(ha.data()[n] - hb.data()[n]));
    scale = std::max(scale, std::fabs(hb.data()[n]));
  }
  return change / scale;
}

void checkStrainRate(bool threeD) {
  const Case c = drumCase(threeD);
  const double masked = strainRateChange(c, true);
  const double plain = strainRateChange(c, false);
  std::cout << (threeD ? "3D" : "2D")
            << ": change of gamma_dot after a change on closed faces: " << masked << " (masked), "
            << plain << " (unmasked)\n";
  EXPECT_EQ(masked, 0.0);
  EXPECT_GT(plain, 1e-2);
}

TEST(TEST_CATEGORY, strain_rate_closed_faces_2d) {
  checkStrainRate(false);
}

TEST(TEST_CATEGORY, strain_rate_closed_faces_3d) {
  checkStrainRate(true);
}

TEST(TEST_CATEGORY, viscous_closed_faces_2d) {
  checkClosedFaces(false);
}

TEST(TEST_CATEGORY, viscous_closed_faces_3d) {
  checkClosedFaces(true);
}

} // namespace
