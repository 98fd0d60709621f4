#pragma once
/// \file Radiation.hpp
/// \brief Radiation between neighbouring particle surfaces and to a fixed environment
/// (physics.md 6.1: q = sigma eps (T_h^4 - T_e^4), a small group of neighbours from the DEM
/// neighbour search, no shadowing).
///
/// Choices (physics.md leaves them open):
/// - A pair whose surface gap is below the radiation range (min(range, skin); contacts included)
///   exchanges P = sigma eps_pair A_pair (T_b^4 - T_a^4) into a, with the outer-shell node
///   temperatures. eps_pair = 1 / (1/eps + 1/eps - 1), two grey surfaces facing each other (close
///   neighbours are nearly parallel surfaces). A_pair = min(S_a, S_b) / neighborShare: in a dense
///   2D packing each of ~6 neighbours faces a sixth of a particle's surface; the smaller surface
///   keeps the exchange symmetric (reciprocity A_a F_ab = A_b F_ba).
/// - Environment: the part of the surface not taken by neighbours, max(0, 1 - n/neighborShare)
///   (n neighbours within range), exchanges convection h and grey radiation with T_env. The
///   convective path includes the half outer shell (node to surface) in series.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/heat/HeatParameters.hpp"

namespace hikiln::dem {

/// \brief Radiant power (W) into surface a from surface b: sigma eps A (T_b^4 - T_a^4).
KOKKOS_INLINE_FUNCTION double radiativeExchange(double emissivityArea, double ta, double tb) {
  const double a2 = ta * ta, b2 = tb * tb;
  return constants::stefanBoltzmann * emissivityArea * (b2 * b2 - a2 * a2);
}

/// \brief Exchange area (m^2) of a radiating pair with outer surfaces sa, sb.
KOKKOS_INLINE_FUNCTION double radiativePairArea(double sa, double sb, double neighborShare) {
  return math::min(sa, sb) / neighborShare;
}

/// \brief Fraction of a particle's surface that sees the environment with n neighbours in range.
KOKKOS_INLINE_FUNCTION double environmentExposure(int n, double neighborShare) {
  return math::max(0.0, 1.0 - n / neighborShare);
}

/// \brief Power (W) into a particle's outer shell (node temperature t, outer surface area s,
/// node-to-surface conductance gSurface) from the environment over the exposed fraction.
KOKKOS_INLINE_FUNCTION double environmentPower(const HeatCoefficients& c, double exposure, double s,
                                               double gSurface, double t) {
  if (!c.environmentExchange || !(exposure > 0.0)) {
    return 0.0;
  }
  double p = 0.0;
  if (c.environmentHeatTransfer > 0.0) {
    const double hs = c.environmentHeatTransfer * exposure * s;
    const double gs = gSurface * exposure;
    p += hs * gs / (hs + gs) * (c.environmentTemperature - t);
  }
  if (c.environmentRadiation) {
    p += radiativeExchange(c.emissivity * exposure * s, t, c.environmentTemperature);
  }
  return p;
}

} // namespace hikiln::dem
