#pragma once
/// \file CoarseGrainInvariants.hpp
/// \brief 2D invariants of the averaged stress and strain-rate tensors (physics.md 3), as point
/// functions usable on the host and in kernels.
///
/// Stress convention: compressive positive (sigma = -sigma_tension), so that
/// p = sigma_ii / 2 > 0 in a bed. Deviator s = sigma - p I; q = sqrt(s_ij s_ij / 2), of the
/// symmetric part of sigma (the antisymmetric part of a contact stress is a couple-stress effect
/// that carries no shear in the continuum model). Drucker-Prager: q = m p. In a simple shear
/// [[p, tau], [tau, p]] this gives q = |tau| and m = |tau| / p, i.e. m = tan(phi) with
/// tau / sigma_n = tan(phi) on the shear plane (the convention documented in
/// docs/averaged-fields.md and tested in tests/dem/tstCoarseGrainFields.hpp).

#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem::cg {

/// \brief Pressure p and shear stress q of a 2D stress.
struct StressInvariants {
  double pressure = 0.0; ///< p = (sigma_xx + sigma_yy) / 2, compressive positive (Pa)
  double shear = 0.0;    ///< q = sqrt(s_ij s_ij / 2) of the symmetric deviator (Pa)
};

/// \brief p and q of the compressive-positive stress [[sxx, sxy], [syx, syy]].
KOKKOS_INLINE_FUNCTION StressInvariants stressInvariants(double sxx, double sxy, double syx,
                                                         double syy) {
  StressInvariants out;
  out.pressure = 0.5 * (sxx + syy);
  const double normalDifference = 0.5 * (sxx - syy);
  const double shear = 0.5 * (sxy + syx);
  out.shear = math::sqrt(normalDifference * normalDifference + shear * shear);
  return out;
}

/// \brief gamma_dot = sqrt(2 D':D') of a symmetric 2D strain rate D (D' its deviator):
/// sqrt((D_xx - D_yy)^2 + 4 D_xy^2); |a| for the simple shear u = (a y, 0). Valid in any
/// orthonormal frame (D_rr, D_rtheta, D_thetatheta as well).
KOKKOS_INLINE_FUNCTION double strainRateInvariant(double dxx, double dxy, double dyy) {
  const double d = dxx - dyy;
  return math::sqrt(d * d + 4.0 * dxy * dxy);
}

} // namespace hikiln::dem::cg
