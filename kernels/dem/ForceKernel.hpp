#pragma once
/// \file ForceKernel.hpp
/// \brief Contact, wall and gravity forces of every particle from its full neighbour row, fused
/// with the second velocity-Verlet half kick. Each particle sums in registers and writes only its
/// own entries (force, torque, its history row, its wall history): no atomics, and the result does
/// not depend on the thread count.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ContactLaw.hpp"
#include "kernels/dem/Integrator.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Periodic.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem {

/// \brief Everything the force kernel needs besides the arrays (trivially copyable).
struct ForceSettings {
  ContactCoefficients particle; ///< particle-particle law
  ContactCoefficients wall;     ///< particle-wall law (m_eff = particle mass, R_r = radius)
  WallSet walls;
  PeriodicX periodic;
  double gravityX = 0.0, gravityY = 0.0;
  double dt = 0.0;
  bool updateHistory = true; ///< false for the set-up evaluation (history not advanced)
};

namespace detail {

/// \brief Per-particle body of the force evaluation; Kick also writes the half-kicked velocity.
template <class MemorySpace, bool Kick> struct ForceFunctor {
  using Vec = Kokkos::View<double* [2], MemorySpace>;
  using Scalar = Kokkos::View<double*, MemorySpace>;
  using Wall = Kokkos::View<double* [wallSlotCount], MemorySpace>;
  Vec x, v, f, vOut;
  Scalar w, tq, wOut, radius, mass, invM, invI;
  Kokkos::View<int*, MemorySpace> count;
  Kokkos::View<int**, MemorySpace> index;
  Kokkos::View<double**, MemorySpace> shear, slotFn, slotFt;
  Wall wallShear, wallFn, wallFt;
  ForceSettings s;
  int capacity;

  /// \brief Applies one wall contact (or clears its slot when not touching).
  KOKKOS_INLINE_FUNCTION void wallContact(int i, int slot, bool touching, const ContactFrame& fr,
                                          double mi, double ri, double relativeSpin, double& fx,
                                          double& fy, double& t) const {
    if (!touching) {
      wallShear(i, slot) = 0.0;
      wallFn(i, slot) = 0.0;
      wallFt(i, slot) = 0.0;
      return;
    }
    const ContactForce c = evaluateContact(s.wall, fr, mi, ri, relativeSpin, wallShear(i, slot),
                                           s.dt, s.updateHistory);
    wallShear(i, slot) = c.shear;
    wallFn(i, slot) = c.normal;
    wallFt(i, slot) = c.tangential;
    fx += -c.normal * fr.nx + c.tangential * (-fr.ny);
    fy += -c.normal * fr.ny + c.tangential * fr.nx;
    t += ri * c.tangential + c.rollingTorque;
  }

  KOKKOS_INLINE_FUNCTION void operator()(int i) const {
    const double xi = x(i, 0), yi = x(i, 1);
    const double vxi = v(i, 0), vyi = v(i, 1);
    const double wi = w(i), ri = radius(i), mi = mass(i);
    double fx = 0.0, fy = 0.0, t = 0.0;
    const int n = count(i) < capacity ? count(i) : capacity;
    for (int k = 0; k < n; ++k) { // ascending neighbour id: a fixed summation order
      const int j = index(i, k);
      const double rj = radius(j);
      ContactFrame fr;
      if (!pairFrame(s.periodic.minimumImage(x(j, 0) - xi), x(j, 1) - yi, v(j, 0) - vxi,
                     v(j, 1) - vyi, ri, rj, wi, w(j), fr)) {
        shear(i, k) = 0.0;
        slotFn(i, k) = 0.0;
        slotFt(i, k) = 0.0;
        continue;
      }
      const double rr = s.particle.rolling ? rollingRadius(ri, rj) : 0.0;
      const ContactForce c = evaluateContact(s.particle, fr, effectiveMass(mi, mass(j)), rr,
                                             wi - w(j), shear(i, k), s.dt, s.updateHistory);
      shear(i, k) = c.shear;
      slotFn(i, k) = c.normal;
      slotFt(i, k) = c.tangential;
      fx += -c.normal * fr.nx + c.tangential * (-fr.ny);
      fy += -c.normal * fr.ny + c.tangential * fr.nx;
      t += ri * c.tangential + c.rollingTorque;
    }
    ContactFrame fr;
    if (s.walls.drum.enabled) {
      const bool touching = drumFrame(s.walls.drum, xi, yi, vxi, vyi, wi, ri, fr);
      wallContact(i, 0, touching, fr, mi, ri, wi - s.walls.drum.angularVelocity, fx, fy, t);
    }
    for (int k = 0; k < s.walls.numFlat; ++k) {
      const bool touching = flatFrame(s.walls.flat[k], xi, yi, vxi, vyi, wi, ri, fr);
      wallContact(i, 1 + k, touching, fr, mi, ri, wi, fx, fy, t);
    }
    fx += mi * s.gravityX;
    fy += mi * s.gravityY;
    f(i, 0) = fx;
    f(i, 1) = fy;
    tq(i) = t;
    if (Kick) {
      const double halfDt = 0.5 * s.dt;
      vOut(i, 0) = halfKick(vxi, halfDt, fx, invM(i));
      vOut(i, 1) = halfKick(vyi, halfDt, fy, invM(i));
      wOut(i) = halfKick(wi, halfDt, t, invI(i));
    }
  }
};

template <bool Kick, class ExecutionSpace, class MemorySpace>
void launchForces(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                  NeighborList<MemorySpace> const& list, WallContactState<MemorySpace> const& walls,
                  ForceSettings const& settings,
                  Kokkos::View<double* [2], MemorySpace> const& velocityOut,
                  Kokkos::View<double*, MemorySpace> const& angularVelocityOut, const char* label) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::computeForces: particle memory not accessible");
  ForceFunctor<MemorySpace, Kick> fun;
  fun.x = p.position;
  fun.v = p.velocity;
  fun.f = p.force;
  fun.vOut = velocityOut;
  fun.w = p.angularVelocity;
  fun.tq = p.torque;
  fun.wOut = angularVelocityOut;
  fun.radius = p.radius;
  fun.mass = p.mass;
  fun.invM = p.inverseMass;
  fun.invI = p.inverseInertia;
  fun.count = list.count;
  fun.index = list.index;
  fun.shear = list.shear;
  fun.slotFn = list.normalForce;
  fun.slotFt = list.tangentialForce;
  fun.wallShear = walls.shear;
  fun.wallFn = walls.normalForce;
  fun.wallFt = walls.tangentialForce;
  fun.s = settings;
  fun.capacity = list.capacity();
  Kokkos::parallel_for(label, Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()), fun);
}

} // namespace detail

