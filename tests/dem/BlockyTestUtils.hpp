// Helpers for the blocky-particle tests: turning a disc set into superquadrics of the same
// bounding radius, and comparing orientations.
#pragma once

#include "DemTestUtils.hpp"
#include "kernels/dem/BlockyArrays.hpp"
#include "solvers/dem/DemSystem.hpp"

#include <cmath>
#include <cstdint>
#include <map>
#include <random>

namespace hikiln::dem::test {

/// Shapes for the particles of `h`: blockiness `n`, aspect ratio b/a = 1/aspect, scaled so that
/// the bounding radius equals the disc radius (a disc set without overlaps stays so), random
/// orientations; then radius, mass and inertia from the shapes (disc = prism convention).
inline BlockyArrays<Kokkos::HostSpace> blockify(const ParticleArrays<Kokkos::HostSpace>& h,
                                                double n, double aspect, unsigned seed,
                                                double density = 2700.0, double thickness = 0.01) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 2.0 * constants::pi);
  BlockyArrays<Kokkos::HostSpace> b(h.capacity());
  const SuperquadricShape unit{1.0, 1.0 / aspect, n};
  const double reach = isCircle(unit) ? 1.0 : boundingRadius(unit);
  for (std::size_t i = 0; i < h.count(); ++i) {
    const double scale = h.radius(i) / reach;
    b.shape(i) = SuperquadricShape{scale, scale / aspect, n};
    b.orientation(i) = isCircle(unit) ? 0.0 : u(gen);
  }
  assignBlockyMassPropertiesHost(h, b, density, MassConvention::Disc, thickness);
  return b;
}

/// A rotating drum (radius 0.12 m, 3 rad/s) with a frictional bed: rolling resistance on, soft
/// springs for quick settling.
inline DemConfig blockyDrumConfig() {
  DemConfig cfg;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = 0.12;
  cfg.walls.drum.angularVelocity = 3.0;
  cfg.particleContact.normalStiffness = 2.0e3;
  cfg.particleContact.tangentialStiffness = 1.0e3;
  cfg.wallContact = cfg.particleContact;
  cfg.particleContact.rolling = RollingModel::ConstantTorque;
  cfg.particleContact.rollingFriction = 0.05;
  return cfg;
}

/// n discs of radius 5 mm (+-10 %) packed from the bottom of blockyDrumConfig()'s drum.
inline ParticleArrays<Kokkos::HostSpace> blockyDrumBed(std::size_t n, unsigned seed) {
  return drumParticles(n, 0.12, 0.005, 0.1, 0.05, seed, 1.05, true);
}

/// Orientation of every particle keyed by id.
template <class System> std::map<std::int64_t, double> orientationById(const System& sys) {
  const auto h = sys.hostParticles();
  const auto b = sys.hostShapes();
  std::map<std::int64_t, double> out;
  for (std::size_t i = 0; i < h.count(); ++i) {
    out[h.id(i)] = b.orientation(i);
  }
  return out;
}

} // namespace hikiln::dem::test
