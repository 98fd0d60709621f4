// Kramers-Croockewit bed-depth profile: validation.md's worked example (uniform depth and the
// profile from a 5 mm discharge depth), Saeman's flow at the uniform depth, the horizontal kiln,
// and bad parameters.
#include "drivers/cfd/KramersCroockewit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace {
using hikiln::cfd::KramersCroockewit;
constexpr double pi = 3.14159265358979323846;
constexpr double degree = pi / 180.0;

// validation.md: R = 0.2 m, 3 rpm, alpha = 2 deg, beta = 35 deg, q_v = 0.1 m3/h.
KramersCroockewit smallKiln() {
  KramersCroockewit kc;
  kc.radius = 0.2;
  kc.revolutionsPerSecond = 3.0 / 60.0;
  kc.slope = 2.0 * degree;
  kc.reposeAngle = 35.0 * degree;
  kc.feed = 0.1 / 3600.0;
  return kc;
}

TEST(KramersCroockewit, UniformDepthOfTheWorkedExample) {
  const KramersCroockewit kc = smallKiln();
  const double h = kc.uniformDepth();
  EXPECT_NEAR(h, 0.0477, 5e-5);
  EXPECT_NEAR(kc.depthGradient(h), 0.0, 1e-12);
  // Saeman's flow with dh/dx = 0 at that depth carries the feed
  const double s = h / kc.radius;
  const double saeman = 4.0 / 3.0 * pi * kc.revolutionsPerSecond * std::pow(kc.radius, 3) *
                        std::pow(2.0 * s - s * s, 1.5) * std::tan(kc.slope) /
                        std::sin(kc.reposeAngle);
  EXPECT_NEAR(saeman / kc.feed, 1.0, 1e-10);
}

TEST(KramersCroockewit, ProfileOfTheWorkedExample) {
  const KramersCroockewit kc = smallKiln();
  const std::vector<double> h = kc.profile(0.0, 0.005, {1.0, 2.0, 3.0, 4.0});
  const double expected[] = {0.0423, 0.0462, 0.0472, 0.0476};
  for (int n = 0; n < 4; ++n) {
    EXPECT_NEAR(h[n], expected[n], 5e-5) << "z = " << n + 1 << " m";
  }
  // the integration has converged: a step ten times finer moves nothing visible
  const std::vector<double> fine = kc.profile(0.0, 0.005, {1.0, 2.0, 3.0, 4.0}, 1e-4);
  for (int n = 0; n < 4; ++n) {
    EXPECT_NEAR(fine[n], h[n], 1e-9);
  }
}

TEST(KramersCroockewit, HorizontalKilnDeepensTowardsTheInlet) {
  KramersCroockewit kc = smallKiln();
  kc.slope = 0.0;
  EXPECT_TRUE(std::isinf(kc.uniformDepth()));
  const std::vector<double> h = kc.profile(0.0, 0.04, {0.5, 1.0, 2.0});
  EXPECT_GT(h[0], 0.04);
  EXPECT_GT(h[1], h[0]);
  EXPECT_GT(h[2], h[1]);
  // a dam raises the whole profile
  const std::vector<double> dammed = kc.profile(0.0, 0.06, {0.5, 1.0, 2.0});
  for (int n = 0; n < 3; ++n) {
    EXPECT_GT(dammed[n], h[n]);
  }
}

TEST(KramersCroockewit, MoreFeedThanTheKilnCarriesHasNoUniformDepth) {
  KramersCroockewit kc = smallKiln();
  kc.feed = 100.0 / 3600.0;
  EXPECT_TRUE(std::isinf(kc.uniformDepth()));
}

TEST(KramersCroockewit, BadParametersAreNamed) {
  KramersCroockewit kc = smallKiln();
  kc.reposeAngle = 0.0;
  try {
    kc.uniformDepth();
    FAIL() << "no error";
  } catch (std::invalid_argument const& e) {
    EXPECT_NE(std::string(e.what()).find("reposeAngle"), std::string::npos) << e.what();
  }
  kc = smallKiln();
  EXPECT_THROW(kc.profile(0.0, 0.5, {1.0}), std::invalid_argument);  // deeper than 2R
  EXPECT_THROW(kc.profile(1.0, 0.01, {0.5}), std::invalid_argument); // behind the start
}

} // namespace
