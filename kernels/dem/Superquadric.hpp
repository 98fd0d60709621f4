#pragma once
/// \file Superquadric.hpp
/// \brief 2D superquadric ("blocky") particle shapes |x/a|^N + |y/b|^N = 1 in the body frame:
/// inside-outside function, boundary points and normals, support function, and (host) bounding
/// radius, area, polar second moment and mass properties.
///
/// N = 2 is an ellipse (a disc when a = b); N = 3, 4, 6, 8 are increasingly square. The shape is
/// the unit ball of the norm ||(x/a, y/b)||_N, so its support function is the dual norm h(u) = ||(a
/// u_x, b u_y)||_M with 1/N + 1/M = 1 (closed form, used by the contact search).
///
/// Mass convention (2D): a blocky particle is a prism of the given thickness t, m = rho t A and
/// I = rho t J (J the polar second moment of the outline about its centre), which is
/// MassConvention::Disc for a circle. For a circle (N = 2, a = b) both conventions delegate to
/// particleMass()/particleInertia(), so the disc engine's values are reproduced exactly; the Sphere
/// convention has no blocky counterpart and is refused for other shapes.

#include "kernels/common/Compat.hpp"
#include "kernels/common/Roots.hpp"
#include "kernels/dem/ParticleArrays.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hikiln::dem {

/// \brief Outline |x/a|^n + |y/b|^n = 1 in the body frame (semi-axes a along body x, b along body
/// y).
struct SuperquadricShape {
  double a = 1.0; ///< semi-axis along the body x axis (m)
  double b = 1.0; ///< semi-axis along the body y axis (m)
  double n = 2.0; ///< blockiness index N >= 2
};

/// \brief Smallest and largest blockiness and the largest aspect ratio the contact search is
/// verified for (tstSuperquadricGeometry.hpp).
inline constexpr double minBlockiness = 2.0;
inline constexpr double maxBlockiness = 8.0;
inline constexpr double maxAspectRatio = 3.0;

/// \brief True for a circle (N = 2, a = b): contacts then use the disc engine's exact formulas.
KOKKOS_INLINE_FUNCTION bool isCircle(const SuperquadricShape& s) {
  return s.n == 2.0 && s.a == s.b;
}

/// \brief x^(1/k) for x >= 0, with cheap root forms for the orders blocky shapes need most
/// (k = 1 to 6 and 8; math::wholeRoot() for the third and fifth roots); pow otherwise.
KOKKOS_FORCEINLINE_FUNCTION double rootOfOrder(double x, double k) {
  if (k == 1.0) {
    return x;
  }
  if (k == 2.0) {
    return math::sqrt(x);
  }
  if (k == 3.0) {
    return math::wholeRoot<3>(x);
  }
  if (k == 4.0) {
    return math::sqrt(math::sqrt(x));
  }
  if (k == 5.0) {
    return math::wholeRoot<5>(x);
  }
  if (k == 6.0) {
    return math::sqrt(math::wholeRoot<3>(x));
  }
  if (k == 8.0) {
    return math::sqrt(math::sqrt(math::sqrt(x)));
  }
  return x > 0.0 ? math::pow(x, 1.0 / k) : 0.0;
}

/// \brief x^k for x >= 0, by products for the whole orders 1 to 7; pow otherwise.
KOKKOS_INLINE_FUNCTION double powerOfOrder(double x, double k) {
  if (k == 1.0) {
    return x;
  }
  if (k == 2.0) {
    return x * x;
  }
  if (k == 3.0) {
    return x * x * x;
  }
  const double x2 = x * x;
  if (k == 4.0) {
    return x2 * x2;
  }
  if (k == 5.0) {
    return x2 * x2 * x;
  }
  if (k == 6.0) {
    return x2 * x2 * x2;
  }
  if (k == 7.0) {
    return x2 * x2 * x2 * x;
  }
  return math::pow(x, k);
}

/// \brief Inside-outside function F = |x/a|^N + |y/b|^N - 1 at a body-frame point (< 0 inside).
KOKKOS_INLINE_FUNCTION double insideOutside(const SuperquadricShape& s, double x, double y) {
  return math::pow(math::fabs(x / s.a), s.n) + math::pow(math::fabs(y / s.b), s.n) - 1.0;
}

/// \brief Gradient of insideOutside() at a body-frame point.
KOKKOS_INLINE_FUNCTION void insideOutsideGradient(const SuperquadricShape& s, double x, double y,
                                                  double& gx, double& gy) {
  const double ux = math::fabs(x / s.a), uy = math::fabs(y / s.b);
  gx = s.n / s.a * math::pow(ux, s.n - 1.0) * (x < 0.0 ? -1.0 : 1.0);
  gy = s.n / s.b * math::pow(uy, s.n - 1.0) * (y < 0.0 ? -1.0 : 1.0);
}

