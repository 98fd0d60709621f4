#pragma once
/// \file BlockyForceKernel.hpp
/// \brief Contact, wall and gravity forces of blocky (superquadric) particles from their full
/// neighbour rows, as ForceKernel.hpp does for discs: each particle sums its own force and torque
/// in neighbour-id order (no atomics, thread-count independent).
///
/// Broad phase: the neighbour list on bounding circles (ParticleArrays::radius = bounding radius);
/// a slot is tested with the bounding circles before the narrow phase (SuperquadricContact.hpp).
/// The contact law, the tangential history per slot and the infinite-mass rule for fixed
/// particles are the disc engine's (ContactLaw.hpp). Torques use the lever from the centre to the
/// contact point, r x F.
///
/// Pair symmetry: a pair of non-circles is always evaluated with the lower id as the first body,
/// so both rows get bitwise the same frame, force and history, and the forces are exactly
/// opposite. A pair of circles takes the disc engine's pairFrame() from the row owner's side and
/// the torque r F_t, so an all-circle system reproduces DemSystem bitwise.
///
/// Each pair of non-circles is evaluated once per step (the narrow phase is the cost): a first
/// pass (BlockyPairFunctor) evaluates it in the lower id's row and writes each side's force and
/// torque and the updated history into the pair's slot in both rows (BlockyPairOutcomes; each
/// slot has that one writer); the second pass (BlockyForceFunctor) sums each row in neighbour
/// order from its own slots. The sums are bitwise those of every row evaluating its pairs with
/// BlockyContacts::pair() (tstBlockyForcePasses.hpp).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/BlockyArrays.hpp"
#include "kernels/dem/CoarseGrainContact.hpp"
#include "kernels/dem/ContactLaw.hpp"
#include "kernels/dem/ForceKernel.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/SuperquadricContact.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

#include <stdexcept>

