#pragma once
/// \file Integrator.hpp
/// \brief Velocity Verlet for translation and rotation (LAMMPS nve/sphere): half kick, drift,
/// forces, half kick. The second half kick is fused into the force kernel (ForceKernel.hpp).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Periodic.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem {

/// \brief v + (dt/2) f / m for one component (also used for spin with torque and inertia).
KOKKOS_INLINE_FUNCTION double halfKick(double v, double halfDt, double f, double inverseMass) {
  return v + halfDt * f * inverseMass;
}

/// \brief First half of a step for particles [0, n): v += dt/2 f/m, omega += dt/2 T/I,
/// x += dt v (wrapped when periodic). Returns the largest squared displacement (minimum image)
/// from `reference`, the positions at the last neighbour-list build: the rebuild test.
template <class ExecutionSpace, class MemorySpace, class ReferenceView>
double initialIntegrate(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                        double dt, PeriodicX const& periodic, ReferenceView const& reference) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::initialIntegrate: particle memory not accessible");
  auto x = p.position;
  auto v = p.velocity;
  auto w = p.angularVelocity;
  auto f = p.force;
  auto tq = p.torque;
  auto invM = p.inverseMass;
  auto invI = p.inverseInertia;
  const double halfDt = 0.5 * dt;
  double maxDisplacement2 = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::dem::initialIntegrate", Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()),
      KOKKOS_LAMBDA(int i, double& maxD2) {
        const double im = invM(i);
        const double vx = halfKick(v(i, 0), halfDt, f(i, 0), im);
        const double vy = halfKick(v(i, 1), halfDt, f(i, 1), im);
        v(i, 0) = vx;
        v(i, 1) = vy;
        w(i) = halfKick(w(i), halfDt, tq(i), invI(i));
        const double nx = periodic.wrap(x(i, 0) + dt * vx);
        const double ny = x(i, 1) + dt * vy;
        x(i, 0) = nx;
        x(i, 1) = ny;
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

} // namespace hikiln::dem