/// \brief Body-frame boundary point for the parameter phi:
/// (a sgn(cos) |cos|^(2/N), b sgn(sin) |sin|^(2/N)).
KOKKOS_INLINE_FUNCTION void boundaryPoint(const SuperquadricShape& s, double phi, double& x,
                                          double& y) {
  const double c = math::cos(phi), sn = math::sin(phi);
  x = s.a * (c < 0.0 ? -1.0 : 1.0) * math::pow(math::fabs(c), 2.0 / s.n);
  y = s.b * (sn < 0.0 ? -1.0 : 1.0) * math::pow(math::fabs(sn), 2.0 / s.n);
}

/// \brief Unit outward normal (body frame) at boundaryPoint(phi).
KOKKOS_INLINE_FUNCTION void boundaryNormal(const SuperquadricShape& s, double phi, double& nx,
                                           double& ny) {
  const double c = math::cos(phi), sn = math::sin(phi);
  const double e = 2.0 * (s.n - 1.0) / s.n;
  nx = (c < 0.0 ? -1.0 : 1.0) * math::pow(math::fabs(c), e) / s.a;
  ny = (sn < 0.0 ? -1.0 : 1.0) * math::pow(math::fabs(sn), e) / s.b;
  const double len = math::sqrt(nx * nx + ny * ny);
  nx /= len;
  ny /= len;
}

/// \brief Support of a shape in a body-frame direction (u, v) (unit): h = max over the outline of
/// p . (u, v) and the point p that attains it.
struct Support {
  double h = 0.0;           ///< support value (m)
  double x = 0.0, y = 0.0;  ///< support point (m)
  double radius = 0.0;      ///< radius of curvature there (m), where asked for (supportPoint())
  double radiusSlope = 0.0; ///< its slope over the direction's angle (m / rad), where asked for
  /// t = min / max of (a |u|, b |v|) and its root r = t^(1/(N-1))
  /// (detail::UnitSupport), the variable in which the support is smooth next to a face centre
  double t = 0.0, r = 0.0;
};

