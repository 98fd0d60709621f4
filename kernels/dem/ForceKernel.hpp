#pragma once
/// \file ForceKernel.hpp
/// \brief Contact, wall and gravity forces of every particle from its full neighbour row
/// (optionally fused with the second velocity-Verlet half kick). Each particle sums in registers
/// and writes only its own entries (force, torque, its history row, its wall history): no atomics,
/// and the result does not depend on the thread count. PairOnceForces.hpp runs the same functor
/// over half of each row instead (an option: each pair evaluated once).
///
/// The time step stores no per-contact forces (they would double the list's memory traffic);
/// computeContactForces() re-evaluates them for the current state when a sampler needs them.
/// Slots are tested with the squared distance before any neighbour velocity is loaded.
///
/// Fixed and shell particles (ParticleKind) are bodies of infinite mass: a contact of a free
/// particle of mass m with one of them uses m_eff = m in the dashpot (the limit of
/// m m_j / (m + m_j) for m_j -> infinity; both sides of the pair use it, so the pair stays exactly
/// antisymmetric), two of them never interact, and they feel no gravity and no analytic walls.
/// Their force and torque are still the sum of their contacts with free particles (the load on
/// the base, for samplers) but nothing integrates them.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ContactLaw.hpp"
#include "kernels/dem/Integrator.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Periodic.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

#include <stdexcept>

namespace hikiln::dem {

/// \brief Everything the force kernel needs besides the arrays (trivially copyable).
struct ForceSettings {
  ContactCoefficients particle; ///< particle-particle law
  ContactCoefficients wall;     ///< particle-wall law (m_eff = particle mass, R_r = radius)
  WallSet walls;
  PeriodicX periodic;
  double gravityX = 0.0, gravityY = 0.0;
  double dt = 0.0;
  bool updateHistory = true; ///< false for the set-up evaluation (history not advanced)
};

/// \brief Per-slice settings of a batch of independent systems advanced together (DemBatch.hpp):
/// particle i uses settings(slice(i)). Empty (the default): every particle uses the common
/// settings.
template <class MemorySpace> struct SliceTable {
  Kokkos::View<const int*, MemorySpace> slice;
  Kokkos::View<const ForceSettings*, MemorySpace> settings;
  KOKKOS_INLINE_FUNCTION bool enabled() const { return slice.extent(0) > 0; }
};

namespace detail {

/// \brief Particles per dynamically scheduled chunk of the force kernel (a few microseconds).
inline constexpr int forceChunk = 64;

/// \brief Exact sums of what partners give a particle in the pair-once pass: force x and y as
/// integers of 1 / forceScale N, the torque of 1 / torqueScale N m, and a flag for a contribution
/// that did not fit (it turns the force into NaN).
template <class MemorySpace> struct PartnerSums {
  Kokkos::View<std::int64_t* [4], MemorySpace> sums;
  double forceScale = 0.0, torqueScale = 0.0;
};

/// \brief Per-particle body of the force evaluation; Kick also writes the half-kicked velocity.
/// Sample evaluates without touching the state: contact history, force and torque are left as
/// they are and the contact forces go to slotFn/slotFt and wallFn/wallFt instead. PairOnce
/// evaluates only the slots of higher neighbour ids (rows are sorted by id) and gives each
/// partner its side through `partner`, leaving the partner's copy of the history to
/// mirrorPairOnceHistory() (computeForcesPairOnce()).
template <class MemorySpace, bool Kick, bool Sample = false, bool PairOnce = false>
struct ForceFunctor {
  using Vec = Kokkos::View<double* [2], MemorySpace>;
  using Scalar = Kokkos::View<double*, MemorySpace>;
  using Wall = Kokkos::View<double* [wallSlotCount], MemorySpace>;
  Vec x, v, f, vOut;
  Scalar w, tq, wOut, radius, mass, invM, invI;
  Kokkos::View<int*, MemorySpace> count;
  Kokkos::View<std::uint8_t*, MemorySpace> kind;
  Kokkos::View<int*, MemorySpace> firstHigher; ///< PairOnce only: first slot of a higher id
  PartnerSums<MemorySpace> partner;            ///< PairOnce only
  Kokkos::View<int**, MemorySpace> index;
  Kokkos::View<double**, MemorySpace> shear, slotFn, slotFt;
  Wall wallShear, wallFn, wallFt;
  ForceSettings common;           ///< settings of every particle, unless batched
  SliceTable<MemorySpace> slices; ///< batches: per-slice settings
  int capacity;

