#include "solvers/calibration/NewtonianTest.hpp"

#include <cmath>

namespace hikiln::calibration {

NewtonianTest testNewtonian(const std::vector<double>& strainRate,
                            const std::vector<double>& shearStress, double tolerance) {
  NewtonianTest test;
  test.fit = fitPowerLaw(strainRate, shearStress);
  test.tolerance = tolerance;
  test.newtonian = std::fabs(test.fit.exponent - 1.0) <= tolerance;
  return test;
}

} // namespace hikiln::calibration
