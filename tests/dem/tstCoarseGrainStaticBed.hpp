// Coarse-grained stress of a bed of discs settled under gravity in a still drum:
// (1) virial identity: the contact stress integrated over all cells, -W with
//     W = sum_i sum_c (x_c - x_i) (x) f_ic, equals -(sum_walls x_w (x) f_w - sum_i x_i (x) G_i),
//     G_i = F_i - m_i g (F_i the total force of the DEM step), on both grids, within 1e-6 of
//     sum |x_i| m_i g: exact but for the damping parts of the sampled contact forces, which use
//     the full-step velocities where the step used the half-step ones (O(dt); ~1e-8 at rest);
// (2) vertical force balance: over horizontal strips of the Cartesian grid, the integral of the
//     CG vertical stress sigma_yy dA t equals the integral over the strip's heights of the force
//     P(y) the material below transmits upwards: the sum over particle centres above y of G_iy
//     less the shell forces applied above y (at rest: the weight above y less the shell's support
//     above y); within 4 % of the largest strip value (measured 1.6 %; the error is the centre
//     assignment of contacts that straddle a strip edge).
#include "CoarseGrainTestUtils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
constexpr double drumRadius = 0.25;
constexpr double gravity = 9.81;

DemConfig bedConfig() {
  DemConfig cfg;
  cfg.gravityY = -gravity;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = drumRadius;
  cfg.particleContact.normalStiffness = 1.0e4; // soft: settles in few steps, overlaps ~1e-2 r
  cfg.particleContact.tangentialStiffness = 5.0e3;
  cfg.particleContact.restitution = 0.3;
  cfg.wallContact = cfg.particleContact;
  return cfg;
}

// ~300 discs dropped from a loose lattice and settled until their kinetic energy is below
// 1e-6 m g d per particle.
DemSystem<space> settledBed() {
  auto h = test::drumParticles(300, drumRadius, 0.01, 0.1, 0.0, 3, 1.02, true);
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  DemSystem<space> sys(bedConfig());
  sys.setParticles(h);
  const double rest = 1e-8 * 0.0113 * gravity * 0.02 * static_cast<double>(h.count());
  for (int chunk = 0; chunk < 200 && !(sys.time() > 1.5 && sys.energy().kinetic() < rest);
       ++chunk) {
    sys.advance(500);
  }
  return sys;
}

struct WallForce {
  double fx = 0.0, fy = 0.0, px = 0.0, py = 0.0; // force on the particle, contact point
};

// Drum contact force on each particle and the contact point (middle of the overlap).
std::vector<WallForce> wallForces(const DemSystem<space>& sys,
                                  const ParticleArrays<Kokkos::HostSpace>& p) {
  const auto fn =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, sys.wallContacts().normalForce);
  const auto ft =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, sys.wallContacts().tangentialForce);
  std::vector<WallForce> out(p.count());
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double x = p.position(i, 0), y = p.position(i, 1), r = p.radius(i);
    const double d = std::hypot(x, y), nx = x / d, ny = y / d;
    const double b = r - 0.5 * (r - (drumRadius - d));
    out[i].fx = -fn(i, 0) * nx - ft(i, 0) * ny;
    out[i].fy = -fn(i, 0) * ny + ft(i, 0) * nx;
    out[i].px = x + b * nx;
    out[i].py = y + b * ny;
  }
  return out;
}

