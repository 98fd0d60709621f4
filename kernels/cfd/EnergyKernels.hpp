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
/// closed (adiabatic) unless the shell is hot (ShellHeatTransfer, implicit), so a closed drum
/// conserves heat to the solver tolerance. At an open end (a kiln's inlet and discharge) heat is
/// carried in and out with the flow only (no diffusive flux through the end).

#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/OpenEndKernels.hpp"
#include "kernels/cfd/ShellGeometry.hpp"
#include "kernels/cfd/ViscousOperator.hpp"
#include "kernels/cfd/VolumeFractionFct.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace hikiln::cfd {

/// \brief Thermal parameters of the mixture.
struct ThermalParameters {
  double solidHeatCapacity = 1000.0; ///< c_s of the grains [J/(kg K)]
  double gasHeatCapacity = 1005.0;   ///< c_g [J/(kg K)]
  double alphaEff = 1e-6;            ///< effective bed diffusivity [m2/s]
  double gasConductivity = 0.026;    ///< [W/(m K)]
  /// A hot shell (off while both coefficients are 0): heat flows from the shell at
  /// wallTemperature into a wall cell at h (wallTemperature - T) per unit shell area, with
  /// h = s wallBedTransfer + (1 - s) wallGasTransfer, s = phi / phiMax (the bed's contact and the
  /// gas's convection). The shell is the cut faces normal to x and y (the cylinder); end plates
  /// and a dam ring's faces stay adiabatic.
  double wallTemperature = 0.0; ///< [K]
  double wallBedTransfer = 0.0; ///< [W/(m2 K)]
  double wallGasTransfer = 0.0; ///< [W/(m2 K)]

