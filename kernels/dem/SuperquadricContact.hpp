#pragma once
/// \file SuperquadricContact.hpp
/// \brief Narrow phase for 2D superquadric particles: overlap, unit normal and contact point of a
/// particle pair, of a particle inside the rotating drum shell and of a particle on a flat wall.
///
/// Pair method (minimum translational distance, no dynamic memory, fixed work bounds): for two
/// convex bodies A, B with centres x_A, x_B (d = x_B - x_A) the penetration along a unit direction
/// n is pen(n) = h_A(n) + h_B(-n) - d . n with the closed-form support functions h
/// (Superquadric.hpp); the overlap is min_n pen(n) and the contact normal its minimiser. Both
/// shapes are centrally symmetric, so pen(n) - pen(-n) = -2 d . n and the minimum lies on the half
/// circle around d/|d|: it is scanned at 15 angles 11.25 degrees apart, from d/|d| outwards (any
/// sample with pen <= 0 is a separating axis: no contact, the usual early exit, mostly at the
/// first sample; a root-free upper bound of pen, supportValueBound(), is tried first and decides
/// a clear gap without the exact value), then the root of the exact derivative
/// pen'(phi) = (s_A - s_B) . t (s the support points, t = perp(n)) within a sample spacing of the
/// best sample, downhill, is found by safeguarded Newton steps (refineNewton(), the second
/// derivative from the radii of curvature, below), until |pen'| is below 1e-12 of the shapes'
/// size, the bracket below 1e-13 rad or a Newton step short enough (at most
/// contactRefineIterations steps). At the root s_A - s_B is parallel to n, so the contact point,
/// the midpoint of s_A and s_B, lies on the line of action through both support points: the torques
/// are those of the potential k_n overlap^2 / 2 (energy consistent) and equal and opposite about it
/// (angular momentum kept). Accuracy: the overlap to round-off, the normal to ~1e-12 rad. On
/// near-flat faces (large N) the support point slides fast with the normal, ~|dphi|^(1/(N-1)), so
/// the contact point of a face-to-face contact is known to ~1 % of the face width at N = 8 only.
/// The scan can pick a local minimum that is not the global one when two are within its resolution
/// of each other: found in 0.2 % of 20000 random placements (N in [2, 8], aspect ratios in [1, 3],
/// overlaps up to 70 % of the size), never in those of them with overlaps below 5 % of the size.
/// Cold cost: 1-2 us per touching pair for N = 2, 3-7 us for N = 3-8 on one x86 core (the roots
/// of the support function dominate).
///
/// Cheap paths in front of the scan (superquadricPair()): the oriented bounding rectangles apart
/// (a superquadric with N >= 2 lies inside its a x b rectangle): no contact; a guess, the pair's
/// last separating axis or last contact normal, which the force kernel keeps per neighbour slot:
/// pen(guess) <= 0 is still a separating axis (no contact; the root-free bound first, then one
/// support evaluation per shape); a last normal (the force kernel turns it by the pair's mean
/// spin over the step: spunNormalGuess()) with pen > 0 starts a local search: safeguarded
/// Newton steps on pen' = 0 with the exact pen'' = rho_A + rho_B - pen (rho the radii of
/// curvature at the support points, from the same roots), taken in the support's root next to a
/// face centre, where the slope behaves like |x|^(1/(N-1)) (faceNewtonTarget()), bisection where
/// they overshoot, and the scan when no sign change lies within 0.5 rad. A Newton step in the
/// angle below contactExtrapolateStep is the last: it is taken without evaluating the supports
/// again, which follow it to third order (LastSupports::advance()), so a search from a normal a
/// step old takes one or two evaluations (docs/blocky-particles.md); so does a step in a flat
/// support's root below contactFaceExtrapolateStep, which ends on that root's point
/// (PairObjective::endAt()). A warm-started search
/// follows its basin of pen continuously; the cold scan takes the deepest sampled one. The
/// searches carry each angle with its direction (detail::Heading) and turn the direction by the
/// series of cos and sin for steps below 1e-2 rad, so most of their steps take no sincos.
///
/// Drum: overlap = max over the outline of |p| - R = max_n (x_c . n + h(n)) - R, found the same way
/// around x_c/|x_c|; the contact point is the particle's deepest point. Flat wall: the support
/// point against the wall normal (closed form).
///
/// Circles (N = 2, a = b) never come here in the force kernel: they use pairFrame()/drumFrame()
/// exactly as the disc engine does (blockyPairContact()).

#include <cfloat>

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ContactLaw.hpp"
#include "kernels/dem/Superquadric.hpp"
#include "kernels/dem/Walls.hpp"