namespace detail {

/// \brief The radius of curvature supportCurvature() gives a flat face's centre (m).
inline constexpr double flatRadius = 1e300;

/// \brief The support of the N-norm ball in the direction (U, V) >= 0 (not both 0) in two roots:
/// with big = max(U, V), t = min(U, V) / big in [0, 1], r = t^(1/(N-1)) and q = 1 + t r
/// = 1 + t^M in [1, 2], g = q^(1/N): h = big q / g, and the support point's coordinates are 1 / g
/// (along the bigger component) and r / g (along the smaller one), both in [0, 1].
struct UnitSupport {
  double h = 0.0;
  double pU = 0.0, pV = 0.0;                    ///< support point / (a, b), without signs
  double t = 0.0, r = 0.0, q = 1.0, invG = 1.0; ///< the roots' arguments and results
  bool uBig = true;
};

/// \brief q^(-1/N) for q in [1, 2] (the support's second root, unitSupport()): for N = 3, 4 and 6
/// a degree-9 fit in Chebyshev nodes in powers of s = q - 3/2 (2.3e-9 relative at most), then one
/// Newton step for z^-N = q, z <- z + z (1 - q z^N) / N, which squares that error: within 3 ulp,
/// with no root and no division. 1 / rootOfOrder() for other N.
KOKKOS_FORCEINLINE_FUNCTION double inverseRootOnOneTwo(double n, double q) {
  constexpr double fit3[10] = {0.8735804677870591,    -0.19412900292839008,  0.08627894871788673,
                               -0.044736694704773414, 0.024873179733175023,  -0.014378917188588315,
                               0.008302882754196902,  -0.004966772415384195, 0.00403162490376082,
                               -0.002562107275973898};
  constexpr double fit4[10] = {0.9036020055292137,    -0.1506003406531167,    0.06274975947860591,
                               -0.03137453849948809,  0.017006780412551704,   -0.009642089418471157,
                               0.005487478446304371,  -0.0032401490212262195, 0.0025842126865489963,
                               -0.0016258316398577942};
  constexpr double fit6[10] = {0.934655266249352,     -0.10385058871889852,   0.04038612786565816,
                               -0.019444981738455575, 0.01026941938420379,    -0.005707982490773124,
                               0.003200755278518444,  -0.0018651446681815134, 0.0014615605901295559,
                               -0.0009102232302861165};
  const double* c = n == 3.0 ? fit3 : n == 4.0 ? fit4 : n == 6.0 ? fit6 : nullptr;
  if (c == nullptr) {
    return 1.0 / rootOfOrder(q, n);
  }
  const double z = math::detail::polynomial9(c, q - 1.5);
  const double z2 = z * z, z3 = z2 * z;
  const double zN = n == 3.0 ? z3 : n == 4.0 ? z2 * z2 : z3 * z3;
  const double invN = n == 3.0 ? 1.0 / 3.0 : n == 4.0 ? 0.25 : 1.0 / 6.0;
  return z + z * (1.0 - q * zN) * invN;
}

/// \brief unitSupport() from its first root r = t^(1/(N-1)) (big = max(U, V), t = min / max).
KOKKOS_FORCEINLINE_FUNCTION UnitSupport unitSupportOfRoot(double n, double big, double t, double r,
                                                          bool uBig) {
  UnitSupport out;
  const double q = 1.0 + t * r;
  const double invG = inverseRootOnOneTwo(n, q);
  out.h = big * q * invG;
  out.pU = uBig ? invG : r * invG;
  out.pV = uBig ? r * invG : invG;
  out.t = t;
  out.r = r;
  out.q = q;
  out.invG = invG;
  out.uBig = uBig;
  return out;
}

/// \brief The N-norm ball's support in the direction (U, V) >= 0, not both 0 (UnitSupport).
KOKKOS_FORCEINLINE_FUNCTION UnitSupport unitSupport(double n, double U, double V) {
  const bool uBig = U >= V;
  const double big = uBig ? U : V;
  if (!(big > 0.0)) {
    return UnitSupport{};
  }
  const double t = (uBig ? V : U) / big;
  return unitSupportOfRoot(n, big, t, rootOfOrder(t, n - 1.0), uBig);
}

/// \brief Radius of curvature at a support point and its slope over the direction's angle.
struct SupportCurvature {
  double radius = 0.0; ///< rho (m)
  double slope = 0.0;  ///< d rho / d psi (m / rad); 0 at a face centre
};

/// \brief Radius of curvature of the outline (semi-axes a, b) at the support point of `unit`,
/// from its roots: with X, Y the support point over (a, b), the curvature of |x/a|^N + |y/b|^N = 1
/// is (N - 1) (X Y)^(N-2) / (a^2 b^2 (X^(2N-2) / a^2 + Y^(2N-2) / b^2)^(3/2)), which in the
/// roots is rho = A^2 B^2 (r / t) w^(3/2) / ((N - 1) g q), w = 1 / A^2 + t^2 / B^2, A the
/// semi-axis of the bigger component. Infinite at a face centre (t = 0) for N > 2 (returned as
/// flatRadius), the circle's radius for N = 2, a = b (tstSuperquadricGeometry.hpp checks it
/// against h + h''). Its slope over the direction's angle psi: with W = B^2 + t^2 A^2,
/// dt / dpsi = +-W / (A B) (tSign: + where t grows with psi) and
/// d ln rho / dt = -(N - 2) / ((N - 1) t) + 3 t A^2 / W - (N + 1) r / ((N - 1) q).
KOKKOS_INLINE_FUNCTION SupportCurvature supportCurvature(double n, double a, double b,
                                                         const UnitSupport& unit, double tSign) {
  const double A = unit.uBig ? a : b, B = unit.uBig ? b : a, t = unit.t, q = unit.q;
  // A^2 B^2 w^(3/2) = W^(3/2) / (A B) with W = A^2 B^2 w: one division
  const double W = B * B + t * t * (A * A);
  SupportCurvature out;
  if (n == 2.0) { // r / t = 1, and t may be 0
    const double inverse = 1.0 / (A * B * q);
    out.radius = W * math::sqrt(W) * unit.invG * inverse;
    out.slope = tSign * out.radius * inverse * 3.0 * t * (A * A - B * B);
    return out;
  }
  if (!(t > 0.0)) {
    out.radius = flatRadius;
    return out;
  }
  const double inverse = 1.0 / (t * A * B * (n - 1.0) * q); // 1 / (A B) = t (N - 1) q inverse
  out.radius = unit.r * W * math::sqrt(W) * unit.invG * inverse;
  out.slope =
      tSign * out.radius * inverse *
      (3.0 * t * t * (A * A) * (n - 1.0) * q - (n - 2.0) * W * q - (n + 1.0) * unit.r * W * t);
  return out;
}

/// \brief The support value and point (no radius) of `unit`, found for the body-frame direction
/// (u, v) of shape s.
KOKKOS_FORCEINLINE_FUNCTION Support supportOfUnit(const SuperquadricShape& s,
                                                  const UnitSupport& unit, double u, double v) {
  Support out;
  out.h = unit.h;
  out.x = s.a * unit.pU * (u < 0.0 ? -1.0 : 1.0);
  out.y = s.b * unit.pV * (v < 0.0 ? -1.0 : 1.0);
  out.t = unit.t;
  out.r = unit.r;
  return out;
}

} // namespace detail