  bool wallHeating() const { return wallBedTransfer > 0.0 || wallGasTransfer > 0.0; }
  /// \brief True when heat diffuses (else the energy step is advection only).
  bool conducts() const { return alphaEff > 0.0 || gasConductivity > 0.0 || wallHeating(); }

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
    if (!(wallBedTransfer >= 0.0))
      fail("wall_bed_transfer", "must be >= 0");
    if (!(wallGasTransfer >= 0.0))
      fail("wall_gas_transfer", "must be >= 0");
    if (wallHeating() && !(wallTemperature > 0.0))
      fail("wall_temperature", "must be > 0 K");
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

namespace detail {

/// \brief Donor-cell heat transport on the step's fluxes (see advectHeat()): the fluxes of one
/// face, the outgoing heat capacity of a cell (for the number of sub-steps), and one sub-step
/// src -> dst carrying `fraction` of the step's fluxes from phi(begin) to phi(end) (phi
/// interpolated linearly between phiOld and phiNew, as the fluxes are split evenly).
template <class MemorySpace> struct HeatAdvection {
  Grid grid;
  int dims = 2;
  int off[3] = {0, 0, 0};
  int n[3] = {1, 1, 1};
  bool periodic[3] = {false, false, false};
  Field<MemorySpace> cap, ap[3], u[3], low[3], anti[3], phiOld, phiNew, src, dst;
  HeatCapacities heat;
  double dt = 0.0, densePhi = 0.0;
  double fraction = 1.0, begin = 0.0, end = 1.0; // of the step: flux share, phi interpolation

  /// \brief Solids and gas fluxes along +a through the a-face at storage index (F0, F1, F2),
  /// per unit cell volume, for the whole step; false for a closed face.
  KOKKOS_INLINE_FUNCTION bool faceFluxes(int a, int F0, int F1, int F2, double& solid,
                                         double& gas) const {
    const double open = ap[a](F0, F1, F2);
    if (open <= 0.0) {
      return false;
    }
    solid = low[a](F0, F1, F2) + anti[a](F0, F1, F2);
    gas = open * u[a](F0, F1, F2) * dt / grid.spacing(a) - solid;
    return true;
  }

  /// \brief Heat carried along +a through the a-face whose high cell is `face` (logical
  /// indices) in this sub-step, per unit cell volume; false for a closed face. lo, hi take in
  /// the temperatures of the face's two cells. Beyond a non-periodic side the cells are the
  /// ghost layer (what flows in at an open end; never reconstructed).
  KOKKOS_INLINE_FUNCTION bool faceHeat(int a, const int (&face)[3], double& flux, double& lo,
                                       double& hi) const {
    double solid = 0.0, gas = 0.0;
    if (!faceFluxes(a, face[0] + off[0], face[1] + off[1], face[2] + off[2], solid, gas)) {
      return false;
    }
    // the cells along a around the face: lowLow | low | face | high | highHigh
    double Tcell[4];
    bool usable[4];
    for (int q = 0; q < 4; ++q) {
      int nb[3] = {face[0], face[1], face[2]};
      int& c = nb[a];
      c += q - 2;
      const bool inside = periodic[a] || (c >= 0 && c < n[a]);
      if (periodic[a]) {
        c = c < 0 ? c + n[a] : (c >= n[a] ? c - n[a] : c);
      } else {
        c = c < -1 ? -1 : (c > n[a] ? n[a] : c); // the one ghost layer
      }
      const int N0 = nb[0] + off[0], N1 = nb[1] + off[1], N2 = nb[2] + off[2];
      usable[q] = inside && cap(N0, N1, N2) > 0.0 && phiOld(N0, N1, N2) >= densePhi;
      Tcell[q] = src(N0, N1, N2);
    }
    const double Tup = faceTemperature(Tcell, usable, true);    // flow along +a
    const double Tdown = faceTemperature(Tcell, usable, false); // flow along -a
    flux = fraction * (heat.solid * solid * (solid >= 0.0 ? Tup : Tdown) +
                       heat.gas * gas * (gas >= 0.0 ? Tup : Tdown));
    lo = math::fmin(lo, math::fmin(Tcell[1], Tcell[2]));
    hi = math::fmax(hi, math::fmax(Tcell[1], Tcell[2]));
    return true;
  }

  KOKKOS_INLINE_FUNCTION double capacityAt(int I, int J, int K, double s) const {
    const double phi = phiOld(I, J, K) + s * (phiNew(I, J, K) - phiOld(I, J, K));
    return cap(I, J, K) * heat.mixture(phi);
  }

  /// \brief Heat capacity leaving cell (i, j, k) over the step, over the smaller of its
  /// capacities before and after (0 for solid cells).
  KOKKOS_INLINE_FUNCTION double outflowRatio(int i, int j, int k) const {
    const int I = i + off[0], J = j + off[1], K = k + off[2];
    if (cap(I, J, K) <= 0.0) {
      return 0.0;
    }
    double out = 0.0;
    for (int a = 0; a < dims; ++a) {
      for (int side = 0; side < 2; ++side) {
        double solid = 0.0, gas = 0.0;
        if (faceFluxes(a, I + (a == 0) * side, J + (a == 1) * side, K + (a == 2) * side, solid,
                       gas)) {
          const double sign = side == 0 ? -1.0 : 1.0; // outward along +a on the upper face
          out +=
              heat.solid * math::fmax(0.0, sign * solid) + heat.gas * math::fmax(0.0, sign * gas);
        }
      }
    }
    const double smallest = math::fmin(capacityAt(I, J, K, 0.0), capacityAt(I, J, K, 1.0));
    return smallest > 0.0 ? out / smallest : 0.0;
  }

  KOKKOS_INLINE_FUNCTION void operator()(const int i, const int j, const int k) const {
    const int I = i + off[0], J = j + off[1], K = k + off[2];
    if (cap(I, J, K) <= 0.0) {
      dst(I, J, K) = src(I, J, K);
      return;
    }
    double content = capacityAt(I, J, K, begin) * src(I, J, K);
    double lo = src(I, J, K), hi = lo; // range of the temperatures exchanged (see advectHeat())
    for (int a = 0; a < dims; ++a) {
      for (int side = 0; side < 2; ++side) {
        int face[3] = {i, j, k};
        face[a] += side;
        double flux = 0.0;
        if (faceHeat(a, face, flux, lo, hi)) {
          content += side == 0 ? flux : -flux;
        }
      }
    }
    const double capacity = capacityAt(I, J, K, end);
    const double Tnew = capacity > 0.0 ? content / capacity : src(I, J, K);
    dst(I, J, K) = math::fmin(math::fmax(Tnew, lo), hi);
  }
};

/// \brief Heat leaving the grid through the faces of a non-periodic side (2 axis + 0 low / 1
/// high) in h's sub-step, exactly as the cells next to it count it; 0 on a periodic side.
template <class ExecutionSpace, class MemorySpace>
double boundaryHeatOutflow(ExecutionSpace const& space, HeatAdvection<MemorySpace> const& h,
                           int side) {
  const int a = side / 2;
  if (h.periodic[a]) {
    return 0.0;
  }
  int lo[3] = {0, 0, 0};
  int hi[3] = {h.n[0], h.n[1], h.n[2]};
  lo[a] = side % 2 == 0 ? 0 : h.n[a];
  hi[a] = lo[a] + 1;
  const double outwardSign = side % 2 == 0 ? -1.0 : 1.0;
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::boundaryHeatOutflow", gridPolicy(space, lo, hi),
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& total) {
        const int face[3] = {i, j, k};
        double flux = 0.0, tLo = 0.0, tHi = 0.0;
        if (h.faceHeat(a, face, flux, tLo, tHi)) {
          total += outwardSign * flux;
        }
      },
      sum);
  return sum;
}

} // namespace detail

