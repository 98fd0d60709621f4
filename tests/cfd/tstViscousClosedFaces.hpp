// The viscous operator with the stresses that read closed faces left out (ViscousOperator.hpp,
// "Closed faces"), on the cut cells of a drum shell (2D, and 3D periodic along the axis):
// - it stays symmetric and positive semi-definite: <A x, y> = <x, A y> and <A x, x> >= 0;
// - changing the velocity on closed faces only leaves A x unchanged on every open face (the
//   shell does not pull on the fluid through the viscous stencil), whereas the operator without
//   the mask does change there (so the check can fail);
// - the strain rate with the same apertures is blind to closed faces as well (every cell).
// And on host spaces, where each launch walks rows that the compiler vectorises (SplitLoop.hpp),
// the viscous and the cell operator's apply, residual and red-black sweeps give bitwise the values
// of their stencils evaluated one unknown at a time through the boundary closures (with -0.0
// among the inputs).
#include "CfdTestUtils.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/GranularRheology.hpp"
#include "kernels/cfd/ShellGeometry.hpp"
#include "kernels/cfd/ViscousOperator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <iostream>
#include <string>
#include <type_traits>

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

// Whether two fields hold bitwise the same values.
bool sameBits(field const& a, field const& b) {
  const auto ha = test::toHost(a);
  const auto hb = test::toHost(b);
  return ha.span() == hb.span() &&
         std::memcmp(ha.data(), hb.data(), ha.span() * sizeof(double)) == 0;
}

// Sets the first half of a's stored values (ghosts included) and every third of the rest to
// -0.0. The interior rows take a neighbour's value as x and the closures as 1.0 * x + 0.0, which
// differ on -0.0 alone (neighbourValue(), AxisClosure.hpp); where all of a cell's neighbours are
// -0.0 only the sums' +0.0 start keeps the rows on the closures' bits.
void sprinkleNegativeZeros(field const& a) {
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), a);
  for (std::size_t n = 0; n < h.span(); ++n) {
    if (n < h.span() / 2 || n % 3 == 0) {
      h.data()[n] = -0.0;
    }
  }
  Kokkos::deep_copy(a, h);
}

field copyOf(field const& a) {
  field b(std::string(a.label()) + "_copy", a.layout());
  Kokkos::deep_copy(b, a);
  return b;
}

// Calls body.cell<noAxes>(i, j, k) (the closures' path, one unknown at a time) on the unknowns of
// split of the given colour (-1: all) and returns the sum of what it returns.
template <class Body> double cellByCell(BoxSplit const& split, Body const& body, int colour) {
  double sum = 0.0;
  for (int k = split.lo[2]; k < split.hi[2]; ++k)
    for (int j = split.lo[1]; j < split.hi[1]; ++j)
      for (int i = split.lo[0]; i < split.hi[0]; ++i)
        if (colour < 0 || ((i + j + k) & 1) == colour) {
          sum += body.template cell<noAxes>(i, j, k);
        }
  return sum;
}

// The viscous operator's component C of form (Dims, alpha A, masks M), one unknown at a time:
// out = A u (mode 0), out = f - A u (mode 1, returns its squared norm) or a sweep of colour
// mode - 2 on u.
template <int Dims, int C, bool A, bool M>
double viscousByUnknown(ViscousOperator<memory> const& op, velocity const& u, velocity const& f,
                        field const& out, bool affine, int mode) {
  using Stencil = detail::ViscousStencil<Dims, C, A, M, memory>;
  const BoxSplit split = componentSplit(op, C);
  if (mode == 0) {
    return cellByCell(split, StencilApply<Stencil>{{op, u, affine}, out}, -1);
  }
  if (mode == 1) {
    return cellByCell(split, StencilResidual<Stencil>{{op, u, affine}, f.comp[C], out}, -1);
  }
  return cellByCell(split, StencilGaussSeidel<Stencil>{{op, u, affine}, f.comp[C]}, mode - 2);
}

template <int Dims, bool A, bool M>
double viscousByUnknown(ViscousOperator<memory> const& op, int comp, velocity const& u,
                        velocity const& f, field const& out, bool affine, int mode) {
  if (comp == 0) {
    return viscousByUnknown<Dims, 0, A, M>(op, u, f, out, affine, mode);
  }
  if constexpr (Dims == 3) {
    if (comp == 2) {
      return viscousByUnknown<Dims, 2, A, M>(op, u, f, out, affine, mode);
    }
  }
  return viscousByUnknown<Dims, 1, A, M>(op, u, f, out, affine, mode);
}

