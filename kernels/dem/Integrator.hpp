#pragma once
/// \file Integrator.hpp
/// \brief Velocity Verlet for translation and rotation (LAMMPS nve/sphere): half kick, drift,
/// forces, half kick. The second half kick can be fused into the force kernel (ForceKernel.hpp)
/// or deferred into the next step's initialIntegrate() (previousHalfDt): the same operations on
/// the same values in the same order, so both give bitwise the same trajectory. finishHalfKick()
/// applies a deferred kick on its own (before the velocities are read between steps).
/// Only free particles are integrated: fixed ones keep their place (v = omega = 0) and shell ones
/// are placed from the shell's rotation (PrescribedMotion.hpp).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Periodic.hpp"
#include "kernels/dem/PrescribedMotion.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem {

/// \brief Particles per dynamically scheduled chunk of the integration kernels: dynamic chunks
/// keep a step going when one thread of a busy machine is descheduled (a static split would make
/// the others wait for it at the join).
inline constexpr int integrateChunk = 256;

/// \brief v + (dt/2) f / m for one component (also used for spin with torque and inertia).
KOKKOS_INLINE_FUNCTION double halfKick(double v, double halfDt, double f, double inverseMass) {
  return v + halfDt * f * inverseMass;
}

/// \brief Second half kick on its own for particles [0, n): v += halfDt f/m, omega += halfDt T/I.
template <class ExecutionSpace, class MemorySpace>
void finishHalfKick(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                    double halfDt) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::finishHalfKick: particle memory not accessible");
  auto v = p.velocity;
  auto w = p.angularVelocity;
  auto f = p.force;
  auto tq = p.torque;
  auto invM = p.inverseMass;
  auto invI = p.inverseInertia;
  auto kind = p.kind;
  Kokkos::parallel_for(
      "hikiln::dem::finishHalfKick",
      Kokkos::RangePolicy<ExecutionSpace, Kokkos::Schedule<Kokkos::Dynamic>>(space, 0, p.count())
          .set_chunk_size(integrateChunk),
      KOKKOS_LAMBDA(int i) {
        if (!isFree(kind(i))) {
          return;
        }
        const double im = invM(i);
        v(i, 0) = halfKick(v(i, 0), halfDt, f(i, 0), im);
        v(i, 1) = halfKick(v(i, 1), halfDt, f(i, 1), im);
        w(i) = halfKick(w(i), halfDt, tq(i), invI(i));
      });
}

/// \brief Multiplies the velocity and spin of the free particles [0, n) by `factor` (settling
/// removes motion this way; fixed and shell particles keep their prescribed motion).
template <class ExecutionSpace, class MemorySpace>
void scaleFreeMotion(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                     double factor) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::scaleFreeMotion: particle memory not accessible");
  auto v = p.velocity;
  auto w = p.angularVelocity;
  auto kind = p.kind;
  Kokkos::parallel_for(
      "hikiln::dem::scaleFreeMotion", Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()),
      KOKKOS_LAMBDA(int i) {
        if (isFree(kind(i))) {
          v(i, 0) *= factor;
          v(i, 1) *= factor;
          w(i) *= factor;
        }
      });
}

/// \brief No shell particles: an empty home View for initialIntegrate().
template <class MemorySpace>
Kokkos::View<double* [2], MemorySpace> noShellHome() {
  return Kokkos::View<double* [2], MemorySpace>();
}

/// \brief First half of a step for particles [0, n): first the previous step's deferred second
/// half kick with previousHalfDt (0: none), i.e. v += previousHalfDt f/m, then v += dt/2 f/m,
/// omega += dt/2 T/I, x += dt v (wrapped when periodic) for free particles; shell particles are
/// placed from `shell` (already advanced to the new step) and their home positions `home`; fixed
/// ones stay. Returns the largest squared displacement (minimum image) from `reference`, the
/// positions at the last neighbour-list build: the rebuild test.
template <class ExecutionSpace, class MemorySpace, class ReferenceView>
double initialIntegrate(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                        double dt, PeriodicX const& periodic, ReferenceView const& reference,
                        double previousHalfDt, ShellMotion const& shell,
                        Kokkos::View<double* [2], MemorySpace> const& home) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::initialIntegrate: particle memory not accessible");
  auto x = p.position;
  auto v = p.velocity;
  auto w = p.angularVelocity;
  auto f = p.force;
  auto tq = p.torque;
  auto invM = p.inverseMass;
  auto invI = p.inverseInertia;
  auto kind = p.kind;
  auto id = p.id;
  const double halfDt = 0.5 * dt;
  const bool finishPrevious = previousHalfDt != 0.0;
  double maxDisplacement2 = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::dem::initialIntegrate",
      Kokkos::RangePolicy<ExecutionSpace, Kokkos::Schedule<Kokkos::Dynamic>>(space, 0, p.count())
          .set_chunk_size(integrateChunk),
      KOKKOS_LAMBDA(int i, double& maxD2) {
        const std::uint8_t k = kind(i);
        double nx = x(i, 0), ny = x(i, 1);
        if (isFree(k)) {
          const double im = invM(i);
          const double fx = f(i, 0), fy = f(i, 1), t = tq(i), ii = invI(i);
          double vx = v(i, 0), vy = v(i, 1), wi = w(i);
          if (finishPrevious) {
            vx = halfKick(vx, previousHalfDt, fx, im);
            vy = halfKick(vy, previousHalfDt, fy, im);
            wi = halfKick(wi, previousHalfDt, t, ii);
          }
          vx = halfKick(vx, halfDt, fx, im);
          vy = halfKick(vy, halfDt, fy, im);
          v(i, 0) = vx;
          v(i, 1) = vy;
          w(i) = halfKick(wi, halfDt, t, ii);
          nx = periodic.wrap(nx + dt * vx);
          ny = ny + dt * vy;
          x(i, 0) = nx;
          x(i, 1) = ny;
        } else if (k == static_cast<std::uint8_t>(ParticleKind::Shell)) {
          const auto h = static_cast<int>(id(i) - shell.firstId);
          double vx, vy, wi;
          placeOnShell(shell, home(h, 0), home(h, 1), nx, ny, vx, vy, wi);
          x(i, 0) = nx;
          x(i, 1) = ny;
          v(i, 0) = vx;
          v(i, 1) = vy;
          w(i) = wi;
        }
        const double dx = periodic.minimumImage(nx - reference(i, 0));
        const double dy = ny - reference(i, 1);
        const double d2 = dx * dx + dy * dy;
        // written so that a NaN position always triggers a rebuild (which then reports it)
        if (!(d2 <= maxD2)) {
          maxD2 = math::isfinite(d2) ? d2 : 1.0e300;
        }
      },
      Kokkos::Max<double>(maxDisplacement2));
  return p.count() == 0 ? 0.0 : maxDisplacement2;
}

/// \brief initialIntegrate() for a system without shell particles.
template <class ExecutionSpace, class MemorySpace, class ReferenceView>
double initialIntegrate(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                        double dt, PeriodicX const& periodic, ReferenceView const& reference,
                        double previousHalfDt = 0.0) {
  return initialIntegrate(space, p, dt, periodic, reference, previousHalfDt, ShellMotion{},
                          noShellHome<MemorySpace>());
}

} // namespace hikiln::dem
