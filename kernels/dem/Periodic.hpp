#pragma once
/// \file Periodic.hpp
/// \brief Optional periodic boundary in x (for chute flows): wrapping and minimum image.

#include <Kokkos_Core.hpp>

namespace hikiln::dem {

/// \brief Periodic boundary in x over [xlo, xlo + length); disabled by default.
struct PeriodicX {
  bool enabled = false;
  double xlo = 0.0;
  double length = 0.0;

  /// \brief Minimum-image x separation, exactly antisymmetric:
  /// minimumImage(-d) == -minimumImage(d).
  KOKKOS_INLINE_FUNCTION double minimumImage(double dx) const {
    if (!enabled) {
      return dx;
    }
    const double half = 0.5 * length;
    if (dx > half) {
      return dx - length;
    }
    if (dx < -half) {
      return dx + length;
    }
    return dx;
  }

  /// \brief x wrapped into [xlo, xlo + length) (for particles that moved less than one period).
  KOKKOS_INLINE_FUNCTION double wrap(double x) const {
    if (!enabled) {
      return x;
    }
    if (x >= xlo + length) {
      return x - length;
    }
    if (x < xlo) {
      return x + length;
    }
    return x;
  }
};

} // namespace hikiln::dem
