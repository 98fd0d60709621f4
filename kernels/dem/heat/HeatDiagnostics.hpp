#pragma once
/// \file HeatDiagnostics.hpp
/// \brief Heat content and mean temperatures of the particles (the energy the heat model
/// conserves: shells, outer-shell bulk and boundary layers).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/heat/HeatArrays.hpp"
#include "kernels/dem/heat/HeatParameters.hpp"
#include "kernels/dem/heat/ShellModel.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem {

namespace detail {

/// \brief Heat content (J, relative to 0 K) of particle i: interior shells, the outer-shell bulk
/// (its capacity less its layers') and its own contact layers.
template <class MemorySpace> struct ParticleHeatContent {
  Kokkos::View<double*, MemorySpace> radius, mass;
  HeatParticles<MemorySpace> state;
  HeatSlots<MemorySpace> slots;
  HeatCoefficients c;

  KOKKOS_INLINE_FUNCTION double operator()(int i) const {
    const int ns = c.shells;
    const ParticleHeat ph = particleHeat(c, radius(i), mass(i));
    double e = 0.0;
    for (int s = 0; s + 1 < ns; ++s) {
      e += ph.capacity * shellVolumeFraction(c.geometry, ns, s) * state.temperature(i, s);
    }
    const int cap = slots.capacity();
    const int n = slots.count(i) < cap ? slots.count(i) : cap;
    double layers = 0.0, layerCapacity = 0.0;
    for (int k = 0; k < n; ++k) {
      const double cl = ph.layerCapacityPerArea * slots.area(i, k);
      layerCapacity += cl;
      layers += cl * slots.layerSelf(i, k);
    }
    return e + (ph.outerCapacity - layerCapacity) * state.temperature(i, ns - 1) + layers;
  }
};

} // namespace detail

/// \brief Total heat content (J) of particles [0, n) with the given radii and masses (rows
/// aligned with state and slots).
template <class ExecutionSpace, class MemorySpace>
double heatContent(ExecutionSpace const& space, Kokkos::View<double*, MemorySpace> const& radius,
                   Kokkos::View<double*, MemorySpace> const& mass, std::size_t n,
                   HeatParticles<MemorySpace> const& state, HeatSlots<MemorySpace> const& slots,
                   HeatCoefficients const& coefficients) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::heatContent: heat memory not accessible");
  const detail::ParticleHeatContent<MemorySpace> content{radius, mass, state, slots, coefficients};
  double total = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::dem::heat::content", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i, double& sum) { sum += content(i); }, total);
  return total;
}

/// \brief Heat received from the environment (J) by particles [0, n) so far.
template <class ExecutionSpace, class MemorySpace>
double environmentHeatTotal(ExecutionSpace const& space, HeatParticles<MemorySpace> const& state,
                            std::size_t n) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::environmentHeatTotal: heat memory not accessible");
  const auto q = state.environmentHeat;
  double total = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::dem::heat::environmentTotal", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i, double& sum) { sum += q(i); }, total);
  return total;
}

/// \brief Mean temperature (K) of each particle [0, n), its heat content over m c, into `out`.
template <class ExecutionSpace, class MemorySpace>
void particleMeanTemperature(ExecutionSpace const& space,
                             Kokkos::View<double*, MemorySpace> const& radius,
                             Kokkos::View<double*, MemorySpace> const& mass, std::size_t n,
                             HeatParticles<MemorySpace> const& state,
                             HeatSlots<MemorySpace> const& slots,
                             HeatCoefficients const& coefficients,
                             Kokkos::View<double*, MemorySpace> const& out) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::particleMeanTemperature: heat memory not accessible");
  const detail::ParticleHeatContent<MemorySpace> content{radius, mass, state, slots, coefficients};
  const double c = coefficients.specificHeat;
  Kokkos::parallel_for(
      "hikiln::dem::heat::meanTemperature", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(int i) { out(i) = content(i) / (mass(i) * c); });
}

} // namespace hikiln::dem
