#pragma once
/// \file EnergyKernels.hpp
/// \brief The continuum energy equation (physics.md 6.3) on cut cells,
///   d(C T)/dt + div(u C T) = div(kappa grad T),
/// C = phi rhoS cS + (1 - phi) rhoG cG the volumetric heat capacity of the mixture and
/// kappa = phi rhoS cS alphaEff + (1 - phi / phiMax) kGas (the bed's effective diffusivity
/// alphaEff lumps particle conduction, radiation and small-scale jostling; clamped at phi =
/// phiMax).
///
/// Advection rides on the volume-fraction transport (VolumeFractionFct.hpp): the solids carry
/// heat with exactly the limited solids fluxes of the step and the gas with the rest of the
/// volume flux, each at its donor's temperature reconstructed to the face with a minmod-limited
/// slope (faceTemperature: first-order upwind smeared a 20 % fill drum's mixing layer over about
/// half the bed in 10 s at 64^2, an effective diffusivity u h / 2 ~ 2e-3 m^2/s, larger than any
/// bed diffusivity to be fitted), so the heat content sum(capacity C T) moves between cells
/// only through faces. Diffusion is
/// implicit (CellMultigrid on capacity C / dt T - div(aperture kappa grad T)); shell faces are
/// closed (adiabatic), so a closed drum conserves heat to the solver tolerance.

#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/ShellGeometry.hpp"
#include "kernels/cfd/ViscousOperator.hpp"
#include "kernels/cfd/VolumeFractionFct.hpp"

#include <Kokkos_Core.hpp>

#include <stdexcept>
#include <string>

namespace hikiln::cfd {

/// \brief Thermal parameters of the mixture.
struct ThermalParameters {
  double solidHeatCapacity = 1000.0; ///< c_s of the grains [J/(kg K)]
  double gasHeatCapacity = 1005.0;   ///< c_g [J/(kg K)]
  double alphaEff = 1e-6;            ///< effective bed diffusivity [m2/s]
  double gasConductivity = 0.026;    ///< [W/(m K)]

