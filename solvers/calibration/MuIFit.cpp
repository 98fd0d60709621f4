#include "solvers/calibration/MuIFit.hpp"

#include "solvers/calibration/LeastSquares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hikiln::calibration {

double inertialNumber(double strainRate, double particleDiameter, double pressure,
                      double particleDensity) {
  return strainRate * particleDiameter / std::sqrt(pressure / particleDensity);
}

double evaluateMuI(const MuIParameters& parameters, double inertial) {
  // (m_2 - m_s) I / (I + I0) is the same law, finite at I = 0.
  return parameters.staticFriction + (parameters.limitFriction - parameters.staticFriction) *
                                         inertial / (inertial + parameters.inertialScale);
}

namespace {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

// theta = (m_s, m_2, ln I0).
MuIParameters fromTheta(const Vector3& theta) {
  return {theta[0], theta[1], std::exp(theta[2])};
}

double sumOfSquares(const Eigen::VectorXd& inertial, const Eigen::VectorXd& friction,
                    const Vector3& theta) {
  const MuIParameters p = fromTheta(theta);
  double ssr = 0.0;
  for (Eigen::Index i = 0; i < inertial.size(); ++i) {
    const double r = friction[i] - evaluateMuI(p, inertial[i]);
    ssr += r * r;
  }
  return ssr;
}

// Residuals r = y - f and the Jacobian of f with respect to theta.
void linearise(const Eigen::VectorXd& inertial, const Eigen::VectorXd& friction,
               const Vector3& theta, Eigen::VectorXd& residual, Eigen::MatrixXd& jacobian) {
  const MuIParameters p = fromTheta(theta);
  for (Eigen::Index i = 0; i < inertial.size(); ++i) {
    const double g = inertial[i] / (inertial[i] + p.inertialScale);
    residual[i] = friction[i] - evaluateMuI(p, inertial[i]);
    jacobian(i, 0) = 1.0 - g;
    jacobian(i, 1) = g;
    // d f / d ln I0 = I0 * d f / d I0 = -(m_2 - m_s) I I0 / (I + I0)^2.
    jacobian(i, 2) = -(p.limitFriction - p.staticFriction) * g * (1.0 - g);
  }
}

// For a fixed I0 the law is linear in (m_s, m_2): scan I0 and keep the best linear solution.
Vector3 initialGuess(const Eigen::VectorXd& inertial, const Eigen::VectorXd& friction) {
  const double lo = std::log(inertial.minCoeff()) - std::log(100.0);
  const double hi = std::log(inertial.maxCoeff()) + std::log(100.0);
  constexpr int trials = 121;
  Vector3 best(friction.minCoeff(), friction.maxCoeff(), 0.5 * (lo + hi));
  double bestSsr = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd design(inertial.size(), 2);
  for (int t = 0; t < trials; ++t) {
    const double logScale = lo + (hi - lo) * t / (trials - 1);
    const double scale = std::exp(logScale);
    for (Eigen::Index i = 0; i < inertial.size(); ++i) {
      const double g = inertial[i] / (inertial[i] + scale);
      design(i, 0) = 1.0 - g;
      design(i, 1) = g;
    }
    LeastSquaresSolution solution;
    try {
      solution = solveLeastSquares(design, friction);
    } catch (const std::invalid_argument&) {
      continue; // all g equal at this I0: it cannot separate m_s from m_2
    }
    if (solution.weightedSsr < bestSsr) {
      bestSsr = solution.weightedSsr;
      best = Vector3(solution.coefficients[0], solution.coefficients[1], logScale);
    }
  }
  return best;
}

} // namespace

MuIFit fitMuI(const std::vector<double>& inertial, const std::vector<double>& friction,
              const MuIFitOptions& options) {
  const std::size_t n = inertial.size();
  if (friction.size() != n)
    throw std::invalid_argument("mu(I) fit: I and m differ in length");
  if (n < 3)
    throw std::invalid_argument("mu(I) fit: needs at least 3 points, got " + std::to_string(n));
  Eigen::VectorXd x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(inertial[i] > 0.0) || !std::isfinite(inertial[i]) || !std::isfinite(friction[i]))
      throw std::invalid_argument("mu(I) fit: I must be finite and > 0 and m finite");
    x[static_cast<Eigen::Index>(i)] = inertial[i];
    y[static_cast<Eigen::Index>(i)] = friction[i];
  }

  Vector3 theta = initialGuess(x, y);
  Eigen::VectorXd residual(n);
  Eigen::MatrixXd jacobian(n, 3);
  double ssr = sumOfSquares(x, y, theta);
  double lambda = 1e-3;
  MuIFit fit;
  for (fit.iterations = 0; fit.iterations < options.maxIterations; ++fit.iterations) {
    linearise(x, y, theta, residual, jacobian);
    const Matrix3 jtj = jacobian.transpose() * jacobian;
    const Vector3 jtr = jacobian.transpose() * residual;
    if (ssr == 0.0 || jtr.cwiseAbs().maxCoeff() == 0.0) {
      fit.converged = true;
      break;
    }
    bool improved = false;
    Vector3 step = Vector3::Zero();
    // Marquardt's scaling: damp each parameter by its own curvature.
    while (lambda < 1e16) {
      Matrix3 damped = jtj;
      damped.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-300);
      step = damped.ldlt().solve(jtr);
      const double trialSsr = sumOfSquares(x, y, theta + step);
      if (std::isfinite(trialSsr) && trialSsr <= ssr) {
        improved = true;
        theta += step;
        ssr = trialSsr;
        lambda = std::max(lambda / 10.0, 1e-12);
        break;
      }
      lambda *= 10.0;
    }
    const double scale = theta.cwiseAbs().maxCoeff() + 1.0;
    if (!improved || step.cwiseAbs().maxCoeff() <= options.relativeTolerance * scale) {
      fit.converged = true;
      ++fit.iterations;
      break;
    }
  }

  fit.parameters = fromTheta(theta);
  linearise(x, y, theta, residual, jacobian);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  fit.standardErrors = {nan, nan, nan};
  if (n > 3) {
    const Matrix3 jtj = jacobian.transpose() * jacobian;
    const Eigen::FullPivLU<Matrix3> lu(jtj);
    if (lu.isInvertible()) {
      const Matrix3 covariance = lu.inverse() * (ssr / static_cast<double>(n - 3));
      fit.standardErrors.staticFriction = std::sqrt(covariance(0, 0));
      fit.standardErrors.limitFriction = std::sqrt(covariance(1, 1));
      fit.standardErrors.inertialScale = fit.parameters.inertialScale * std::sqrt(covariance(2, 2));
    }
  }
  std::vector<double> predicted(n);
  for (std::size_t i = 0; i < n; ++i)
    predicted[i] = evaluateMuI(fit.parameters, inertial[i]);
  fit.quality = assessFit(friction, predicted);
  return fit;
}

} // namespace hikiln::calibration
