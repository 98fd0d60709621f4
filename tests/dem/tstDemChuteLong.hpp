// The chute of tstDemChute.hpp, larger and longer (label long): 30 d long, ~30 d deep, 600
// sqrt(d/g) to reach steady state and 2 x 200 sqrt(d/g) of averages. Same assertions, tighter where
// the longer averages allow.
#include "ChuteTestUtils.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;

TEST(TEST_CATEGORY, dem_chute_thick_steady_flow_has_bagnold_profile) {
  ChuteSpec spec;
  spec.angleDegrees = 22.0;
  spec.lengthDiameters = 30.0;
  spec.heightDiameters = 30.0;
  const test::ChuteResult r = test::runChute<space>(spec, 600.0, 200.0);
  const ChuteProfile& p = r.profile;
  const double d = spec.meanDiameter;
  const double scale = std::sqrt(spec.gravity * d);
  ASSERT_GT(p.height, 0.8 * spec.heightDiameters * d);
  ASSERT_LT(p.height, 1.2 * spec.heightDiameters * d);
  const double zMin = 3 * d, zMax = p.height - 4 * d;
  const ProfileFit bagnold = fitPowerProfile(p, 1.5, zMin, zMax);
  const ProfileFit best = fitBestExponent(p, zMin, zMax);
  const ProfileFit linear = fitPowerProfile(p, 1.0, zMin, zMax);
  const double spread = test::relativeSpread(p, zMin, zMax);
  std::cout << "thick chute: h = " << p.height / d << " d, bulk solid fraction "
            << p.bulkSolidFraction << " (relative spread " << spread << "), mean speed "
            << r.meanSpeedFirst / scale << " -> " << r.meanSpeedSecond / scale
            << " sqrt(g d); Bagnold R^2 " << bagnold.rSquared << ", linear R^2 " << linear.rSquared
            << ", best exponent " << best.exponent << " (" << best.points << " slabs)\n";
  EXPECT_GT(r.meanSpeedSecond, 2.0 * scale);
  EXPECT_NEAR(r.meanSpeedSecond / r.meanSpeedFirst, 1.0, 0.04);
  EXPECT_GT(bagnold.rSquared, 0.99);
  EXPECT_NEAR(best.exponent, 1.5, 0.2);
  EXPECT_LT(linear.rSquared, bagnold.rSquared);
  EXPECT_LT(spread, 0.02);
}

} // namespace
