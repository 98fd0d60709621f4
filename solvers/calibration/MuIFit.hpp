#pragma once
/// \file MuIFit.hpp
/// \brief The mu(I)-type friction law m(I) = m_s + (m_2 - m_s) / (1 + I0 / I) (Jop, Forterre &
/// Pouliquen 2006), fitted by Levenberg-Marquardt on its three parameters.

#include "solvers/calibration/FitQuality.hpp"

#include <vector>

namespace hikiln::calibration {

/// \brief Parameters of the mu(I) law (also used for their standard errors).
struct MuIParameters {
  double staticFriction = 0.0; ///< m_s, the I -> 0 limit
  double limitFriction = 0.0;  ///< m_2, the I -> infinity limit
  double inertialScale = 0.0;  ///< I0 > 0, the I at which m is half way
};

/// \brief Inertial number I = gamma_dot d / sqrt(p / rho_p) (SI units; p > 0).
double inertialNumber(double strainRate, double particleDiameter, double pressure,
                      double particleDensity);

/// \brief m(I) for I >= 0 (m(0) = m_s).
double evaluateMuI(const MuIParameters& parameters, double inertial);

/// \brief Iteration controls for fitMuI.
struct MuIFitOptions {
  int maxIterations = 200;
  double relativeTolerance = 1e-14; ///< stop when the step changes no parameter by more than this
};

/// \brief A fitted mu(I) law with its uncertainty.
struct MuIFit {
  MuIParameters parameters;
  MuIParameters standardErrors; ///< from s^2 (J^T J)^-1 at the optimum; NaN with 3 points
  FitQuality quality;
  int iterations = 0;
  bool converged = false; ///< false: iteration limit reached, parameters are the best found
};

/// \brief Least squares fit of m against I (both dimensionless, I > 0). The start is the best
/// of a scan over I0 (for each trial I0 the law is linear in m_s and m_2), so no initial guess
/// is needed; Levenberg-Marquardt then refines all three, I0 through ln I0 to keep it positive.
/// Throws std::invalid_argument for mismatched sizes, fewer than 3 points or I <= 0.
MuIFit fitMuI(const std::vector<double>& inertial, const std::vector<double>& friction,
              const MuIFitOptions& options = {});

} // namespace hikiln::calibration