/// \brief What advectHeat() did: its sub-steps, and the heat that crossed each side of the grid
/// (2 axis + 0 low / 1 high; outward positive, heatContent() units), nonzero only where the
/// side has open faces (a kiln's inlet and discharge).
struct HeatAdvectionReport {
  int substeps = 1;
  double outward[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
};

/// \brief Most sub-steps advectHeat() takes in one step.
inline constexpr int maxHeatSubsteps = 64;
/// \brief Largest share of a cell's heat capacity that may leave it in one sub-step.
inline constexpr double heatOutflowLimit = 0.5;

/// \brief T* (into `out`) after advecting the heat content with the step's fluxes: solids fluxes
/// `solidFlux` (the limited FCT fluxes, low + anti, per unit cell volume), volume fluxes
/// aperture u dt / h; phiOld and phiNew the volume fractions before and after the transport;
/// the face reconstruction (faceTemperature) only between cells with phiOld >= densePhi. T is
/// used as scratch. An open face of a non-periodic side carries the heat of its ghost cell in
/// (what flows in: fill T's ghost layer there first) or of its cell out (upwind).
///
/// The gas flux is the volume flux minus the limited solids flux, so at the bed surface (drift
/// flux) a cell can send out more heat capacity in one step than it holds (the solids entering
/// from above push gas out through the other faces); a donor-cell update then gives its own
/// temperature a negative weight and leaves every bound. The step is therefore split into m
/// equal sub-steps (fluxes / m, phi interpolated linearly, which is exact: the fluxes are what
/// changes phi), m the smallest that lets at most heatOutflowLimit of any cell's capacity leave
/// per sub-step (at most maxHeatSubsteps). Each sub-step still clamps T* to the temperatures
/// exchanged, a safeguard that changes the heat only where it acts (reported per step in
/// summary.json); with the sub-steps it acts only at round-off level in the tests' drums.
template <class ExecutionSpace, class MemorySpace>
HeatAdvectionReport advectHeat(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                               bool const (&periodicAxes)[3], VelocityFields<MemorySpace> const& u,
                               FctWork<MemorySpace> const& fluxes, double dt, double densePhi,
                               HeatCapacities const& heat, Field<MemorySpace> const& phiOld,
                               Field<MemorySpace> const& phiNew, Field<MemorySpace> const& T,
                               Field<MemorySpace> const& out) {
  detail::HeatAdvection<MemorySpace> h;
  h.grid = cc.grid;
  h.dims = h.grid.is3D() ? 3 : 2;
  h.off[0] = h.grid.ghost, h.off[1] = h.grid.ghost, h.off[2] = h.grid.ghostZ();
  h.n[0] = h.grid.nx, h.n[1] = h.grid.ny, h.n[2] = h.grid.nz;
  h.cap = cc.capacity;
  for (int a = 0; a < 3; ++a) {
    const int b = a < h.dims ? a : 0; // 2D: the unused third axis is never read
    h.periodic[a] = periodicAxes[a];
    h.ap[a] = cc.aperture[b];
    h.u[a] = u.comp[b];
    h.low[a] = fluxes.low[b];
    h.anti[a] = fluxes.anti[b];
  }
  h.phiOld = phiOld;
  h.phiNew = phiNew;
  h.heat = heat;
  h.dt = dt;
  h.densePhi = densePhi;
  const auto cells = gridPolicy(space, {0, 0, 0}, {h.grid.nx, h.grid.ny, h.grid.nz});
  double ratio = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::heatOutflowRatio", cells,
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& worst) {
        worst = math::fmax(worst, h.outflowRatio(i, j, k));
      },
      Kokkos::Max<double>(ratio));
  const int m = static_cast<int>(
      std::min<double>(maxHeatSubsteps, std::max(1.0, std::ceil(ratio / heatOutflowLimit))));
  h.fraction = 1.0 / m;
  HeatAdvectionReport report;
  report.substeps = m;
  if (m > 1) {
    Kokkos::deep_copy(space, out, T); // the sub-steps alternate: both need T's ghost layer
  }
  Field<MemorySpace> from = T, to = out;
  for (int s = 0; s < m; ++s) {
    h.src = from;
    h.dst = to;
    h.begin = static_cast<double>(s) / m;
    h.end = s + 1 == m ? 1.0 : static_cast<double>(s + 1) / m;
    for (int side = 0; side < 2 * h.dims; ++side) {
      report.outward[side] += detail::boundaryHeatOutflow(space, h, side);
    }
    Kokkos::parallel_for("hikiln::cfd::advectHeat", cells, h);
    std::swap(from, to);
  }
  if (from.data() != out.data()) {
    Kokkos::deep_copy(space, out, from);
  }
  return report;
}

