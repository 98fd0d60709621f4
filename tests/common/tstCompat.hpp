// Every wrapper of kernels/common/Compat.hpp, evaluated inside a kernel on TEST_EXECSPACE and
// compared with the C++ standard library on the host.
#include "kernels/common/Compat.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

constexpr int numResults = 26;

// Kernels live in free functions: CUDA extended lambdas may not sit in a gtest TestBody (private).
Kokkos::View<double*, TEST_EXECSPACE::memory_space> evaluateWrappers(double x, double y) {
  using space = TEST_EXECSPACE;
  Kokkos::View<double*, space::memory_space> out("hikiln::test::compat", numResults);
  Kokkos::parallel_for(
      "hikiln::test::compat_math", Kokkos::RangePolicy<space>(space(), 0, 1), KOKKOS_LAMBDA(int) {
        namespace m = hikiln::math;
        out(0) = m::fabs(-x);
        out(1) = m::sqrt(y);
        out(2) = m::cbrt(y);
        out(3) = m::exp(x);
        out(4) = m::log(y);
        out(5) = m::sin(x);
        out(6) = m::cos(x);
        out(7) = m::tan(x);
        out(8) = m::asin(x);
        out(9) = m::acos(x);
        out(10) = m::atan(x);
        out(11) = m::erf(x);
        out(12) = m::floor(y);
        out(13) = m::ceil(y);
        out(14) = m::isfinite(x / (y - y)) ? 1.0 : 0.0;
        out(15) = m::isnan(0.0 / (x - x)) ? 1.0 : 0.0;
        out(16) = m::fmin(x, y);
        out(17) = m::fmax(x, y);
        out(18) = m::pow(y, x);
        out(19) = m::atan2(x, -y);
        out(20) = m::hypot(x, y);
        out(21) = m::fmod(y, x);
        out(22) = m::min(3, -4);
        out(23) = m::max(3.5, -4.0);
        out(24) = m::clamp(7.0, 0.0, 2.0);
        out(25) = hikiln::constants::pi;
      });
  return out;
}

TEST(TEST_CATEGORY, compat_math_wrappers_match_std) {
  const double x = 0.37, y = 1.9;
  auto out = evaluateWrappers(x, y);
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, out);
  const double expected[numResults] = {0.37,
                                       std::sqrt(y),
                                       std::cbrt(y),
                                       std::exp(x),
                                       std::log(y),
                                       std::sin(x),
                                       std::cos(x),
                                       std::tan(x),
                                       std::asin(x),
                                       std::acos(x),
                                       std::atan(x),
                                       std::erf(x),
                                       1.0,
                                       2.0,
                                       0.0,
                                       1.0,
                                       x,
                                       y,
                                       std::pow(y, x),
                                       std::atan2(x, -y),
                                       std::hypot(x, y),
                                       std::fmod(y, x),
                                       -4.0,
                                       3.5,
                                       2.0,
                                       std::acos(-1.0)};
  for (int i = 0; i < numResults; ++i)
    EXPECT_NEAR(h(i), expected[i], 1e-14) << "result " << i;
}

TEST(TEST_CATEGORY, compat_scoped_region_and_version) {
  { hikiln::ScopedRegion region("hikiln::test::region"); }
  const std::string v = hikiln::kokkosVersionString();
  EXPECT_EQ(v.substr(0, v.find('.')), std::to_string(KOKKOS_VERSION / 10000));
  EXPECT_GE(KOKKOS_VERSION, 30400);
}

} // namespace