namespace hikiln::dem {

namespace detail {

/// \brief Offset of a stored angle (NeighborList::normalAngle, see encodeAngle()).
inline constexpr double storedAngleOffset = 8.0;

/// \brief Slot value of a pair's direction phi: +(phi' + offset) for a contact normal, -(phi' +
/// offset) for a separating axis, with phi' = phi wrapped into [-pi, pi], so that 0 means none.
KOKKOS_INLINE_FUNCTION double encodeAngle(double phi, bool normal) {
  const double turn = 2.0 * constants::pi;
  const double wrapped = phi - turn * math::floor(phi / turn + 0.5);
  return normal ? wrapped + storedAngleOffset : -(wrapped + storedAngleOffset);
}

/// \brief The angle of a slot value (see encodeAngle()); 0 for none.
KOKKOS_INLINE_FUNCTION double decodeAngle(double stored) {
  return stored > 0.0 ? stored - storedAngleOffset
                      : (stored < 0.0 ? -stored - storedAngleOffset : 0.0);
}

/// \brief Views of a blocky system and the per-slot / per-wall contact evaluation shared by the
/// force and energy kernels.
template <class MemorySpace> struct BlockyContacts {
  using Vec = Kokkos::View<double* [2], MemorySpace>;
  using Scalar = Kokkos::View<double*, MemorySpace>;
  Vec x, v;
  Scalar w, radius, mass;
  Vec axis; ///< (cos, sin) of the orientations (BlockyArrays::axis)
  Kokkos::View<SuperquadricShape*, MemorySpace> shape;
  Kokkos::View<std::int64_t*, MemorySpace> id;
  Kokkos::View<std::uint8_t*, MemorySpace> kind;
  Kokkos::View<int*, MemorySpace> count;
  Kokkos::View<int**, MemorySpace> index;
  Kokkos::View<double**, MemorySpace> shear;
  Kokkos::View<double**, MemorySpace> normalAngle; ///< empty: no warm starts
  Kokkos::View<double* [wallSlotCount], MemorySpace> wallShear;
  ForceSettings s;
  int capacity = 0;

  /// \brief Body axis of particle i.
  KOKKOS_INLINE_FUNCTION BodyAxis axisOf(int i) const { return BodyAxis{axis(i, 0), axis(i, 1)}; }

  /// \brief What a slot holds before the narrow phase: bounding circles apart or both particles
  /// fixed (Apart, no contact), two circles (the disc engine's formula) or a pair for the
  /// superquadric narrow phase.
  enum class PairKind : int { Apart, Circles, Shapes };

  /// \brief The PairKind of particles i and j (no velocity loads).
  KOKKOS_INLINE_FUNCTION PairKind screen(int i, int j) const {
    const double dx = s.periodic.minimumImage(x(j, 0) - x(i, 0));
    const double dy = x(j, 1) - x(i, 1);
    const double radsum = radius(i) + radius(j);
    if (!(dx * dx + dy * dy < radsum * radsum) || !(isFree(kind(i)) || isFree(kind(j)))) {
      return PairKind::Apart;
    }
    return isCircle(shape(i)) && isCircle(shape(j)) ? PairKind::Circles : PairKind::Shapes;
  }

  /// \brief Contact of row owner i with neighbour j. On contact: the frame as seen by the first
  /// body (i for circles, else the lower id; iFirst says which), the contact force and i's
  /// force and torque from it. Returns false (nothing else set) when not touching. angle: the
  /// slot's stored direction (encodeAngle() of the pair's last normal or separating axis, seen
  /// from the lower id; 0: none), updated to this evaluation's (0 for circles, bounding circles or
  /// rectangles apart). lx, ly: i's lever to the contact point as the coarse-graining takes it
  /// (non-circles: the torque's lever; circles: (r_i - overlap / 2) n, as CoarseGrainContact.hpp).
  KOKKOS_INLINE_FUNCTION bool pair(int i, int j, double shearOld, bool updateHistory,
                                   ContactFrame& frame, ContactForce& c, double& fx, double& fy,
                                   double& t, double& angle, double& lx, double& ly) const {
    return pairOfKind(screen(i, j), i, j, shearOld, updateHistory, frame, c, fx, fy, t, angle, lx,
                      ly);
  }

  /// \brief pair() with the pair's screen() result.
  KOKKOS_INLINE_FUNCTION bool pairOfKind(PairKind pairKind, int i, int j, double shearOld,
                                         bool updateHistory, ContactFrame& frame, ContactForce& c,
                                         double& fx, double& fy, double& t, double& angle,
                                         double& lx, double& ly) const {
    if (pairKind != PairKind::Shapes) { // apart pairs and circles keep no direction
      angle = 0.0;
    }
    if (pairKind == PairKind::Apart) {
      return false;
    }
    if (pairKind == PairKind::Circles) { // the disc engine, from i's side
      const double ri = radius(i), rj = radius(j);
      const double dx = s.periodic.minimumImage(x(j, 0) - x(i, 0));
      const double dy = x(j, 1) - x(i, 1);
      const bool freeI = isFree(kind(i)), freeJ = isFree(kind(j));
      const double wi = w(i), wj = w(j);
      if (!pairFrame(dx, dy, v(j, 0) - v(i, 0), v(j, 1) - v(i, 1), ri, rj, wi, wj, frame)) {
        return false;
      }
      const double rr = s.particle.rolling ? rollingRadius(ri, rj) : 0.0;
      c = evaluateContact(s.particle, frame, pairEffectiveMass(mass(i), freeI, mass(j), freeJ), rr,
                          wi - wj, shearOld, s.dt, updateHistory);
      fx = -c.normal * frame.nx + c.tangential * (-frame.ny);
      fy = -c.normal * frame.ny + c.tangential * frame.nx;
      t = ri * c.tangential + c.rollingTorque;
      lx = cg::contactBranchLength(ri, frame.overlap) * frame.nx; // the disc coarse-graining's
      ly = cg::contactBranchLength(ri, frame.overlap) * frame.ny;
      return true;
    }
    const bool iFirst = id(i) < id(j);
    PairContact pc;
    if (!orderedPair(iFirst ? i : j, iFirst ? j : i, shearOld, updateHistory, pc, c, angle)) {
      return false;
    }
    frame = pc.frame;
    side(pc, c, iFirst, fx, fy, t, lx, ly);
    return true;
  }

  /// \brief A pair of non-circles with a the lower id (the first body) whose bounding circles
  /// overlap and of which one is free: pc (frame seen by a, levers) and c on contact. angle: the
  /// slot's stored direction in, this evaluation's out (as pair()).
  KOKKOS_INLINE_FUNCTION bool orderedPair(int a, int b, double shearOld, bool updateHistory,
                                          PairContact& pc, ContactForce& c, double& angle) const {
    const double stored = angle;
    const double abx = s.periodic.minimumImage(x(b, 0) - x(a, 0));
    const double aby = x(b, 1) - x(a, 1);
    const PairGuess guessKind =
        stored > 0.0 ? PairGuess::Normal : (stored < 0.0 ? PairGuess::Axis : PairGuess::None);
    const double guess = guessKind == PairGuess::Normal
                             ? spunNormalGuess(decodeAngle(stored), w(a), w(b), s.dt)
                             : decodeAngle(stored);
    const bool touching =
        blockyPairContact(shape(a), axisOf(a), shape(b), axisOf(b), abx, aby, v(b, 0) - v(a, 0),
                          v(b, 1) - v(a, 1), w(a), w(b), pc, guessKind, guess);
    angle = pc.axis ? encodeAngle(pc.angle, touching) : 0.0;
    if (!touching) {
      return false;
    }
    const double rr = s.particle.rolling ? rollingRadius(radius(a), radius(b)) : 0.0;
    c = evaluateContact(s.particle, pc.frame,
                        pairEffectiveMass(mass(a), isFree(kind(a)), mass(b), isFree(kind(b))), rr,
                        w(a) - w(b), shearOld, s.dt, updateHistory);
    return true;
  }

  /// \brief Force, torque and lever of the first body (first) or of the second from an
  /// orderedPair() contact; the second body's force is the exact opposite.
  KOKKOS_INLINE_FUNCTION static void side(const PairContact& pc, const ContactForce& c, bool first,
                                          double& fx, double& fy, double& t, double& lx,
                                          double& ly) {
    const double sign = first ? 1.0 : -1.0;
    fx = sign * (-c.normal * pc.frame.nx + c.tangential * (-pc.frame.ny));
    fy = sign * (-c.normal * pc.frame.ny + c.tangential * pc.frame.nx);
    lx = first ? pc.rAx : pc.rBx;
    ly = first ? pc.rAy : pc.rBy;
    t = lx * fy - ly * fx + sign * c.rollingTorque;
  }

  /// \brief The slot of i in row j (-1 when j's row lacks it: a truncated row).
  KOKKOS_INLINE_FUNCTION int partnerSlot(int j, int i) const {
    const int n = count(j) < capacity ? count(j) : capacity;
    for (int m = 0; m < n; ++m) {
      if (index(j, m) == i) {
        return m;
      }
    }
    return -1;
  }

  /// \brief Contact of particle i with wall slot `slot` (0 drum, 1 + k flat wall k); as pair().
  KOKKOS_INLINE_FUNCTION bool wall(int i, int slot, double shearOld, bool updateHistory,
                                   ContactFrame& frame, ContactForce& c, double& fx, double& fy,
                                   double& t, double& lx, double& ly) const {
    if (!isFree(kind(i))) {
      return false;
    }
    const SuperquadricShape si = shape(i);
    const double ri = radius(i), wi = w(i);
    const bool touching = slot == 0
                              ? blockyDrumContact(si, axisOf(i), ri, s.walls.drum, x(i, 0), x(i, 1),
                                                  v(i, 0), v(i, 1), wi, frame, lx, ly)
                              : blockyFlatContact(si, axisOf(i), s.walls.flat[slot - 1], x(i, 0),
                                                  x(i, 1), v(i, 0), v(i, 1), wi, frame, lx, ly);
    if (!touching) {
      return false;
    }
    const double spin = slot == 0 ? wi - s.walls.drum.angularVelocity : wi;
    c = evaluateContact(s.wall, frame, mass(i), ri, spin, shearOld, s.dt, updateHistory);
    fx = -c.normal * frame.nx + c.tangential * (-frame.ny);
    fy = -c.normal * frame.ny + c.tangential * frame.nx;
    if (isCircle(si)) {
      t = ri * c.tangential + c.rollingTorque;
      lx = cg::contactBranchLength(ri, frame.overlap) * frame.nx; // the disc coarse-graining's
      ly = cg::contactBranchLength(ri, frame.overlap) * frame.ny;
    } else {
      t = lx * fy - ly * fx + c.rollingTorque;
    }
    return true;
  }
};

/// \brief A slot's pair of non-circles as the first pass left it for the row owner: its force
/// and torque from the pair, and whether it was evaluated (cleared by the second pass).
struct PairOutcome {
  double fx = 0.0, fy = 0.0, torque = 0.0;
  int state = 0; ///< 0: not evaluated, 1: evaluated, apart, 2: evaluated, touching
};

/// \brief First pass: each pair of non-circles (PairKind::Shapes) evaluated once, in the row of
/// its lower id with that slot's history; the outcome and the updated history go to the slots of
/// the pair in both rows (each slot has one writer: the pair's lower id).
template <class MemorySpace> struct BlockyPairFunctor {
  BlockyContacts<MemorySpace> b;
  Kokkos::View<PairOutcome**, MemorySpace> outcome;
  using PairKind = typename BlockyContacts<MemorySpace>::PairKind;

  KOKKOS_INLINE_FUNCTION void operator()(int i) const {
    const int n = b.count(i) < b.capacity ? b.count(i) : b.capacity;
    const bool warm = b.normalAngle.extent(0) > 0;
    const bool circle = isCircle(b.shape(i));
    for (int k = 0; k < n; ++k) {
      const int j = b.index(i, k);
      if (!(b.id(i) < b.id(j)) || (circle && isCircle(b.shape(j))) ||
          b.screen(i, j) != PairKind::Shapes) {
        continue; // the partner's row evaluates it, or the second pass does (see there)
      }
      const int m = b.partnerSlot(j, i);
      if (m < 0) {
        continue; // j's row lacks i (not in a full list): each row evaluates it in the second pass
      }
      PairOutcome first, second;
      first.state = second.state = 1;
      double angle = warm ? b.normalAngle(i, k) : 0.0;
      PairContact pc;
      ContactForce c;
      const bool touching = b.orderedPair(i, j, b.shear(i, k), b.s.updateHistory, pc, c, angle);
      if (touching) {
        double lx, ly;
        b.side(pc, c, true, first.fx, first.fy, first.torque, lx, ly);
        b.side(pc, c, false, second.fx, second.fy, second.torque, lx, ly);
        first.state = second.state = 2;
      }
      outcome(i, k) = first;
      outcome(j, m) = second;
      if (warm) {
        b.normalAngle(i, k) = angle;
        b.normalAngle(j, m) = angle;
      }
      const double shear = touching ? c.shear : 0.0; // history ends with the contact
      b.shear(i, k) = shear;
      b.shear(j, m) = shear;
    }
  }
};

/// \brief Second pass: each particle's force and torque summed over its row in neighbour order
/// (pairs of non-circles from the first pass; circles, and pairs apart, evaluated here as
/// pair() does), walls and gravity.
template <class MemorySpace> struct BlockyForceFunctor {
  BlockyContacts<MemorySpace> b;
  Kokkos::View<PairOutcome**, MemorySpace> outcome;
  Kokkos::View<double* [2], MemorySpace> f;
  Kokkos::View<double*, MemorySpace> tq;
  using PairKind = typename BlockyContacts<MemorySpace>::PairKind;

  KOKKOS_INLINE_FUNCTION void operator()(int i) const {
    double fx = 0.0, fy = 0.0, t = 0.0;
    const int n = b.count(i) < b.capacity ? b.count(i) : b.capacity;
    const bool warm = b.normalAngle.extent(0) > 0;
    for (int k = 0; k < n; ++k) { // ascending neighbour id: a fixed summation order
      const int j = b.index(i, k);
      const PairKind pairKind = b.screen(i, j);
      if (pairKind == PairKind::Shapes && outcome(i, k).state != 0) {
        const PairOutcome o = outcome(i, k);
        outcome(i, k).state = 0;
        if (o.state == 2) {
          fx += o.fx;
          fy += o.fy;
          t += o.torque;
        }
        continue;
      }
      ContactFrame frame; // circles, pairs apart, or a slot the partner's row lacks
      ContactForce c;
      double px = 0.0, py = 0.0, pt = 0.0, lx = 0.0, ly = 0.0;
      double angle = warm ? b.normalAngle(i, k) : 0.0;
      const bool touching = b.pairOfKind(pairKind, i, j, b.shear(i, k), b.s.updateHistory, frame, c,
                                         px, py, pt, angle, lx, ly);
      if (warm && angle != b.normalAngle(i, k)) { // circle rows stay 0: no stores
        b.normalAngle(i, k) = angle;
      }
      if (touching) {
        b.shear(i, k) = c.shear;
        fx += px;
        fy += py;
        t += pt;
      } else if (b.shear(i, k) != 0.0) { // history ends with the contact
        b.shear(i, k) = 0.0;
      }
    }
    const int slots = 1 + b.s.walls.numFlat;
    for (int slot = b.s.walls.drum.enabled ? 0 : 1; slot < slots; ++slot) {
      ContactFrame frame;
      ContactForce c;
      double px = 0.0, py = 0.0, pt = 0.0, lx = 0.0, ly = 0.0;
      if (b.wall(i, slot, b.wallShear(i, slot), b.s.updateHistory, frame, c, px, py, pt, lx, ly)) {
        b.wallShear(i, slot) = c.shear;
        fx += px;
        fy += py;
        t += pt;
      } else if (b.wallShear(i, slot) != 0.0) {
        b.wallShear(i, slot) = 0.0;
      }
    }
    if (isFree(b.kind(i))) {
      fx += b.mass(i) * b.s.gravityX;
      fy += b.mass(i) * b.s.gravityY;
    }
    f(i, 0) = fx;
    f(i, 1) = fy;
    tq(i) = t;
  }
};

/// \brief Elastic energy of the contacts (k_n delta^2 + k_t shear^2) / 2, pairs counted half from
/// each side.
template <class MemorySpace> struct BlockyElasticFunctor {
  BlockyContacts<MemorySpace> b;
  bool walls = false; ///< false: particle pairs, true: wall contacts

  KOKKOS_INLINE_FUNCTION void operator()(int i, double& sum) const {
    ContactFrame frame;
    ContactForce c;
    double fx, fy, t, lx, ly;
    if (!walls) {
      const int n = b.count(i) < b.capacity ? b.count(i) : b.capacity;
      for (int k = 0; k < n; ++k) {
        const double xi = b.shear(i, k);
        double angle = b.normalAngle.extent(0) > 0 ? b.normalAngle(i, k) : 0.0; // not stored
        if (b.pair(i, b.index(i, k), xi, false, frame, c, fx, fy, t, angle, lx, ly)) {
          sum +=
              0.25 * (b.s.particle.kn * frame.overlap * frame.overlap + b.s.particle.kt * xi * xi);
        }
      }
      return;
    }
    for (int slot = b.s.walls.drum.enabled ? 0 : 1; slot < 1 + b.s.walls.numFlat; ++slot) {
      const double xi = b.wallShear(i, slot);
      if (b.wall(i, slot, xi, false, frame, c, fx, fy, t, lx, ly)) {
        sum += 0.5 * (b.s.wall.kn * frame.overlap * frame.overlap + b.s.wall.kt * xi * xi);
      }
    }
  }
};

/// \brief Sampling evaluation (nothing of the state changes): F_n, F_t per neighbour and wall slot
/// (zero when not touching; F_t along the row owner's t) and the particle's contact virial
/// sum (x_c - x_i) (x) f_i (xx, xy, yx, yy; tension positive), with the levers of pair() / wall().
template <class MemorySpace> struct BlockySampleFunctor {
  BlockyContacts<MemorySpace> b;
  Kokkos::View<double**, MemorySpace> slotFn, slotFt;
  Kokkos::View<double*[wallSlotCount], MemorySpace> wallFn, wallFt;
  Kokkos::View<double* [4], MemorySpace> virial;

  KOKKOS_INLINE_FUNCTION void operator()(int i) const {
    double wxx = 0.0, wxy = 0.0, wyx = 0.0, wyy = 0.0;
    const auto add = [&](double lx, double ly, double fx, double fy) {
      wxx += lx * fx;
      wxy += lx * fy;
      wyx += ly * fx;
      wyy += ly * fy;
    };
    const int n = b.count(i) < b.capacity ? b.count(i) : b.capacity;
    const bool warm = b.normalAngle.extent(0) > 0;
    for (int k = 0; k < n; ++k) {
      ContactFrame frame;
      ContactForce c;
      double fx = 0.0, fy = 0.0, t = 0.0, lx = 0.0, ly = 0.0;
      double angle = warm ? b.normalAngle(i, k) : 0.0; // a local copy: not stored
      const bool touching =
          b.pair(i, b.index(i, k), b.shear(i, k), false, frame, c, fx, fy, t, angle, lx, ly);
      slotFn(i, k) = touching ? c.normal : 0.0;
      slotFt(i, k) = touching ? c.tangential : 0.0;
      if (touching) {
        add(lx, ly, fx, fy);
      }
    }
    for (int slot = 0; slot < wallSlotCount; ++slot) {
      ContactFrame frame;
      ContactForce c;
      double fx = 0.0, fy = 0.0, t = 0.0, lx = 0.0, ly = 0.0;
      const bool present = slot == 0 ? b.s.walls.drum.enabled : slot <= b.s.walls.numFlat;
      const bool touching =
          present && b.wall(i, slot, b.wallShear(i, slot), false, frame, c, fx, fy, t, lx, ly);
      wallFn(i, slot) = touching ? c.normal : 0.0;
      wallFt(i, slot) = touching ? c.tangential : 0.0;
      if (touching) {
        add(lx, ly, fx, fy);
      }
    }
    virial(i, 0) = wxx;
    virial(i, 1) = wxy;
    virial(i, 2) = wyx;
    virial(i, 3) = wyy;
  }
};

template <class MemorySpace>
BlockyContacts<MemorySpace>
blockyContacts(ParticleArrays<MemorySpace> const& p, BlockyArrays<MemorySpace> const& blocky,
               NeighborList<MemorySpace> const& list, WallContactState<MemorySpace> const& walls,
               ForceSettings const& settings) {
  BlockyContacts<MemorySpace> b;
  b.x = p.position;
  b.v = p.velocity;
  b.w = p.angularVelocity;
  b.radius = p.radius;
  b.mass = p.mass;
  b.axis = blocky.axis;
  b.shape = blocky.shape;
  b.id = p.id;
  b.kind = p.kind;
  b.count = list.count;
  b.index = list.index;
  b.shear = list.shear;
  b.normalAngle = list.normalAngle;
  b.wallShear = walls.shear;
  b.s = settings;
  b.capacity = list.capacity();
  return b;
}

} // namespace detail

/// \brief Per-slot scratch of the first force pass (see the file comment); computeBlockyForces()
/// sizes it to the neighbour list.
template <class MemorySpace>
using BlockyPairOutcomes = Kokkos::View<detail::PairOutcome**, MemorySpace>;

/// \brief Forces and torques of blocky particles [0, n) into p.force / p.torque; `outcomes` is
/// reallocated when it does not match the list's shape. Its circle branch gives bitwise the
/// forces, torques and histories of the disc engine's computeForces() (tstBlockyForcePasses.hpp),
/// so a system of circles only calls that instead (DemSystem::evaluateForces): this kernel's
/// per-slot shape and direction bookkeeping made an all-circle drum about twice as slow.
template <class ExecutionSpace, class MemorySpace>
void computeBlockyForces(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                         BlockyArrays<MemorySpace> const& blocky,
                         NeighborList<MemorySpace> const& list,
                         WallContactState<MemorySpace> const& walls, ForceSettings const& settings,
                         BlockyPairOutcomes<MemorySpace>& outcomes) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::computeBlockyForces: particle memory not accessible");
  if (outcomes.extent(0) != list.rows() ||
      outcomes.extent(1) != static_cast<std::size_t>(list.capacity())) {
    outcomes = BlockyPairOutcomes<MemorySpace>(
        Kokkos::view_alloc(space, std::string("hikiln::dem::pairOutcomes")), // zero: not evaluated
        list.rows(), list.capacity());
  }
  const auto contacts = detail::blockyContacts(p, blocky, list, walls, settings);
  const auto policy =
      Kokkos::RangePolicy<ExecutionSpace, Kokkos::Schedule<Kokkos::Dynamic>>(space, 0, p.count())
          .set_chunk_size(detail::forceChunk);
  Kokkos::parallel_for("hikiln::dem::blockyPairs", policy,
                       detail::BlockyPairFunctor<MemorySpace>{contacts, outcomes});
  Kokkos::parallel_for(
      "hikiln::dem::computeBlockyForces", policy,
      detail::BlockyForceFunctor<MemorySpace>{contacts, outcomes, p.force, p.torque});
}

