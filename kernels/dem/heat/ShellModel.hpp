#pragma once
/// \file ShellModel.hpp
/// \brief Radial finite-volume model of the temperature inside one particle: N shells of equal
/// width dr = R/N, node m at the shell's mid-radius, in sphere or disc (cylinder) geometry.
///
/// Shell m spans [m dr, (m+1) dr]. Its heat capacity is the particle's (mass x c) times its volume
/// fraction, ((m+1)^3 - m^3)/N^3 (sphere) or ((m+1)^2 - m^2)/N^2 (disc), so the particle's heat
/// content is sum C_m T_m exactly. Face f (1 <= f < N, at r = f dr) conducts G_f (T_f - T_{f-1})
/// with G_f = k area(f dr) / dr: 4 pi k R f^2 / N (sphere, area 4 pi r^2) or 2 pi k t f (disc,
/// area 2 pi r t). Each face flux is added to one shell and subtracted from the other, so the
/// explicit update conserves energy by construction.
///
/// The outer shell additionally exchanges with its contact boundary layers, its radiating
/// neighbours and (optionally) the environment. Boundary layers (ContactConduction.hpp) are the
/// outer half of the outer shell under a contact patch: thickness dr/2 with the layer node in its
/// middle, so the gradient length of each half is delta = dr/4 and node-to-surface conduction in
/// series, k A / (2 delta) = k A / (dr/2), equals the half-cell conductance of the radial model.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/heat/HeatParameters.hpp"

