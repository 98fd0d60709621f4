#pragma once
/// \file DrumAnalysis.hpp
/// \brief Bed measures of a rotating-drum snapshot, defined exactly as the LAMMPS reference
/// analysis
/// (../shared/reference/lammps-drum2d-analyse.py) so the two codes are compared like for like.

#include "kernels/dem/ParticleArrays.hpp"

namespace hikiln::dem {

/// \brief Radius the bed meets the shell at: drumRadius for a smooth shell, the inner reach of the
/// shell-attached discs (the smallest |x| - r among them) for a rough one.
double shellInnerRadius(const ParticleArrays<Kokkos::HostSpace>& p, double drumRadius);

/// \brief Wall slip = 1 - <v_theta of particles touching the shell> / (omega R), as a fraction.
/// "Touching": centre farther than R - r - touchGap from the axis. NaN if none touch or omega = 0.
/// Only free particles count. With a rough shell R is shellInnerRadius() instead of drumRadius:
/// the first free layer rides on the bump tops, which move at omega times that radius.
double wallSlip(const ParticleArrays<Kokkos::HostSpace>& p, double drumRadius, double omega,
                double touchGap = 0.002);

/// \brief Slope of the free surface (degrees, positive when the surface rises towards +x): a least
/// squares line through the highest particle centre per x-bin of width binWidth over the middle
/// 60 % of the bed's x extent, free particles only. NaN with fewer than 4 bins.
double surfaceAngleDegrees(const ParticleArrays<Kokkos::HostSpace>& p, double binWidth = 0.04);

} // namespace hikiln::dem
