#pragma once
/// \file CoulombFit.hpp
/// \brief Coulomb line tau = c + mu_fr p through shear stress against pressure (physics.md 3).

#include "solvers/calibration/FitQuality.hpp"

#include <vector>

namespace hikiln::calibration {

/// \brief Fitted Coulomb yield line; tan(phi) = mu_fr.
struct CoulombFit {
  double frictionCoefficient = 0.0; ///< mu_fr
  double cohesion = 0.0;            ///< c [Pa]
  double frictionAngleDeg = 0.0;    ///< phi = atan(mu_fr) [degrees]
  double frictionCoefficientStdError = 0.0;
  double cohesionStdError = 0.0;         ///< [Pa]
  double frictionAngleDegStdError = 0.0; ///< propagated: se(mu_fr) / (1 + mu_fr^2), in degrees
  FitQuality quality;                    ///< in Pa
};

/// \brief Least squares line of `shearStress` against `pressure` (both Pa). Throws
/// std::invalid_argument as fitLinear does.
CoulombFit fitCoulomb(const std::vector<double>& pressure, const std::vector<double>& shearStress);

} // namespace hikiln::calibration