namespace hikiln::dem {

/// \brief Fraction of the particle volume in shell m of n.
KOKKOS_INLINE_FUNCTION double shellVolumeFraction(MassConvention g, int n, int m) {
  const double a = m, b = m + 1, nn = n;
  return g == MassConvention::Sphere ? (b * b * b - a * a * a) / (nn * nn * nn)
                                     : (b * b - a * a) / (nn * nn);
}

/// \brief Conductance k area / dr (W/K) of face f (between shells f-1 and f) of a particle of
/// radius r with n shells.
KOKKOS_INLINE_FUNCTION double shellFaceConductance(MassConvention g, int n, int f, double k,
                                                   double r, double thickness) {
  const double ff = f;
  return g == MassConvention::Sphere ? 4.0 * constants::pi * k * r * ff * ff / n
                                     : 2.0 * constants::pi * k * thickness * ff;
}

/// \brief Outer surface area (m^2): 4 pi r^2 (sphere) or 2 pi r t (disc rim; the flat faces
/// are insulated, as in the infinite cylinder).
KOKKOS_INLINE_FUNCTION double particleSurfaceArea(MassConvention g, double r, double thickness) {
  return g == MassConvention::Sphere ? 4.0 * constants::pi * r * r
                                     : 2.0 * constants::pi * r * thickness;
}

/// \brief Volume (m^3): 4/3 pi r^3 (sphere) or pi r^2 t (disc).
KOKKOS_INLINE_FUNCTION double particleVolume(MassConvention g, double r, double thickness) {
  return g == MassConvention::Sphere ? 4.0 / 3.0 * constants::pi * r * r * r
                                     : constants::pi * r * r * thickness;
}

/// \brief Face conductance of face f over k and over the particle's faceScale (ParticleHeat):
/// 4 pi f^2 / n (sphere, faceScale = r) or 2 pi t f (disc, faceScale = 1).
KOKKOS_INLINE_FUNCTION double shellFaceFactor(MassConvention g, int n, int f, double thickness) {
  const double ff = f;
  return g == MassConvention::Sphere ? 4.0 * constants::pi * ff * ff / n
                                     : 2.0 * constants::pi * thickness * ff;
}

/// \brief Per-particle constants of the heat model, derived from radius and mass.
struct ParticleHeat {
  double capacity = 0.0;        ///< m c (J/K)
  double inverseCapacity = 0.0; ///< 1 / (m c)
  double outerCapacity = 0.0;   ///< heat capacity of the outer shell (J/K)
  double surface = 0.0;         ///< outer surface area (m^2)
  /// Boundary-layer heat capacity per contact area, rho c dr/2 (J/K/m^2), rho = m / volume.
  double layerCapacityPerArea = 0.0;
  /// Boundary-layer conductance per contact area, k / delta with delta = dr/4 (W/K/m^2).
  double layerConductancePerArea = 0.0;
  /// Conductance from the outer node to the surface, k surface / (dr/2) (W/K).
  double surfaceConductance = 0.0;
  /// Face conductance = k faceScale shellFaceFactor(): r (sphere) or 1 (disc).
  double faceScale = 0.0;
};

/// \brief The heat constants of a particle of radius r and mass m.
KOKKOS_INLINE_FUNCTION ParticleHeat particleHeat(const HeatCoefficients& c, double r, double m) {
  ParticleHeat p;
  const int n = c.shells;
  const double dr = r / n;
  p.capacity = m * c.specificHeat;
  p.inverseCapacity = 1.0 / p.capacity;
  p.outerCapacity = p.capacity * shellVolumeFraction(c.geometry, n, n - 1);
  p.surface = particleSurfaceArea(c.geometry, r, c.thickness);
  p.layerCapacityPerArea = p.capacity / particleVolume(c.geometry, r, c.thickness) * 0.5 * dr;
  p.layerConductancePerArea = c.conductivity / (0.25 * dr);
  p.surfaceConductance = c.conductivity * p.surface / (0.5 * dr);
  p.faceScale = c.geometry == MassConvention::Sphere ? r : 1.0;
  return p;
}

/// \brief Largest stable explicit heat step (s) of one particle of radius r and mass m: the
/// minimum over shells of C_m / (sum of its conductances), where the outer shell's conductances
/// are bounded from above: contact layers at most listCapacity contacts each capped at
/// maxContactAreaFraction of the surface (at most the whole surface), with the bulk of the outer
/// shell reduced by those layers' capacity; radiation linearised at temperatureMax
/// (4 sigma eps T^3 per area) over max(1, listCapacity/neighborShare) surfaces; the environment
/// over the whole surface. Returns 0 when the layers could exceed the outer shell's capacity.
/// Interior shells: exactly dr^2/(2 alpha) in a disc, dr^2/(3 alpha) at a
/// sphere's centre. Host or device.
KOKKOS_INLINE_FUNCTION double stableHeatTimeStep(const HeatCoefficients& c, double r, double m,
                                                 int listCapacity, double temperatureMax) {
  const ParticleHeat p = particleHeat(c, r, m);
  const int n = c.shells;
  double dt = 1.0e300;
  for (int s = 0; s + 1 < n; ++s) {
    const double g =
        (s > 0 ? shellFaceConductance(c.geometry, n, s, c.conductivity, r, c.thickness) : 0.0) +
        shellFaceConductance(c.geometry, n, s + 1, c.conductivity, r, c.thickness);
    dt = math::min(dt, p.capacity * shellVolumeFraction(c.geometry, n, s) / g);
  }
  double g =
      n > 1 ? shellFaceConductance(c.geometry, n, n - 1, c.conductivity, r, c.thickness) : 0.0;
  double bulk = p.outerCapacity;
  if (c.contactConduction) {
    const double areaBound = math::min(1.0, listCapacity * c.maxContactAreaFraction) * p.surface;
    g += p.layerConductancePerArea * areaBound;
    bulk -= p.layerCapacityPerArea * areaBound;
  }
  const double t3 = temperatureMax * temperatureMax * temperatureMax;
  if (c.radiation) {
    const double shared = math::max(1.0, listCapacity / c.neighborShare);
    g += 4.0 * constants::stefanBoltzmann * c.pairEmissivity * t3 * p.surface * shared;
  }
  if (c.environmentExchange) {
    g += c.environmentHeatTransfer * p.surface;
    if (c.environmentRadiation) {
      g += 4.0 * constants::stefanBoltzmann * c.emissivity * t3 * p.surface;
    }
  }
  if (!(bulk > 0.0)) {
    return 0.0; // the layers could take the whole outer shell: reject (caller reports)
  }
  if (g > 0.0) {
    dt = math::min(dt, bulk / g);
  }
  return dt;
}

} // namespace hikiln::dem
