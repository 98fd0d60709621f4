#pragma once
/// \file Diagnostics.hpp
/// \brief Energy and momentum sums over the particles (reductions; for monitoring, not per step).
/// Only free particles count: fixed and shell-attached ones are parts of the boundary (their
/// contacts with free particles count in the elastic energy, as wall contacts do).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ForceKernel.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem {

/// \brief Energies (J per unit depth convention of the mass) of the current state.
struct EnergyReport {
  double translational = 0.0; ///< sum m v^2 / 2
  double rotational = 0.0;    ///< sum I omega^2 / 2
  double gravitational = 0.0; ///< sum -m g . x (zero at the origin)
  double elasticPair = 0.0;   ///< sum over contacts k_n delta^2 / 2 + k_t shear^2 / 2
  double elasticWall = 0.0;   ///< the same for wall contacts
  /// \brief Translational plus rotational kinetic energy.
  double kinetic() const { return translational + rotational; }
  /// \brief Kinetic + gravitational + elastic energy.
  double total() const { return kinetic() + gravitational + elasticPair + elasticWall; }
};

/// \brief Linear momentum and angular momentum about the origin (orbital + spin).
struct MomentumReport {
  double px = 0.0, py = 0.0;
  double angular = 0.0;
};

/// \brief Energies of particles [0, n) with the springs of `settings` and the stored histories.
template <class ExecutionSpace, class MemorySpace>
EnergyReport computeEnergy(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                           NeighborList<MemorySpace> const& list,
                           WallContactState<MemorySpace> const& walls, ForceSettings const& s) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::computeEnergy: particle memory not accessible");
  EnergyReport e;
  const auto policy = Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count());
  auto x = p.position;
  auto v = p.velocity;
  auto w = p.angularVelocity;
  auto m = p.mass;
  auto inertia = p.inertia;
  auto radius = p.radius;
  auto kind = p.kind;
  Kokkos::parallel_reduce(
      "hikiln::dem::energyTranslational", policy,
      KOKKOS_LAMBDA(int i, double& sum) {
        if (isFree(kind(i))) {
          sum += 0.5 * m(i) * (v(i, 0) * v(i, 0) + v(i, 1) * v(i, 1));
        }
      },
      e.translational);
  Kokkos::parallel_reduce(
      "hikiln::dem::energyRotational", policy,
      KOKKOS_LAMBDA(int i, double& sum) {
        if (isFree(kind(i))) {
          sum += 0.5 * inertia(i) * w(i) * w(i);
        }
      },
      e.rotational);
  Kokkos::parallel_reduce(
      "hikiln::dem::energyGravitational", policy,
      KOKKOS_LAMBDA(int i, double& sum) {
        if (isFree(kind(i))) {
          sum -= m(i) * (s.gravityX * x(i, 0) + s.gravityY * x(i, 1));
        }
      },
      e.gravitational);
  auto count = list.count;
  auto index = list.index;
  auto shear = list.shear;
  const int capacity = list.capacity();
  Kokkos::parallel_reduce(
      "hikiln::dem::energyElasticPair", policy,
      KOKKOS_LAMBDA(int i, double& sum) {
        const int n = count(i) < capacity ? count(i) : capacity;
        for (int k = 0; k < n; ++k) {
          const int j = index(i, k);
          const double dx = s.periodic.minimumImage(x(j, 0) - x(i, 0));
          const double dy = x(j, 1) - x(i, 1);
          const double delta = radius(i) + radius(j) - math::sqrt(dx * dx + dy * dy);
          if (delta > 0.0 &&
              (isFree(kind(i)) ||
               isFree(kind(j)))) { // each pair is seen from both sides: half each time
            sum +=
                0.25 * (s.particle.kn * delta * delta + s.particle.kt * shear(i, k) * shear(i, k));
          }
        }
      },
      e.elasticPair);
  auto wallShear = walls.shear;
  Kokkos::parallel_reduce(
      "hikiln::dem::energyElasticWall", policy,
      KOKKOS_LAMBDA(int i, double& sum) {
        ContactFrame fr;
        if (!isFree(kind(i))) {
          return;
        }
        if (s.walls.drum.enabled &&
            drumFrame(s.walls.drum, x(i, 0), x(i, 1), 0.0, 0.0, 0.0, radius(i), fr)) {
          sum += 0.5 * (s.wall.kn * fr.overlap * fr.overlap +
                        s.wall.kt * wallShear(i, 0) * wallShear(i, 0));
        }
        for (int k = 0; k < s.walls.numFlat; ++k) {
          if (flatFrame(s.walls.flat[k], x(i, 0), x(i, 1), 0.0, 0.0, 0.0, radius(i), fr)) {
            sum += 0.5 * (s.wall.kn * fr.overlap * fr.overlap +
                          s.wall.kt * wallShear(i, 1 + k) * wallShear(i, 1 + k));
          }
        }
      },
      e.elasticWall);
  return e;
}

/// \brief Linear and angular momentum of particles [0, n).
template <class ExecutionSpace, class MemorySpace>
MomentumReport computeMomentum(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::computeMomentum: particle memory not accessible");
  MomentumReport r;
  const auto policy = Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count());
  auto x = p.position;
  auto v = p.velocity;
  auto w = p.angularVelocity;
  auto m = p.mass;
  auto inertia = p.inertia;
  auto kind = p.kind;
  Kokkos::parallel_reduce(
      "hikiln::dem::momentumX", policy,
      KOKKOS_LAMBDA(int i, double& sum) { sum += isFree(kind(i)) ? m(i) * v(i, 0) : 0.0; }, r.px);
  Kokkos::parallel_reduce(
      "hikiln::dem::momentumY", policy,
      KOKKOS_LAMBDA(int i, double& sum) { sum += isFree(kind(i)) ? m(i) * v(i, 1) : 0.0; }, r.py);
  Kokkos::parallel_reduce(
      "hikiln::dem::angularMomentum", policy,
      KOKKOS_LAMBDA(int i, double& sum) {
        if (isFree(kind(i))) {
          sum += m(i) * (x(i, 0) * v(i, 1) - x(i, 1) * v(i, 0)) + inertia(i) * w(i);
        }
      },
      r.angular);
  return r;
}

} // namespace hikiln::dem
