#pragma once
/// \file ContactLaw.hpp
/// \brief Linear spring-dashpot contact law with tangential history, Coulomb slip and optional
/// rolling resistance, as point functions usable on the host and in kernels.
///
/// Conventions (one contact seen from particle i): n is the unit normal from i towards the other
/// body, t = perp(n) = (-n_y, n_x); the relative velocity is that of the other body's surface with
/// respect to i's surface at the contact. The force on i is -F_n n + F_t t and the torque on i is
/// r_i F_t + M_roll. Seen from the other particle every vector flips sign exactly, the scalars
/// (overlap, v_n, v_t, shear, F_n, F_t) are bitwise the same, so pair forces are exactly
/// antisymmetric.

#include "kernels/common/Compat.hpp"

#include <stdexcept>
#include <string>

namespace hikiln::dem {

/// \brief How the dashpot coefficients are set.
/// Restitution: c_n = 2 zeta sqrt(k_n m_eff) with zeta from the coefficient of restitution e, and
/// c_t = tangentialDampingFactor * c_n. Rate (LAMMPS gran/hooke): c_n = gamma_n m_eff,
/// c_t = gamma_t m_eff with gamma in 1/s.
enum class DampingMode { Restitution, Rate };

/// \brief Rolling resistance model.
/// ConstantTorque: the constant directional torque model (type A of Ai et al. 2011, Powder
/// Technol. 206:269; EDEM's "CDT"): M_r = -mu_r R_r |F_n| sign(omega_i - omega_j) with
/// R_r = r_i r_j / (r_i + r_j), or r_i at a wall. It has no history; near zero relative spin it
/// flips sign every step (a small chatter of the spin, the known price of this model).
enum class RollingModel { None, ConstantTorque };

/// \brief User-facing parameters of one contact type (particle-particle or particle-wall).
/// Defaults are the physics.md base case with e = 0.5, c_t = c_n / 2 and no rolling resistance.
struct ContactParameters {
  double normalStiffness = 1.0e5;     ///< k_n (N/m)
  double tangentialStiffness = 5.0e4; ///< k_t (N/m)
  double friction = 0.5;              ///< Coulomb coefficient mu
  DampingMode dampingMode = DampingMode::Restitution;
  double restitution = 0.5;             ///< e in (0, 1] (Restitution mode)
  double tangentialDampingFactor = 0.5; ///< c_t / c_n (Restitution mode)
  double normalDampingRate = 0.0;       ///< gamma_n (1/s) (Rate mode)
  double tangentialDampingRate = 0.0;   ///< gamma_t (1/s) (Rate mode)
  bool tangentialDamping = true;        ///< LAMMPS dampflag: false drops the tangential dashpot
  bool limitDamping = true;             ///< clamp F_n >= 0 (no tensile dashpot force); LAMMPS's
                                        ///< default (no limit_damping keyword) is false
  RollingModel rolling = RollingModel::None;
  double rollingFriction = 0.0; ///< mu_r (dimensionless) for ConstantTorque
};

/// \brief Damping ratio zeta that gives coefficient of restitution e for a linear spring-dashpot:
/// zeta = -ln(e) / sqrt(pi^2 + ln(e)^2).
KOKKOS_INLINE_FUNCTION double dampingRatioFromRestitution(double e) {
  const double le = math::log(e);
  return -le / math::sqrt(constants::pi * constants::pi + le * le);
}

/// \brief Coefficient of restitution of a linear spring-dashpot with damping ratio zeta < 1:
/// e = exp(-pi zeta / sqrt(1 - zeta^2)).
KOKKOS_INLINE_FUNCTION double restitutionFromDampingRatio(double zeta) {
  return math::exp(-constants::pi * zeta / math::sqrt(1.0 - zeta * zeta));
}

/// \brief Duration of a linear spring-dashpot contact, t_c = pi / sqrt(k/m - (c/2m)^2); infinite
/// (returned as a huge value) when overdamped.
KOKKOS_INLINE_FUNCTION double contactDuration(double k, double m, double c) {
  const double w2 = k / m - (c / (2.0 * m)) * (c / (2.0 * m));
  return w2 > 0.0 ? constants::pi / math::sqrt(w2) : 1.0e300;
}

/// \brief Contact coefficients in the form the kernels use (see prepareContact()).
struct ContactCoefficients {
  double kn = 0.0;
  double kt = 0.0;
  double mu = 0.0;
  bool rateMode = false;
  double normalDamping = 0.0;     ///< 2 zeta (Restitution) or gamma_n (Rate)
  double tangentialDamping = 0.0; ///< c_t/c_n (Restitution) or gamma_t (Rate); 0 when off
  bool limitDamping = true;
  bool rolling = false;
  double rollingFriction = 0.0;
};

/// \brief Validates user parameters and turns them into kernel coefficients (host).
inline ContactCoefficients prepareContact(const ContactParameters& p) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("hikiln::dem::ContactParameters: " + what);
  };
  if (!(p.normalStiffness > 0.0)) {
    fail("normalStiffness must be > 0");
  }
  if (!(p.tangentialStiffness >= 0.0)) {
    fail("tangentialStiffness must be >= 0");
  }
  if (!(p.friction >= 0.0)) {
    fail("friction must be >= 0");
  }
  ContactCoefficients c;
  c.kn = p.normalStiffness;
  c.kt = p.tangentialStiffness;
  c.mu = p.friction;
  c.limitDamping = p.limitDamping;
  if (p.dampingMode == DampingMode::Restitution) {
    if (!(p.restitution > 0.0 && p.restitution <= 1.0)) {
      fail("restitution must be in (0, 1]");
    }
    if (!(p.tangentialDampingFactor >= 0.0)) {
      fail("tangentialDampingFactor must be >= 0");
    }
    c.rateMode = false;
    c.normalDamping = 2.0 * dampingRatioFromRestitution(p.restitution);
    c.tangentialDamping = p.tangentialDamping ? p.tangentialDampingFactor : 0.0;
  } else {
    if (!(p.normalDampingRate >= 0.0 && p.tangentialDampingRate >= 0.0)) {
      fail("damping rates must be >= 0");
    }
    c.rateMode = true;
    c.normalDamping = p.normalDampingRate;
    c.tangentialDamping = p.tangentialDamping ? p.tangentialDampingRate : 0.0;
  }
  if (p.rolling == RollingModel::ConstantTorque) {
    if (!(p.rollingFriction >= 0.0)) {
      fail("rollingFriction must be >= 0");
    }
    c.rolling = p.rollingFriction > 0.0;
    c.rollingFriction = p.rollingFriction;
  }
  return c;
}

