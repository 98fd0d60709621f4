#pragma once
/// \file NewtonianTest.hpp
/// \brief Is the bed a Newtonian fluid? Fit tau = K gamma_dot^n: n = 1 would say yes.

#include "solvers/calibration/PowerLawFit.hpp"

#include <vector>

namespace hikiln::calibration {

/// \brief Power-law fit of shear stress against strain rate and the verdict.
struct NewtonianTest {
  PowerLawFit fit;        ///< tau = K gamma_dot^n (K is the consistency, Pa s^n)
  double tolerance = 0.0; ///< |n - 1| allowed for a Newtonian verdict
  bool newtonian = false; ///< |n - 1| <= tolerance
};

/// \brief Fits shear stress (Pa) against strain rate (1/s) and calls it Newtonian when the
/// exponent lies within `tolerance` of 1. Throws std::invalid_argument as fitPowerLaw does.
NewtonianTest testNewtonian(const std::vector<double>& strainRate,
                            const std::vector<double>& shearStress, double tolerance = 0.1);

} // namespace hikiln::calibration