/// \brief Support value only: h = (|a u|^M + |b v|^M)^(1/M), M = N/(N-1), written as
/// h = big (1 + t^M)^(1/M), t = small / big <= 1 (detail::unitSupport()): two roots, t^(1/(N-1))
/// (rootOfOrder()) and (1 + t^M)^(-1/N) (detail::inverseRootOnOneTwo()), neither a library call
/// on the host for N = 2, 3, 4, 6.
KOKKOS_INLINE_FUNCTION double supportValue(const SuperquadricShape& s, double u, double v) {
  return detail::unitSupport(s.n, s.a * math::fabs(u), s.b * math::fabs(v)).h;
}

/// \brief Support value and point: p = (a sgn(u) (U/h)^(1/(N-1)), b sgn(v) (V/h)^(1/(N-1))), which
/// lies on the outline and has the outward normal (u, v); from the same two roots as
/// supportValue(). WithRadius: also the radius of curvature there and its slope
/// (detail::supportCurvature()), h + h'' and h' + h''' of the support function over the
/// direction's angle.
template <bool WithRadius = false>
KOKKOS_INLINE_FUNCTION Support supportPoint(const SuperquadricShape& s, double u, double v) {
  const detail::UnitSupport unit =
      detail::unitSupport(s.n, s.a * math::fabs(u), s.b * math::fabs(v));
  Support out = detail::supportOfUnit(s, unit, u, v);
  if constexpr (WithRadius) {
    // t grows with the angle where the angle's smaller component grows: (u v >= 0) == uBig
    const detail::SupportCurvature k =
        detail::supportCurvature(s.n, s.a, s.b, unit, ((u * v >= 0.0) == unit.uBig) ? 1.0 : -1.0);
    out.radius = k.radius;
    out.radiusSlope = k.slope;
  }
  return out;
}

/// \brief The support point (value and point, no radius) in the body-frame direction (u, v)
/// whose root r = t^(1/(N-1)) (Support::r) is given instead of taken: next to a face centre the
/// point moves with r, not with the angle, and a search that steps in r (faceNewtonTarget() in
/// SuperquadricContact.hpp) ends on the point of its step's r. No root but the second
/// (detail::inverseRootOnOneTwo()); (u, v) gives the face and the signs.
KOKKOS_INLINE_FUNCTION Support supportAtRoot(const SuperquadricShape& s, double u, double v,
                                             double r) {
  const double U = s.a * math::fabs(u), V = s.b * math::fabs(v);
  const bool uBig = U >= V;
  const detail::UnitSupport unit =
      detail::unitSupportOfRoot(s.n, uBig ? U : V, powerOfOrder(r, s.n - 1.0), r, uBig);
  return detail::supportOfUnit(s, unit, u, v);
}

/// \brief An upper bound of supportValue() without roots, for separating-axis tests. With
/// U = a |u|, V = b |v|, big = max(U, V), small = min(U, V) and t = small / big, h = big f(t) with
/// f(t) = (1 + t^M)^(1/M) (detail::unitSupport()); f, a norm along a line, is convex, so below its
/// chord on [0, 1]: h <= big + (2^(1/M) - 1) small, 1/M = 1 - 1/N. Exact towards the face centres
/// (small = 0) and the corners (U = V), at most 8 % (N = 2) to 3 % (N = 8) above in between;
/// widened by 1e-15 against round-off. 2^(1/M) is a constant for N = 2, 3, 4, 6, 8.
KOKKOS_INLINE_FUNCTION double supportValueBound(const SuperquadricShape& s, double u, double v) {
  const double U = s.a * math::fabs(u), V = s.b * math::fabs(v);
  double corner = 0.0; // 2^(1 - 1/N), rounded up
  if (s.n == 2.0) {
    corner = 1.4142135623730952;
  } else if (s.n == 3.0) {
    corner = 1.5874010519681996;
  } else if (s.n == 4.0) {
    corner = 1.6817928305074292;
  } else if (s.n == 6.0) {
    corner = 1.7817974362806788;
  } else if (s.n == 8.0) {
    corner = 1.8340080864093427;
  } else {
    corner = math::pow(2.0, 1.0 - 1.0 / s.n) * (1.0 + 1e-15);
  }
  const bool uBig = U >= V;
  return ((uBig ? U : V) + (corner - 1.0) * (uBig ? V : U)) * (1.0 + 1e-15);
}

