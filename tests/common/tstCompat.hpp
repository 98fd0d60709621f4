// Every wrapper of kernels/common/Compat.hpp, evaluated inside a kernel on TEST_EXECSPACE and
// compared with the C++ standard library on the host; math::wholeRoot() (Roots.hpp) against
// long double roots.
#include "kernels/common/Compat.hpp"
#include "kernels/common/Roots.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

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

// x^(1/3) and x^(1/5) of n values log-uniform over the normal doubles, in a kernel.
// (the host copy keeps the device View's layout: LayoutLeft on CUDA)
Kokkos::View<double**, TEST_EXECSPACE::array_layout, Kokkos::HostSpace> wholeRootsInKernel(int n) {
  using space = TEST_EXECSPACE;
  Kokkos::View<double**, space::memory_space> out("hikiln::test::roots", n, 3);
  Kokkos::parallel_for(
      "hikiln::test::whole_roots", Kokkos::RangePolicy<space>(space(), 0, n), KOKKOS_LAMBDA(int i) {
        const double x = hikiln::math::exp(-700.0 + 1400.0 * (i + 0.5) / n);
        out(i, 0) = x;
        out(i, 1) = hikiln::math::wholeRoot<3>(x);
        out(i, 2) = hikiln::math::wholeRoot<5>(x);
      });
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, out);
}

// Error of a root of x in units of the last place of the exact root (the spacing above it).
template <int K> double rootErrorInUlps(double x, double root) {
  const long double exact =
      K == 3 ? std::cbrt(static_cast<long double>(x)) : std::pow(static_cast<long double>(x), 0.2L);
  const double ulp =
      std::nextafter(static_cast<double>(exact), DBL_MAX) - static_cast<double>(exact);
  return static_cast<double>(std::fabs(root - exact)) / ulp;
}

TEST(TEST_CATEGORY, compat_whole_roots_within_three_ulps) {
  // On the host the roots are a polynomial and a Newton step (no library call); the blocky
  // narrow phase takes two per support evaluation, so they must be as good as cbrt and pow.
  double worst3 = 0.0, worst5 = 0.0;
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> exponent(-708.0, 709.0);
  for (int i = 0; i < 200000; ++i) {
    const double x = std::exp(exponent(gen));
    worst3 = std::max(worst3, rootErrorInUlps<3>(x, hikiln::math::wholeRoot<3>(x)));
    worst5 = std::max(worst5, rootErrorInUlps<5>(x, hikiln::math::wholeRoot<5>(x)));
  }
  // every mantissa interval's ends and the exponents' residues modulo 3 and 5
  for (int e = -1022; e <= 1023; ++e) {
    for (const double m : {1.0, 1.0 + DBL_EPSILON, 1.5, 2.0 - DBL_EPSILON}) {
      const double x = std::ldexp(m, e);
      worst3 = std::max(worst3, rootErrorInUlps<3>(x, hikiln::math::wholeRoot<3>(x)));
      worst5 = std::max(worst5, rootErrorInUlps<5>(x, hikiln::math::wholeRoot<5>(x)));
    }
  }
  double worstLibrary = 0.0; // for scale: the C library's cbrt on the same values
  for (int e = -1022; e <= 1023; ++e) {
    for (const double m : {1.0, 1.0 + DBL_EPSILON, 1.5, 2.0 - DBL_EPSILON}) {
      const double x = std::ldexp(m, e);
      worstLibrary = std::max(worstLibrary, rootErrorInUlps<3>(x, std::cbrt(x)));
    }
  }
  std::printf("whole roots on the host: largest error %.2f ulp (cube), %.2f ulp (fifth); "
              "std::cbrt %.2f ulp on the same powers of two\n",
              worst3, worst5, worstLibrary);
  EXPECT_LE(worst3, 3.0);
  EXPECT_LE(worst5, 3.0);
  // exact cubes and fifth powers stay exact; zero, subnormals and specials take the library path
  EXPECT_EQ(hikiln::math::wholeRoot<3>(1.0), 1.0);
  EXPECT_EQ(hikiln::math::wholeRoot<3>(27.0), 3.0);
  EXPECT_EQ(hikiln::math::wholeRoot<3>(0.125), 0.5);
  EXPECT_EQ(hikiln::math::wholeRoot<5>(1.0), 1.0);
  EXPECT_EQ(hikiln::math::wholeRoot<5>(32.0), 2.0);
  EXPECT_EQ(hikiln::math::wholeRoot<3>(0.0), 0.0);
  EXPECT_TRUE(std::isnan(hikiln::math::wholeRoot<5>(std::nan(""))));
  EXPECT_EQ(hikiln::math::wholeRoot<5>(0.0), 0.0);
  EXPECT_NEAR(hikiln::math::wholeRoot<3>(1e-310), std::cbrt(1e-310), 1e-118);
  EXPECT_TRUE(std::isnan(hikiln::math::wholeRoot<3>(std::nan(""))));
  EXPECT_TRUE(std::isinf(hikiln::math::wholeRoot<3>(HUGE_VAL)));

  // the same inside a kernel: on a device the library's cbrt, and pow(x, 0.2), whose exponent is
  // 1/5 only to 1.1e-17, so that its root is off by up to that times |ln x|
  const auto h = wholeRootsInKernel(4096);
  for (int i = 0; i < static_cast<int>(h.extent(0)); ++i) {
    const double x = h(i, 0), fifth = std::pow(static_cast<long double>(x), 0.2L);
    EXPECT_LE(rootErrorInUlps<3>(x, h(i, 1)), 3.0) << x;
    EXPECT_LE(std::fabs(h(i, 2) - fifth) / fifth, 4.5e-16 + 1.2e-17 * std::fabs(std::log(x))) << x;
  }
}

TEST(TEST_CATEGORY, compat_fmin_fmax_bitwise_as_libm_on_specials) {
  // math::fmin / fmax are written out (Compat.hpp); on the host they must give the library's
  // bits for NaN arguments, infinities and equal values, and on x86-64 also the sign of a zero
  // from +0 and -0 (glibc returns the first argument; other libraries may choose otherwise,
  // which IEEE 754 allows). Volatile arguments keep the compiler from folding std::fmin / fmax.
  const double values[] = {0.0,       -0.0,         1.5,     -2.25,        HUGE_VAL,
                           -HUGE_VAL, std::nan(""), DBL_MIN, -DBL_TRUE_MIN};
  int checked = 0;
  for (const double vx : values) {
    for (const double vy : values) {
      volatile double x = vx, y = vy;
      const double got[2] = {hikiln::math::fmin(vx, vy), hikiln::math::fmax(vx, vy)};
      const double want[2] = {std::fmin(x, y), std::fmax(x, y)};
      for (int m = 0; m < 2; ++m) {
        if (std::isnan(want[m])) {
          EXPECT_TRUE(std::isnan(got[m])) << vx << " " << vy;
          continue;
        }
        EXPECT_EQ(got[m], want[m]) << m << ": " << vx << " " << vy;
#if defined(__x86_64__)
        EXPECT_EQ(std::signbit(got[m]), std::signbit(want[m])) << m << ": " << vx << " " << vy;
#endif
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 160); // 81 pairs x 2, less fmin and fmax of (NaN, NaN)
}

} // namespace
