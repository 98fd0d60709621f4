#pragma once
/// \file GranularRheology.hpp
/// \brief The viscous-plastic Drucker-Prager bed rheology with strain-rate dependent friction
/// m(gamma_dot) (physics.md 3), the Newtonian gas, and their per-cell kernels (strain-rate
/// invariant, mixture viscosity).
///
/// Convention (the DEM coarse-graining's, kernels/dem/CoarseGrainInvariants.hpp): compressive
/// positive stress, p = sigma_ii / d, q = sqrt(s_ij s_ij / 2) of the deviator s, and the
/// strain-rate invariant gamma_dot = sqrt(2 D':D') (D' the deviator of D). With s = 2 eta D' this
/// gives q = eta gamma_dot, so eta = m p / gamma_dot puts every flowing cell on the yield surface
/// q = m p, and in simple shear tau / sigma_n = q / p = m = tan(phi).
///
/// Law: m(gamma_dot) = m0 + m1 gamma_dot (the calibration file's `rheology` section), i.e. a
/// Bingham fluid with yield stress m0 p and plastic viscosity m1 p at given p;
///   eta_bed = min(max(m(gamma_dot) p / max(gamma_dot, strainRateFloor), viscosityMin),
///                 viscosityMax),
/// regularised below strainRateFloor (a bi-viscous plug), capped at viscosityMax and floored at
/// viscosityMin; all are parameters (defaults 1e-3 1/s, 1e5 Pa s and 0). The floor matters
/// where the bed pressure is 0 (the surface, or a bed in tension): there the law alone leaves
/// the bed without any viscosity. Under the incremental projection the 30 % drum at 128 x 128
/// cells burst at the shell in such a region (docs/compare.md); 10 Pa s stopped that. Wall layer
/// (cells cut by the shell): m = min(m(gamma_dot), muWall), so the shear stress the bed transmits
/// across that layer does not exceed the Coulomb wall friction either (the friction itself is the
/// capped wall drag of ProjectionKernels.hpp; measured alone, this cap changed the wall slip by < 2
/// %). Mixture: mu = muGas + (phi / phiMax) eta_bed (phi clamped to [0, phiMax]).

#include "kernels/cfd/GhostFill.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/SplitLoop.hpp"
#include "kernels/cfd/ViscousOperator.hpp"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace hikiln::cfd {

/// \brief Parameters of the bed and gas rheology (see the file comment).
struct GranularRheology {
  double m0 = 0.5;               ///< friction m at zero strain rate [1]
  double m1 = 0.0;               ///< dm / d gamma_dot [s] (m is floored at 0)
  double strainRateFloor = 1e-3; ///< regularisation of gamma_dot -> 0 [1/s]
  double viscosityMax = 1e5;     ///< cap of the bed viscosity [Pa s]
  double viscosityMin = 0.0;     ///< floor of the bed viscosity [Pa s]
  double muWall = 0.3;           ///< bed-shell Coulomb friction coefficient
  double gasViscosity = 1.8e-5;  ///< Newtonian gas [Pa s]
  double phiMax = 0.6;           ///< solids volume fraction of the settled bed