  /// \brief Applies one wall contact (or clears its slot when not touching).
  KOKKOS_INLINE_FUNCTION void wallContact(const ForceSettings& s, int i, int slot, bool touching,
                                          const ContactFrame& fr, double mi, double ri,
                                          double relativeSpin, double& fx, double& fy,
                                          double& t) const {
    if (!touching) {
      if (Sample) {
        wallFn(i, slot) = 0.0;
        wallFt(i, slot) = 0.0;
      } else if (wallShear(i, slot) != 0.0) { // most particles never touch: no store
        wallShear(i, slot) = 0.0;
      }
      return;
    }
    const ContactForce c = evaluateContact(s.wall, fr, mi, ri, relativeSpin, wallShear(i, slot),
                                           s.dt, Sample ? false : s.updateHistory);
    if (Sample) {
      wallFn(i, slot) = c.normal;
      wallFt(i, slot) = c.tangential;
    } else {
      wallShear(i, slot) = c.shear;
    }
    fx += -c.normal * fr.nx + c.tangential * (-fr.ny);
    fy += -c.normal * fr.ny + c.tangential * fr.nx;
    t += ri * c.tangential + c.rollingTorque;
  }

  /// \brief PairOnce: adds a force or torque component to partner j's exact sum (column c); a
  /// value too large for the integers (or NaN) flags j instead.
  KOKKOS_INLINE_FUNCTION void givePartner(int j, int c, double value) const {
    // 2^56: the 64 terms of the widest row still fit in 63 bits
    static_assert(maxNeighborCapacity <= 64, "hikiln::dem: partner sums sized for 64 terms");
    constexpr double limit = 72057594037927936.0;
    const double scaled = value * (c == 2 ? partner.torqueScale : partner.forceScale);
    if (math::fabs(scaled) < limit) {
      partner.sums(j, c) += static_cast<std::int64_t>(scaled);
    } else {
      partner.sums(j, 3) = 1;
    }
  }

  KOKKOS_INLINE_FUNCTION void operator()(int i) const {
    if (slices.enabled()) {
      evaluate(i, slices.settings(slices.slice(i)));
    } else {
      evaluate(i, common);
    }
  }

