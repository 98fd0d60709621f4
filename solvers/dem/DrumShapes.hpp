#pragma once
/// \file DrumShapes.hpp
/// \brief Particle shapes of a drum fill: discs, or superquadrics of one blockiness and aspect
/// ratio sized by their equal-area diameter (so a shape study changes the shape alone, not the
/// particle mass or count). Host side, used by DrumFill.cpp and the `hikiln dem` driver.

#include "kernels/dem/BlockyArrays.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Superquadric.hpp"

#include <cstddef>
#include <vector>

namespace hikiln::dem {

/// \brief The shape of every particle of a fill (the glued shell discs stay circles).
struct ParticleShapeSpec {
  bool superquadric = false; ///< false: discs (the disc engine alone)
  double blockiness = 2.0;   ///< N in [2, 8]
  double aspectRatio = 1.0;  ///< b / a in [1, 3]
};

/// \brief The superquadric of `spec` whose area is pi d^2 / 4 (a from superquadricArea(), b =
/// aspect a). N = 2 with aspect 1 gives the circle a = b = d/2 exactly, which the contact kernels
/// treat as a disc.
SuperquadricShape equalAreaShape(const ParticleShapeSpec& spec, double diameter);

/// \brief Bounding radius over equal-area radius d/2 of the shapes of `spec` (the same for every
/// d); 1 for discs.
double boundingRadiusRatio(const ParticleShapeSpec& spec);

/// \brief Area of particle i: its superquadric's if `shapes` holds one per particle, else pi r^2.
double particleArea(const ParticleArrays<Kokkos::HostSpace>& particles,
                    const BlockyArrays<Kokkos::HostSpace>& shapes, std::size_t i);

/// \brief Shapes and orientations of the particles at `keep` (indices into `shapes`), in that
/// order.
BlockyArrays<Kokkos::HostSpace> subsetShapes(const BlockyArrays<Kokkos::HostSpace>& shapes,
                                             const std::vector<std::size_t>& keep);

} // namespace hikiln::dem
