#pragma once
/// \file HeatKernel.hpp
/// \brief One explicit heat sub-step of every particle: contact boundary layers, radiation to
/// neighbours and the environment, and radial conduction, fused in one launch.
///
/// Each particle walks its own neighbour row in neighbour-id order (the order the force kernel
/// uses), evaluates every pair quantity from the pair's lower-id side (bitwise the same from both
/// sides), accumulates its own outer-shell heat in registers and writes only its own rows: no
/// atomics, results independent of the thread count. Neighbours' outer-shell temperatures are read
/// from the old buffer, the new temperatures go to a second buffer (swapped by the caller).
///
/// Outer shell (the bulk, capacity C_out minus its layers' capacity):
///   E_bulk' = (C_out - S_old) T + sum(capacity exchange) - sum(heat into layers)
///             + radiation + environment - (heat conducted to the next shell inward)
///   T' = E_bulk' / (C_out - S_new)
/// Interior shells: T_m' = T_m + (F_{m+1} - F_m) / C_m, F_f = dt G_f (T_f - T_{f-1}).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Periodic.hpp"
#include "kernels/dem/heat/ContactConduction.hpp"
#include "kernels/dem/heat/HeatArrays.hpp"
#include "kernels/dem/heat/HeatParameters.hpp"
#include "kernels/dem/heat/Radiation.hpp"
#include "kernels/dem/heat/ShellModel.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>

