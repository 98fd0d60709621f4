#pragma once
/// \file BlockyArrays.hpp
/// \brief Per-particle shape and orientation of blocky (superquadric) particles, kept next to the
/// disc engine's ParticleArrays (same indices). ParticleArrays::radius holds the bounding radius,
/// so the cell grid, the neighbour list and the rebuild test work unchanged.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Superquadric.hpp"

#include <Kokkos_Core.hpp>

#include <string>

namespace hikiln::dem {

/// \brief Shape and orientation per particle, in MemorySpace.
template <class MemorySpace> struct BlockyArrays {
  using memory_space = MemorySpace;
  Kokkos::View<double*, MemorySpace> orientation;      ///< body x axis angle (rad, ccw)
  Kokkos::View<SuperquadricShape*, MemorySpace> shape; ///< outline in the body frame
  /// (cos, sin) of the orientation, the body x axis: a cache the force kernel reads, set by
  /// updateOrientationAxes() and advanceOrientation() (DemSystem keeps it current; circles keep
  /// the axis of their initial orientation, which their outline does not depend on).
  Kokkos::View<double* [2], MemorySpace> axis;

  BlockyArrays() = default;
  /// \brief Zero-filled orientation and unit circles for `capacity` particles.
  explicit BlockyArrays(std::size_t capacity)
      : orientation("hikiln::dem::orientation", capacity), shape("hikiln::dem::shape", capacity),
        axis("hikiln::dem::orientationAxis", capacity) {}

  /// \brief Number of particles the Views can hold.
  std::size_t capacity() const { return orientation.extent(0); }
};

/// \brief Copy of `src` in another memory space.
template <class DstSpace, class SrcSpace>
BlockyArrays<DstSpace> copyBlocky(const BlockyArrays<SrcSpace>& src) {
  BlockyArrays<DstSpace> dst;
  dst.orientation = Kokkos::View<double*, DstSpace>(
      Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("hikiln::dem::orientation")),
      src.capacity());
  dst.shape = Kokkos::View<SuperquadricShape*, DstSpace>(
      Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("hikiln::dem::shape")),
      src.capacity());
  dst.axis = Kokkos::View<double* [2], DstSpace>(
      Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("hikiln::dem::orientationAxis")),
      src.capacity());
  Kokkos::deep_copy(dst.orientation, src.orientation);
  Kokkos::deep_copy(dst.shape, src.shape);
  if (src.axis.extent(0) == src.capacity()) {
    Kokkos::deep_copy(dst.axis, src.axis);
  } else {
    Kokkos::deep_copy(dst.axis, 0.0);
  }
  return dst;
}

/// \brief Sets radius (the bounding radius), mass, inertia and their inverses of the live particles
/// of a host container from their shapes (superquadricMassProperties(); circles get exactly the
/// disc engine's values). Throws, naming the particle id, for a shape outside the verified range.
inline void assignBlockyMassPropertiesHost(ParticleArrays<Kokkos::HostSpace> const& p,
                                           BlockyArrays<Kokkos::HostSpace> const& b, double density,
                                           MassConvention convention, double thickness = 1.0) {
  for (std::size_t i = 0; i < p.count(); ++i) {
    const SuperquadricShape& s = b.shape(i);
    validateShape(s, "hikiln::dem: particle " + std::to_string(p.id(i)));
    const MassProperties m = superquadricMassProperties(s, density, convention, thickness);
    p.radius(i) = isCircle(s) ? s.a : boundingRadius(s);
    p.mass(i) = m.mass;
    p.inertia(i) = m.inertia;
    p.inverseMass(i) = 1.0 / m.mass;
    p.inverseInertia(i) = 1.0 / m.inertia;
  }
}

/// \brief axis = (cos, sin)(orientation) for particles [0, n).
template <class ExecutionSpace, class MemorySpace>
void updateOrientationAxes(ExecutionSpace const& space, BlockyArrays<MemorySpace> const& b,
                           std::size_t n) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::updateOrientationAxes: particle memory not accessible");
  auto theta = b.orientation;
  auto axis = b.axis;
  Kokkos::parallel_for(
      "hikiln::dem::updateOrientationAxes", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        const double angle = theta(i); // one value for both: a single sincos
        axis(i, 0) = math::cos(angle);
        axis(i, 1) = math::sin(angle);
      });
}

/// \brief theta += dt omega for the free particles [0, n), with omega the half-step spin that
/// initialIntegrate() has just set (velocity Verlet for the angle); the axis cache follows, except
/// for circles (N = 2, a = b), whose outline and contacts do not depend on it.
template <class ExecutionSpace, class MemorySpace>
void advanceOrientation(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                        BlockyArrays<MemorySpace> const& b, double dt) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::advanceOrientation: particle memory not accessible");
  auto theta = b.orientation;
  auto axis = b.axis;
  auto shape = b.shape;
  auto w = p.angularVelocity;
  auto kind = p.kind;
  Kokkos::parallel_for(
      "hikiln::dem::advanceOrientation", Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()),
      KOKKOS_LAMBDA(int i) {
        if (isFree(kind(i))) {
          const double angle = theta(i) + dt * w(i); // one value for both: a single sincos
          theta(i) = angle;
          if (!isCircle(shape(i))) { // a circle's outline does not depend on its axis
            axis(i, 0) = math::cos(angle);
            axis(i, 1) = math::sin(angle);
          }
        }
      });
}

} // namespace hikiln::dem