/// \brief Normal dashpot coefficient c_n (N s/m) for effective mass m_eff.
KOKKOS_INLINE_FUNCTION double normalDampingCoefficient(const ContactCoefficients& c, double meff) {
  return c.rateMode ? c.normalDamping * meff : c.normalDamping * math::sqrt(c.kn * meff);
}

/// \brief Tangential dashpot coefficient c_t (N s/m) for effective mass m_eff.
KOKKOS_INLINE_FUNCTION double tangentialDampingCoefficient(const ContactCoefficients& c,
                                                           double meff) {
  return c.rateMode ? c.tangentialDamping * meff
                    : c.tangentialDamping * normalDampingCoefficient(c, meff);
}

/// \brief Geometry and relative motion of one contact as seen from particle i.
struct ContactFrame {
  double nx = 0.0, ny = 0.0;    ///< unit normal from i towards the other body
  double overlap = 0.0;         ///< > 0 when touching (m)
  double normalSpeed = 0.0;     ///< relative velocity . n, < 0 when approaching (m/s)
  double tangentialSpeed = 0.0; ///< relative velocity . t (m/s)
};

/// \brief Contact frame of particle i with particle j from dx = x_j - x_i (minimum image) and
/// dv = v_j - v_i. Returns false (frame untouched) when the discs do not overlap or coincide.
/// Every operation is chosen so that swapping i and j negates the vectors exactly.
KOKKOS_INLINE_FUNCTION bool pairFrame(double dx, double dy, double dvx, double dvy, double ri,
                                      double rj, double wi, double wj, ContactFrame& f) {
  const double radsum = ri + rj;
  const double r2 = dx * dx + dy * dy;
  if (!(r2 < radsum * radsum) || r2 == 0.0) {
    return false;
  }
  const double r = math::sqrt(r2);
  const double inv = 1.0 / r; // one division; (-dx) * inv == -(dx * inv) keeps the symmetry
  f.nx = dx * inv;
  f.ny = dy * inv;
  f.overlap = radsum - r;
  // surface speeds: i's contact point moves w_i r_i t, j's moves -w_j r_j t; t flips with n
  const double spin = wi * ri + wj * rj;
  const double vrx = dvx - spin * (-f.ny);
  const double vry = dvy - spin * f.nx;
  f.normalSpeed = vrx * f.nx + vry * f.ny;
  f.tangentialSpeed = vrx * (-f.ny) + vry * f.nx;
  return true;
}

