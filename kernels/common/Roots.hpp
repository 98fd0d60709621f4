#pragma once
/// \file Roots.hpp
/// \brief x^(1/3) and x^(1/5) without library calls on the host. The blocky narrow phase takes two
/// such roots per support evaluation; glibc's cbrt spends a third of its time in its frexp and
/// scalbn calls and pow(x, 0.2) is dearer still (docs/blocky-particles.md, Performance). Device
/// code keeps the library functions, which are fast there.

#include "kernels/common/Compat.hpp"

#include <cfloat>
#include <cstdint>
#include <cstring>

namespace hikiln::math {

namespace detail {

/// \brief The degree-9 polynomial with coefficients c[0..9] at s, by Estrin's scheme (short
/// dependency chains: the roots sit on the narrow phase's critical path).
KOKKOS_FORCEINLINE_FUNCTION double polynomial9(const double* c, double s) {
  const double s2 = s * s, s4 = s2 * s2;
  return (c[0] + c[1] * s + (c[2] + c[3] * s) * s2) +
         (c[4] + c[5] * s + (c[6] + c[7] * s) * s2) * s4 + (c[8] + c[9] * s) * s4 * s4;
}

/// \brief Degree-9 fits in Chebyshev nodes, in powers of s = m - 3/2, on m in [1, 2]: root[] of
/// m^(1/K) (6.8e-10 relative for K = 3, 6.1e-10 for 5) and slope[] of m^(-(K-1)/K), the inverse of
/// the derivative of y^K over K (1.6e-8, 2.7e-8).
template <int K> struct RootFit;
template <> struct RootFit<3> {
  static constexpr double root[10] = {
      1.144714241985577,      0.2543809446640395,   -0.05652898596029491,   0.020936554768939634,
      -0.009308746779927476,  0.004552479321678461, -0.0023200979581070916, 0.001243921936269883,
      -0.0008759677995882716, 0.0005120310813291812};
  static constexpr double slope[10] = {
      0.7631428399362498,   -0.3391746325131185,  0.18842804186202028,  -0.11165908926294695,
      0.0683100151974783,   -0.04253241462401034, 0.025951931439989973, -0.01632592256767063,
      0.014214391190737523, -0.00939461121371235};
};
template <> struct RootFit<5> {
  static constexpr double root[10] = {
      1.0844717706894214,     0.14459623786086612,   -0.038558895676941034,  0.015423463926940358,
      -0.007200851250692333,  0.0036497898536137718, -0.0019103253624319473, 0.001047981714473018,
      -0.0007594756701100117, 0.00045168930249132937};
  static constexpr double slope[10] = {
      0.722981198307664,   -0.3855900276514966,   0.23135051837334053, -0.14394848854818987,
      0.09127931904153647, -0.058461173715924505, 0.03642121746213767, -0.023360890018932278,
      0.02091605803896837, -0.014036276299908805};
};

/// \brief 2^(r/K) for r = 0 .. K-1, correctly rounded.
template <int K> inline double twoToThe(int r);
template <> inline double twoToThe<3>(int r) {
  constexpr double table[3] = {1.0, 1.2599210498948732, 1.5874010519681996};
  return table[r];
}
template <> inline double twoToThe<5>(int r) {
  constexpr double table[5] = {1.0, 1.148698354997035, 1.3195079107728942, 1.515716566510398,
                               1.7411011265922482};
  return table[r];
}

/// \brief wholeRoot() on the host for positive normal x: x = m 2^e with m in [1, 2) and
/// e = K q + r, so x^(1/K) = m^(1/K) 2^(r/K) 2^q. m^(1/K) is RootFit's y, corrected by one Newton
/// step for y^K = m with the fitted inverse slope, y + (m - y^K) m^(-(K-1)/K) / K, which squares
/// y's error: 2.3 ulp at most (tests/common/tstCompat.hpp checks 3), with no division.
template <int K> [[gnu::always_inline]] inline double wholeRootOnHost(double x) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  const int e = static_cast<int>(bits >> 52) - 1023;
  const std::uint64_t mantissa = (bits & 0x000FFFFFFFFFFFFFull) | 0x3FF0000000000000ull;
  double m = 0.0;
  std::memcpy(&m, &mantissa, sizeof m);
  constexpr int offset = K * (1022 / K + 1); // a multiple of K above -e
  const int q = (e + offset) / K - offset / K, r = (e + offset) % K;
  const double y = polynomial9(RootFit<K>::root, m - 1.5);
  const double w = polynomial9(RootFit<K>::slope, m - 1.5);
  const double y2 = y * y;
  const double yK = K == 3 ? y2 * y : y2 * y2 * y;
  const double root = y + (m - yK) * w * (1.0 / K);
  const std::uint64_t scaleBits = static_cast<std::uint64_t>(q + 1023) << 52;
  double scale = 0.0;
  std::memcpy(&scale, &scaleBits, sizeof scale);
  return root * twoToThe<K>(r) * scale;
}

} // namespace detail

/// \brief x^(1/K) for x >= 0, K = 3 or 5: the library's cbrt or pow on devices, and for zero,
/// subnormal, infinite or NaN x; detail::wholeRootOnHost() otherwise.
template <int K> KOKKOS_FORCEINLINE_FUNCTION double wholeRoot(double x) {
  static_assert(K == 3 || K == 5, "wholeRoot: K = 3 or 5");
#if defined(__CUDA_ARCH__) || defined(__HIP_DEVICE_COMPILE__)
  return K == 3 ? math::cbrt(x) : math::pow(x, 0.2);
#else
  if (!(x >= DBL_MIN && x <= DBL_MAX)) {
    return K == 3 ? math::cbrt(x) : math::pow(x, 0.2);
  }
  return detail::wholeRootOnHost<K>(x);
#endif
}

} // namespace hikiln::math