  KOKKOS_INLINE_FUNCTION void evaluate(int i, const ForceSettings& s) const {
    const double xi = x(i, 0), yi = x(i, 1);
    const double vxi = v(i, 0), vyi = v(i, 1);
    const double wi = w(i), ri = radius(i), mi = mass(i);
    const bool freeI = isFree(kind(i));
    double fx = 0.0, fy = 0.0, t = 0.0;
    const int n = count(i) < capacity ? count(i) : capacity;
    const int first = PairOnce ? firstHigher(i) : 0;
    for (int k = first; k < n; ++k) { // ascending neighbour id: a fixed summation order
      const int j = index(i, k);
      const double rj = radius(j);
      const double dx = s.periodic.minimumImage(x(j, 0) - xi);
      const double dy = x(j, 1) - yi;
      const double radsum = ri + rj;
      ContactFrame fr;
      // distance first: a slot out of contact loads no velocities (pairFrame repeats the test)
      // (and two non-free particles never interact)
      const bool near = dx * dx + dy * dy < radsum * radsum;
      const bool freeJ = near ? isFree(kind(j)) : true;
      if (!near || !(freeI || freeJ) ||
          !pairFrame(dx, dy, v(j, 0) - vxi, v(j, 1) - vyi, ri, rj, wi, w(j), fr)) {
        if (Sample) {
          slotFn(i, k) = 0.0;
          slotFt(i, k) = 0.0;
        } else if (shear(i, k) != 0.0) { // history ends with the contact
          shear(i, k) = 0.0;
        }
        continue;
      }
      const double rr = s.particle.rolling ? rollingRadius(ri, rj) : 0.0;
      const ContactForce c =
          evaluateContact(s.particle, fr, pairEffectiveMass(mi, freeI, mass(j), freeJ), rr,
                          wi - w(j), shear(i, k), s.dt, Sample ? false : s.updateHistory);
      if (Sample) {
        slotFn(i, k) = c.normal;
        slotFt(i, k) = c.tangential;
      } else {
        shear(i, k) = c.shear;
      }
      const double px = -c.normal * fr.nx + c.tangential * (-fr.ny);
      const double py = -c.normal * fr.ny + c.tangential * fr.nx;
      fx += px;
      fy += py;
      t += ri * c.tangential + c.rollingTorque;
      if (PairOnce) { // j's side: the opposite force, its own lever, the opposite rolling torque
        givePartner(j, 0, -px);
        givePartner(j, 1, -py);
        givePartner(j, 2, rj * c.tangential - c.rollingTorque);
      }
    }
    ContactFrame fr;
    if (s.walls.drum.enabled) {
      const bool touching = freeI && drumFrame(s.walls.drum, xi, yi, vxi, vyi, wi, ri, fr);
      wallContact(s, i, 0, touching, fr, mi, ri, wi - s.walls.drum.angularVelocity, fx, fy, t);
    }
    for (int k = 0; k < s.walls.numFlat; ++k) {
      const bool touching = freeI && flatFrame(s.walls.flat[k], xi, yi, vxi, vyi, wi, ri, fr);
      wallContact(s, i, 1 + k, touching, fr, mi, ri, wi, fx, fy, t);
    }
    if (Sample) {
      return;
    }
    if (freeI) {
      fx += mi * s.gravityX;
      fy += mi * s.gravityY;
    }
    f(i, 0) = fx;
    f(i, 1) = fy;
    tq(i) = t;
    if (Kick) {
      const double halfDt = freeI ? 0.5 * s.dt : 0.0; // prescribed velocities stay as they are
      vOut(i, 0) = halfKick(vxi, halfDt, fx, invM(i));
      vOut(i, 1) = halfKick(vyi, halfDt, fy, invM(i));
      wOut(i) = halfKick(wi, halfDt, t, invI(i));
    }
  }
};

/// \brief The force functor over p, the list's rows and the wall history (see ForceFunctor).
template <bool Kick, bool Sample = false, bool PairOnce = false, class MemorySpace>
ForceFunctor<MemorySpace, Kick, Sample, PairOnce>
makeForceFunctor(ParticleArrays<MemorySpace> const& p, NeighborList<MemorySpace> const& list,
                 WallContactState<MemorySpace> const& walls, ForceSettings const& settings,
                 SliceTable<MemorySpace> const& slices,
                 Kokkos::View<double* [2], MemorySpace> const& velocityOut,
                 Kokkos::View<double*, MemorySpace> const& angularVelocityOut) {
  ForceFunctor<MemorySpace, Kick, Sample, PairOnce> fun;
  fun.x = p.position;
  fun.v = p.velocity;
  fun.f = p.force;
  fun.vOut = velocityOut;
  fun.w = p.angularVelocity;
  fun.tq = p.torque;
  fun.wOut = angularVelocityOut;
  fun.radius = p.radius;
  fun.mass = p.mass;
  fun.invM = p.inverseMass;
  fun.invI = p.inverseInertia;
  fun.count = list.count;
  fun.kind = p.kind;
  fun.index = list.index;
  fun.shear = list.shear;
  fun.slotFn = list.normalForce;
  fun.slotFt = list.tangentialForce;
  fun.wallShear = walls.shear;
  fun.wallFn = walls.normalForce;
  fun.wallFt = walls.tangentialForce;
  fun.common = settings;
  fun.slices = slices;
  fun.capacity = list.capacity();
  return fun;
}

template <bool Kick, bool Sample = false, class ExecutionSpace, class MemorySpace>
void launchForces(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                  NeighborList<MemorySpace> const& list, WallContactState<MemorySpace> const& walls,
                  ForceSettings const& settings, SliceTable<MemorySpace> const& slices,
                  Kokkos::View<double* [2], MemorySpace> const& velocityOut,
                  Kokkos::View<double*, MemorySpace> const& angularVelocityOut, const char* label) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::computeForces: particle memory not accessible");
  const auto fun = makeForceFunctor<Kick, Sample>(p, list, walls, settings, slices, velocityOut,
                                                  angularVelocityOut);
  // dynamic chunks: particles differ in contact count, and on a busy machine a thread that is
  // descheduled for a while leaves its remaining chunks to the others instead of stalling them
  Kokkos::parallel_for(
      label,
      Kokkos::RangePolicy<ExecutionSpace, Kokkos::Schedule<Kokkos::Dynamic>>(space, 0, p.count())
          .set_chunk_size(forceChunk),
      fun);
}

} // namespace detail