/// \brief The shell's heat transfer into a cell per unit cell volume and kelvin [W/(m3 K)]:
/// h(phi) (ThermalParameters) x the shell area in the cell / its volume. The area comes from the
/// apertures (a cut cell's wall area vector is the difference of its opposite faces' open areas;
/// exact for a flat cut), x and y only: the cylinder, not end plates.
template <class MemorySpace> struct ShellHeatTransfer {
  Field<MemorySpace> cap, ax, ay;
  double hx = 1.0, hy = 1.0, phiMax = 1.0, bed = 0.0, gas = 0.0;

  ShellHeatTransfer(CutCells<MemorySpace> const& cc, ThermalParameters const& thermal,
                    double phiMaxIn)
      : cap(cc.capacity), ax(cc.aperture[0]), ay(cc.aperture[1]), hx(cc.grid.hx), hy(cc.grid.hy),
        phiMax(phiMaxIn), bed(thermal.wallBedTransfer), gas(thermal.wallGasTransfer) {}

  KOKKOS_INLINE_FUNCTION double operator()(int I, int J, int K, double phi) const {
    if (cap(I, J, K) <= 0.0) {
      return 0.0;
    }
    const double dx = (ax(I + 1, J, K) - ax(I, J, K)) / hx;
    const double dy = (ay(I, J + 1, K) - ay(I, J, K)) / hy;
    const double s = math::fmin(math::fmax(phi / phiMax, 0.0), 1.0);
    return (s * bed + (1.0 - s) * gas) * math::sqrt(dx * dx + dy * dy);
  }
};

/// \brief Heat flowing in from the shell per second, heatContent() units / s (x cell volume =
/// W), at the temperature T (0 without wall heating).
template <class ExecutionSpace, class MemorySpace>
double shellHeatRate(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                     ThermalParameters const& thermal, double phiMax, Field<MemorySpace> const& phi,
                     Field<MemorySpace> const& T) {
  if (!thermal.wallHeating()) {
    return 0.0;
  }
  const Grid grid = cc.grid;
  const int g = grid.ghost, gz = grid.ghostZ();
  const ShellHeatTransfer<MemorySpace> shell(cc, thermal, phiMax);
  const double Tw = thermal.wallTemperature;
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::shellHeatRate", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& s) {
        const int I = i + g, J = j + g, K = k + gz;
        s += shell(I, J, K, phi(I, J, K)) * (Tw - T(I, J, K));
      },
      sum);
  return sum;
}

/// \brief Coefficients of the implicit diffusion step
///   alpha T - div(beta grad T) = f: alpha = capacity C / dt, beta = aperture x harmonic mean of
/// kappa, f = alpha T*; in solid cells (capacity 0) alpha = C_gas-like 1 / dt and f = alpha T*
/// (T kept, decoupled). A hot shell adds its transfer H (ShellHeatTransfer) to alpha and
/// H T_wall to f (implicit).
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
  const ShellHeatTransfer<MemorySpace> shell(cc, thermal, phiMax);
  const double Tw = thermal.wallTemperature;
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
        const double H = shell(I, J, K, f);
        alpha(I, J, K) = a + H;
        rhs(I, J, K) = a * Tstar(I, J, K) + H * Tw;
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

/// \brief T's ghost cells beyond an open z side (OpenEndKernels.hpp): on an inflow side the
/// mixture temperature of what flows in (solids at solidT, gas at gasT, phiIn the inflow's
/// solids fraction per face: the heat brought in is then exactly each phase's), else the cell
/// inside (zero gradient).
template <class ExecutionSpace, class MemorySpace>
void fillEndTemperatureGhosts(ExecutionSpace const& space, Grid const& grid, int side, bool inflow,
                              Field<MemorySpace> const& phiIn, HeatCapacities const& heat,
                              double solidT, double gasT, Field<MemorySpace> const& T) {
  const int ghost = side == ZLow ? -1 : 0;
  const int inside = side == ZLow ? 0 : -1;
  Kokkos::parallel_for(
      "hikiln::cfd::fillEndTemperatureGhosts", endFacePolicy(space, grid, side),
      KOKKOS_LAMBDA(const int I, const int J, const int K) {
        if (!inflow) {
          T(I, J, K + ghost) = T(I, J, K + inside);
          return;
        }
        const double f = phiIn(I, J, K);
        const double c = heat.mixture(f);
        T(I, J, K + ghost) =
            c > 0.0 ? (f * heat.solid * solidT + (1.0 - f) * heat.gas * gasT) / c : gasT;
      });
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