/// \brief Result of one contact evaluation (scalars in the frame of particle i).
struct ContactForce {
  double normal = 0.0;        ///< F_n >= 0 when limitDamping (repulsive), force on i is -F_n n
  double tangential = 0.0;    ///< F_t along t, force on i
  double shear = 0.0;         ///< updated tangential history displacement (m)
  double rollingTorque = 0.0; ///< rolling-resistance torque on i (N m)
};

/// \brief Evaluates the contact law. shearOld is the stored tangential displacement; when
/// updateHistory it is advanced by v_t dt first (LAMMPS skips that during setup). relativeSpin is
/// omega_i - omega_other, rollingRadius R_r. On Coulomb slip the history is rescaled so that
/// k_t shear + c_t v_t equals the capped force (LAMMPS gran/hooke/history). Forced inline: GCC
/// called it out of line from the pair-once force loop, which then ran slower than the full rows.
KOKKOS_FORCEINLINE_FUNCTION ContactForce evaluateContact(const ContactCoefficients& c,
                                                         const ContactFrame& f, double meff,
                                                         double rollingRadius, double relativeSpin,
                                                         double shearOld, double dt,
                                                         bool updateHistory) {
  ContactForce out;
  const double cn = normalDampingCoefficient(c, meff);
  double fn = c.kn * f.overlap - cn * f.normalSpeed;
  if (c.limitDamping && fn < 0.0) {
    fn = 0.0;
  }
  out.normal = fn;

  const double shear = updateHistory ? shearOld + f.tangentialSpeed * dt : shearOld;
  // = tangentialDampingCoefficient(c, meff), reusing c_n in Restitution mode
  const double ct = c.rateMode ? c.tangentialDamping * meff : c.tangentialDamping * cn;
  const double ft = c.kt * shear + ct * f.tangentialSpeed;
  const double cap = c.mu * math::fabs(fn);
  if (math::fabs(ft) > cap) {
    const double capped = ft > 0.0 ? cap : -cap;
    out.tangential = capped;
    out.shear = c.kt > 0.0 ? (capped - ct * f.tangentialSpeed) / c.kt : 0.0;
  } else {
    out.tangential = ft;
    out.shear = shear;
  }

  if (c.rolling && relativeSpin != 0.0) {
    const double m = c.rollingFriction * rollingRadius * math::fabs(fn);
    out.rollingTorque = relativeSpin > 0.0 ? -m : m;
  }
  return out;
}

/// \brief Effective mass of a pair, m_i m_j / (m_i + m_j) (symmetric in i and j bitwise).
KOKKOS_INLINE_FUNCTION double effectiveMass(double mi, double mj) {
  return mi * mj / (mi + mj);
}

/// \brief Effective mass of a pair where a non-free particle (fixed or shell-attached) has
/// infinite mass: the free one's mass; effectiveMass() when both are free. Symmetric in i and j.
KOKKOS_INLINE_FUNCTION double pairEffectiveMass(double mi, bool freeI, double mj, bool freeJ) {
  return freeI ? (freeJ ? effectiveMass(mi, mj) : mi) : mj;
}

/// \brief Rolling radius of a pair, r_i r_j / (r_i + r_j).
KOKKOS_INLINE_FUNCTION double rollingRadius(double ri, double rj) {
  return ri * rj / (ri + rj);
}

} // namespace hikiln::dem
