// Helpers shared by the coarse-graining tests: systems of particles placed by hand (no contacts)
// and readers of the finalised fields.
#pragma once

#include "DemTestUtils.hpp"
#include "solvers/dem/FieldAverager.hpp"

#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace hikiln::dem::test {

/// A particle to place: centre, velocity, radius and mass (inertia = m r^2 / 2).
struct Placed {
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0, r = 0.0, m = 0.0;
};

/// Host container of the placed particles (ids 100 + 7 i).
inline ParticleArrays<Kokkos::HostSpace> placedParticles(const std::vector<Placed>& placed) {
  auto h = hostParticles(placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Placed& p = placed[i];
    h.position(i, 0) = p.x;
    h.position(i, 1) = p.y;
    h.velocity(i, 0) = p.vx;
    h.velocity(i, 1) = p.vy;
    h.radius(i) = p.r;
    h.mass(i) = p.m;
    h.inertia(i) = 0.5 * p.m * p.r * p.r;
  }
  return h;
}

/// A system without walls holding the placed particles (they must not touch: no contacts).
template <class Space> DemSystem<Space> placedSystem(const std::vector<Placed>& placed) {
  DemConfig cfg;
  cfg.neighborCapacity = 4;
  DemSystem<Space> sys(cfg);
  sys.setParticles(placedParticles(placed));
  return sys;
}

/// A velocity field u(x, y) written into vx, vy of every placed particle.
inline void setVelocity(std::vector<Placed>& placed,
                        const std::function<void(double, double, double&, double&)>& u) {
  for (Placed& p : placed)
    u(p.x, p.y, p.vx, p.vy);
}

/// 4 x 4 particles per cell of a Cartesian grid at the centres of its sub-cells (so the mean of
/// any linear field over a cell's particles is its value at the cell centre), equal masses.
inline std::vector<Placed> cartesianLattice(const cg::CartesianGrid& g, double radius,
                                            double mass) {
  std::vector<Placed> out;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix)
      for (int sy = 0; sy < 4; ++sy)
        for (int sx = 0; sx < 4; ++sx) {
          Placed p;
          p.x = g.x0 + (ix + (sx + 0.5) / 4.0) * g.dx;
          p.y = g.y0 + (iy + (sy + 0.5) / 4.0) * g.dy;
          p.r = radius;
          p.m = mass;
          out.push_back(p);
        }
  return out;
}

/// 4 x 4 particles per cell of a polar grid, at the area centroids of its sub-sectors, with masses
/// proportional to the sub-sector areas: each cell's mass centroid is its area centroid, so the
/// mass-weighted mean of a linear field over a cell is its value at PolarGrid::centroidRadius.
inline std::vector<Placed> polarLattice(const cg::PolarGrid& g, double radius, double density) {
  std::vector<Placed> out;
  const double h = g.radius / g.nr / 4.0, w = g.sectorWidth() / 4.0;
  for (int it = 0; it < 4 * g.ntheta; ++it)
    for (int ir = 0; ir < 4 * g.nr; ++ir) {
      const double r1 = ir * h, r2 = (ir + 1) * h, theta = (it + 0.5) * w;
      const double rho = 2.0 / 3.0 * (r2 * r2 * r2 - r1 * r1 * r1) / (r2 * r2 - r1 * r1) *
                         std::sin(0.5 * w) / (0.5 * w);
      Placed p;
      p.x = rho * std::cos(theta);
      p.y = rho * std::sin(theta);
      p.r = radius;
      p.m = density * 0.5 * (r2 * r2 - r1 * r1) * w;
      out.push_back(p);
    }
  return out;
}

} // namespace hikiln::dem::test
