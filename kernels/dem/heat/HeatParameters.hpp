#pragma once
/// \file HeatParameters.hpp
/// \brief Material properties, model choices and switches of the DEM heat model (physics.md 6.1),
/// and their kernel form.
///
/// Material defaults: a limestone/calcite-like mineral feed, matching the DEM density of
/// 2700 kg/m^3 (physics.md base case). Handbook values at 300 K (Incropera & DeWitt, Fundamentals
/// of Heat and Mass Transfer, Table A.3): marble 2680 kg/m^3, k = 2.8 W/m/K, c = 830 J/kg/K;
/// limestone k = 2.15 W/m/K, c = 810 J/kg/K. Between 400 and 800 C (the mixing runs of physics.md
/// 6.2) the conductivity of carbonates falls and the heat capacity rises to about 1100 J/kg/K, so
/// k = 2.5 W/m/K and c = 1000 J/kg/K are used. Total emissivity of limestone and oxide surfaces
/// 0.8-0.95: 0.85. Young's modulus of calcite 70-80 GPa, Poisson ratio 0.25-0.3: 70 GPa, 0.25.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ParticleArrays.hpp"

#include <stdexcept>
#include <string>

namespace hikiln::dem {

/// \brief How the real (thermal) contact area is obtained from a DEM contact of overlap delta.
/// The geometric area of a contact is, with r_eff = r_i r_j / (r_i + r_j):
///   Sphere geometry: a circle of radius a, a^2 = r_eff delta, A = pi a^2 (area ~ overlap);
///   Disc geometry (thickness t): a chord of half-length a = sqrt(2 r_eff delta), A = 2 a t.
/// - Overlap: the geometric area at the DEM overlap (no correction: soft springs inflate it).
/// - StiffnessRatio: the geometric area at the overlap the material would have under the same
///   spring force, delta k_sim / k_real, with k_real = realStiffness, or E* 2 r_eff (the usual
///   k ~ E d estimate) when realStiffness <= 0. Area scales by k_sim/k_real for spheres and by
///   sqrt(k_sim/k_real) for discs (chord ~ sqrt(overlap)).
/// - Hertz (default): the area of an elastic (Hertz) contact of the material under the DEM's
///   elastic force F = k_sim delta: sphere a^3 = 3 F r_eff / (4 E*), A = pi a^2; disc (line
///   contact per unit thickness F/t) half-width b = sqrt(4 F r_eff / (pi E* t)), A = 2 b t. This is
///   StiffnessRatio with k_real the secant stiffness F/delta_real of the material's own contact at
///   that force, so it needs no length scale.
/// E* = E / (2 (1 - nu^2)) for two particles of the same material.
enum class ContactAreaModel { Overlap, StiffnessRatio, Hertz };

/// \brief User-facing parameters of the DEM heat model (one material for all particles).
struct HeatParameters {
  // material
  double conductivity = 2.5;     ///< k (W/m/K)
  double specificHeat = 1000.0;  ///< c (J/kg/K); a particle's heat capacity is its mass times c
  double emissivity = 0.85;      ///< total hemispherical emissivity of the surfaces
  double youngsModulus = 70.0e9; ///< E (Pa), for the real contact area
  double poissonRatio = 0.25;    ///< nu

  // intra-particle model (always on; shells = 1 is a lumped particle)
  MassConvention geometry = MassConvention::Sphere; ///< radial shells of a sphere or of a disc
  double thickness = 0.02; ///< disc thickness (m), Disc geometry (areas and volumes)
  int shells = 8; ///< radial shells (centre error at Bi = 1 below 1.5e-3: tstHeatConduction.hpp)
  double timeStepSafety = 0.5; ///< heat sub-step = safety x the explicit stability limit

  // contact conduction (boundary-layer model)
  bool contactConduction = true;
  ContactAreaModel contactArea = ContactAreaModel::Hertz;
  double realStiffness = 0.0; ///< k_real (N/m) for StiffnessRatio; <= 0: E* 2 r_eff
  /// A contact's area is capped at this fraction of the smaller particle's outer surface (only
  /// absurd overlaps reach it; it bounds the stable heat step).
  double maxContactAreaFraction = 1.0 / 24.0;

  // radiation between neighbouring surfaces
  bool radiation = true;
  /// Surface gap (m) up to which neighbours exchange radiation; < 0: the neighbour-list skin. The
  /// range in use is min(range, skin): the list holds no farther pairs.
  double radiationRange = -1.0;
  /// Each neighbour within range sees 1/neighborShare of the smaller particle's surface; the part
  /// of a particle's surface not taken by neighbours, max(0, 1 - n/neighborShare), sees the
  /// environment. 6: the coordination of a dense 2D disc packing.
  double neighborShare = 6.0;

