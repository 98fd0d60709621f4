#pragma once
/// \file ContactConduction.hpp
/// \brief Contact conduction with thermal boundary layers (physics.md 6.1), as point functions.
///
/// Per contact and per side a boundary layer: the outer half (thickness dr/2) of the outer shell
/// under the contact patch of area A, with its own temperature L. Its heat capacity, rho c A dr/2,
/// is taken out of the outer shell's bulk (so the particle's capacity stays m c); it exchanges
/// k A (T_shell - L) / delta with the outer-shell node and k A (T_edge - L) / delta with the
/// contact surface, delta = dr/4 (ShellModel.hpp). The contact surface temperature T_edge makes
/// the two sides' fluxes equal and opposite,
///   T_edge = (h_a L_a + h_b L_b) / (h_a + h_b),   h = k / delta,
/// so the flux into side a is A h_a h_b / (h_a + h_b) (L_b - L_a).
/// The two layers are advanced together by backward Euler with the outer shells' temperatures
/// frozen over the sub-step (a 2x2 solve: unconditionally stable, so the fast layers, time
/// constant ~ delta^2/alpha, do not limit the heat step). Every coefficient is proportional to A,
/// so the new layer temperatures do not depend on A and the heat a contact passes is exactly
/// proportional to its area.
/// When A changes, capacity moves between a layer and its bulk: a growing layer takes bulk
/// material at the bulk temperature, a shrinking one returns material at the layer temperature
/// (exactly conservative mixing); a vanishing contact returns all of it.
///
/// Pair quantities are evaluated from the side with the lower particle id (side a), so both
/// particles of a pair compute bitwise identical numbers and the heat into one is exactly minus
/// the heat into the other.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/heat/HeatParameters.hpp"
#include "kernels/dem/heat/ShellModel.hpp"

