#pragma once
/// \file ParticleArrays.hpp
/// \brief Structure-of-arrays storage of 2D DEM discs and their mass properties.

#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace hikiln::dem {

/// \brief How a 2D disc gets its mass and moment of inertia.
/// Sphere: the sphere of the disc's diameter (LAMMPS atom_style sphere in 2D), m = 4/3 pi r^3 rho,
/// I = 2/5 m r^2. Disc: a cylinder of thickness t, m = pi r^2 t rho, I = 1/2 m r^2.
enum class MassConvention { Sphere, Disc };

/// \brief How a particle moves (one byte per particle in ParticleArrays::kind).
/// Free: integrated from forces. Fixed: glued in place (v = 0, omega = 0), e.g. the rough base of a
/// chute. Shell: attached to the rotating drum shell, its position, velocity omega x r and spin
/// omega prescribed exactly from the shell's rotation (PrescribedMotion.hpp). Fixed and Shell
/// particles feel no gravity and no analytic walls; they act on free particles through the normal
/// contact law as bodies of infinite mass, and two of them never interact.
enum class ParticleKind : std::uint8_t { Free = 0, Fixed = 1, Shell = 2 };

/// \brief True for particles integrated from their forces (kind byte as stored).
KOKKOS_INLINE_FUNCTION bool isFree(std::uint8_t kind) {
  return kind == static_cast<std::uint8_t>(ParticleKind::Free);
}

/// \brief Mass of a particle of radius r and density rho under the given convention.
KOKKOS_INLINE_FUNCTION double particleMass(MassConvention convention, double r, double rho,
                                           double thickness) {
  return convention == MassConvention::Sphere ? 4.0 / 3.0 * constants::pi * r * r * r * rho
                                              : constants::pi * r * r * thickness * rho;
}

/// \brief Moment of inertia about the disc axis for mass m and radius r under the convention.
KOKKOS_INLINE_FUNCTION double particleInertia(MassConvention convention, double m, double r) {
  return (convention == MassConvention::Sphere ? 0.4 : 0.5) * m * r * r;
}

/// \brief Particle data as Views in MemorySpace; entries [0, count()) are live, the rest is spare
/// capacity. Indices change when particles are reordered; id is the stable global tag.
template <class MemorySpace> struct ParticleArrays {
  using memory_space = MemorySpace;
  template <class T> using view_type = Kokkos::View<T, MemorySpace>;

  view_type<double* [2]> position;    ///< centre (m)
  view_type<double* [2]> velocity;    ///< translational velocity (m/s)
  view_type<double*> angularVelocity; ///< counter-clockwise positive (rad/s)
  view_type<double* [2]> force;       ///< total force of the last evaluation (N)
  view_type<double*> torque;          ///< total torque of the last evaluation (N m)
  view_type<double*> radius;          ///< (m)
  view_type<double*> mass;            ///< (kg)
  view_type<double*> inertia;         ///< moment of inertia about the axis (kg m^2)
  view_type<double*> inverseMass;     ///< 1/mass, kept in step with mass
  view_type<double*> inverseInertia;  ///< 1/inertia
  view_type<std::int64_t*> id;        ///< global tag, stable across reordering
  view_type<std::uint8_t*> kind;      ///< ParticleKind; zero-filled storage is all Free

  ParticleArrays() = default;

  /// \brief Allocates zero-filled storage for `capacity` particles, `count` of them live (filled by
  /// the default execution space of the memory space).
  explicit ParticleArrays(std::size_t capacity, std::size_t count = 0) {
    allocate(capacity, count);
  }

  /// \brief As above, zero-filled by the execution space instance `space`.
  template <class ExecutionSpace,
            class = std::enable_if_t<Kokkos::is_execution_space<ExecutionSpace>::value>>
  ParticleArrays(ExecutionSpace const& space, std::size_t capacity, std::size_t count) {
    allocate(capacity, count, space);
  }

  /// \brief Number of live particles.
  std::size_t count() const { return _count; }
  /// \brief Number of particles the Views can hold.
  std::size_t capacity() const { return radius.extent(0); }

  /// \brief Sets the number of live particles (at most capacity()).
  void setCount(std::size_t n) {
    if (n > capacity()) {
      throw std::length_error("hikiln::dem::ParticleArrays: count " + std::to_string(n) +
                              " exceeds capacity " + std::to_string(capacity()));
    }
    _count = n;
  }

  /// \brief Replaces the storage by new Views for `capacity` particles; props are passed to
  /// Kokkos::view_alloc (an execution space instance, Kokkos::WithoutInitializing).
  template <class... Props>
  void allocate(std::size_t capacity, std::size_t count, Props const&... props) {
    const auto make = [&](auto& view, const char* label) {
      using V = std::decay_t<decltype(view)>;
      view = V(Kokkos::view_alloc(props..., std::string(label)), capacity);
    };
    make(position, "hikiln::dem::position");
    make(velocity, "hikiln::dem::velocity");
    make(angularVelocity, "hikiln::dem::angularVelocity");
    make(force, "hikiln::dem::force");
    make(torque, "hikiln::dem::torque");
    make(radius, "hikiln::dem::radius");
    make(mass, "hikiln::dem::mass");
    make(inertia, "hikiln::dem::inertia");
    make(inverseMass, "hikiln::dem::inverseMass");
    make(inverseInertia, "hikiln::dem::inverseInertia");
    make(id, "hikiln::dem::id");
    make(kind, "hikiln::dem::kind");
    _count = 0;
    setCount(count);
  }

  /// \brief Swaps all View handles and counts with another container (no data is copied).
  void swap(ParticleArrays& other) {
    std::swap(position, other.position);
    std::swap(velocity, other.velocity);
    std::swap(angularVelocity, other.angularVelocity);
    std::swap(force, other.force);
    std::swap(torque, other.torque);
    std::swap(radius, other.radius);
    std::swap(mass, other.mass);
    std::swap(inertia, other.inertia);
    std::swap(inverseMass, other.inverseMass);
    std::swap(inverseInertia, other.inverseInertia);
    std::swap(id, other.id);
    std::swap(kind, other.kind);
    std::swap(_count, other._count);
  }

private:
  std::size_t _count = 0;
};