/// \brief Forces and torques of particles [0, n) into p.force / p.torque (no integration), e.g. for
/// the set-up evaluation before the first step.
template <class ExecutionSpace, class MemorySpace>
void computeForces(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                   NeighborList<MemorySpace> const& list,
                   WallContactState<MemorySpace> const& walls, ForceSettings const& settings,
                   SliceTable<MemorySpace> const& slices = {}) {
  detail::launchForces<false>(space, p, list, walls, settings, slices, p.velocity,
                              p.angularVelocity, "hikiln::dem::computeForces");
}

/// \brief The contact forces of the current state, for samplers (stress, wall shear): F_n and F_t
/// of every neighbour slot into list.normalForce / list.tangentialForce (zero when not touching)
/// and of every wall slot into walls.normalForce / walls.tangentialForce, all of which must be
/// allocated (NeighborList::allocateOptional(); rows x list.capacity(), and n x wallSlotCount).
/// Evaluated from the positions, velocities and stored history without advancing the history, so
/// nothing of the state changes. Called between steps they are the forces at x^n, v^n; the last
/// step used its half-step velocities, so damping parts differ by O(dt) from the step's values.
template <class ExecutionSpace, class MemorySpace>
void computeContactForces(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                          NeighborList<MemorySpace> const& list,
                          WallContactState<MemorySpace> const& walls, ForceSettings const& settings,
                          SliceTable<MemorySpace> const& slices = {}) {
  if (list.normalForce.extent(0) < p.count() || list.tangentialForce.extent(0) < p.count() ||
      list.normalForce.extent(1) != list.index.extent(1) ||
      list.tangentialForce.extent(1) != list.index.extent(1) ||
      walls.normalForce.extent(0) < p.count() || walls.tangentialForce.extent(0) < p.count()) {
    throw std::invalid_argument("hikiln::dem::computeContactForces: force views not allocated "
                                "to the list's shape");
  }
  detail::launchForces<false, true>(space, p, list, walls, settings, slices, p.velocity,
                                    p.angularVelocity, "hikiln::dem::computeContactForces");
}

/// \brief Forces and torques as computeForces(), fused with the second half kick: velocityOut and
/// angularVelocityOut (distinct from p's Views, which neighbours still read) receive
/// v + dt/2 f/m and omega + dt/2 T/I.
template <class ExecutionSpace, class MemorySpace>
void computeForcesAndKick(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                          NeighborList<MemorySpace> const& list,
                          WallContactState<MemorySpace> const& walls, ForceSettings const& settings,
                          Kokkos::View<double* [2], MemorySpace> const& velocityOut,
                          Kokkos::View<double*, MemorySpace> const& angularVelocityOut,
                          SliceTable<MemorySpace> const& slices = {}) {
  detail::launchForces<true>(space, p, list, walls, settings, slices, velocityOut,
                             angularVelocityOut, "hikiln::dem::computeForcesAndKick");
}

} // namespace hikiln::dem