  /// \brief m(gamma_dot), never negative.
  KOKKOS_INLINE_FUNCTION double friction(double gammaDot) const {
    return math::fmax(m0 + m1 * gammaDot, 0.0);
  }
  /// \brief Bed viscosity at bed pressure p and strain rate gammaDot (wall: Coulomb wall layer).
  KOKKOS_INLINE_FUNCTION double bedViscosity(double p, double gammaDot, bool wall) const {
    const double m = wall ? math::fmin(friction(gammaDot), muWall) : friction(gammaDot);
    return math::fmin(
        math::fmax(m * math::fmax(p, 0.0) / math::fmax(gammaDot, strainRateFloor), viscosityMin),
        viscosityMax);
  }
  /// \brief Mixture viscosity at solids fraction phi.
  KOKKOS_INLINE_FUNCTION double mixtureViscosity(double phi, double p, double gammaDot,
                                                 bool wall) const {
    const double s = math::fmin(math::fmax(phi / phiMax, 0.0), 1.0);
    return gasViscosity + s * bedViscosity(p, gammaDot, wall);
  }
  /// \brief Throws std::invalid_argument naming the first bad parameter (`who` prefixes it).
  void validate(std::string const& who) const {
    const auto fail = [&](char const* key, char const* why) {
      throw std::invalid_argument(who + ": " + key + " " + why);
    };
    if (!(m0 >= 0.0))
      fail("m0", "must be >= 0");
    if (!std::isfinite(m1))
      fail("m1", "must be finite");
    if (!(strainRateFloor > 0.0))
      fail("strain_rate_floor", "must be > 0");
    if (!(viscosityMax > gasViscosity))
      fail("viscosity_max", "must exceed the gas viscosity");
    if (!(viscosityMin >= 0.0 && viscosityMin < viscosityMax))
      fail("viscosity_min", "must be >= 0 and below viscosity_max");
    if (!(muWall >= 0.0))
      fail("mu_wall", "must be >= 0");
    if (!(gasViscosity > 0.0))
      fail("gas_viscosity", "must be > 0");
    if (!(phiMax > 0.0 && phiMax <= 1.0))
      fail("phi_max", "must be in (0, 1]");
  }
};

namespace detail {

/// gamma_dot of one cell (strainRateInvariant). Dims is a template argument so that the loops
/// over axes, edges and sides unroll and the index arrays stay in registers (with a run-time
/// count the kernel took ~34 ns a cell on two threads, 256 x 256 drum).
template <int Dims, class MemorySpace> struct StrainRateInvariant {
  Grid grid;
  int off[3];
  Field<MemorySpace> u[3];
  Field<MemorySpace> open[3]; ///< apertures of the faces of each component, when masked
  bool masked;
  Field<MemorySpace> out;

  KOKKOS_INLINE_FUNCTION double at(int c, int const (&p)[3]) const {
    return u[c](p[0] + off[0], p[1] + off[1], p[2] + off[2]);
  }
  // face of component c at p is open (always without apertures)
  KOKKOS_INLINE_FUNCTION bool isOpen(int c, int const (&p)[3]) const {
    return !masked || !shellHeldFaceOf<Dims>(open[c], grid, c, p);
  }

  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int i, const int j, const int k) const {
    double d[3][3] = {};
    for (int a = 0; a < Dims; ++a) {
      int p[3] = {i, j, k};
      const double low = at(a, p);
      const bool lowOpen = isOpen(a, p);
      p[a] += 1;
      d[a][a] = lowOpen && isOpen(a, p) ? (at(a, p) - low) / grid.spacing(a) : 0.0;
    }
    for (int a = 0; a < Dims; ++a) {
      for (int b = a + 1; b < Dims; ++b) {
        double sum = 0.0;
        int edges = 0;
        for (int sa = 0; sa < 2; ++sa) {
          for (int sb = 0; sb < 2; ++sb) {
            // edge at node (i_a + sa, i_b + sb): du_a/dx_b + du_b/dx_a
            int p[3] = {i, j, k};
            p[a] += sa;
            p[b] += sb;
            const double uaHigh = at(a, p);
            bool edgeOpen = isOpen(a, p);
            p[b] -= 1;
            const double uaLow = at(a, p);
            edgeOpen = edgeOpen && isOpen(a, p);
            p[b] += 1;
            const double ubHigh = at(b, p);
            edgeOpen = edgeOpen && isOpen(b, p);
            p[a] -= 1;
            const double ubLow = at(b, p);
            edgeOpen = edgeOpen && isOpen(b, p);
            if (edgeOpen) {
              sum += (uaHigh - uaLow) / grid.spacing(b) + (ubHigh - ubLow) / grid.spacing(a);
              ++edges;
            }
          }
        }
        d[a][b] = d[b][a] = edges > 0 ? 0.5 * sum / edges : 0.0;
      }
    }
    const double trace = d[0][0] + d[1][1] + d[2][2];
    double dd = 0.0;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        const double dev = d[a][b] - (a == b ? trace / 3.0 : 0.0);
        dd += dev * dev;
      }
    }
    out(i + off[0], j + off[1], k + off[2]) = math::sqrt(2.0 * dd);
  }
};

