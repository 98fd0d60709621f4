#pragma once
/// \file StencilBodies.hpp
/// \brief The three things a solver does with a linear stencil, as bodies for SplitLoop.hpp:
/// apply (y = A x), residual (r = f - A x, returning r^2 for a norm) and the Gauss-Seidel update
/// of one unknown (x = (f + rest) / diag). The stencil S provides
///
///     field_type x;  int ghost, ghostZ;
///     template <unsigned Axes> void stencil(int i, int j, int k, double& diag, double& rest)
///     const;
///
/// with A x = diag x(i, j, k) - rest at the unknown (i, j, k) (CellOperator.hpp,
/// ViscousOperator.hpp).

#include <Kokkos_Core.hpp>

namespace hikiln::cfd {

/// \brief y = A x.
template <class S> struct StencilApply {
  S s;
  typename S::field_type y;
  template <unsigned Axes> KOKKOS_FORCEINLINE_FUNCTION double cell(int i, int j, int k) const {
    const int g = s.ghost, gz = s.ghostZ;
    double diag, rest;
    s.template stencil<Axes>(i, j, k, diag, rest);
    y(i + g, j + g, k + gz) = diag * s.x(i + g, j + g, k + gz) - rest;
    return 0.0;
  }
};

/// \brief r = f - A x; returns r^2.
template <class S> struct StencilResidual {
  S s;
  typename S::field_type f, r;
  template <unsigned Axes> KOKKOS_FORCEINLINE_FUNCTION double cell(int i, int j, int k) const {
    const int g = s.ghost, gz = s.ghostZ;
    double diag, rest;
    s.template stencil<Axes>(i, j, k, diag, rest);
    const double res = f(i + g, j + g, k + gz) - (diag * s.x(i + g, j + g, k + gz) - rest);
    r(i + g, j + g, k + gz) = res;
    return res * res;
  }
};

/// \brief x = (f + rest) / diag: solves the unknown's row with its neighbours fixed.
template <class S> struct StencilGaussSeidel {
  S s;
  typename S::field_type f;
  template <unsigned Axes> KOKKOS_FORCEINLINE_FUNCTION double cell(int i, int j, int k) const {
    const int g = s.ghost, gz = s.ghostZ;
    double diag, rest;
    s.template stencil<Axes>(i, j, k, diag, rest);
    s.x(i + g, j + g, k + gz) = (f(i + g, j + g, k + gz) + rest) / diag;
    return 0.0;
  }
};

} // namespace hikiln::cfd