namespace hikiln::dem {

/// \brief The scan samples phi0 + j pi / (2 M + 2) for |j| <= M = contactScanHalf (11.25 degrees).
inline constexpr int contactScanHalf = 7;
/// \brief Most refinement steps (safeguarded Newton).
inline constexpr int contactRefineIterations = 64;
/// \brief First step of a warm-started search away from the last normal where Newton gives none
/// (rad); such steps double up to contactWarmReach.
inline constexpr double contactWarmStep = 1e-4;
/// \brief Farthest a warm-started search looks for the slope's sign change before it scans (rad).
inline constexpr double contactWarmReach = 0.5;
/// \brief Refinement stops when the support points are aligned along n to this fraction of the
/// shapes' size...
inline constexpr double contactSlopeTolerance = 1e-12;
/// \brief ... or when the bracket of the normal angle is this narrow (rad), or a converging Newton
/// step this short...
inline constexpr double contactAngleTolerance = 1e-13;
/// \brief ... or, next to a face centre, a converging Newton step in the support's root this short
/// (the contact point moves with the root, not with the angle: faceNewtonTarget()).
inline constexpr double contactRootTolerance = 1e-10;
/// \brief A Newton step in the angle this short (rad) ends a search without a further
/// evaluation: the step, corrected by the third derivative, is taken and the support points
/// follow it to third order (LastSupports::advance()); the error after it, of order step^3, is
/// ~1e-11 rad. A warm search from the last DEM step's normal mostly turns by 1e-6 to 1e-4 rad,
/// so many end after the one evaluation at the guess (docs/blocky-particles.md).
inline constexpr double contactExtrapolateStep = 3e-5;
/// \brief The same next to a face centre, for a Newton step in the support's root
/// (faceNewtonTarget()) this short: the step is taken, the flat support's point is the one of
/// the step's root (supportAtRoot()), the other support follows the angle to third order, or,
/// when flat too, is evaluated there.
inline constexpr double contactFaceExtrapolateStep = 1e-5;

/// \brief Result of a narrow-phase test.
struct ContactGeometry {
  double nx = 0.0, ny = 0.0; ///< unit normal from the first body towards the other (or the wall)
  double overlap = 0.0;      ///< > 0 when touching (m)
  double angle = 0.0;        ///< pairs: angle of the normal, or of a separating axis (rad)
  bool axis = false;         ///< pairs: angle is set (also when not touching, see superquadricPair)
  double px = 0.0, py = 0.0; ///< contact point relative to the first body's centre (m)
};

/// \brief A body's x axis in world axes, (cos theta, sin theta) of its orientation theta.
struct BodyAxis {
  double c = 1.0, s = 0.0;
};

/// \brief The body axis of the orientation angle theta.
KOKKOS_INLINE_FUNCTION BodyAxis bodyAxis(double theta) {
  return BodyAxis{math::cos(theta), math::sin(theta)};
}

/// \brief A support in body axes turned to world axes (orientation (c, sn)).
KOKKOS_INLINE_FUNCTION Support toWorld(Support w, double c, double sn) {
  const double bx = w.x;
  w.x = c * bx - sn * w.y;
  w.y = sn * bx + c * w.y;
  return w;
}

/// \brief Support of a shape with orientation (cos, sin) in the world direction (nx, ny); the
/// point is relative to the shape's centre, in world axes (WithRadius: supportPoint()).
template <bool WithRadius = false>
KOKKOS_INLINE_FUNCTION Support worldSupport(const SuperquadricShape& s, double c, double sn,
                                            double nx, double ny) {
  return toWorld(supportPoint<WithRadius>(s, c * nx + sn * ny, -sn * nx + c * ny), c, sn);
}

/// \brief supportAtRoot() in the world direction (nx, ny).
KOKKOS_INLINE_FUNCTION Support worldSupportAtRoot(const SuperquadricShape& s, double c, double sn,
                                                  double nx, double ny, double r) {
  return toWorld(supportAtRoot(s, c * nx + sn * ny, -sn * nx + c * ny, r), c, sn);
}

/// \brief Support value only, in the world direction (nx, ny).
KOKKOS_INLINE_FUNCTION double worldSupportValue(const SuperquadricShape& s, double c, double sn,
                                                double nx, double ny) {
  return supportValue(s, c * nx + sn * ny, -sn * nx + c * ny);
}

/// \brief supportValueBound() in the world direction (nx, ny).
KOKKOS_INLINE_FUNCTION double worldSupportValueBound(const SuperquadricShape& s, double c,
                                                     double sn, double nx, double ny) {
  return supportValueBound(s, c * nx + sn * ny, -sn * nx + c * ny);
}

namespace detail {

/// \brief An angle and its unit direction, carried through a search so that its small turns need
/// no cos and sin (a sincos per evaluation was a tenth of a flowing drum's time).
struct Heading {
  double phi = 0.0, x = 1.0, y = 0.0;
};

/// \brief The heading of the angle phi.
KOKKOS_INLINE_FUNCTION Heading headingOf(double phi) {
  return Heading{phi, math::cos(phi), math::sin(phi)};
}

/// \brief The heading of the vector (x, y) (of angle 0 for the zero vector).
KOKKOS_INLINE_FUNCTION Heading headingAlong(double x, double y) {
  if (x == 0.0 && y == 0.0) {
    return Heading{};
  }
  const double length = math::sqrt(x * x + y * y);
  return Heading{math::atan2(y, x), x / length, y / length};
}

/// \brief The heading of the angle phi, turned from `from`: for turns d below 1e-2 rad by the
/// series of cos d and sin d to d^7 (the first term left out is below 3e-21), headingOf(phi)
/// otherwise.
KOKKOS_INLINE_FUNCTION Heading turnedTo(const Heading& from, double phi) {
  const double d = phi - from.phi;
  if (!(math::fabs(d) < 1e-2)) {
    return headingOf(phi);
  }
  const double d2 = d * d;
  const double c = 1.0 - d2 * (0.5 - d2 * (1.0 / 24.0 - d2 * (1.0 / 720.0)));
  const double s = d * (1.0 - d2 * (1.0 / 6.0 - d2 * (1.0 / 120.0 - d2 * (1.0 / 5040.0))));
  return Heading{phi, c * from.x - s * from.y, s * from.x + c * from.y};
}

/// \brief The support points of an objective's last evaluation with both, in the direction
/// (nx, ny). A search ends on its result's direction, so the caller takes the contact from them
/// instead of taking the roots again (the same numbers).
struct LastSupports {
  double nx = 2.0, ny = 0.0; ///< none yet (not a unit vector)
  Support first, second;
  KOKKOS_INLINE_FUNCTION void keep(double ux, double uy, const Support& p, const Support& q) {
    nx = ux;
    ny = uy;
    first = p;
    second = q;
  }
  KOKKOS_INLINE_FUNCTION bool at(double ux, double uy) const { return ux == nx && uy == ny; }
  /// \brief Moves both supports (radii and their slopes kept by the evaluation) to the
  /// direction turned by a short step s, without roots: a support point moves along the tangent t
  /// at the rate of its radius of curvature, p' = rho t, p'' = rho' t - rho n and
  /// p''' = rho'' t - 2 rho' n - rho t, and h' = p . t, h'' = rho - h, h''' = rho' - h' (the
  /// second support at -n: t -> -t, n -> -n). All but the rho'' s^3 / 6 term are taken; searches
  /// ended this way put the contact point within 7.3e-11 of the size of the cold search's
  /// (superquadric_short_warm_step_takes_one_evaluation).
  KOKKOS_INLINE_FUNCTION void advance(double s) {
    follow(first, 1.0, s);
    follow(second, -1.0, s);
    turn(s);
  }
  /// \brief Moves one support (the first, sign 1, or the second, -1) by the turn s, as advance().
  KOKKOS_INLINE_FUNCTION void follow(Support& p, double sign, double s) const {
    const double tx = -ny, ty = nx, s2 = 0.5 * s * s, s3 = s * s * s / 6.0;
    const double rho = p.radius, slope = p.radiusSlope;
    const double rate = sign * (p.x * tx + p.y * ty); // h'
    p.h += rate * s + (rho - p.h) * s2 + (slope - rate) * s3;
    const double along = sign * (rho * s + slope * s2 - rho * s3);
    const double inward = sign * (rho * s2 + 2.0 * slope * s3);
    p.x += along * tx - inward * nx;
    p.y += along * ty - inward * ny; // the radii stay the evaluation's: nothing reads them after
  }
  /// \brief Turns the direction by s (after the supports followed it).
  KOKKOS_INLINE_FUNCTION void turn(double s) {
    const Heading turned = turnedTo(Heading{0.0, nx, ny}, s);
    nx = turned.x;
    ny = turned.y;
  }
};

/// \brief The Newton step -slope / curvature of a minimisation, or 0 where the curvature gives
/// none (not positive, or a flat face's).
KOKKOS_INLINE_FUNCTION double newtonStep(double slope, double curvature) {
  return curvature > 0.0 && curvature < 1e-3 * flatRadius ? -slope / curvature : 0.0;
}

/// \brief atan z, for |z| below 1e-2 by its series to z^9 (the first term left out is below
/// 1e-20 of z), math::atan otherwise: the steps in a face's root turn the normal by little, and
/// the library's atan was 2.3 % of a drum of N = 6 blocks.
KOKKOS_INLINE_FUNCTION double atanOfSmall(double z) {
  if (!(math::fabs(z) < 1e-2)) {
    return math::atan(z);
  }
  const double z2 = z * z;
  return z * (1.0 - z2 * (1.0 / 3.0 - z2 * (1.0 / 5.0 - z2 * (1.0 / 7.0 - z2 * (1.0 / 9.0)))));
}

/// \brief Whether the outline of s is near-flat at its support p: a radius of curvature above 4
/// of its semi-axes (a face centre's is flatRadius).
KOKKOS_INLINE_FUNCTION bool nearlyFlat(const SuperquadricShape& s, const Support& p) {
  return p.radius > 4.0 * (s.a + s.b);
}

/// \brief Where a Newton step lands, and whether it was short enough to stop after it.
struct NewtonTarget {
  double phi = 0.0;
  bool converged = false;
  bool takeWithoutEvaluation = false; ///< short enough to end on (contactExtrapolateStep)
  bool alongFace = false;  ///< the step was in a flat support's root (faceNewtonTarget())
  bool faceOfFirst = true; ///< that support: the objective's first (else its second)
  double root = 0.0;       ///< alongFace: that support's root after the step
};

/// \brief The Newton step of a minimisation in the angle from phi (slope g, curvature c). A
/// step short enough to end on (contactExtrapolateStep) takes the third derivative c3 too: the
/// root of g + c s + c3 s^2 / 2 (one correction of the Newton step), whose error is of order s^3.
KOKKOS_INLINE_FUNCTION NewtonTarget plainNewtonTarget(double phi, double g, double c, double c3) {
  NewtonTarget plain;
  const double step = newtonStep(g, c);
  plain.phi = phi + step;
  plain.converged = step != 0.0 && math::fabs(step) <= contactAngleTolerance;
  plain.takeWithoutEvaluation = step != 0.0 && math::fabs(step) <= contactExtrapolateStep;
  if (plain.takeWithoutEvaluation && !plain.converged) {
    plain.phi -= 0.5 * c3 / c * step * step;
  }
  return plain;
}

/// \brief The Newton step of a minimisation at the angle phi (direction (nx, ny), slope g,
/// curvature c, third derivative c3) where shape s (orientation (cs, ss)) has the support `p`. Next
/// to a face centre the slope grows like |x|^(1/(N-1)) with the angle x from the face normal, so
/// Newton steps in phi overshoot by up to N - 1 times (and the safeguard bisects, ~30 steps to the
/// angle tolerance); the slope cannot reach its tolerance there in double precision either. The
/// support is smooth in its root r = t^(1/(N-1)) (Superquadric.hpp), so the step is taken in
/// y = sgn(x) r, with tan x = sgn(x) (A / B) t (A the semi-axis along the face normal): one step
/// lands on the root of a slope linear in y, and the step in y, which moves the contact point,
/// decides convergence (contactRootTolerance; or a step in phi at round-off); a step in y below
/// contactFaceExtrapolateStep is the last (its error, of order its square, is ~1e-10 in y: the
/// contact point moves ~1e-10 of the size). Plain Newton in
/// phi (contactAngleTolerance) for an ellipse (no faces) and where the outline is not flat
/// (radius below 4 of its semi-axes).
KOKKOS_INLINE_FUNCTION NewtonTarget faceNewtonTarget(const SuperquadricShape& s, double cs,
                                                     double ss, const Support& p, double nx,
                                                     double ny, double phi, double g, double c,
                                                     double c3) {
  const NewtonTarget plain = plainNewtonTarget(phi, g, c, c3);
  if (s.n == 2.0 || !nearlyFlat(s, p) || !(p.radius < 1e-3 * flatRadius) || !(p.t > 0.0)) {
    return plain;
  }
  const double u = cs * nx + ss * ny, v = -ss * nx + cs * ny; // the direction in the body frame
  const bool uBig = math::fabs(s.a * u) >= math::fabs(s.b * v);
  const double ratio = uBig ? s.a / s.b : s.b / s.a;         // A / B
  const double sign = ((u * v >= 0.0) == uBig) ? 1.0 : -1.0; // of x
  const double tanX = sign * ratio * p.t;
  const double dPhiDy = ratio * (s.n - 1.0) * (p.t / p.r) / (1.0 + tanX * tanX);
  const double slopeInY = c * dPhiDy;
  if (!(slopeInY > 0.0)) {
    return plain;
  }
  const double stepInY = -g / slopeInY;
  const double y = sign * p.r + stepInY;
  const double tanNew = (y < 0.0 ? -ratio : ratio) * powerOfOrder(math::fabs(y), s.n - 1.0);
  const double cosine = 1.0 + tanNew * tanX; // of the step, times cos x cos x'
  if (!(cosine > 0.0)) {
    return plain;
  }
  NewtonTarget face;
  const double stepInPhi = atanOfSmall((tanNew - tanX) / cosine);
  face.phi = phi + stepInPhi;
  face.converged = math::fabs(stepInY) <= contactRootTolerance ||
                   math::fabs(stepInPhi) <= 4.0 * DBL_EPSILON * (1.0 + math::fabs(phi));
  face.takeWithoutEvaluation = math::fabs(stepInY) <= contactFaceExtrapolateStep;
  face.alongFace = true;
  face.root = math::fabs(y);
  return face;
}

/// \brief pen(phi) of a pair and its derivative (see the file comment).
struct PairObjective {
  SuperquadricShape A, B;
  double ca, sa, cb, sb, dx, dy;
  mutable LastSupports last;
  KOKKOS_INLINE_FUNCTION double value(double nx, double ny) const {
    return worldSupportValue(A, ca, sa, nx, ny) + worldSupportValue(B, cb, sb, -nx, -ny) -
           (dx * nx + dy * ny);
  }
  /// \brief An upper bound of value() without roots (supportValueBound()): <= 0 proves a
  /// separating axis.
  KOKKOS_INLINE_FUNCTION double valueBound(double nx, double ny) const {
    return worldSupportValueBound(A, ca, sa, nx, ny) + worldSupportValueBound(B, cb, sb, -nx, -ny) -
           (dx * nx + dy * ny);
  }
  /// \brief value(), its slope and its second derivative pen'' = rho_A + rho_B - pen from one
  /// pair of support points (h + h'' = rho, the radius of curvature at the support point, and
  /// (d . n)'' = -d . n).
  KOKKOS_INLINE_FUNCTION double evaluate(double nx, double ny, double& slopeOut,
                                         double& curvatureOut) const {
    const Support a = worldSupport<true>(A, ca, sa, nx, ny);
    const Support b = worldSupport<true>(B, cb, sb, -nx, -ny);
    last.keep(nx, ny, a, b);
    slopeOut = (a.x - b.x - dx) * (-ny) + (a.y - b.y - dy) * nx;
    const double value = a.h + b.h - (dx * nx + dy * ny);
    curvatureOut = a.radius + b.radius - value;
    return value;
  }
  /// \brief Where a Newton step from phi (slope g, curvature c of the last evaluate(), there)
  /// lands: in the face variable of the flatter support (faceNewtonTarget()); pen''' =
  /// rho_A' + rho_B' - pen'.
  KOKKOS_INLINE_FUNCTION NewtonTarget newtonTarget(double phi, double g, double c) const {
    const double c3 = last.first.radiusSlope + last.second.radiusSlope - g;
    const bool firstFlatter = last.first.radius >= last.second.radius;
    NewtonTarget target =
        firstFlatter ? faceNewtonTarget(A, ca, sa, last.first, last.nx, last.ny, phi, g, c, c3)
                     : faceNewtonTarget(B, cb, sb, last.second, last.nx, last.ny, phi, g, c, c3);
    target.faceOfFirst = firstFlatter;
    return target;
  }
  /// \brief Ends a search on target (takeWithoutEvaluation) from the last evaluation at `at`: a
  /// step in the angle moves both supports to third order (LastSupports::advance()); a step in a
  /// flat support's root (faceNewtonTarget()) takes that support's point of the root
  /// (worldSupportAtRoot()) and moves the other to third order, or evaluates it where it is flat
  /// too (it slides fast with the angle then; a face against a face).
  KOKKOS_INLINE_FUNCTION void endAt(const Heading& at, const NewtonTarget& target) const {
    const double s = target.phi - at.phi;
    if (!target.alongFace) {
      last.advance(s);
      return;
    }
    const bool first = target.faceOfFirst;
    Support& other = first ? last.second : last.first;
    const bool otherFlat = nearlyFlat(first ? B : A, other);
    if (!otherFlat) {
      last.follow(other, first ? -1.0 : 1.0, s);
    }
    last.turn(s);
    const double nx = last.nx, ny = last.ny;
    if (first) {
      last.first = worldSupportAtRoot(A, ca, sa, nx, ny, target.root);
    } else {
      last.second = worldSupportAtRoot(B, cb, sb, -nx, -ny, target.root);
    }
    if (otherFlat) {
      other = first ? worldSupport(B, cb, sb, -nx, -ny) : worldSupport(A, ca, sa, nx, ny);
    }
  }
};

/// \brief -(x_c . n + h(n)) of a particle in the drum and its derivative.
struct DrumObjective {
  SuperquadricShape S;
  double c, sn, x, y;
  mutable LastSupports last; ///< first: the particle's support point
  KOKKOS_INLINE_FUNCTION double value(double nx, double ny) const {
    return -(x * nx + y * ny + worldSupportValue(S, c, sn, nx, ny));
  }
  /// \brief An upper bound of value(): the value itself (the drum's scan never stops early).
  KOKKOS_INLINE_FUNCTION double valueBound(double nx, double ny) const { return value(nx, ny); }
  /// \brief value(), its slope and its second derivative -value - rho (h + h'' = rho, the
  /// radius of curvature at the support point, and (x_c . n)'' = -x_c . n).
  KOKKOS_INLINE_FUNCTION double evaluate(double nx, double ny, double& slopeOut,
                                         double& curvatureOut) const {
    const Support s = worldSupport<true>(S, c, sn, nx, ny);
    last.keep(nx, ny, s, s);
    slopeOut = -((x + s.x) * (-ny) + (y + s.y) * nx);
    const double value = -(x * nx + y * ny + s.h);
    curvatureOut = -value - s.radius;
    return value;
  }
  /// \brief Where a Newton step from phi lands: the deepest point is a corner or an ellipse's
  /// end, where the outline is smooth, so in the angle; pen''' = -pen' - rho'.
  KOKKOS_INLINE_FUNCTION NewtonTarget newtonTarget(double phi, double g, double curv) const {
    return plainNewtonTarget(phi, g, curv, -g - last.first.radiusSlope);
  }
  /// \brief Ends a search on target from the last evaluation at `at` (LastSupports::advance()).
  KOKKOS_INLINE_FUNCTION void endAt(const Heading& at, const NewtonTarget& target) const {
    last.advance(target.phi - at.phi);
  }
};

/// \brief Ends a search at target.phi from `at`, f's last evaluation, without evaluating there
/// (NewtonTarget::takeWithoutEvaluation): the supports follow the step (f.endAt()).
template <class Objective>
KOKKOS_INLINE_FUNCTION Heading takeLastStep(const Objective& f, const Heading& at,
                                            const NewtonTarget& target) {
  f.endAt(at, target);
  return Heading{target.phi, f.last.nx, f.last.ny};
}

/// \brief Root of f's slope in the bracket [lo, hi] (slope < 0 at lo, > 0 at hi; the scans presume
/// the far end's sign, see minimiseHalfCircle()), from the iterate `at` (one of its ends, slope g
/// and curvature c there): Newton steps while they land inside the
/// bracket and at least halve the step before last, bisection otherwise (near-flat faces, where
/// the slope behaves like |phi - phi*|^(1/(N-1)) and Newton overshoots; f.newtonTarget() steps in
/// the support's root there); stops when |slope| <= tolerance, when the bracket is narrower than
/// contactAngleTolerance or after a converged Newton step (NewtonTarget). Returns the last
/// iterate, the direction of f's last evaluation.
template <class Objective>
KOKKOS_INLINE_FUNCTION Heading refineNewton(const Objective& f, double lo, double hi, Heading at,
                                            double g, double c, double tolerance) {
  double phi = at.phi;
  double stepOld = hi - lo, step = stepOld;
  for (int it = 0; it < contactRefineIterations; ++it) {
    const NewtonTarget target = f.newtonTarget(phi, g, c);
    if (target.converged) {
      break; // the root is closer to phi than that short step
    }
    if (target.takeWithoutEvaluation && target.phi > lo && target.phi < hi) {
      return takeLastStep(f, at, target);
    }
    const double newton = target.phi;
    const double stepNewton = math::fabs(newton - phi);
    const bool takeNewton =
        newton > lo && newton < hi && stepNewton > 0.0 && stepNewton <= 0.5 * stepOld;
    if (takeNewton) {
      stepOld = step;
      step = stepNewton;
      phi = newton;
    } else {
      stepOld = step;
      step = 0.5 * (hi - lo);
      phi = 0.5 * (lo + hi);
    }
    at = turnedTo(at, phi);
    f.evaluate(at.x, at.y, g, c);
    if (math::fabs(g) <= tolerance) {
      break;
    }
    if (g > 0.0) {
      hi = phi;
    } else {
      lo = phi;
    }
    if (hi - lo <= contactAngleTolerance) {
      break;
    }
  }
  return at;
}

/// \brief Minimises f over the angles (phi0 - halfWidth, phi0 + halfWidth), halfWidth <= pi/2,
/// phi0 = centre.phi: 2 M + 1 samples from phi0 outwards (a separating direction is usually near
/// phi0), then the root of the slope within a sample spacing of the best sample (refineNewton()).
/// Returns false at once when stopAtNonPositive and a sample has f <= 0 (out: that sample, a
/// separating axis of a pair). slopeScale sets the slope tolerance (a length).
template <class Objective>
KOKKOS_INLINE_FUNCTION bool minimiseHalfCircle(const Objective& f, const Heading& centre,
                                               double halfWidth, bool stopAtNonPositive,
                                               double slopeScale, Heading& out) {
  constexpr int M = contactScanHalf;
  const double phi0 = centre.phi;
  const double step = halfWidth / (M + 1);
  const double cs = math::cos(step), ss = math::sin(step);
  double upx = centre.x, upy = centre.y, dnx = upx, dny = upy;
  // a sample whose bound (no roots) is <= 0 already proves a separating axis
  const auto sample = [&](double nx, double ny) {
    return stopAtNonPositive && !(f.valueBound(nx, ny) > 0.0) ? 0.0 : f.value(nx, ny);
  };
  int best = 0;
  double bestValue = sample(upx, upy), bestX = upx, bestY = upy;
  if (stopAtNonPositive && !(bestValue > 0.0)) {
    out = centre;
    return false; // a separating axis
  }
  for (int j = 1; j <= M; ++j) {
    const double ux = cs * upx - ss * upy, dx = cs * dnx + ss * dny; // rotate by +step, -step
    upy = ss * upx + cs * upy;
    dny = -ss * dnx + cs * dny;
    upx = ux;
    dnx = dx;
    const double vu = sample(upx, upy), vd = sample(dnx, dny);
    if (stopAtNonPositive && !(vu > 0.0 && vd > 0.0)) {
      out = vu > 0.0 ? Heading{phi0 - j * step, dnx, dny} : Heading{phi0 + j * step, upx, upy};
      return false;
    }
    if (vu < bestValue) {
      best = j;
      bestValue = vu;
      bestX = upx;
      bestY = upy;
    }
    if (vd < bestValue) {
      best = -j;
      bestValue = vd;
      bestX = dnx;
      bestY = dny;
    }
  }
  const double phiBest = phi0 + best * step;
  double g = 0.0, c = 0.0;
  f.evaluate(bestX, bestY, g, c);
  out = Heading{phiBest, bestX, bestY};
  const double tolerance = contactSlopeTolerance * slopeScale;
  if (math::fabs(g) <= tolerance) {
    return true;
  }
  // the minimum lies within a step of the best sample, downhill (at |best| = M the step
  // reaches past the range)
  out = g > 0.0 ? refineNewton(f, phiBest - step, phiBest, out, g, c, tolerance)
                : refineNewton(f, phiBest, phiBest + step, out, g, c, tolerance);
  return true;
}

/// \brief Outcome of a warm-started pair search.
enum class WarmStart { Separated, Found, Failed };

/// \brief Local minimum of a pair's pen next to the angle `guess` (the last normal of the pair):
/// pen(guess) <= 0 is a separating axis (Separated); otherwise Newton steps on pen' = 0 downhill
/// (pen'' from the radii of curvature, PairObjective::evaluate()), each at least twice the last
/// where the slope fell by less than half (near-flat faces; contactWarmStep where Newton gives no
/// step), until the slope vanishes (Found) or changes sign, then refineNewton() in that bracket
/// (Found). Failed when the walk leaves contactWarmReach of the guess: the caller scans.
template <class Objective>
KOKKOS_INLINE_FUNCTION WarmStart minimiseFromGuess(const Objective& f, double guess,
                                                   double slopeScale, Heading& out) {
  double g = 0.0, c = 0.0;
  Heading near = headingOf(guess);
  if (!(f.evaluate(near.x, near.y, g, c) > 0.0)) {
    return WarmStart::Separated;
  }
  out = near;
  const double tolerance = contactSlopeTolerance * slopeScale;
  if (math::fabs(g) <= tolerance) {
    return WarmStart::Found;
  }
  const double direction = g > 0.0 ? -1.0 : 1.0; // downhill
  double gNear = g, delta = 0.0;
  bool slow = false;
  for (int it = 0; it < contactRefineIterations; ++it) {
    const NewtonTarget target = f.newtonTarget(near.phi, gNear, c);
    if (target.converged) {
      return WarmStart::Found; // out: near
    }
    if (target.takeWithoutEvaluation && !slow) {
      out = takeLastStep(f, near, target);
      return WarmStart::Found;
    }
    double step = math::fabs(target.phi - near.phi);
    if (!(step > 0.0)) {
      step = delta > 0.0 ? 2.0 * delta : contactWarmStep;
    } else if (slow && step < 2.0 * delta) {
      step = 2.0 * delta;
    }
    delta = step;
    const double farPhi = near.phi + direction * delta;
    if (!(math::fabs(farPhi - guess) <= contactWarmReach)) {
      return WarmStart::Failed;
    }
    const Heading far = turnedTo(near, farPhi);
    double gFar = 0.0;
    f.evaluate(far.x, far.y, gFar, c);
    out = far;
    if (math::fabs(gFar) <= tolerance) {
      return WarmStart::Found;
    }
    if (direction * gFar > 0.0) { // the slope changed sign between near and far
      out = direction > 0.0 ? refineNewton(f, near.phi, far.phi, far, gFar, c, tolerance)
                            : refineNewton(f, far.phi, near.phi, far, gFar, c, tolerance);
      return WarmStart::Found;
    }
    slow = !(math::fabs(gFar) < 0.5 * math::fabs(gNear));
    near = far;
    gNear = gFar;
  }
  return WarmStart::Failed;
}

} // namespace detail

/// \brief What the angle handed to superquadricPair() is: nothing, the pair's last contact normal,
/// or its last separating axis.
enum class PairGuess { None, Normal, Axis };

/// \brief The warm search's guess for a pair whose last normal had the angle phi, a step dt ago:
/// that normal turned by the pair's mean spin over the step. A corner on a face keeps the face's
/// normal, which turns with the face's body, and in a flowing bed touching blocks mostly turn
/// alike; with the guess turned, the warm searches of the 2 m drum took 1.48 evaluations each
/// instead of 1.90 (N = 6; 1.30 instead of 1.53 at N = 4; docs/blocky-particles.md).
KOKKOS_INLINE_FUNCTION double spunNormalGuess(double phi, double spinA, double spinB, double dt) {
  return phi + 0.5 * (spinA + spinB) * dt;
}

/// \brief True when the a x b bounding rectangles of two shapes (orientations (ca, sa), (cb, sb),
/// d = x_B - x_A) are apart along one of their four axes. A superquadric with N >= 2 lies inside
/// its rectangle, so the shapes are apart too; a margin of 1e-12 of the sizes keeps touching pairs
/// at round-off from being rejected.
KOKKOS_INLINE_FUNCTION bool boundingRectanglesApart(const SuperquadricShape& A, double ca,
                                                    double sa, const SuperquadricShape& B,
                                                    double cb, double sb, double dx, double dy) {
  const double c = math::fabs(ca * cb + sa * sb), s = math::fabs(ca * sb - sa * cb);
  const double margin = 1e-12 * (A.a + A.b + B.a + B.b);
  if (math::fabs(ca * dx + sa * dy) > A.a + B.a * c + B.b * s + margin ||
      math::fabs(ca * dy - sa * dx) > A.b + B.a * s + B.b * c + margin) {
    return true;
  }
  return math::fabs(cb * dx + sb * dy) > B.a + A.a * c + A.b * s + margin ||
         math::fabs(cb * dy - sb * dx) > B.b + A.a * s + A.b * c + margin;
}

/// \brief Narrow phase of shape A (orientation angle thetaA) and shape B (thetaB) with
/// d = x_B - x_A; false when they do not overlap. The normal points from A to B (angle g.angle),
/// the contact point is relative to A's centre (see the file comment for the method). With a
/// guess (the pair's last normal or separating axis, kind says which), pen(guess) <= 0 ends the
/// test (still apart); otherwise the search starts from a last normal
/// (detail::minimiseFromGuess()) and scans if that fails or the guess was a separating axis (a
/// new contact). When false, g.axis says whether g.angle holds a separating axis (not when the
/// bounding rectangles are apart); nothing else is set.
KOKKOS_INLINE_FUNCTION bool superquadricPair(const SuperquadricShape& A, BodyAxis axisA,
                                             const SuperquadricShape& B, BodyAxis axisB, double dx,
                                             double dy, ContactGeometry& g,
                                             PairGuess kind = PairGuess::None, double guess = 0.0) {
  detail::PairObjective f{A, B, axisA.c, axisA.s, axisB.c, axisB.s, dx, dy, {}};
  if (boundingRectanglesApart(A, f.ca, f.sa, B, f.cb, f.sb, dx, dy)) {
    return false;
  }
  const double scale = A.a + A.b + B.a + B.b;
  detail::Heading normal;
  detail::WarmStart start = detail::WarmStart::Failed;
  if (kind == PairGuess::Normal) {
    start = detail::minimiseFromGuess(f, guess, scale, normal);
  } else if (kind == PairGuess::Axis) { // the bound first: no roots for a clear gap
    const double gx = math::cos(guess), gy = math::sin(guess);
    if (!(f.valueBound(gx, gy) > 0.0) || !(f.value(gx, gy) > 0.0)) {
      start = detail::WarmStart::Separated;
    }
  }
  if (start == detail::WarmStart::Separated) {
    g.angle = guess; // still a separating axis
    g.axis = true;
    return false;
  }
  if (start == detail::WarmStart::Failed) {
    if (!detail::minimiseHalfCircle(f, detail::headingAlong(dx, dy), 0.5 * constants::pi, true,
                                    scale, normal)) {
      g.angle = normal.phi;
      g.axis = true;
      return false;
    }
  }
  g.angle = normal.phi; // the normal, or a separating axis when pen(phi) <= 0
  g.axis = true;
  const double nx = normal.x, ny = normal.y;
  const bool known = f.last.at(nx, ny);
  const Support a = known ? f.last.first : worldSupport(A, f.ca, f.sa, nx, ny);
  const Support b = known ? f.last.second : worldSupport(B, f.cb, f.sb, -nx, -ny);
  const double overlap = (a.x - b.x - dx) * nx + (a.y - b.y - dy) * ny;
  if (!(overlap > 0.0)) {
    return false;
  }
  g.nx = nx;
  g.ny = ny;
  g.overlap = overlap;
  g.px = 0.5 * (a.x + dx + b.x);
  g.py = 0.5 * (a.y + dy + b.y);
  return true;
}

/// \brief superquadricPair() with the orientation angles thetaA, thetaB.
KOKKOS_INLINE_FUNCTION bool superquadricPair(const SuperquadricShape& A, double thetaA,
                                             const SuperquadricShape& B, double thetaB, double dx,
                                             double dy, ContactGeometry& g,
                                             PairGuess kind = PairGuess::None, double guess = 0.0) {
  return superquadricPair(A, bodyAxis(thetaA), B, bodyAxis(thetaB), dx, dy, g, kind, guess);
}

/// \brief A shape at (x, y) with orientation theta inside the drum shell; false when not touching.
/// The normal points outwards (from the particle to the shell), the contact point is the
/// particle's deepest point relative to its centre. Callers test the bounding circle first.
KOKKOS_INLINE_FUNCTION bool superquadricDrum(const SuperquadricShape& s, BodyAxis axis,
                                             double radius, double x, double y,
                                             ContactGeometry& g) {
  detail::DrumObjective f{s, axis.c, axis.s, x, y, {}};
  // the bounding rectangle inside the shell (its corners are): no contact
  const double ax = f.c * s.a, ay = f.sn * s.a, bx = -f.sn * s.b, by = f.c * s.b;
  const double r2 = radius * radius;
  if ((x + ax + bx) * (x + ax + bx) + (y + ay + by) * (y + ay + by) < r2 &&
      (x + ax - bx) * (x + ax - bx) + (y + ay - by) * (y + ay - by) < r2 &&
      (x - ax + bx) * (x - ax + bx) + (y - ay + by) * (y - ay + by) < r2 &&
      (x - ax - bx) * (x - ax - bx) + (y - ay - by) * (y - ay - by) < r2) {
    return false;
  }
  // the deepest point q = x + p has its normal along q, within asin(|p| / |x|) < (pi / 2) |p| / |x|
  // of x / |x| (|p| <= the rectangle's half diagonal): the scan covers only that range
  const double centre = math::sqrt(x * x + y * y), diagonal = math::sqrt(s.a * s.a + s.b * s.b);
  const double halfWidth = 0.5 * constants::pi * (diagonal < centre ? diagonal / centre : 1.0);
  detail::Heading normal;
  detail::minimiseHalfCircle(f, detail::headingAlong(x, y), halfWidth, false, s.a + s.b + radius,
                             normal);
  const double nx = normal.x, ny = normal.y;
  const Support p = f.last.at(nx, ny) ? f.last.first : worldSupport(s, f.c, f.sn, nx, ny);
  const double overlap = x * nx + y * ny + p.h - radius;
  if (!(overlap > 0.0)) {
    return false;
  }
  g.nx = nx;
  g.ny = ny;
  g.overlap = overlap;
  g.px = p.x;
  g.py = p.y;
  return true;
}

/// \brief superquadricDrum() with the orientation angle theta.
KOKKOS_INLINE_FUNCTION bool superquadricDrum(const SuperquadricShape& s, double theta,
                                             double radius, double x, double y,
                                             ContactGeometry& g) {
  return superquadricDrum(s, bodyAxis(theta), radius, x, y, g);
}

/// \brief A shape at (x, y) with orientation theta on a flat wall; false when not touching. The
/// deepest point is the support point against the wall normal (closed form).
KOKKOS_INLINE_FUNCTION bool superquadricFlat(const SuperquadricShape& s, BodyAxis axis,
                                             const FlatWall& wall, double x, double y,
                                             ContactGeometry& g) {
  const Support p = worldSupport(s, axis.c, axis.s, -wall.normalX, -wall.normalY);
  const double dist = (x - wall.pointX) * wall.normalX + (y - wall.pointY) * wall.normalY;
  const double overlap = p.h - dist;
  if (!(overlap > 0.0)) {
    return false;
  }
  g.nx = -wall.normalX;
  g.ny = -wall.normalY;
  g.overlap = overlap;
  g.px = p.x;
  g.py = p.y;
  return true;
}

/// \brief superquadricFlat() with the orientation angle theta.
KOKKOS_INLINE_FUNCTION bool superquadricFlat(const SuperquadricShape& s, double theta,
                                             const FlatWall& wall, double x, double y,
                                             ContactGeometry& g) {
  return superquadricFlat(s, bodyAxis(theta), wall, x, y, g);
}

/// \brief Contact frame from a contact geometry: relative velocity of the other body's material
/// point at the contact (lever rB from its centre, velocity v + w x rB) with respect to the first
/// body's (lever rA = (px, py)); dv = v_other - v_first.
KOKKOS_INLINE_FUNCTION void frameAtContact(const ContactGeometry& g, double rBx, double rBy,
                                           double dvx, double dvy, double wA, double wB,
                                           ContactFrame& f) {
  const double vrx = dvx - wB * rBy + wA * g.py;
  const double vry = dvy + wB * rBx - wA * g.px;
  f.nx = g.nx;
  f.ny = g.ny;
  f.overlap = g.overlap;
  f.normalSpeed = vrx * g.nx + vry * g.ny;
  f.tangentialSpeed = vrx * (-g.ny) + vry * g.nx;
}

/// \brief One particle-particle contact as the force kernel uses it: the frame (normal from A to
/// B, relative velocity of B's surface with respect to A's at the contact) and the levers from each
/// centre to the contact point. circles: both are circles and the frame is the disc engine's
/// pairFrame() (torque r F_t, lever r n on the surface of each disc, as LAMMPS).
struct PairContact {
  ContactFrame frame;
  double rAx = 0.0, rAy = 0.0, rBx = 0.0, rBy = 0.0;
  double angle = 0.0; ///< non-circles: angle of the normal or of a separating axis (see axis)
  bool axis = false;  ///< non-circles: angle is set (also when not touching)
  bool circles = false;
};

/// \brief Contact of A (body axis axisA) with B from d = x_B - x_A, dv = v_B - v_A and the
/// spins; false when not touching. Circles take the disc engine's exact formula, everything else
/// superquadricPair() (with the guess; c.angle and c.axis are set also when not touching).
KOKKOS_INLINE_FUNCTION bool
blockyPairContact(const SuperquadricShape& A, BodyAxis axisA, const SuperquadricShape& B,
                  BodyAxis axisB, double dx, double dy, double dvx, double dvy, double wA,
                  double wB, PairContact& c, PairGuess kind = PairGuess::None, double guess = 0.0) {
  c.circles = isCircle(A) && isCircle(B);
  if (c.circles) {
    if (!pairFrame(dx, dy, dvx, dvy, A.a, B.a, wA, wB, c.frame)) {
      return false;
    }
    c.rAx = A.a * c.frame.nx;
    c.rAy = A.a * c.frame.ny;
    c.rBx = -B.a * c.frame.nx;
    c.rBy = -B.a * c.frame.ny;
    return true;
  }
  ContactGeometry g;
  const bool touching = superquadricPair(A, axisA, B, axisB, dx, dy, g, kind, guess);
  c.angle = g.angle;
  c.axis = g.axis;
  if (!touching) {
    return false;
  }
  c.rAx = g.px;
  c.rAy = g.py;
  c.rBx = g.px - dx;
  c.rBy = g.py - dy;
  frameAtContact(g, c.rBx, c.rBy, dvx, dvy, wA, wB, c.frame);
  return true;
}

/// \brief blockyPairContact() with the orientation angles thetaA, thetaB.
KOKKOS_INLINE_FUNCTION bool
blockyPairContact(const SuperquadricShape& A, double thetaA, const SuperquadricShape& B,
                  double thetaB, double dx, double dy, double dvx, double dvy, double wA, double wB,
                  PairContact& c, PairGuess kind = PairGuess::None, double guess = 0.0) {
  return blockyPairContact(A, bodyAxis(thetaA), B, bodyAxis(thetaB), dx, dy, dvx, dvy, wA, wB, c,
                           kind, guess);
}

/// \brief Contact of a particle (bounding radius r, centre x, y, velocity vx, vy, spin w) with the
/// drum shell, frame as drumFrame() (normal outwards); rx, ry the lever to the contact point.
/// Circles use drumFrame() itself. The shell's material velocity at the contact point is
/// omega_drum x p.
KOKKOS_INLINE_FUNCTION bool blockyDrumContact(const SuperquadricShape& s, BodyAxis axis, double r,
                                              const DrumWall& drum, double x, double y, double vx,
                                              double vy, double w, ContactFrame& f, double& rx,
                                              double& ry) {
  if (isCircle(s)) {
    if (!drumFrame(drum, x, y, vx, vy, w, s.a, f)) {
      return false;
    }
    rx = s.a * f.nx;
    ry = s.a * f.ny;
    return true;
  }
  const double reach = drum.radius - r; // bounding circle inside: no contact
  if (reach > 0.0 && !(x * x + y * y > reach * reach)) {
    return false;
  }
  ContactGeometry g;
  if (!superquadricDrum(s, axis, drum.radius, x, y, g)) {
    return false;
  }
  const double wallVx = -drum.angularVelocity * (y + g.py);
  const double wallVy = drum.angularVelocity * (x + g.px);
  frameAtContact(g, 0.0, 0.0, wallVx - vx, wallVy - vy, w, 0.0, f);
  rx = g.px;
  ry = g.py;
  return true;
}

/// \brief Contact of a particle with a flat wall, as blockyDrumContact() (circles: flatFrame()).
KOKKOS_INLINE_FUNCTION bool blockyFlatContact(const SuperquadricShape& s, BodyAxis axis,
                                              const FlatWall& wall, double x, double y, double vx,
                                              double vy, double w, ContactFrame& f, double& rx,
                                              double& ry) {
  if (isCircle(s)) {
    if (!flatFrame(wall, x, y, vx, vy, w, s.a, f)) {
      return false;
    }
    rx = s.a * f.nx;
    ry = s.a * f.ny;
    return true;
  }
  ContactGeometry g;
  if (!superquadricFlat(s, axis, wall, x, y, g)) {
    return false;
  }
  // the wall surface slides at tangentialVelocity along (normalY, -normalX) = perp(n)
  const double wallVx = wall.tangentialVelocity * wall.normalY;
  const double wallVy = -wall.tangentialVelocity * wall.normalX;
  frameAtContact(g, 0.0, 0.0, wallVx - vx, wallVy - vy, w, 0.0, f);
  rx = g.px;
  ry = g.py;
  return true;
}

} // namespace hikiln::dem