TEST(TEST_CATEGORY, coarse_grain_static_bed_stress) {
  auto sys = settledBed();
  const auto p = sys.hostParticles();
  double meanDiameter = 0.0, weight = 0.0, scale = 0.0, residual = 0.0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    meanDiameter += 2.0 * p.radius(i) / static_cast<double>(p.count());
    weight += p.mass(i) * gravity;
    scale += std::hypot(p.position(i, 0), p.position(i, 1)) * p.mass(i) * gravity;
    residual += std::hypot(p.force(i, 0), p.force(i, 1));
  }
  EXPECT_LT(residual, 3e-3 * weight) << "the bed is not at rest";
  AveragingSettings s;
  s.drumRadius = drumRadius;
  s.thickness = meanDiameter;
  FieldAverager<space> averager(s);
  averager.sample(sys, sys.time());
  const AveragedFields f = averager.result();
  const auto walls = wallForces(sys, p);

  // (1) virial identity
  // W = sum_w x_w (x) f_w - sum_i x_i (x) (F_i - m_i g): pair contact points cancel in pairs
  double wxx = 0.0, wxy = 0.0, wyx = 0.0, wyy = 0.0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double x = p.position(i, 0), y = p.position(i, 1);
    const double ox = p.force(i, 0), oy = p.force(i, 1) + p.mass(i) * gravity;
    const WallForce& w = walls[i];
    wxx += w.px * w.fx - x * ox;
    wxy += w.px * w.fy - x * oy;
    wyx += w.py * w.fx - y * ox;
    wyy += w.py * w.fy - y * oy;
  }
  EXPECT_GT(-wyy, 0.1 * scale); // compressive: the bed's centre of mass is above its supports
  const auto expectIdentity = [&](const CellFields& c, const auto& grid, const char* name) {
    double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) {
      const double volume = grid.cellArea(static_cast<int>(k)) * s.thickness;
      xx += c.contactXX[k] * volume;
      xy += c.contactXY[k] * volume;
      yx += c.contactYX[k] * volume;
      yy += c.contactYY[k] * volume;
    }
    EXPECT_NEAR(xx, -wxx, 1e-6 * scale) << name;
    EXPECT_NEAR(xy, -wxy, 1e-6 * scale) << name;
    EXPECT_NEAR(yx, -wyx, 1e-6 * scale) << name;
    EXPECT_NEAR(yy, -wyy, 1e-6 * scale) << name;
  };
  expectIdentity(f.polar, f.polarGrid, "polar");
  expectIdentity(f.cartesian, f.cartesianGrid, "cartesian");

  // (2) strips
  const cg::CartesianGrid& g = f.cartesianGrid;
  int lowRow = g.ny, highRow = -1;
  for (std::size_t i = 0; i < p.count(); ++i) {
    const int row = g.cellOf(p.position(i, 0), p.position(i, 1)) / g.nx;
    lowRow = std::min(lowRow, row);
    highRow = std::max(highRow, row);
  }
  const int strips = 4;
  const int rowsPerStrip = (highRow - lowRow + strips) / strips;
  std::vector<double> cgStrip(strips, 0.0), balance(strips, 0.0);
  for (int k = 0; k < strips; ++k) {
    const int r0 = lowRow + k * rowsPerStrip;
    const double ya = g.y0 + r0 * g.dy, yb = ya + rowsPerStrip * g.dy;
    for (int iy = r0; iy < r0 + rowsPerStrip && iy < g.ny; ++iy)
      for (int ix = 0; ix < g.nx; ++ix) {
        const std::size_t c = static_cast<std::size_t>(iy * g.nx + ix);
        cgStrip[k] +=
            (f.cartesian.contactYY[c] + f.cartesian.kineticYY[c]) * g.dx * g.dy * s.thickness;
      }
    // P(y) = sum over centres above y of (F_i - m_i g)_y (all contact forces on them) less the
    // shell forces acting above y (at their contact points)
    for (std::size_t i = 0; i < p.count(); ++i) {
      const double contacts = p.force(i, 1) + p.mass(i) * gravity;
      balance[k] += contacts * std::clamp(p.position(i, 1) - ya, 0.0, yb - ya) -
                    walls[i].fy * std::clamp(walls[i].py - ya, 0.0, yb - ya);
    }
  }
  const double largest = *std::max_element(balance.begin(), balance.end());
  for (int k = 0; k < strips; ++k) {
    EXPECT_NEAR(cgStrip[k], balance[k], 0.04 * largest)
        << "strip " << k << " of " << rowsPerStrip << " rows: CG " << cgStrip[k]
        << " N m, force balance " << balance[k] << " N m";
  }
}

} // namespace
