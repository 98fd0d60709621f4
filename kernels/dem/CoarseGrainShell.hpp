#pragma once
/// \file CoarseGrainShell.hpp
/// \brief Deposits one sample of the drum-shell contacts into angular bins (WallSum columns):
/// contact normal and shear force, contact count, and the tangential speed of the particles at
/// the shell. Atomics as in CoarseGrainDeposit.hpp (sums agree to round-off across threads).
/// A rough shell's glued discs (ParticleKind::Shell) are part of the shell: the force the bed
/// exerts on each of them (its contact sum, p.force, from the last step) is deposited as a shell
/// contact, and the particles "at the shell" are then the free ones within touchGap of the discs'
/// inner reach (ShellBins::radius set to it by the caller).

#include "kernels/common/Compat.hpp"
#include "kernels/dem/CoarseGrainGrid.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Walls.hpp"

#include <Kokkos_Core.hpp>

namespace hikiln::dem::cg {

/// \brief Angular bins of the shell and how a sample is read.
struct ShellBins {
  double radius = 1.0;     ///< drum radius R (m), or a rough shell's inner reach
  int ntheta = 60;         ///< bins over [0, 2 pi) counter-clockwise from +x
  double touchGap = 0.002; ///< "at the shell": centre farther than R - r - touchGap (m)
  double shearSign = 1.0;  ///< +1 when the shell turns counter-clockwise (or rests), else -1
};

/// \brief +1 for omega >= 0, -1 otherwise: the sign that makes the shear along the shell motion.
KOKKOS_INLINE_FUNCTION double shellMotionSign(double omega) {
  return omega < 0.0 ? -1.0 : 1.0;
}

/// \brief True when a particle at distance rho from the axis counts as touching the shell (the
/// criterion of wallSlip() in solvers/dem/DrumAnalysis.hpp).
KOKKOS_INLINE_FUNCTION bool atShell(double rho, double r, double drumRadius, double touchGap) {
  return rho > drumRadius - r - touchGap;
}

/// \brief Adds one sample to `sums` (bins.ntheta x WallSum::Size) from the drum slot (0) of
/// `walls`. F_t is the tangential force on the particle along t = perp(n), counter-clockwise for
/// the outward normal n: it is the shell's drag on the bed, positive along a counter-clockwise
/// shell motion, hence the shearSign factor.
template <class ExecutionSpace, class MemorySpace>
void depositShell(ExecutionSpace const& space, ShellBins const& bins,
                  ParticleArrays<MemorySpace> const& p, WallContactState<MemorySpace> const& walls,
                  Kokkos::View<double**, MemorySpace> const& sums) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, MemorySpace>::accessible,
                "hikiln::dem::cg::depositShell: particle memory not accessible");
  auto x = p.position;
  auto v = p.velocity;
  auto radius = p.radius;
  auto wallFn = walls.normalForce;
  auto wallFt = walls.tangentialForce;
  auto kind = p.kind;
  auto force = p.force;
  Kokkos::parallel_for(
      "hikiln::dem::cg::depositShell", Kokkos::RangePolicy<ExecutionSpace>(space, 0, p.count()),
      KOKKOS_LAMBDA(int i) {
        const double xi = x(i, 0), yi = x(i, 1);
        const double rho = math::sqrt(xi * xi + yi * yi);
        const bool bed = isFree(kind(i));
        double fn = wallFn(i, 0), ft = wallFt(i, 0);
        if (kind(i) == static_cast<std::uint8_t>(ParticleKind::Shell) && rho > 0.0) {
          // the bed pushes the disc with F: normal load F . n, shear on the bed -F . t
          const double nx = xi / rho, ny = yi / rho;
          fn = force(i, 0) * nx + force(i, 1) * ny;
          ft = -(force(i, 0) * (-ny) + force(i, 1) * nx);
        } else if (!bed) {
          return;
        }
        const bool contact = fn != 0.0 || ft != 0.0;
        const bool near = bed && rho > 0.0 && atShell(rho, radius(i), bins.radius, bins.touchGap);
        if (!contact && !near) {
          return;
        }
        const int b = sectorOf(polarAngle(xi, yi), bins.ntheta);
        if (contact) {
          Kokkos::atomic_add(&sums(b, WallSum::NormalForce), fn);
          Kokkos::atomic_add(&sums(b, WallSum::ShearForce), bins.shearSign * ft);
          Kokkos::atomic_add(&sums(b, WallSum::Contacts), 1.0);
        }
        if (near) {
          Kokkos::atomic_add(&sums(b, WallSum::Touching), 1.0);
          Kokkos::atomic_add(&sums(b, WallSum::SpeedSum), (-yi * v(i, 0) + xi * v(i, 1)) / rho);
        }
      });
}

} // namespace hikiln::dem::cg