  /// \brief Throws std::invalid_argument naming the first bad parameter.
  void validate(std::string const& who) const {
    const auto fail = [&](char const* key, char const* why) {
      throw std::invalid_argument(who + ": " + key + " " + why);
    };
    if (!(solidHeatCapacity > 0.0))
      fail("solid_heat_capacity", "must be > 0");
    if (!(gasHeatCapacity >= 0.0))
      fail("gas_heat_capacity", "must be >= 0");
    if (!(alphaEff >= 0.0))
      fail("alpha_eff", "must be >= 0");
    if (!(gasConductivity >= 0.0))
      fail("gas_conductivity", "must be >= 0");
  }
};

/// \brief Volumetric heat capacities of the two phases, rho c [J/(m3 K)].
struct HeatCapacities {
  double solid = 0.0, gas = 0.0;
  KOKKOS_INLINE_FUNCTION double mixture(double phi) const {
    return phi * solid + (1.0 - phi) * gas;
  }
};

/// \brief Temperature carried through a face by a flow along +a (positive) or -a, from the four
/// cells around it (lowLow, low, high, highHigh; `usable`: inside the domain, open and dense bed,
/// phi >= densePhi: in gas and surface cells, whose heat capacity is ~2000 x smaller than the
/// solids passing through, only the upwind value keeps T bounded): the donor's
/// temperature plus half its minmod-limited slope towards the face (second order where T is
/// smooth, the donor's value at extrema and next to walls). The result lies between the donor's
/// and the receiver's temperatures, and both cells of the face compute it alike (conservative).
KOKKOS_INLINE_FUNCTION double faceTemperature(const double (&T)[4], const bool (&usable)[4],
                                              bool positive) {
  const int donor = positive ? 1 : 2, receiver = positive ? 2 : 1, behind = positive ? 0 : 3;
  if (!usable[behind] || !usable[donor] || !usable[receiver]) {
    return T[donor];
  }
  const double ahead = T[receiver] - T[donor], back = T[donor] - T[behind];
  if (ahead * back <= 0.0) {
    return T[donor];
  }
  const double slope = math::fabs(ahead) < math::fabs(back) ? ahead : back;
  return T[donor] + 0.5 * slope;
}

/// \brief T* after advecting the heat content with the step's fluxes: solids fluxes
/// `solidFlux` (the limited FCT fluxes, low + anti, per unit cell volume), volume fluxes
/// aperture u dt / h; phiOld and phiNew the volume fractions before and after the transport;
/// the face reconstruction (faceTemperature) only between cells with phiOld >= densePhi.
template <class ExecutionSpace, class MemorySpace>
void advectHeat(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                bool const (&periodicAxes)[3], VelocityFields<MemorySpace> const& u,
                FctWork<MemorySpace> const& fluxes, double dt, double densePhi,
                HeatCapacities const& heat, Field<MemorySpace> const& phiOld,
                Field<MemorySpace> const& phiNew, Field<MemorySpace> const& T,
                Field<MemorySpace> const& out) {
  const Grid grid = cc.grid;
  const int dims = grid.is3D() ? 3 : 2;
  const int off[3] = {grid.ghost, grid.ghost, grid.ghostZ()};
  const int n[3] = {grid.nx, grid.ny, grid.nz};
  const bool periodic[3] = {periodicAxes[0], periodicAxes[1], periodicAxes[2]};
  const auto cap = cc.capacity;
  const auto ap0 = cc.aperture[0], ap1 = cc.aperture[1], ap2 = cc.aperture[2];
  const auto u0 = u.comp[0], u1 = u.comp[1], u2 = dims == 3 ? u.comp[2] : u.comp[0];
  const auto l0 = fluxes.low[0], l1 = fluxes.low[1], l2 = dims == 3 ? fluxes.low[2] : l0;
  const auto a0 = fluxes.anti[0], a1 = fluxes.anti[1], a2 = dims == 3 ? fluxes.anti[2] : a0;
  Kokkos::parallel_for(
      "hikiln::cfd::advectHeat", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const int I = i + off[0], J = j + off[1], K = k + off[2];
        const double c = cap(I, J, K);
        if (c <= 0.0) {
          out(I, J, K) = T(I, J, K);
          return;
        }
        double content = c * heat.mixture(phiOld(I, J, K)) * T(I, J, K);
        double lo = T(I, J, K), hi = lo; // range of the temperatures exchanged (see below)
        const int idx[3] = {i, j, k};
        for (int a = 0; a < dims; ++a) {
          auto const& apa = a == 0 ? ap0 : (a == 1 ? ap1 : ap2);
          auto const& ua = a == 0 ? u0 : (a == 1 ? u1 : u2);
          auto const& la = a == 0 ? l0 : (a == 1 ? l1 : l2);
          auto const& aa = a == 0 ? a0 : (a == 1 ? a1 : a2);
          for (int side = 0; side < 2; ++side) {
            int f[3] = {I, J, K};
            f[a] += side;
            const double open = apa(f[0], f[1], f[2]);
            if (open <= 0.0) {
              continue;
            }
            // the cells along a around face f: lowLow | low | face | high | highHigh
            double Tcell[4];
            bool usable[4];
            for (int q = 0; q < 4; ++q) {
              int nb[3] = {idx[0], idx[1], idx[2]};
              nb[a] += side - 2 + q; // side 0: face below this cell (high = this cell)
              const bool inside = periodic[a] || (nb[a] >= 0 && nb[a] < n[a]);
              nb[a] = nb[a] < 0 ? nb[a] + n[a] : (nb[a] >= n[a] ? nb[a] - n[a] : nb[a]);
              const int N0 = nb[0] + off[0], N1 = nb[1] + off[1], N2 = nb[2] + off[2];
              usable[q] = inside && cap(N0, N1, N2) > 0.0 && phiOld(N0, N1, N2) >= densePhi;
              Tcell[q] = T(N0, N1, N2);
            }
            // fluxes along +a, per unit cell volume
            const double solid = la(f[0], f[1], f[2]) + aa(f[0], f[1], f[2]);
            const double volume = open * ua(f[0], f[1], f[2]) * dt / grid.spacing(a);
            const double gas = volume - solid;
            const double Tup = faceTemperature(Tcell, usable, true);    // flow along +a
            const double Tdown = faceTemperature(Tcell, usable, false); // flow along -a
            const double flux = heat.solid * solid * (solid >= 0.0 ? Tup : Tdown) +
                                heat.gas * gas * (gas >= 0.0 ? Tup : Tdown);
            content += side == 0 ? flux : -flux;
            lo = math::fmin(lo, math::fmin(Tcell[1], Tcell[2]));
            hi = math::fmax(hi, math::fmax(Tcell[1], Tcell[2]));
          }
        }
        // The gas flux is the volume flux minus the limited solids flux, so at the bed surface
        // (drift flux) a nearly empty cell can send out more gas than it holds: its content, over
        // a heat capacity ~2000 x smaller than the bed's, then leaves every bound and grows
        // without limit. Clamping T* to the temperatures exchanged keeps every cell bounded; it
        // changes the heat only where it acts (gas cells at the surface; none in the closed-drum
        // conservation test), and summary.json reports the heat change per step.
        const double capacityNew = c * heat.mixture(phiNew(I, J, K));
        const double Tnew = capacityNew > 0.0 ? content / capacityNew : T(I, J, K);
        out(I, J, K) = math::fmin(math::fmax(Tnew, lo), hi);
      });
}