  // exchange with a fixed environment (not conserving: accounted separately); off by default
  bool environmentExchange = false;
  double environmentTemperature = 293.15; ///< K
  double environmentHeatTransfer = 0.0;   ///< convective h (W/m^2/K) at the exposed surface
  bool environmentRadiation = true;       ///< grey radiation sigma eps (T_env^4 - T^4) too
};

/// \brief The heat model in the form the kernels use (trivially copyable; see prepareHeat()).
struct HeatCoefficients {
  double conductivity = 0.0;
  double specificHeat = 0.0;
  double pairEmissivity = 0.0;   ///< two grey surfaces facing each other: 1/(2/eps - 1)
  double emissivity = 0.0;       ///< particle to environment
  double effectiveModulus = 0.0; ///< E* = E / (2 (1 - nu^2))
  double springStiffness = 0.0;  ///< k_n of the DEM particle contact law (N/m)
  MassConvention geometry = MassConvention::Sphere;
  double thickness = 0.0;
  int shells = 1;
  bool contactConduction = false;
  ContactAreaModel contactArea = ContactAreaModel::Hertz;
  double realStiffness = 0.0;
  double maxContactAreaFraction = 0.0;
  bool radiation = false;
  double radiationRange = 0.0; ///< in use: min(range, skin)
  double neighborShare = 1.0;
  bool environmentExchange = false;
  double environmentTemperature = 0.0;
  double environmentHeatTransfer = 0.0;
  bool environmentRadiation = false;
};

/// \brief Validates the parameters and turns them into kernel coefficients; springStiffness is the
/// DEM particle contact's k_n and skin the neighbour-list skin (host).
inline HeatCoefficients prepareHeat(const HeatParameters& p, double springStiffness, double skin) {
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument("hikiln::dem::HeatParameters: " + what);
  };
  if (!(p.conductivity > 0.0)) {
    fail("conductivity must be > 0");
  }
  if (!(p.specificHeat > 0.0)) {
    fail("specificHeat must be > 0");
  }
  if (!(p.emissivity > 0.0 && p.emissivity <= 1.0)) {
    fail("emissivity must be in (0, 1]");
  }
  if (!(p.youngsModulus > 0.0)) {
    fail("youngsModulus must be > 0");
  }
  if (!(p.poissonRatio > -1.0 && p.poissonRatio < 0.5)) {
    fail("poissonRatio must be in (-1, 0.5)");
  }
  if (p.geometry == MassConvention::Disc && !(p.thickness > 0.0)) {
    fail("thickness must be > 0 for the disc geometry");
  }
  if (p.shells < 1 || p.shells > 1000) {
    fail("shells must be in [1, 1000]");
  }
  if (!(p.timeStepSafety > 0.0 && p.timeStepSafety <= 1.0)) {
    fail("timeStepSafety must be in (0, 1]");
  }
  if (!(p.maxContactAreaFraction > 0.0 && p.maxContactAreaFraction <= 1.0)) {
    fail("maxContactAreaFraction must be in (0, 1]");
  }
  if (!(p.neighborShare >= 1.0)) {
    fail("neighborShare must be >= 1");
  }
  if (!(p.realStiffness >= 0.0)) {
    fail("realStiffness must be >= 0 (0: from Young's modulus)");
  }
  if (p.environmentExchange &&
      (!(p.environmentTemperature > 0.0) || !(p.environmentHeatTransfer >= 0.0))) {
    fail("environment temperature must be > 0 K and its heat transfer coefficient >= 0");
  }
  if (!(springStiffness > 0.0)) {
    fail("the DEM spring stiffness must be > 0");
  }
  HeatCoefficients c;
  c.conductivity = p.conductivity;
  c.specificHeat = p.specificHeat;
  c.emissivity = p.emissivity;
  c.pairEmissivity = 1.0 / (2.0 / p.emissivity - 1.0);
  c.effectiveModulus = p.youngsModulus / (2.0 * (1.0 - p.poissonRatio * p.poissonRatio));
  c.springStiffness = springStiffness;
  c.geometry = p.geometry;
  c.thickness = p.geometry == MassConvention::Disc ? p.thickness : 0.0;
  c.shells = p.shells;
  c.contactConduction = p.contactConduction;
  c.contactArea = p.contactArea;
  c.realStiffness = p.realStiffness;
  c.maxContactAreaFraction = p.maxContactAreaFraction;
  c.radiation = p.radiation;
  c.radiationRange = p.radiationRange < 0.0 ? skin : math::min(p.radiationRange, skin);
  c.neighborShare = p.neighborShare;
  c.environmentExchange = p.environmentExchange;
  c.environmentTemperature = p.environmentTemperature;
  c.environmentHeatTransfer = p.environmentHeatTransfer;
  c.environmentRadiation = p.environmentRadiation;
  return c;
}

} // namespace hikiln::dem
