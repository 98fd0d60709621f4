#pragma once
/// \file Walls.hpp
/// \brief Analytic walls: the rotating drum (circle about the origin, particles inside) and flat
/// walls (lines), with per-particle contact history in WallContactState.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/ContactLaw.hpp"

#include <Kokkos_Core.hpp>

#include <string>

namespace hikiln::dem {

/// \brief Most flat walls a WallSet can hold.
inline constexpr int maxFlatWalls = 4;
/// \brief Wall history slots per particle: slot 0 is the drum, slot 1 + k flat wall k.
inline constexpr int wallSlotCount = 1 + maxFlatWalls;

/// \brief Rigid circular shell of radius `radius` centred at the origin, particles inside,
/// rotating at angularVelocity (rad/s, counter-clockwise positive).
struct DrumWall {
  bool enabled = false;
  double radius = 1.0;
  double angularVelocity = 0.0;
};

/// \brief Rigid straight wall through (pointX, pointY) with unit normal (normalX, normalY) pointing
/// into the particle side; its surface slides at tangentialVelocity along (normalY, -normalX)
/// (+x for a floor with normal +y). Analytic walls are smooth: a rough wall is built from glued
/// discs (ParticleKind::Fixed, e.g. a chute base, or ParticleKind::Shell on the drum), which meet
/// the flow through the ordinary particle contact law.
struct FlatWall {
  double pointX = 0.0, pointY = 0.0;
  double normalX = 0.0, normalY = 1.0;
  double tangentialVelocity = 0.0;
};

/// \brief All analytic walls of a system (trivially copyable into kernels).
struct WallSet {
  DrumWall drum;
  int numFlat = 0;
  FlatWall flat[maxFlatWalls];
};

/// \brief Per-particle wall contact state: history and the last evaluated forces, one column per
/// wall slot (see wallSlotCount).
template <class MemorySpace> struct WallContactState {
  using memory_space = MemorySpace;
  Kokkos::View<double* [wallSlotCount], MemorySpace> shear;           ///< tangential history (m)
  Kokkos::View<double* [wallSlotCount], MemorySpace> normalForce;     ///< last F_n (N)
  Kokkos::View<double* [wallSlotCount], MemorySpace> tangentialForce; ///< last F_t along t (N)

  WallContactState() = default;
  /// \brief Zero-filled state for `capacity` particles; props go to Kokkos::view_alloc.
  template <class... Props>
  explicit WallContactState(std::size_t capacity, Props const&... props)
      : shear(Kokkos::view_alloc(props..., std::string("hikiln::dem::wallShear")), capacity),
        normalForce(Kokkos::view_alloc(props..., std::string("hikiln::dem::wallNormalForce")),
                    capacity),
        tangentialForce(
            Kokkos::view_alloc(props..., std::string("hikiln::dem::wallTangentialForce")),
            capacity) {}
};

/// \brief Contact frame of a particle (centre x, y, velocity vx, vy, spin w, radius r) with the
/// drum; false when not touching. The wall surface velocity is omega x (R n) at the contact point.
KOKKOS_INLINE_FUNCTION bool drumFrame(const DrumWall& drum, double x, double y, double vx,
                                      double vy, double w, double r, ContactFrame& f) {
  const double d2 = x * x + y * y;
  const double reach = drum.radius - r; // contact when |x| > R - r
  if (reach > 0.0 && !(d2 > reach * reach)) {
    return false;
  }
  if (d2 == 0.0) {
    return false;
  }
  const double d = math::sqrt(d2);
  f.nx = x / d;
  f.ny = y / d;
  f.overlap = r - (drum.radius - d);
  const double wallSpeed = drum.angularVelocity * drum.radius; // along t = perp(n)
  const double spin = w * r;
  const double vrx = -vx - (spin - wallSpeed) * (-f.ny);
  const double vry = -vy - (spin - wallSpeed) * f.nx;
  f.normalSpeed = vrx * f.nx + vry * f.ny;
  f.tangentialSpeed = vrx * (-f.ny) + vry * f.nx;
  return true;
}

/// \brief Contact frame of a particle with a flat wall; false when not touching.
KOKKOS_INLINE_FUNCTION bool flatFrame(const FlatWall& wall, double x, double y, double vx,
                                      double vy, double w, double r, ContactFrame& f) {
  const double dist = (x - wall.pointX) * wall.normalX + (y - wall.pointY) * wall.normalY;
  if (!(dist < r)) {
    return false;
  }
  f.nx = -wall.normalX;
  f.ny = -wall.normalY;
  f.overlap = r - dist;
  // t = perp(n) = (normalY, -normalX): the wall surface velocity along t is tangentialVelocity
  const double spin = w * r;
  const double wallSpeed = wall.tangentialVelocity;
  const double vrx = -vx - (spin - wallSpeed) * (-f.ny);
  const double vry = -vy - (spin - wallSpeed) * f.nx;
  f.normalSpeed = vrx * f.nx + vry * f.ny;
  f.tangentialSpeed = vrx * (-f.ny) + vry * f.nx;
  return true;
}

} // namespace hikiln::dem