/// \brief Coefficients of the implicit diffusion step
///   alpha T - div(beta grad T) = f: alpha = capacity C / dt, beta = aperture x harmonic mean of
/// kappa, f = alpha T*; in solid cells (capacity 0) alpha = C_gas-like 1 / dt and f = alpha T*
/// (T kept, decoupled).
template <class ExecutionSpace, class MemorySpace>
void diffusionCoefficients(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                           bool const (&periodic)[3], HeatCapacities const& heat,
                           ThermalParameters const& thermal, double phiMax, double dt,
                           Field<MemorySpace> const& phi, Field<MemorySpace> const& Tstar,
                           Field<MemorySpace> const& kappa, Field<MemorySpace> const& alpha,
                           Field<MemorySpace> const (&beta)[3], Field<MemorySpace> const& rhs) {
  const Grid grid = cc.grid;
  const int g = grid.ghost, gz = grid.ghostZ();
  const auto cap = cc.capacity;
  const double alphaEff = thermal.alphaEff, kGas = thermal.gasConductivity;
  Kokkos::parallel_for(
      "hikiln::cfd::diffusionCoefficients",
      gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const int I = i + g, J = j + g, K = k + gz;
        const double f = phi(I, J, K);
        const double s = math::fmin(math::fmax(f / phiMax, 0.0), 1.0);
        kappa(I, J, K) = f * heat.solid * alphaEff + (1.0 - s) * kGas;
        const double c = cap(I, J, K);
        const double a = c > 0.0 ? c * heat.mixture(f) / dt : 1.0 / dt;
        alpha(I, J, K) = a;
        rhs(I, J, K) = a * Tstar(I, J, K);
      });
  AxisClosure axes[3];
  ScalarBoundaries bc;
  for (int side = 0; side < 6; ++side) {
    bc.kind[side] = periodic[side / 2] ? BoundaryKind::Periodic : BoundaryKind::Wall;
  }
  scalarClosures(grid, bc, axes);
  harmonicFaceCoefficients(space, grid, axes, kappa, beta);
  for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
    const auto b = beta[a];
    const auto ap = cc.aperture[a];
    const int hi[3] = {grid.nx + (a == 0), grid.ny + (a == 1), grid.nz + (a == 2)};
    Kokkos::parallel_for(
        "hikiln::cfd::diffusionApertures", gridPolicy(space, {0, 0, 0}, hi),
        KOKKOS_LAMBDA(const int i, const int j, const int k) {
          b(i + g, j + g, k + gz) *= ap(i + g, j + g, k + gz);
        });
  }
}

/// \brief Heat content sum over fluid cells of capacity x C(phi) x T (x cell volume = J).
template <class ExecutionSpace, class MemorySpace>
double heatContent(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                   HeatCapacities const& heat, Field<MemorySpace> const& phi,
                   Field<MemorySpace> const& T) {
  const Grid grid = cc.grid;
  const int g = grid.ghost, gz = grid.ghostZ();
  const auto cap = cc.capacity;
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::heatContent", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& s) {
        const int I = i + g, J = j + g, K = k + gz;
        s += cap(I, J, K) * heat.mixture(phi(I, J, K)) * T(I, J, K);
      },
      sum);
  return sum;
}

} // namespace hikiln::cfd
