#include "solvers/dem/DrumShapes.hpp"

#include <cmath>

namespace hikiln::dem {

SuperquadricShape equalAreaShape(const ParticleShapeSpec& spec, double diameter) {
  const double r = 0.5 * diameter;
  if (spec.blockiness == 2.0 && spec.aspectRatio == 1.0)
    return {r, r, 2.0}; // exactly the disc, so the blocky path reproduces the disc engine
  const SuperquadricShape unit{1.0, spec.aspectRatio, spec.blockiness};
  const double a = r * std::sqrt(constants::pi / superquadricArea(unit));
  return {a, spec.aspectRatio * a, spec.blockiness};
}

double boundingRadiusRatio(const ParticleShapeSpec& spec) {
  if (!spec.superquadric)
    return 1.0;
  return boundingRadius(equalAreaShape(spec, 2.0));
}

double particleArea(const ParticleArrays<Kokkos::HostSpace>& p,
                    const BlockyArrays<Kokkos::HostSpace>& shapes, std::size_t i) {
  if (shapes.capacity() > i)
    return superquadricArea(shapes.shape(i));
  return constants::pi * p.radius(i) * p.radius(i);
}

BlockyArrays<Kokkos::HostSpace> subsetShapes(const BlockyArrays<Kokkos::HostSpace>& shapes,
                                             const std::vector<std::size_t>& keep) {
  BlockyArrays<Kokkos::HostSpace> out(keep.size());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    out.orientation(k) = shapes.orientation(keep[k]);
    out.shape(k) = shapes.shape(keep[k]);
    const bool cached = shapes.axis.extent(0) == shapes.capacity();
    out.axis(k, 0) = cached ? shapes.axis(keep[k], 0) : std::cos(out.orientation(k));
    out.axis(k, 1) = cached ? shapes.axis(keep[k], 1) : std::sin(out.orientation(k));
  }
  return out;
}

} // namespace hikiln::dem