velocity zeros(Case const& c) {
  velocity v;
  for (int comp = 0; comp < c.dims; ++comp) {
    v.comp[comp] = makeField(space{}, c.grid, faceStaggering(comp), "hikiln::test::zeros");
  }
  return v;
}

velocity copyOf(Case const& c, velocity const& v) {
  velocity out;
  for (int comp = 0; comp < c.dims; ++comp) {
    out.comp[comp] = copyOf(v.comp[comp]);
  }
  return out;
}

// On host spaces: the row launches of the viscous operator (apply, residual, both colours of
// each component's sweep) against viscousByUnknown(), bitwise (the squared norm to round-off:
// its sum runs in another order).
template <class Space, int Dims> void checkViscousRows(Case const& c, bool withAlpha, bool masked) {
  if constexpr (detail::walksRows<Space>) {
    auto op = makeOperator(c, masked);
    for (int comp = 0; withAlpha && comp < Dims; ++comp) {
      op.alpha[comp] =
          test::fieldFrom(Space{}, c.grid, faceStaggering(comp), [](double x, double y, double z) {
            return 40.0 + 30.0 * std::sin(9.0 * x - 4.0 * y + z);
          });
    }
    const velocity u = randomVelocity(c, 5, false), f = randomVelocity(c, 17, false);
    for (int comp = 0; comp < Dims; ++comp) {
      sprinkleNegativeZeros(u.comp[comp]);
    }
    // mode 0: apply into out, 1: residual into out (returns its squared norm), 2 + colour: sweep x
    const auto byUnknown = [&](int comp, velocity const& x, field const& out, bool affine,
                               int mode) {
      double sum = 0.0;
      detail::withViscousForm(op, [&](auto a, auto m) {
        sum = viscousByUnknown<Dims, decltype(a)::value, decltype(m)::value>(op, comp, x, f, out,
                                                                             affine, mode);
      });
      return sum;
    };
    for (bool affine : {false, true}) {
      const velocity applied = zeros(c), appliedByUnknown = zeros(c);
      const velocity residual = zeros(c), residualByUnknown = zeros(c);
      applyViscousOperator(Space{}, op, u, applied, affine);
      const double norm2 = viscousResidual(Space{}, op, u, f, residual, affine);
      double reference = 0.0;
      for (int comp = 0; comp < Dims; ++comp) {
        byUnknown(comp, u, appliedByUnknown.comp[comp], affine, 0);
        reference += byUnknown(comp, u, residualByUnknown.comp[comp], affine, 1);
        EXPECT_TRUE(sameBits(applied.comp[comp], appliedByUnknown.comp[comp]))
            << "apply, component " << comp << ", affine " << affine;
        EXPECT_TRUE(sameBits(residual.comp[comp], residualByUnknown.comp[comp]))
            << "residual, component " << comp << ", affine " << affine;
        for (int colour = 0; colour < 2; ++colour) {
          const velocity swept = copyOf(c, u), sweptByUnknown = copyOf(c, u);
          smoothViscousColour(Space{}, op, swept, f, comp, colour, affine);
          byUnknown(comp, sweptByUnknown, field(), affine, 2 + colour);
          EXPECT_TRUE(sameBits(swept.comp[comp], sweptByUnknown.comp[comp]))
              << "sweep, component " << comp << ", colour " << colour << ", affine " << affine;
          // the whole sweep in one pass: the two colours' passes, bit for bit
          const velocity oneSweep = copyOf(c, u);
          smoothViscousRedBlack(Space{}, op, oneSweep, f, comp, colour, affine);
          byUnknown(comp, sweptByUnknown, field(), affine, 2 + (1 - colour));
          EXPECT_TRUE(sameBits(oneSweep.comp[comp], sweptByUnknown.comp[comp]))
              << "red-black sweep, component " << comp << ", first colour " << colour << ", affine "
              << affine;
        }
      }
      EXPECT_GT(reference, 0.0);
      EXPECT_NEAR(norm2, reference, 1e-13 * reference);
    }
  } else {
    (void)c, (void)withAlpha, (void)masked;
    GTEST_SKIP() << "rows are walked on host spaces only";
  }
}

TEST(TEST_CATEGORY, viscous_rows_equal_stencil_by_unknown) {
  for (bool threeD : {false, true}) {
    const Case c = drumCase(threeD);
    for (bool withAlpha : {false, true}) {
      for (bool masked : {false, true}) {
        SCOPED_TRACE((threeD ? std::string("3D") : std::string("2D")) + " alpha " +
                     std::to_string(withAlpha) + " masked " + std::to_string(masked));
        if (threeD) {
          checkViscousRows<space, 3>(c, withAlpha, masked);
        } else {
          checkViscousRows<space, 2>(c, withAlpha, masked);
        }
      }
    }
  }
}