namespace hikiln::dem {

namespace detail {

/// \brief Per-particle body of a heat sub-step.
template <class MemorySpace> struct HeatStepFunctor {
  Kokkos::View<double* [2], MemorySpace> x;
  Kokkos::View<double*, MemorySpace> radius;
  Kokkos::View<std::int64_t*, MemorySpace> id;
  Kokkos::View<int*, MemorySpace> count;
  Kokkos::View<int**, MemorySpace> index;
  Kokkos::View<double**, MemorySpace> told, tnew;
  Kokkos::View<double*, MemorySpace> environmentHeat;
  Kokkos::View<double**, MemorySpace> layerSelf, layerOther, area;
  HeatModelViews<MemorySpace> model;
  HeatCoefficients c;
  PeriodicX periodic;
  double dt = 0.0;
  double inverseShare = 0.0;
  int capacity = 0;

  KOKKOS_INLINE_FUNCTION void operator()(int i) const {
    const int ns = c.shells;
    const ParticleHeat own = model.particle(i);
    const std::int64_t idi = id(i);
    const double ti = told(i, ns - 1);
    double sOld = 0.0, sNew = 0.0, exchange = 0.0, intoLayers = 0.0, radiated = 0.0;
    int nearby = 0;
    const int n = count(i) < capacity ? count(i) : capacity;
    for (int k = 0; k < n; ++k) { // ascending neighbour id: a fixed summation order
      const int j = index(i, k);
      const bool lower = idi < id(j); // side a of the pair is the lower id
      const int pa = lower ? i : j;
      const int pb = lower ? j : i;
      const double ra = radius(pa), rb = radius(pb);
      const double dx = periodic.minimumImage(x(pb, 0) - x(pa, 0));
      const double dy = x(pb, 1) - x(pa, 1);
      const double gap = math::sqrt(dx * dx + dy * dy) - (ra + rb);
      if (!(gap < c.radiationRange) && !(area(i, k) > 0.0)) {
        layerSelf(i, k) = ti;  // out of reach and no layer: nothing to exchange (layer values of
        layerOther(i, k) = ti; // a slot without area are never used: growth starts from the bulk)
        continue;
      }
      const double ta = told(pa, ns - 1), tb = told(pb, ns - 1);
      const ParticleHeat other = model.particle(j);
      const ParticleHeat& ha = lower ? own : other;
      const ParticleHeat& hb = lower ? other : own;
      if (gap < c.radiationRange) {
        ++nearby;
        if (c.radiation) {
          const double pairArea = math::min(ha.surface, hb.surface) * inverseShare;
          const double p = dt * radiativeExchange(c.pairEmissivity * pairArea, ta, tb);
          radiated += lower ? p : -p;
        }
      }
      const double areaNew = contactArea(c, ra, rb, -gap);
      const double areaOld = area(i, k);
      if (!(areaNew > 0.0) && !(areaOld > 0.0)) {
        layerSelf(i, k) = ti; // no layer: keep it at the bulk temperature
        layerOther(i, k) = lower ? tb : ta;
        continue;
      }
      LayerSide sa, sb;
      sa.capacityPerArea = ha.layerCapacityPerArea;
      sa.conductancePerArea = ha.layerConductancePerArea;
      sa.shell = ta;
      sa.layer = lower ? layerSelf(i, k) : layerOther(i, k);
      sb.capacityPerArea = hb.layerCapacityPerArea;
      sb.conductancePerArea = hb.layerConductancePerArea;
      sb.shell = tb;
      sb.layer = lower ? layerOther(i, k) : layerSelf(i, k);
      LayerChange ua, ub;
      advanceLayerPair(sa, sb, areaOld, areaNew, dt, ua, ub);
      const LayerChange& mine = lower ? ua : ub;
      layerSelf(i, k) = mine.layer;
      layerOther(i, k) = lower ? ub.layer : ua.layer;
      area(i, k) = areaNew;
      sOld += mine.capacityOld;
      sNew += mine.capacityNew;
      exchange += mine.bulkExchange;
      intoLayers += mine.shellHeat;
    }
    double environment = 0.0;
    if (c.environmentExchange) {
      environment = dt * environmentPower(c, environmentExposure(nearby, c.neighborShare),
                                          own.surface, own.surfaceConductance, ti);
      environmentHeat(i) += environment;
    }
    // radial conduction; `inward` is the heat passed from shell s to shell s - 1
    const double scale = dt * own.faceScale;
    double inward = 0.0;
    for (int s = 0; s + 1 < ns; ++s) {
      const double outer = scale * model.faceConductance(s + 1) * (told(i, s + 1) - told(i, s));
      tnew(i, s) = told(i, s) + (outer - inward) * own.inverseCapacity * model.inverseFraction(s);
      inward = outer;
    }
    const double bulkEnergy =
        (own.outerCapacity - sOld) * ti + exchange - intoLayers + radiated + environment - inward;
    tnew(i, ns - 1) = bulkEnergy / (own.outerCapacity - sNew);
  }
};

} // namespace detail

/// \brief One heat sub-step of length dt for particles [0, p.count()): reads the shell
/// temperatures of `current`, writes them to `next` (a distinct View, swapped by the caller),
/// advances the slot layers in place and adds to current.environmentHeat. `slots` must be
/// aligned with `list` (see carryHeatState()), `model` with the rows; periodic is the DEM's
/// periodic boundary.
template <class ExecutionSpace, class MemorySpace>
void heatSubStep(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                 NeighborList<MemorySpace> const& list, HeatModelViews<MemorySpace> const& model,
                 HeatCoefficients const& coefficients, PeriodicX const& periodic, double dt,
                 HeatParticles<MemorySpace> const& current,
                 Kokkos::View<double**, MemorySpace> const& next,
                 HeatSlots<MemorySpace> const& slots) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::heatSubStep: particle memory not accessible");
  detail::HeatStepFunctor<MemorySpace> f;
  f.x = p.position;
  f.radius = p.radius;
  f.id = p.id;
  f.count = list.count;
  f.index = list.index;
  f.told = current.temperature;
  f.tnew = next;
  f.environmentHeat = current.environmentHeat;
  f.layerSelf = slots.layerSelf;
  f.layerOther = slots.layerOther;
  f.area = slots.area;
  f.model = model;
  f.c = coefficients;
  f.periodic = periodic;
  f.dt = dt;
  f.inverseShare = 1.0 / coefficients.neighborShare;
  f.capacity = list.capacity() < slots.capacity() ? list.capacity() : slots.capacity();
  Kokkos::parallel_for("hikiln::dem::heat::subStep",
                       Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()), f);
}

} // namespace hikiln::dem
