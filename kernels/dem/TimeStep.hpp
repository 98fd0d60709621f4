#pragma once
/// \file TimeStep.hpp
/// \brief Time step from the shortest contact oscillation.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ContactLaw.hpp"

#include <algorithm>
#include <stdexcept>

namespace hikiln::dem {

/// \brief Default fraction of the shortest contact duration used as time step. 1/20 of the
/// tangential period (the shorter one for k_t/k_n = 1/2) gives 2.6e-5 s for the physics.md base
/// case, next to the 2.5e-5 s of the LAMMPS reference run.
inline constexpr double defaultTimeStepSafety = 0.05;

/// \brief Shortest contact duration (s) of a law at effective mass m_eff for particles with
/// inertia I = inertiaFactor m r^2: the normal one, pi / sqrt(k_n/m_eff - (c_n/2m_eff)^2), or the
/// tangential one, pi / sqrt(k_t/m_t) with 1/m_t = (1/m_eff)(1 + 1/inertiaFactor) (the tangential
/// spring also drives the rotation of both bodies), whichever is shorter.
inline double shortestContactDuration(const ContactCoefficients& c, double meff,
                                      double inertiaFactor) {
  if (!(meff > 0.0) || !(inertiaFactor > 0.0)) {
    throw std::invalid_argument("hikiln::dem::shortestContactDuration: mass and inertia factor "
                                "must be > 0");
  }
  double t = contactDuration(c.kn, meff, normalDampingCoefficient(c, meff));
  if (c.kt > 0.0) {
    t = std::min(t, contactDuration(c.kt, meff / (1.0 + 1.0 / inertiaFactor), 0.0));
  }
  return t;
}

/// \brief Recommended time step: safety times the shortest contact duration of the particle law
/// for the lightest pair and of the wall law for the lightest particle (minMass the smallest
/// particle mass, inertiaFactor 0.4 for MassConvention::Sphere, 0.5 for Disc).
inline double recommendedTimeStep(const ContactCoefficients& particle,
                                  const ContactCoefficients& wall, double minMass,
                                  double inertiaFactor, double safety = defaultTimeStepSafety) {
  if (!(safety > 0.0)) {
    throw std::invalid_argument("hikiln::dem::recommendedTimeStep: safety must be > 0");
  }
  // lightest pair: m_eff = minMass / 2; lightest particle on a wall: m_eff = minMass
  const double t = std::min(shortestContactDuration(particle, 0.5 * minMass, inertiaFactor),
                            shortestContactDuration(wall, minMass, inertiaFactor));
  return safety * t;
}

} // namespace hikiln::dem
