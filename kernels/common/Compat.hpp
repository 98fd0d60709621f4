#pragma once
/// \file Compat.hpp
/// \brief The one place that knows which Kokkos version is in use (3.4 .. 4.x). Everything else in
/// hikiln calls these wrappers instead of version-dependent Kokkos names.

#include <Kokkos_Core.hpp>

#include <cstdio>
#include <string>

#if !defined(KOKKOS_VERSION) || KOKKOS_VERSION < 30400
#error "hikiln needs Kokkos 3.4 or newer"
#endif

namespace hikiln {

/// \brief Mathematical functions usable on every backend (Kokkos::Experimental:: before 3.7,
/// Kokkos:: after).
namespace math {
#if KOKKOS_VERSION >= 30700
namespace kmath = ::Kokkos;
#else
namespace kmath = ::Kokkos::Experimental;
#endif
#define HIKILN_COMPAT_UNARY(name)                                                                  \
  template <class T> KOKKOS_INLINE_FUNCTION auto name(T x) {                                       \
    return kmath::name(x);                                                                         \
  }
#define HIKILN_COMPAT_BINARY(name)                                                                 \
  template <class T> KOKKOS_INLINE_FUNCTION auto name(T x, T y) {                                  \
    return kmath::name(x, y);                                                                      \
  }
HIKILN_COMPAT_UNARY(fabs)
HIKILN_COMPAT_UNARY(sqrt)
HIKILN_COMPAT_UNARY(cbrt)
HIKILN_COMPAT_UNARY(exp)
HIKILN_COMPAT_UNARY(log)
HIKILN_COMPAT_UNARY(sin)
HIKILN_COMPAT_UNARY(cos)
HIKILN_COMPAT_UNARY(tan)
HIKILN_COMPAT_UNARY(asin)
HIKILN_COMPAT_UNARY(acos)
HIKILN_COMPAT_UNARY(atan)
HIKILN_COMPAT_UNARY(erf)
HIKILN_COMPAT_UNARY(floor)
HIKILN_COMPAT_UNARY(ceil)
HIKILN_COMPAT_UNARY(isfinite)
HIKILN_COMPAT_UNARY(isnan)
HIKILN_COMPAT_BINARY(pow)
HIKILN_COMPAT_BINARY(atan2)
HIKILN_COMPAT_BINARY(hypot)
HIKILN_COMPAT_BINARY(fmod)
#undef HIKILN_COMPAT_UNARY
#undef HIKILN_COMPAT_BINARY

/// \brief fmin / fmax written out: on x86-64 std::fmin and std::fmax are calls into libm (GCC
/// inlines them only under -ffinite-math-only), which kept the limiter and rheology loops from
/// being inlined and vectorised. Same results as glibc's on x86-64 (test
/// compat_fmin_fmax_bitwise_as_libm_on_specials): the other argument where one is NaN, else the
/// first argument unless the second is strictly smaller (larger), so x for +0 / -0.
/// Written as a select of the plain minimum (maximum) and a NaN test of x, which GCC compiles to
/// minsd / maxsd and a cmov instead of a compare and a branch per call: the FCT limiter, with
/// its 4 x 4 of these a cell on data-dependent signs, took 1.1 instead of 1.7 ms a call
/// (perf/README.md, "Per-step kernels with a compile-time axis").
template <class T> KOKKOS_INLINE_FUNCTION constexpr T fmin(T x, T y) {
  const T smaller = y < x ? y : x;
  return x != x ? y : smaller;
}
template <class T> KOKKOS_INLINE_FUNCTION constexpr T fmax(T x, T y) {
  const T larger = y > x ? y : x;
  return x != x ? y : larger;
}

/// \brief Smaller of two values of any ordered type (Kokkos::min is 3.7+ and moved namespaces).
template <class T> KOKKOS_INLINE_FUNCTION constexpr T min(T a, T b) {
  return b < a ? b : a;
}
/// \brief Larger of two values of any ordered type.
template <class T> KOKKOS_INLINE_FUNCTION constexpr T max(T a, T b) {
  return a < b ? b : a;
}
/// \brief x limited to [lo, hi].
template <class T> KOKKOS_INLINE_FUNCTION constexpr T clamp(T x, T lo, T hi) {
  return x < lo ? lo : (hi < x ? hi : x);
}
} // namespace math

/// \brief Physical and mathematical constants (Kokkos::numbers is 4.0+).
namespace constants {
inline constexpr double pi = 3.14159265358979323846;
inline constexpr double stefanBoltzmann = 5.670374419e-8; ///< W m^-2 K^-4
inline constexpr double standardGravity = 9.80665;        ///< m s^-2
} // namespace constants

/// \brief Profiling region that closes itself (Kokkos::Profiling::ScopedRegion is 4.1+).
class ScopedRegion {
public:
  /// \brief Opens the region "name" for Kokkos tools.
  explicit ScopedRegion(const char* name) { Kokkos::Profiling::pushRegion(name); }
  ~ScopedRegion() { Kokkos::Profiling::popRegion(); }
  ScopedRegion(const ScopedRegion&) = delete;
  ScopedRegion& operator=(const ScopedRegion&) = delete;
};

/// \brief Kokkos version as "major.minor.patch".
inline std::string kokkosVersionString() {
  const int v = KOKKOS_VERSION;
  char text[32];
  std::snprintf(text, sizeof(text), "%d.%d.%02d", v / 10000, (v / 100) % 100, v % 100);
  return text;
}

/// \brief Command-line argument that sets the host backend's thread count at Kokkos
/// initialisation (the option was renamed in 4.0). Setting OMP_NUM_THREADS from inside the
/// program is too late: the OpenMP runtime reads it when the library loads.
inline std::string kokkosThreadsArgument(int threads) {
#if KOKKOS_VERSION >= 40000
  return "--kokkos-num-threads=" + std::to_string(threads);
#else
  return "--kokkos-threads=" + std::to_string(threads);
#endif
}

} // namespace hikiln

/// \brief printf usable inside kernels on every backend (Kokkos::printf is 4.2+).
#if KOKKOS_VERSION >= 40200
#define HIKILN_DEVICE_PRINTF(...) ::Kokkos::printf(__VA_ARGS__)
#else
#define HIKILN_DEVICE_PRINTF(...) ::printf(__VA_ARGS__)
#endif
