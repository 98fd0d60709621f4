#pragma once
/// \file PrescribedMotion.hpp
/// \brief Motion of the particles attached to the rotating drum shell (ParticleKind::Shell): a
/// rigid rotation about the origin of their home positions (where they were when the system was
/// set up). Positions come from the home position and the shell's rotation angle every step, so
/// the attached ring stays exactly rigid and on its circle however long the run (integrating the
/// circular motion step by step would drift).

#include "kernels/common/Compat.hpp"

#include <Kokkos_Core.hpp>

#include <cstdint>

namespace hikiln::dem {

/// \brief Rotation of the shell at the current step (trivially copyable into kernels). Shell
/// particle ids are firstId + k with home position k of the home View.
struct ShellMotion {
  double cosAngle = 1.0;        ///< cos of the rotation angle since the home positions
  double sinAngle = 0.0;        ///< sin of it
  double angularVelocity = 0.0; ///< rad/s, counter-clockwise positive
  std::int64_t firstId = 0;
};

/// \brief Position (x, y), velocity omega x r and spin omega of a shell particle with home
/// position (hx, hy).
KOKKOS_INLINE_FUNCTION void placeOnShell(const ShellMotion& m, double hx, double hy, double& x,
                                         double& y, double& vx, double& vy, double& w) {
  x = m.cosAngle * hx - m.sinAngle * hy;
  y = m.sinAngle * hx + m.cosAngle * hy;
  vx = -m.angularVelocity * y;
  vy = m.angularVelocity * x;
  w = m.angularVelocity;
}

} // namespace hikiln::dem