/// \brief Forces and torques of particles [0, n) into p.force / p.torque (no integration), e.g. for
/// the set-up evaluation before the first step.
template <class ExecutionSpace, class MemorySpace>
void computeForces(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                   NeighborList<MemorySpace> const& list,
                   WallContactState<MemorySpace> const& walls, ForceSettings const& settings) {
  detail::launchForces<false>(space, p, list, walls, settings, p.velocity, p.angularVelocity,
                              "hikiln::dem::computeForces");
}

/// \brief Forces and torques as computeForces(), fused with the second half kick: velocityOut and
/// angularVelocityOut (distinct from p's Views, which neighbours still read) receive
/// v + dt/2 f/m and omega + dt/2 T/I.
template <class ExecutionSpace, class MemorySpace>
void computeForcesAndKick(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                          NeighborList<MemorySpace> const& list,
                          WallContactState<MemorySpace> const& walls, ForceSettings const& settings,
                          Kokkos::View<double* [2], MemorySpace> const& velocityOut,
                          Kokkos::View<double*, MemorySpace> const& angularVelocityOut) {
  detail::launchForces<true>(space, p, list, walls, settings, velocityOut, angularVelocityOut,
                             "hikiln::dem::computeForcesAndKick");
}

} // namespace hikiln::dem