namespace hikiln::dem {

/// \brief Geometric contact area (m^2) of two particles with effective radius rEff at overlap
/// delta >= 0: pi r_eff delta (sphere) or 2 sqrt(2 r_eff delta) t (disc chord).
KOKKOS_INLINE_FUNCTION double geometricContactArea(MassConvention g, double rEff, double delta,
                                                   double thickness) {
  return g == MassConvention::Sphere ? constants::pi * rEff * delta
                                     : 2.0 * math::sqrt(2.0 * rEff * delta) * thickness;
}

/// \brief Area (m^2) of a Hertz contact of the material (effective modulus eStar) pressed by
/// force f: sphere pi a^2 with a^3 = 3 f r_eff / (4 E*); disc 2 b t with
/// b = sqrt(4 f r_eff / (pi E* t)).
KOKKOS_INLINE_FUNCTION double hertzContactArea(MassConvention g, double rEff, double force,
                                               double eStar, double thickness) {
  if (g == MassConvention::Sphere) {
    const double a = math::cbrt(0.75 * force * rEff / eStar);
    return constants::pi * a * a;
  }
  return 2.0 * thickness * math::sqrt(4.0 * force * rEff / (constants::pi * eStar * thickness));
}

/// \brief Real (thermal) contact area (m^2) of particles of radii ra, rb at DEM overlap delta
/// under the model chosen in c (see ContactAreaModel), capped at maxContactAreaFraction of the
/// smaller outer surface; 0 for delta <= 0 or with contact conduction off. Symmetric in a, b.
KOKKOS_INLINE_FUNCTION double contactArea(const HeatCoefficients& c, double ra, double rb,
                                          double delta) {
  if (!c.contactConduction || !(delta > 0.0)) {
    return 0.0;
  }
  const double rEff = ra * rb / (ra + rb);
  double area = 0.0;
  if (c.contactArea == ContactAreaModel::Overlap) {
    area = geometricContactArea(c.geometry, rEff, delta, c.thickness);
  } else if (c.contactArea == ContactAreaModel::StiffnessRatio) {
    const double kReal = c.realStiffness > 0.0 ? c.realStiffness : c.effectiveModulus * 2.0 * rEff;
    area = geometricContactArea(c.geometry, rEff, delta * c.springStiffness / kReal, c.thickness);
  } else {
    area = hertzContactArea(c.geometry, rEff, c.springStiffness * delta, c.effectiveModulus,
                            c.thickness);
  }
  const double cap =
      c.maxContactAreaFraction * math::min(particleSurfaceArea(c.geometry, ra, c.thickness),
                                           particleSurfaceArea(c.geometry, rb, c.thickness));
  return math::min(area, cap);
}

/// \brief Contact-surface temperature that equalises the two sides' fluxes (h = k/delta per side).
KOKKOS_INLINE_FUNCTION double contactEdgeTemperature(double ha, double la, double hb, double lb) {
  return (ha * la + hb * lb) / (ha + hb);
}

/// \brief One side of a contact as the layer update sees it.
struct LayerSide {
  double capacityPerArea = 0.0;    ///< rho c dr/2 (J/K/m^2)
  double conductancePerArea = 0.0; ///< k / delta (W/K/m^2)
  double shell = 0.0;              ///< outer-shell (bulk) temperature, frozen over the sub-step
  double layer = 0.0;              ///< layer temperature before the sub-step
};

/// \brief What one side's layer did over a sub-step.
struct LayerChange {
  double layer = 0.0;       ///< new layer temperature
  double capacityOld = 0.0; ///< layer capacity before (J/K)
  double capacityNew = 0.0; ///< after the area change (J/K)
  /// Heat the bulk gains from the capacity exchange: -(growth) T_shell or +(shrinkage) L (J).
  double bulkExchange = 0.0;
  double shellHeat = 0.0;   ///< heat conducted from the outer-shell node into the layer (J)
  double contactHeat = 0.0; ///< heat through the contact surface into this layer (J)
};

/// \brief Moves layer capacity for an area change areaOld -> area (conservative mixing; a
/// growing layer mixes as L + (1 - areaOld/area) (T_shell - L), `ratio` = areaOld/area shared by
/// both sides); returns the mixed layer temperature and fills capacities and bulkExchange of `out`.
KOKKOS_INLINE_FUNCTION double resizeLayer(const LayerSide& s, double areaOld, double area,
                                          double ratio, LayerChange& out) {
  const double c0 = s.capacityPerArea * areaOld;
  const double c1 = s.capacityPerArea * area;
  out.capacityOld = c0;
  out.capacityNew = c1;
  if (c1 >= c0) { // grows by bulk material at the bulk temperature
    out.bulkExchange = -(c1 - c0) * s.shell;
    return c1 > 0.0 ? s.layer + (1.0 - ratio) * (s.shell - s.layer) : s.shell;
  }
  out.bulkExchange = (c0 - c1) * s.layer; // returns material at the layer temperature
  return s.layer;
}

/// \brief Advances the two boundary layers of one contact over dt (side a: the lower id): area
/// change, then backward Euler of the two layers coupled through the contact surface and each to
/// its frozen outer shell. With area 0 the layers dissolve into their bulks.
KOKKOS_INLINE_FUNCTION void advanceLayerPair(const LayerSide& a, const LayerSide& b, double areaOld,
                                             double area, double dt, LayerChange& ua,
                                             LayerChange& ub) {
  const double ratio = area > areaOld ? areaOld / area : 1.0;
  const double la = resizeLayer(a, areaOld, area, ratio, ua);
  const double lb = resizeLayer(b, areaOld, area, ratio, ub);
  if (!(area > 0.0)) {
    ua.layer = a.shell;
    ub.layer = b.shell;
    ua.shellHeat = ub.shellHeat = ua.contactHeat = ub.contactHeat = 0.0;
    return;
  }
  const double ha = a.conductancePerArea * area; // layer-shell and layer-surface, side a (W/K)
  const double hb = b.conductancePerArea * area;
  const double gc = ha * hb / (ha + hb); // layer to layer through the contact surface
  const double a11 = ua.capacityNew + dt * (gc + ha);
  const double a22 = ub.capacityNew + dt * (gc + hb);
  const double off = dt * gc;
  const double r1 = ua.capacityNew * la + dt * ha * a.shell;
  const double r2 = ub.capacityNew * lb + dt * hb * b.shell;
  const double inverseDet = 1.0 / (a11 * a22 - off * off);
  ua.layer = (r1 * a22 + off * r2) * inverseDet;
  ub.layer = (a11 * r2 + off * r1) * inverseDet;
  ua.shellHeat = dt * ha * (a.shell - ua.layer);
  ub.shellHeat = dt * hb * (b.shell - ub.layer);
  ua.contactHeat = dt * gc * (ub.layer - ua.layer);
  ub.contactHeat = -ua.contactHeat;
}

} // namespace hikiln::dem