template <int Dims, class ExecutionSpace, class MemorySpace>
void strainRateInvariantOf(ExecutionSpace const& space, Grid const& grid,
                           VelocityFields<MemorySpace> const& u, Field<MemorySpace> const& out,
                           VelocityFields<MemorySpace> const& open) {
  StrainRateInvariant<Dims, MemorySpace> rate;
  rate.grid = grid;
  rate.off[0] = rate.off[1] = grid.ghost;
  rate.off[2] = grid.ghostZ();
  rate.masked = open.comp[0].extent(0) > 0;
  for (int c = 0; c < Dims; ++c) {
    rate.u[c] = u.comp[c];
    rate.open[c] = open.comp[c];
  }
  rate.out = out;
  forEachBoxCell(space, "hikiln::cfd::strainRateInvariant", {0, 0, 0}, {grid.nx, grid.ny, grid.nz},
                 rate);
}

} // namespace detail

/// \brief gamma_dot = sqrt(2 D':D') per cell from MAC velocities whose ghosts are filled: normal
/// rates from the two faces of the cell, shear rates as the mean of the four cell edges around
/// it along each pair of axes. D' = D - tr(D) I / 3 is the deviator of the 3D tensor in 2D as
/// well (a 2D grid is a plane-strain slice, D_zz = 0), so a 2D drum and a 3D drum periodic along
/// its axis get the same gamma_dot even in the cut cells at the shell, whose discrete D keeps a
/// trace (their forced faces are not divergence-free). Where tr(D) = 0 it is the DEM's 2D
/// invariant sqrt((D_xx - D_yy)^2 + 4 D_xy^2).
///
/// With `open` (face apertures, as the viscous operator's; ViscousOperator.hpp), the strains that
/// read a closed (shell-held) face are left out as the operator leaves out their stresses: a
/// normal rate whose face is closed is 0, and the shear rate is the mean over the edges whose four
/// faces are open (0 when none is). Ghost faces count as open (their values are the boundary's).
template <class ExecutionSpace, class MemorySpace>
void strainRateInvariant(ExecutionSpace const& space, Grid const& grid,
                         VelocityFields<MemorySpace> const& u, Field<MemorySpace> const& out,
                         VelocityFields<MemorySpace> const& open = VelocityFields<MemorySpace>()) {
  if (grid.is3D()) {
    detail::strainRateInvariantOf<3>(space, grid, u, out, open);
  } else {
    detail::strainRateInvariantOf<2>(space, grid, u, out, open);
  }
}

/// \brief mu = rheology.mixtureViscosity(phi, pBed, gammaDot, wallLayer > 0) per cell.
template <class ExecutionSpace, class MemorySpace>
void mixtureViscosity(ExecutionSpace const& space, Grid const& grid,
                      GranularRheology const& rheology, Field<MemorySpace> const& phi,
                      Field<MemorySpace> const& pBed, Field<MemorySpace> const& gammaDot,
                      Field<MemorySpace> const& wallLayer, Field<MemorySpace> const& mu) {
  const int g = grid.ghost, gz = grid.ghostZ();
  Kokkos::parallel_for(
      "hikiln::cfd::mixtureViscosity", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const int I = i + g, J = j + g, K = k + gz;
        mu(I, J, K) = rheology.mixtureViscosity(phi(I, J, K), pBed(I, J, K), gammaDot(I, J, K),
                                                wallLayer(I, J, K) > 0.0);
      });
}

/// \brief mu += clamp(phi / phiMax, 0, 1) eta per cell: a Newtonian bed of viscosity eta (a
/// verification option of the two-phase solver).
template <class ExecutionSpace, class MemorySpace>
void addConstantBedViscosity(ExecutionSpace const& space, Grid const& grid,
                             Field<MemorySpace> const& phi, double phiMax, double eta,
                             Field<MemorySpace> const& mu) {
  const int g = grid.ghost, gz = grid.ghostZ();
  Kokkos::parallel_for(
      "hikiln::cfd::constantBedViscosity",
      gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const double s = math::fmin(math::fmax(phi(i + g, j + g, k + gz) / phiMax, 0.0), 1.0);
        mu(i + g, j + g, k + gz) += s * eta;
      });
}

} // namespace hikiln::cfd