// The cell operator (pressure / diffusion) of form (Dims, alpha): rows against unknowns, as
// checkViscousRows().
template <int Dims, bool A>
double cellByUnknown(CellOperator<memory> const& op, field const& x, field const& f,
                     field const& out, bool affine, int mode) {
  using Stencil = detail::CellStencil<memory, Dims, A>;
  const BoxSplit split = cellSplit(op);
  if (mode == 0) {
    return cellByCell(split, StencilApply<Stencil>{{op, x, affine}, out}, -1);
  }
  if (mode == 1) {
    return cellByCell(split, StencilResidual<Stencil>{{op, x, affine}, f, out}, -1);
  }
  return cellByCell(split, StencilGaussSeidel<Stencil>{{op, x, affine}, f}, mode - 2);
}

template <class Space, int Dims> void checkCellRows(Case const& c, bool withAlpha) {
  if constexpr (detail::walksRows<Space>) {
    CellOperator<memory> op;
    op.grid = c.grid;
    scalarClosures(c.grid, ScalarBoundaries(), op.axis);
    for (int a = 0; a < Dims; ++a) {
      op.beta[a] =
          test::fieldFrom(Space{}, c.grid, faceStaggering(a), [a](double x, double y, double z) {
            return 1.2 + std::cos(5.0 * x + 3.0 * a - 2.0 * y + z);
          });
    }
    if (withAlpha) {
      op.alpha = test::fieldFrom(Space{}, c.grid, Staggering::Cell,
                                 [](double x, double y, double) { return 3.0 + x * y; });
    }
    const auto rough = [](double x, double y, double z) {
      return std::sin(11.0 * x + 2.0) * std::cos(7.0 * y - z);
    };
    const field x = test::fieldFrom(Space{}, c.grid, Staggering::Cell, rough);
    sprinkleNegativeZeros(x);
    const field f = test::fieldFrom(Space{}, c.grid, Staggering::Cell,
                                    [](double px, double py, double) { return px - 2.0 * py; });
    const auto byUnknown = [&](field const& xIn, field const& out, bool affine, int mode) {
      double sum = 0.0;
      detail::withCellForm(op, [&](auto, auto a) {
        sum = cellByUnknown<Dims, decltype(a)::value>(op, xIn, f, out, affine, mode);
      });
      return sum;
    };
    for (bool affine : {false, true}) {
      const field rows = copyOf(f), cells = copyOf(f);
      applyCellOperator(Space{}, op, x, rows, affine);
      byUnknown(x, cells, affine, 0);
      EXPECT_TRUE(sameBits(rows, cells)) << "apply, affine " << affine;
      const double norm2 = cellResidualNorm2(Space{}, op, x, f, rows, affine);
      const double reference = byUnknown(x, cells, affine, 1);
      EXPECT_TRUE(sameBits(rows, cells)) << "residual, affine " << affine;
      EXPECT_GT(reference, 0.0);
      EXPECT_NEAR(norm2, reference, 1e-13 * reference);
      for (int colour = 0; colour < 2; ++colour) {
        const field swept = copyOf(x), sweptByUnknown = copyOf(x);
        smoothCellColour(Space{}, op, swept, f, colour, affine);
        byUnknown(sweptByUnknown, field(), affine, 2 + colour);
        EXPECT_TRUE(sameBits(swept, sweptByUnknown)) << "sweep, colour " << colour;
        // the whole sweep in one pass: the two colours' passes, bit for bit
        const field oneSweep = copyOf(x);
        smoothCellRedBlack(Space{}, op, oneSweep, f, colour, affine);
        byUnknown(sweptByUnknown, field(), affine, 2 + (1 - colour));
        EXPECT_TRUE(sameBits(oneSweep, sweptByUnknown)) << "red-black sweep, first " << colour;
      }
    }
  } else {
    (void)c, (void)withAlpha;
    GTEST_SKIP() << "rows are walked on host spaces only";
  }
}

TEST(TEST_CATEGORY, cell_operator_rows_equal_stencil_by_unknown) {
  for (bool threeD : {false, true}) {
    const Case c = drumCase(threeD);
    for (bool withAlpha : {false, true}) {
      SCOPED_TRACE((threeD ? std::string("3D") : std::string("2D")) + " alpha " +
                   std::to_string(withAlpha));
      if (threeD) {
        checkCellRows<space, 3>(c, withAlpha);
      } else {
        checkCellRows<space, 2>(c, withAlpha);
      }
    }
  }
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