/// \brief Throws std::invalid_argument (naming `where`) unless N in [2, 8], a, b > 0 and the
/// aspect ratio max(a, b)/min(a, b) <= 3: the range the contact search is verified for.
inline void validateShape(const SuperquadricShape& s, const std::string& where) {
  if (!(s.n >= minBlockiness && s.n <= maxBlockiness)) {
    throw std::invalid_argument(where + ": blockiness " + std::to_string(s.n) + " outside [2, 8]");
  }
  if (!(s.a > 0.0) || !(s.b > 0.0)) {
    throw std::invalid_argument(where + ": semi-axes must be > 0");
  }
  const double ratio = s.a > s.b ? s.a / s.b : s.b / s.a;
  if (!(ratio <= maxAspectRatio * (1.0 + 1e-12))) {
    throw std::invalid_argument(where + ": aspect ratio " + std::to_string(ratio) +
                                " outside [1, 3]");
  }
}

/// \brief Radius of the smallest centred circle holding the outline, max |p| (host). Exact for
/// ellipses (max(a, b)); otherwise the maximum of |p(phi)| on the first quadrant by a 256-point
/// scan and a golden-section refinement (relative accuracy ~1e-15), widened by 1e-12 so that the
/// broad phase never misses a contact by round-off.
inline double boundingRadius(const SuperquadricShape& s) {
  if (s.n == 2.0) {
    return s.a > s.b ? s.a : s.b;
  }
  const auto radius2 = [&](double phi) {
    double x = 0.0, y = 0.0;
    boundaryPoint(s, phi, x, y);
    return x * x + y * y;
  };
  const int samples = 256;
  const double step = 0.5 * constants::pi / samples;
  int best = 0;
  for (int k = 1; k <= samples; ++k) {
    if (radius2(k * step) > radius2(best * step)) {
      best = k;
    }
  }
  double lo = std::max(0.0, (best - 1) * step),
         hi = std::min(0.5 * constants::pi, (best + 1) * step);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 80; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (radius2(m1) > radius2(m2)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  const double r2 = std::max({radius2(0.5 * (lo + hi)), s.a * s.a, s.b * s.b});
  return std::sqrt(r2) * (1.0 + 1e-12);
}

/// \brief Area of the outline, A = 4 a b Gamma(1 + 1/N)^2 / Gamma(1 + 2/N) (host, closed form).
inline double superquadricArea(const SuperquadricShape& s) {
  const double g = std::tgamma(1.0 + 1.0 / s.n);
  return 4.0 * s.a * s.b * g * g / std::tgamma(1.0 + 2.0 / s.n);
}

/// \brief Polar second moment of the area about the centre, J = int (x^2 + y^2) dA
/// = (4/N) B(3/N, 1 + 1/N) (a^3 b + a b^3) with the Beta function B (host, closed form; from
/// int x^2 dA = 4 a^3 b int_0^1 u^2 (1 - u^N)^(1/N) du and the substitution t = u^N).
inline double superquadricPolarMoment(const SuperquadricShape& s) {
  const double p = 3.0 / s.n, q = 1.0 + 1.0 / s.n;
  const double beta = std::tgamma(p) * std::tgamma(q) / std::tgamma(p + q);
  return 4.0 / s.n * beta * (s.a * s.a * s.a * s.b + s.a * s.b * s.b * s.b);
}

/// \brief Mass and moment of inertia of one particle.
struct MassProperties {
  double mass = 0.0;    ///< kg
  double inertia = 0.0; ///< kg m^2
};

/// \brief Mass properties of a shape of density rho as a prism of the given thickness (see the file
/// comment); circles delegate to the disc engine's functions under either convention.
inline MassProperties superquadricMassProperties(const SuperquadricShape& s, double density,
                                                 MassConvention convention, double thickness) {
  MassProperties out;
  if (isCircle(s)) {
    out.mass = particleMass(convention, s.a, density, thickness);
    out.inertia = particleInertia(convention, out.mass, s.a);
    return out;
  }
  if (convention != MassConvention::Disc) {
    throw std::invalid_argument("hikiln::dem::superquadricMassProperties: the sphere mass "
                                "convention has no blocky counterpart; use the disc (prism) "
                                "convention");
  }
  out.mass = density * thickness * superquadricArea(s);
  out.inertia = density * thickness * superquadricPolarMoment(s);
  return out;
}

} // namespace hikiln::dem