/// \brief Copies every field of `src` (live entries and spare capacity) into a container in
/// another memory space, allocated to the same capacity.
template <class DstSpace, class SrcSpace>
ParticleArrays<DstSpace> copyParticles(const ParticleArrays<SrcSpace>& src) {
  ParticleArrays<DstSpace> dst;
  dst.allocate(src.capacity(), src.count(), Kokkos::WithoutInitializing);
  Kokkos::deep_copy(dst.position, src.position);
  Kokkos::deep_copy(dst.velocity, src.velocity);
  Kokkos::deep_copy(dst.angularVelocity, src.angularVelocity);
  Kokkos::deep_copy(dst.force, src.force);
  Kokkos::deep_copy(dst.torque, src.torque);
  Kokkos::deep_copy(dst.radius, src.radius);
  Kokkos::deep_copy(dst.mass, src.mass);
  Kokkos::deep_copy(dst.inertia, src.inertia);
  Kokkos::deep_copy(dst.inverseMass, src.inverseMass);
  Kokkos::deep_copy(dst.inverseInertia, src.inverseInertia);
  Kokkos::deep_copy(dst.id, src.id);
  Kokkos::deep_copy(dst.kind, src.kind);
  return dst;
}

/// \brief Sets mass, inertia and their inverses of the live particles from radius and density.
template <class ExecutionSpace, class MemorySpace>
void assignMassProperties(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                          double density, MassConvention convention, double thickness = 1.0) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::assignMassProperties: particle memory not accessible");
  auto radius = p.radius;
  auto mass = p.mass;
  auto inertia = p.inertia;
  auto invMass = p.inverseMass;
  auto invInertia = p.inverseInertia;
  Kokkos::parallel_for(
      "hikiln::dem::assignMassProperties", Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()),
      KOKKOS_LAMBDA(int i) {
        const double r = radius(i);
        const double m = particleMass(convention, r, density, thickness);
        const double in = particleInertia(convention, m, r);
        mass(i) = m;
        inertia(i) = in;
        invMass(i) = 1.0 / m;
        invInertia(i) = 1.0 / in;
      });
}

/// \brief Host loop version of assignMassProperties() for containers being filled on the host.
inline void assignMassPropertiesHost(ParticleArrays<Kokkos::HostSpace> const& p, double density,
                                     MassConvention convention, double thickness = 1.0) {
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double r = p.radius(i);
    const double m = particleMass(convention, r, density, thickness);
    const double in = particleInertia(convention, m, r);
    p.mass(i) = m;
    p.inertia(i) = in;
    p.inverseMass(i) = 1.0 / m;
    p.inverseInertia(i) = 1.0 / in;
  }
}

/// \brief Recomputes inverseMass and inverseInertia of the live particles from mass and inertia.
template <class ExecutionSpace, class MemorySpace>
void updateInverseMassProperties(ExecutionSpace const& space,
                                 ParticleArrays<MemorySpace> const& p) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::updateInverseMassProperties: particle memory not accessible");
  auto mass = p.mass;
  auto inertia = p.inertia;
  auto invMass = p.inverseMass;
  auto invInertia = p.inverseInertia;
  Kokkos::parallel_for(
      "hikiln::dem::updateInverseMassProperties",
      Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()), KOKKOS_LAMBDA(int i) {
        invMass(i) = 1.0 / mass(i);
        invInertia(i) = 1.0 / inertia(i);
      });
}

/// \brief to(i, :) = from(i, :) for i in [0, n) as a kernel on `space` (unlike a host deep_copy,
/// which may run on other threads than the space's).
template <class ExecutionSpace, class MemorySpace>
void copyPositions(ExecutionSpace const& space, Kokkos::View<double* [2], MemorySpace> const& from,
                   Kokkos::View<double* [2], MemorySpace> const& to, std::size_t n) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::copyPositions: memory not accessible");
  Kokkos::parallel_for(
      "hikiln::dem::copyPositions", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) {
        to(i, 0) = from(i, 0);
        to(i, 1) = from(i, 1);
      });
}

} // namespace hikiln::dem