/// \brief The contact forces of the current state for samplers, as computeContactForces() for
/// discs (list.normalForce / tangentialForce, walls.normalForce / tangentialForce allocated to the
/// list's shape), plus each particle's contact virial into `virial` (n x 4: xx, xy, yx, yy).
template <class ExecutionSpace, class MemorySpace>
void computeBlockyContactForces(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                                BlockyArrays<MemorySpace> const& blocky,
                                NeighborList<MemorySpace> const& list,
                                WallContactState<MemorySpace> const& walls,
                                ForceSettings const& settings,
                                Kokkos::View<double* [4], MemorySpace> const& virial) {
  if (list.normalForce.extent(0) < p.count() ||
      list.normalForce.extent(1) != list.index.extent(1) ||
      list.tangentialForce.extent(1) != list.index.extent(1) ||
      walls.normalForce.extent(0) < p.count() || virial.extent(0) < p.count()) {
    throw std::invalid_argument("hikiln::dem::computeBlockyContactForces: force or virial views "
                                "not allocated to the list's shape");
  }
  detail::BlockySampleFunctor<MemorySpace> fun{
      detail::blockyContacts(p, blocky, list, walls, settings),
      list.normalForce,
      list.tangentialForce,
      walls.normalForce,
      walls.tangentialForce,
      virial};
  Kokkos::parallel_for(
      "hikiln::dem::computeBlockyContactForces",
      Kokkos::RangePolicy<ExecutionSpace, Kokkos::Schedule<Kokkos::Dynamic>>(space, 0, p.count())
          .set_chunk_size(detail::forceChunk),
      fun);
}

/// \brief Elastic energy of the particle pairs (first) and of the wall contacts (second) with the
/// stored histories.
template <class ExecutionSpace, class MemorySpace>
Kokkos::pair<double, double>
blockyElasticEnergy(ExecutionSpace const& space, ParticleArrays<MemorySpace> const& p,
                    BlockyArrays<MemorySpace> const& blocky, NeighborList<MemorySpace> const& list,
                    WallContactState<MemorySpace> const& walls, ForceSettings const& settings) {
  const auto contacts = detail::blockyContacts(p, blocky, list, walls, settings);
  const auto policy = Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count());
  double pairs = 0.0, wall = 0.0;
  Kokkos::parallel_reduce("hikiln::dem::blockyElasticPairs", policy,
                          detail::BlockyElasticFunctor<MemorySpace>{contacts, false}, pairs);
  Kokkos::parallel_reduce("hikiln::dem::blockyElasticWalls", policy,
                          detail::BlockyElasticFunctor<MemorySpace>{contacts, true}, wall);
  return {pairs, wall};
}

} // namespace hikiln::dem
