#pragma once
/// \file TwoPhaseSolver.hpp
/// \brief One time step of the two-phase (gas + granular solids) continuum model in a rotating
/// shell on cut cells: a mixture (one-velocity) model with the solids volume fraction phi as
/// the phase indicator, and a projection method.
///
/// Step n -> n + 1 (dt from stableTimeStep):
/// 1. phi by flux-corrected transport with the divergence-free face velocities u^n
///    (VolumeFractionFct.hpp): conservative to round-off, bounded in [0, phiMax], sharp surface;
///    in equal sub-steps when the settling needs shorter ones than the advection
///    (transportVolumeFractionInSubsteps).
/// 2. rho = phi rhoSolid + (1 - phi) rhoGas in cells, arithmetic means on faces.
/// 3. Rheology from u^n and p^n: gamma_dot per cell, the bed pressure p_bed (total pressure less
///    the hydrostatic gas pressure, ProjectionKernels.hpp: gauge-free, 0 at the bed surface),
///    mu = muGas + phi / phiMax eta(p_bed, gamma_dot) (GranularRheology.hpp; Coulomb wall layer).
/// 4. Momentum predictor, viscous terms implicit (ViscousMultigrid, PCG):
///    rho (u* - u^n) / dt = -rho (u^n . grad) u^n + div(mu (grad u* + grad u*^T)) + rho a^n
///    + Brinkman forcing to the shell velocity on faces that are not fully open.
///    Bed viscosities of 1e3-1e5 Pa s therefore do not limit dt. With the Coulomb wall, the
///    viscous stresses (and in step 3 the strain rates) that read a closed face are left out
///    (ViscousOperator.hpp): the shell pulls on the bed only through the capped forcing on the
///    cut faces, mu_wall sigma_n. With `incrementalProjection` (off by default) the predictor
///    adds rho a^n, what gravity and the pressure gradient did to each face's velocity in the
///    last step (CarriedAcceleration.hpp; on a cut face only its open share, aperture x a^n, so
///    that the pressure exerts no torque about the shell's axis), and u_hat = u* - dt a^n;
///    otherwise (plain) a^n = 0 and u_hat = u*. The plain form's stresses act on a velocity that
///    lacks the pressure gradient, so its steady state depends on dt (a 2D drum's wall slip moved
///    by 6 points between dt 0.02 and 0.005 s, and an inclined layer's base slips:
///    test_cfd_inclined_layer); the incremental form's does not. It is not the default yet: with
///    the default arithmetic edge viscosities its beds stand about 13 deg above their friction
///    angle (harmonicEdgeViscosity mends that: test_cfd_drum_repose_angle), and without a bed
///    viscosity floor the inclined Kramers kiln's step collapses (docs/compare.md, last
///    section).
///    With `warmStart` (the default) the solve starts from u^n moved by the last step's
///    u* - u^n and stops where the start from u^n would have (warmMomentumStart); steps 5 and 6
///    likewise start the pressure from p^n against the cold start's residual (project).
/// 5. Projection (CellMultigrid, PCG) for the full pressure with gravity (balanced force):
///    u** = u_hat + dt g, div(a / rho grad p) = div(a u**) / dt with a the face apertures,
///    u^{n+1} = u** - dt / rho grad p on open faces, a^{n+1} = (u^{n+1} - u_hat) / dt. Gravity
///    and the pressure gradient meet on the same faces with the same (new) face density, so a
///    layered bed at rest stays exactly at rest. (Carrying grad p^n into the predictor instead
///    was tried and abandoned: p^n balances the old density, and on a face that the bed has just
///    left grad p^n / rho_gas accelerated the gas to metres per second.) The aperture-weighted
///    divergence of u^{n+1} is zero to the solver tolerance.
/// 6. Energy (optional, EnergyKernels.hpp): the heat content rides on step 1's fluxes, then an
///    implicit diffusion with the effective bed diffusivity and a hot shell's transfer
///    (CellMultigrid, PCG). Open ends carry heat in (at the inflow's temperatures,
///    setInflowTemperature) and out with the flow only.
/// dt is the largest step whose advective outflow from every cell is at most `cfl` of its fluid
/// volume, capped by dtMax; the reason is returned with the step. (Counting the settling in dt
/// too, as the code did before, took 2.4-3.1 times the steps in the 2D drums at 128 x 128.)
///
/// Open ends (a kiln's inlet and discharge, OpenSides): an Inflow face carries its given
/// velocity and phi (upwind in step 1); an Outflow face gets the zero-gradient velocity of the
/// predictor, then the projection's correction against the gas's hydrostatic pressure held on
/// the face (step 5 solves for p - rho_gas g.x, 0 there). In a closed domain nothing changes.

#include "kernels/cfd/CarriedAcceleration.hpp"
#include "kernels/cfd/EnergyKernels.hpp"
#include "kernels/cfd/FieldOps.hpp"
#include "kernels/cfd/GhostFill.hpp"
#include "kernels/cfd/GranularRheology.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/KilnGeometry.hpp"
#include "kernels/cfd/OpenEndKernels.hpp"
#include "kernels/cfd/ProjectionKernels.hpp"
#include "kernels/cfd/ShellGeometry.hpp"
#include "kernels/cfd/ShellTorque.hpp"
#include "kernels/cfd/VolumeFractionFct.hpp"
#include "solvers/cfd/CellMultigrid.hpp"
#include "solvers/cfd/SolveStats.hpp"
#include "solvers/cfd/ViscousMultigrid.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace hikiln::cfd {

/// With TwoPhaseParameters::shellHoldsGas, a cut face is all gas (held by the shell) without
/// solids and all bed (Coulomb cap) from this share of phi_max on (WallFriction::gasShare).
inline constexpr double gasShellShare = 0.1;

/// \brief Physical and numerical parameters of the two-phase model.
struct TwoPhaseParameters {
  double solidDensity = 2500.0; ///< grain material density [kg/m3] (bed density phi x this)
  double gasDensity = 1.2;      ///< [kg/m3]
  double gravity[3] = {0.0, -9.81, 0.0};
  GranularRheology rheology;
  double constantBedViscosity = 0.0;  ///< > 0: Newtonian bed of this viscosity (no rheology)
  double cfl = 0.5;                   ///< outflow per step / cell fluid volume
  double dtMax = 0.01;                ///< [s]
  double penalty = 1e6;               ///< Brinkman forcing strength (multiple of the operator)
  double gasPhi = 1e-3;               ///< cells with phi below this are gas (bed pressure)
  double settlingVelocity = 0.5;      ///< grains falling through the gas [m/s] (drift flux)
  bool coulombWall = true;            ///< Coulomb friction on the cut faces (else no-slip)
  bool incrementalProjection = false; ///< carry the last step's acceleration (step 4)
  bool harmonicEdgeViscosity = false; ///< shear stress viscosities (ViscousOperator.hpp)
  bool shellHoldsGas = true;          ///< the shell holds gas, uncapped (gasShellShare)
  bool energy = false;                ///< solve the energy equation (temperature())
  ThermalParameters thermal;
  double pressureTolerance = 1e-11; ///< relative residual of the pressure solve
  double viscousTolerance = 1e-9;   ///< relative residual of the momentum solve
  bool warmStart = true;            ///< solves start from the last step's (warmMomentumStart)
  int maxIterations = 200;

  /// \brief Throws std::invalid_argument naming the first bad parameter.
  void validate() const {
    const std::string who = "hikiln::cfd::TwoPhaseParameters";
    rheology.validate(who);
    const auto fail = [&](char const* key, char const* why) {
      throw std::invalid_argument(who + ": " + key + " " + why);
    };
    if (!(solidDensity > 0.0))
      fail("solid_density", "must be > 0");
    if (!(gasDensity > 0.0))
      fail("gas_density", "must be > 0");
    if (!(constantBedViscosity >= 0.0))
      fail("constant_bed_viscosity", "must be >= 0");
    if (!(cfl > 0.0 && cfl <= 1.0))
      fail("cfl", "must be in (0, 1]");
    if (!(dtMax > 0.0))
      fail("dt_max", "must be > 0");
    if (!(penalty >= 1.0))
      fail("penalty", "must be >= 1");
  }
};

/// \brief Open ends of the domain (a kiln's inlet and discharge faces; only the z sides of a 3D
/// grid that is not periodic along z), per side (2 axis + 0 low / 1 high):
/// - Wall (the default): a closed side.
/// - Inflow: the normal velocity and the solids fraction flowing in are given per boundary face
///   (TwoPhaseSolver::setInflow; 0 where the shape closes the face); the tangential velocity is
///   0 (no slip), the pressure has zero normal gradient there.
/// - Outflow: the pressure on the open boundary faces is that of the gas at rest, rho_gas g.x
///   (the bed pours out, the freeboard gas stays still), the tangential velocity and phi have
///   zero normal gradient, the normal velocity comes from the projection.
/// The shape says which boundary faces are open (CutCellOptions::open; KilnDomain).
struct OpenSides {
  BoundaryKind kind[6] = {BoundaryKind::Wall, BoundaryKind::Wall, BoundaryKind::Wall,
                          BoundaryKind::Wall, BoundaryKind::Wall, BoundaryKind::Wall};
  /// \brief True when some side has the given kind.
  bool has(BoundaryKind k) const {
    return std::find(std::begin(kind), std::end(kind), k) != std::end(kind);
  }
};

/// \brief What one step did.
struct TwoPhaseStepReport {
  double dt = 0.0;
  std::string limitedBy;     ///< "advection (CFL)" or "dt_max"
  double solidsBefore = 0.0; ///< sum of capacity x phi before the step
  double solidsAfter = 0.0;  ///< ... after it
  double solidsIn = 0.0;     ///< carried in through Inflow sides in the step (solids() units)
  double solidsOut = 0.0;    ///< carried out through Outflow sides in the step
  SolveStats viscous, pressure, energy;
  double heatBefore = 0.0;    ///< heat content before the step (energy on)
  double heatAfter = 0.0;     ///< ... after it
  double heatIn = 0.0;        ///< carried in through Inflow sides in the step (heat() units)
  double heatOut = 0.0;       ///< carried out through Outflow sides in the step
  double heatFromShell = 0.0; ///< from a hot shell in the step (ThermalParameters)
  int heatSubsteps = 0;       ///< sub-steps of the heat advection (advectHeat())
  int transportSubsteps = 0;  ///< sub-steps of the volume fraction's transport (settling)
  double maxDivergence = 0.0; ///< max |aperture-weighted div u| after the projection [1/s]
};

/// \brief Temperatures of what flows in through the Inflow sides (the energy equation and each
/// temperature tracer have their own) [K, or tracer units].
struct InflowTemperature {
  double solid = 0.0, gas = 0.0;
};

/// \brief The two-phase continuum model in a shell (see the file comment).
template <class ExecutionSpace, class Shape = DrumShell> class TwoPhaseSolver {
public:
  using memory_space = typename ExecutionSpace::memory_space;
  using field_type = Field<memory_space>;
  using velocity_type = VelocityFields<memory_space>;

  /// \brief A solver on grid for the fluid inside shape, everything at rest, phi = 0, p = 0,
  /// closed or with open ends (OpenSides).
  TwoPhaseSolver(ExecutionSpace const& space, Grid const& grid, Shape const& shape,
                 TwoPhaseParameters const& params, CutCellOptions const& cutOptions = {},
                 OpenSides const& openSides = {});

  /// \brief Sets what flows in through the Inflow sides: on each open boundary face, the speed
  /// into the domain inflow.axialVelocity(x, y) and the solids fraction inflow.inflowPhi(x, y)
  /// (e.g. KilnInlet), at the centroid of the face's open part. u becomes divergence-free with
  /// that inflow (see startInflow). Throws std::invalid_argument when an inflow phi leaves
  /// [0, phiMax].
  template <class Inflow> void setInflow(Inflow const& inflow) {
    double lo = 0.0, hi = 0.0;
    for (int side : {ZLow, ZHigh}) {
      if (_open.kind[side] == BoundaryKind::Inflow) {
        double sideLo, sideHi;
        evaluateInflow(_space, _cut, side, inflow, _inflowW, _inflowPhi, sideLo, sideHi);
        lo = std::min(lo, sideLo);
        hi = std::max(hi, sideHi);
      }
    }
    if (!(lo >= 0.0 && hi <= _params.rheology.phiMax)) {
      throw std::invalid_argument("hikiln::cfd::TwoPhaseSolver::setInflow: the inflow's solids "
                                  "fraction must be in [0, phi_max = " +
                                  std::to_string(_params.rheology.phiMax) + "]");
    }
    _inflowSet = true;
    startInflow();
  }

  /// \brief Temperatures of the solids and the gas flowing in through the Inflow sides (energy
  /// on); both 0 K until set, so set them before stepping a kiln with energy.
  void setInflowTemperature(InflowTemperature const& t) { _inflowT = t; }

  /// \brief Replaces the shape (a kiln's dam ring switched on) and measures the cut cells again.
  /// phi keeps its value where the fluid stays and counts for nothing where the new shape is
  /// solid; u is made divergence-free with the new apertures (a projection without gravity).
  /// Returns the solids content the new walls took (solids() units).
  double changeShape(Shape const& shape);

  /// \brief Solids carried in through the Inflow sides and out through the Outflow sides since
  /// the start (solids() units).
  double solidsInTotal() const { return _solidsIn; }
  double solidsOutTotal() const { return _solidsOut; }

  /// \brief Volume flux (m^3/s) of the mixture through the open boundary faces of `side`,
  /// positive out of the domain.
  double volumeOutflow(int side) { return endVolumeOutflow(_space, _cut, side, _u.comp[2]); }

  /// \brief Sets phi = phiMax x the fraction of each fluid cell below the plane y = level (a flat
  /// bed at rest), u = 0 and p to the hydrostatic pressure of that bed.
  void setFlatBed(double level);

  /// \brief Sets phi = phiMax in every fluid cell (a full drum), u = 0, hydrostatic p.
  void setFull() { setFlatBed(_grid.y0 + 2.0 * _grid.ny * _grid.hy); }

  /// \brief p such that the gravity g - grad p / rho is discretely divergence-free (a projection
  /// of gravity; exactly hydrostatic for a layered density).
  void hydrostaticPressure();

  /// \brief The largest stable step and what limits it.
  double stableTimeStep(std::string& reason) {
    const double noSettling[3] = {0.0, 0.0, 0.0}; // the transport sub-steps for it (step())
    const double rate = maxCourantRate(_space, _cut, _u, noSettling);
    const double advective = rate > 0.0 ? _params.cfl / rate : _params.dtMax;
    if (advective < _params.dtMax) {
      reason = "advection (CFL)";
      return advective;
    }
    reason = "dt_max";
    return _params.dtMax;
  }

  /// \brief One step of the stable length.
  TwoPhaseStepReport advance() {
    std::string reason;
    const double dt = stableTimeStep(reason);
    TwoPhaseStepReport report = step(dt);
    report.limitedBy = reason;
    return report;
  }

  /// \brief One step of length dt (see the file comment).
  TwoPhaseStepReport step(double dt);

  /// \brief The momentum solve's start: the predictor's cold guess (u^n, the shell's velocity on
  /// faces it closes in part) in _uStar, moved by what the last solve added to its own cold
  /// guess, scaled by the step ratio (u* - u^n is dt times the viscous and advective
  /// acceleration, which changes little from step to step; on the cut faces where the bed
  /// slips, u* is far from the shell's velocity, and most of the cold residual is there).
  /// Returns the cold guess's residual, which the solve's tolerance keeps referring to: the
  /// accuracy asked for is unchanged, the start is closer. On return _predictorChange holds
  /// minus the cold guess; step() adds the solution to it.
  double warmMomentumStart(ViscousMultigrid<ExecutionSpace>& viscous, double dt) {
    if (!_params.warmStart) {
      return 0.0;
    }
    viscous.fillBoundaries(_uStar);
    const double coldResidual = viscous.residualNorm(_uStar, _rhs);
    const double ratio = _lastDt > 0.0 ? dt / _lastDt : 0.0;
    viscous.axpby(ratio, _predictorChange, 1.0, _uStar);
    viscous.axpby(-1.0, _uStar, ratio, _predictorChange);
    return coldResidual;
  }

  /// \brief Heat content sum(capacity x C x T) (x cell volume = J); 0 without energy.
  double heat() {
    return _params.energy ? heatContent(_space, _cut, heatCapacities(_params.thermal), _phi, _T)
                          : 0.0;
  }
  /// \brief The temperature field (empty without energy); fill it before stepping.
  field_type const& temperature() const { return _T; }

  /// \brief Adds a passive temperature field with its own effective bed diffusivity, advected
  /// and diffused every step exactly as temperature() is (the flow does not depend on it), and
  /// returns its index. Many tracers share one flow computation: `hikiln fit-diffusivity` runs
  /// all its candidate diffusivities in one continuum run. Fill it before stepping.
  int addTemperatureTracer(double alphaEff) {
    ThermalParameters thermal = _params.thermal;
    thermal.alphaEff = alphaEff;
    return addTemperatureTracer(thermal);
  }
  /// \brief Adds a passive tracer with its own thermal parameters. A solids tracer (e.g. a
  /// residence-time pulse in a kiln's feed) has gasHeatCapacity = 0 and nothing that conducts
  /// (ThermalParameters::conducts()): it is then advected with the solids only, and its content
  /// (tracerHeat) is solids volume x solidHeatCapacity x concentration. Give it a trace of gas
  /// heat capacity wherever cells may run empty of solids: a cell with no heat capacity has no
  /// defined concentration, and solids passing through it within a step would be tagged from
  /// nothing (the limiter then breaks the conservation; see KilnRun.cpp).
  int addTemperatureTracer(ThermalParameters const& thermal) {
    TemperatureTracer tracer;
    tracer.thermal = thermal;
    tracer.thermal.validate("hikiln::cfd::TwoPhaseSolver::addTemperatureTracer");
    tracer.temperature = makeField(_space, _grid, Staggering::Cell, "hikiln::cfd::tracerT");
    allocateHeatWork();
    _tracers.push_back(tracer);
    return static_cast<int>(_tracers.size()) - 1;
  }
  /// \brief Temperature field of tracer n (addTemperatureTracer).
  field_type const& tracerTemperature(int n) const { return _tracers.at(n).temperature; }
  /// \brief Heat content of tracer n, as heat() with the tracer's heat capacities.
  double tracerHeat(int n) {
    TemperatureTracer const& t = _tracers.at(n);
    return heatContent(_space, _cut, heatCapacities(t.thermal), _phi, t.temperature);
  }
  /// \brief What flows in with tracer n through the Inflow sides (from the next step on).
  void setTracerInflow(int n, InflowTemperature const& t) { _tracers.at(n).inflow = t; }
  /// \brief Tracer n's content carried in and out through the open ends in the last step
  /// (tracerHeat() units).
  double tracerInLastStep(int n) const { return _tracers.at(n).lastIn; }
  double tracerOutLastStep(int n) const { return _tracers.at(n).lastOut; }

  /// \brief The torque budget about the shell's axis of the last step, per metre of drum (2D
  /// drums only, all 0 in 3D, for a shape without an axis or before the first step;
  /// ShellTorque.hpp).
  ShellTorque shellTorque() const {
    if (_grid.is3D() || !(_lastDt > 0.0)) {
      return ShellTorque();
    }
    ShellTorque sum = shellTorqueOf(_u, _lastDt);
    sum.wallDrag = _dragTorque.wallDrag;
    sum.wallDragBound = _dragTorque.wallDragBound;
    return sum;
  }

  /// \brief Solids content sum(capacity x phi) (x cell volume = m^3).
  double solids() { return solidsContent(_space, _cut, _phi); }
  /// \brief Wall slip as the DEM stage defines it (physics.md 2): 1 - (tangential bed speed at
  /// the wall / shell speed), over the wall-layer cells holding bed (phi >= phiMax / 2), each at
  /// its centre against omega r there, weighted by capacity x phi. A cell's velocity component
  /// is the aperture-weighted mean of its two faces: a closed face is held at the shell
  /// velocity and is not bed, so it does not count (a cell with no open face along an axis is
  /// skipped). NaN when the shell does not turn, no bed touches it or the shape has no axis
  /// (a DrumShell-like shape has cx, cy, omega).
  double wallSlip();

  /// \brief Smallest and largest phi over fluid cells.
  void phiRange(double& lo, double& hi);

  int dims() const { return _grid.is3D() ? 3 : 2; }
  double time() const { return _time; }
  Grid const& grid() const { return _grid; }
  Shape const& shape() const { return _shape; }
  TwoPhaseParameters const& parameters() const { return _params; }
  CutCells<memory_space> const& cutCells() const { return _cut; }
  field_type const& volumeFraction() const { return _phi; }
  field_type const& pressure() const { return _p; }
  field_type const& bedPressureField() const { return _pBed; }
  field_type const& viscosity() const { return _mu; }
  field_type const& strainRate() const { return _gammaDot; }
  field_type const& density() const { return _rho; }
  velocity_type const& velocity() const { return _u; }

private:
  struct Settling {
    double v[3] = {0.0, 0.0, 0.0};
  };
  struct RheologyView {
    double phiMax;
  };
  RheologyView rheologyView() const { return RheologyView{_params.rheology.phiMax}; }
  field_type cellField(char const* label) const {
    return makeField(_space, _grid, Staggering::Cell, label);
  }

  /// \brief The settling velocity vector: settlingVelocity along gravity.
  Settling settling() const {
    Settling s;
    const double* g = _params.gravity;
    const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    for (int a = 0; a < 3; ++a) {
      s.v[a] = norm > 0.0 ? _params.settlingVelocity * g[a] / norm : 0.0;
    }
    return s;
  }

  HeatCapacities heatCapacities(ThermalParameters const& thermal) const {
    return HeatCapacities{_params.solidDensity * thermal.solidHeatCapacity,
                          _params.gasDensity * thermal.gasHeatCapacity};
  }

  /// \brief Scratch fields of the energy step (shared by temperature() and the tracers).
  void allocateHeatWork() {
    if (_Tstar.extent(0) > 0) {
      return;
    }
    _Tstar = cellField("hikiln::cfd::Tstar");
    _phiOld = cellField("hikiln::cfd::phiOld");
    _kappa = cellField("hikiln::cfd::kappa");
    _tAlpha = cellField("hikiln::cfd::tAlpha");
    _tRhs = cellField("hikiln::cfd::tRhs");
    for (int a = 0; a < 3; ++a) {
      _tBeta[a] = makeField(_space, _grid, faceStaggering(a), "hikiln::cfd::tBeta");
    }
  }

  /// \brief What one energy step did to one temperature field (heat() units).
  struct HeatStep {
    SolveStats solve;
    int substeps = 0;
    double in = 0.0, out = 0.0, shell = 0.0;
  };

  /// \brief Advects the temperature T with the fluxes of the volume-fraction step just taken
  /// (u^n; at the open ends what flows in has the temperatures `inflow`) and diffuses it
  /// implicitly with the given thermal parameters (skipped when nothing conducts).
  HeatStep energyStep(double dt, field_type const& T, ThermalParameters const& thermal,
                      InflowTemperature const& inflow) {
    HeatStep result;
    const HeatCapacities heat = heatCapacities(thermal);
    for (int side : {ZLow, ZHigh}) {
      if (_open.kind[side] != BoundaryKind::Wall) {
        fillEndTemperatureGhosts(_space, _grid, side, _open.kind[side] == BoundaryKind::Inflow,
                                 _inflowPhi, heat, inflow.solid, inflow.gas, T);
      }
    }
    const double phiMax = _params.rheology.phiMax;
    const HeatAdvectionReport advected = advectHeat(_space, _cut, _periodic, _u, _fct, dt,
                                                    0.5 * phiMax, heat, _phiOld, _phi, T, _Tstar);
    result.substeps = advected.substeps;
    for (int side : {ZLow, ZHigh}) {
      if (_open.kind[side] == BoundaryKind::Inflow) {
        result.in -= advected.outward[side];
      } else if (_open.kind[side] == BoundaryKind::Outflow) {
        result.out += advected.outward[side];
      }
    }
    if (!thermal.conducts()) {
      Kokkos::deep_copy(_space, T, _Tstar);
      return result;
    }
    diffusionCoefficients(_space, _cut, _periodic, heat, thermal, phiMax, dt, _phi, _Tstar, _kappa,
                          _tAlpha, _tBeta, _tRhs);
    CellMultigrid<ExecutionSpace>& mg = keptMultigrid(_heatMg, [&] {
      return std::make_unique<CellMultigrid<ExecutionSpace>>(
          _space, _grid, _heatBc, _tAlpha, _tBeta, multigridOptions(_params.pressureTolerance));
    });
    Kokkos::deep_copy(_space, T, _Tstar);
    result.solve = mg.solvePcg(T, _tRhs);
    if (!result.solve.converged) {
      throw std::runtime_error("hikiln::cfd::TwoPhaseSolver: energy solve did not converge (" +
                               std::to_string(result.solve.iterations) + " iterations)");
    }
    result.shell = dt * shellHeatRate(_space, _cut, thermal, phiMax, _phi, T);
    return result;
  }

  void updateDensity() {
    mixtureDensity(_space, _grid, _params.solidDensity, _params.gasDensity, _phi, _rho);
    faceDensities(_space, _grid, _periodic, _rho, _rhoFace);
  }

  WallFriction wallFriction() const {
    WallFriction friction;
    friction.enabled = coulombWallOn();
    friction.muWall = _params.rheology.muWall;
    friction.gasDensity = _params.gasDensity;
    friction.solidDensity = _params.solidDensity;
    friction.dilutePhi = _params.shellHoldsGas ? gasShellShare * _params.rheology.phiMax : 0.0;
    return friction;
  }

  /// True when the shell acts through the Coulomb wall law (else it is a no-slip wall).
  bool coulombWallOn() const { return _params.coulombWall && _params.constantBedViscosity == 0.0; }

  /// The face apertures when the Coulomb wall is on, else empty: the viscous stresses and the
  /// strain rates then leave out what reads a closed (shell-held) face (ViscousOperator.hpp).
  velocity_type wallLawApertures() const {
    velocity_type open;
    if (coulombWallOn()) {
      for (int c = 0; c < dims(); ++c) {
        open.comp[c] = _cut.aperture[c];
      }
    }
    return open;
  }

  /// ShellTorque.hpp's budget with the drag on velocity u and the last predictor's alpha.
  ShellTorque shellTorqueOf(velocity_type const& u, double dt) const {
    ShellTorque sum; // all 0 for a shape without an axis
    if constexpr (HasAxis<Shape>::value) {
      for (int c = 0; c < 2; ++c) {
        sum += shellTorqueOfComponent(_space, _cut, _shape, c, u.comp[c], _rhoFace[c], _alpha[c],
                                      _p, _pBed, _params.gravity[c], dt, wallFriction(),
                                      _params.incrementalProjection);
      }
    }
    return sum;
  }

  void updateViscosity() {
    for (int c = 0; c < dims(); ++c) {
      fillGhostsVelocity(_space, _grid, _velocityBc, c, _u.comp[c]);
    }
    strainRateInvariant(_space, _grid, _u, _gammaDot, wallLawApertures());
    bedPressure(_space, _cut, _phi, _p, _params.gasDensity, _params.gravity, _params.gasPhi, _pBed);
    GranularRheology rheology = _params.rheology;
    if (_params.constantBedViscosity > 0.0) {
      // a Newtonian bed: m p / max(gamma_dot, floor) with m = 0 replaced by a fixed viscosity
      rheology.m0 = 0.0;
      rheology.m1 = 0.0;
    }
    mixtureViscosity(_space, _grid, rheology, _phi, _pBed, _gammaDot, _cut.wallLayer, _mu);
    if (_params.constantBedViscosity > 0.0) {
      addConstantBedViscosity(_space, _grid, _phi, rheology.phiMax, _params.constantBedViscosity,
                              _mu);
    }
  }

  /// \brief u at rest but for the given inflow, made divergence-free (a projection without
  /// gravity, the potential kept apart from p): the volume-fraction transport is bounded only
  /// with divergence-free fluxes.
  void startInflow();

  /// \brief Projects u without gravity, the potential kept apart from p.
  void makeDivergenceFree() {
    const field_type potential = makeField(_space, _grid, Staggering::Cell, "hikiln::cfd::phi0");
    project(1.0, _u, potential, false);
  }

  /// \brief Projects u (in place) with step dt; p becomes the pressure (withGasHead: the full
  /// pressure; else the potential of a projection that is 0 on the outflow faces). The Inflow
  /// faces carry the given inflow (withInflow) or nothing.
  SolveStats project(double dt, velocity_type const& u, field_type const& p,
                     bool withGasHead = true, bool withInflow = true) {
    const bool outflow = _open.has(BoundaryKind::Outflow) && withGasHead;
    if (outflow) {
      // solve for p' = p - rho_gas g.x, which is 0 on the outflow faces: the gas head's
      // gradient (rho_gas g on every face) comes off u first
      correctVelocity(_space, _cut, _rhoFace, dt, _gasHead, u);
    }
    imposeInflow(u.comp[2], withInflow ? 1.0 : 0.0);
    const auto start = startSolveClock();
    // cells outside the shell (no open face): any positive alpha decouples them. The
    // multigrid coarsens alpha over the fluid cells only (the capacity as its mask), so that
    // alpha stays out of the coarse cells that straddle the shell; averaged into them it was a
    // sink the fine problem does not have, and the drums' pressure iterations grew with the grid
    // (14 / 21 / 29 at 64 / 128 / 256 cells across, now 10-12). A closed shell's fluid cells are
    // then singular on every level (p up to a constant): the coarsest level's pseudo-inverse
    // drops that mode, and the multigrid keeps the right-hand side and the residuals free of it
    // (CellMultigrid::setupOpenNullVector; without that, round-off fed the mode until a
    // 256 x 256 drum's solve diverged at t = 3 s). The constant, which no term reads, is whatever
    // the iteration leaves (bedPressure is gauge-free).
    const double hMin = std::min(_grid.hx, _grid.hy);
    const double removedAlpha = 1.0 / (_params.solidDensity * hMin * hMin);
    pressureCoefficients(_space, _cut, _rhoFace, removedAlpha, _pAlpha, _beta);
    apertureDivergence(_space, _cut, u, _div);
    axpbyUnknowns(_space, _cells, -1.0 / dt, _div, 0.0, _div);
    CellMultigrid<ExecutionSpace>& mg = keptMultigrid(_pressureMg, [&] {
      return std::make_unique<CellMultigrid<ExecutionSpace>>(
          _space, _grid, _pressureBc, _pAlpha, _beta, multigridOptions(_params.pressureTolerance),
          _cut.capacity);
    });
    // The stopping rule refers to the cold start's residual (p = 0). A warm start from the last
    // pressure (less the gas head where p' is solved for) only gets there sooner; referred to its
    // own, much smaller residual, round-off stalled the iteration.
    double coldResidual = 0.0;
    if (_params.warmStart) {
      coldResidual = mg.residualNorm(_zeroCells, _div);
      if (outflow) {
        axpbyUnknowns(_space, _cells, -1.0, _gasHead, 1.0, p);
      }
    } else {
      Kokkos::deep_copy(_space, p, 0.0);
    }
    SolveStats stats = mg.solvePcg(p, _div, coldResidual);
    stats.seconds = elapsedSince(start);
    if (!stats.converged) {
      throw std::runtime_error("hikiln::cfd::TwoPhaseSolver: pressure solve did not converge (" +
                               std::to_string(stats.iterations) + " iterations)");
    }
    if (_open.has(BoundaryKind::Outflow)) {
      fillGhostsScalar(_space, _grid, _pressureBc, p); // the outflow faces read p's ghosts
    }
    // the inflow faces keep their velocity: p's ghost mirrors the cell there (zero gradient)
    correctVelocity(_space, _cut, _rhoFace, dt, p, u);
    if (outflow) {
      axpbyUnknowns(_space, _cells, 1.0, _gasHead, 1.0, p);
    }
    return stats;
  }

  // The three solves' multigrids reference this solver's coefficient fields (_alpha and _mu;
  // _pAlpha, _beta and the capacity; _tAlpha and _tBeta). Made by the first solve, they are
  // refreshed with the new coefficients by every later one, so a step allocates nothing.
  template <class Multigrid, class Make>
  static Multigrid& keptMultigrid(std::unique_ptr<Multigrid>& kept, Make&& make) {
    if (kept) {
      kept->refresh();
    } else {
      kept = make();
    }
    return *kept;
  }
  MultigridOptions multigridOptions(double tolerance) const {
    MultigridOptions options;
    options.tolerance = tolerance;
    options.maxIterations = _params.maxIterations;
    options.harmonicEdgeViscosity = _params.harmonicEdgeViscosity; // viscous solves only
    return options;
  }

  /// \brief The time a solve starts, once the work queued before it has finished.
  std::chrono::steady_clock::time_point startSolveClock() const {
    _space.fence();
    return std::chrono::steady_clock::now();
  }
  /// \brief Seconds since start, once the solve's work has finished.
  double elapsedSince(std::chrono::steady_clock::time_point start) const {
    _space.fence();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// \brief Throws unless the open sides are the z sides of a 3D grid not periodic along z,
  /// and an inflow has an outflow (the mixture is incompressible).
  void validateOpenSides() const {
    const std::string who = "hikiln::cfd::TwoPhaseSolver: ";
    for (int side = 0; side < 6; ++side) {
      const BoundaryKind k = _open.kind[side];
      if (k != BoundaryKind::Wall && k != BoundaryKind::Inflow && k != BoundaryKind::Outflow) {
        throw std::invalid_argument(who + "an open side must be Wall, Inflow or Outflow");
      }
      if (k != BoundaryKind::Wall && (side / 2 != 2 || !_grid.is3D() || _periodic[2])) {
        throw std::invalid_argument(who +
                                    "only the z ends of a 3D grid not periodic along z "
                                    "can be open (side " +
                                    std::to_string(side) + ")");
      }
    }
    if (_open.has(BoundaryKind::Inflow) && !_open.has(BoundaryKind::Outflow)) {
      throw std::invalid_argument(who + "an inflow needs an outflow side (the mixture is "
                                        "incompressible)");
    }
  }

  /// \brief w on the Inflow sides' boundary faces = scale x the given inflow (setInflow).
  void imposeInflow(field_type const& w, double scale = 1.0) {
    for (int side : {ZLow, ZHigh}) {
      if (_open.kind[side] == BoundaryKind::Inflow) {
        copyEndFaces(_space, _grid, side, _inflowW, w, scale);
      }
    }
  }

  /// \brief Copies the boundary faces of the open sides from `from` to `to`.
  void copyEndNodes(field_type const& from, field_type const& to) {
    for (int side : {ZLow, ZHigh}) {
      if (_open.kind[side] != BoundaryKind::Wall) {
        copyEndFaces(_space, _grid, side, from, to);
      }
    }
  }

  /// \brief The Outflow sides' boundary faces take the velocity of the faces inside them (zero
  /// gradient); the projection then corrects them.
  void extrapolateOutflow(field_type const& w) {
    for (int side : {ZLow, ZHigh}) {
      if (_open.kind[side] == BoundaryKind::Outflow) {
        extrapolateEndFaces(_space, _grid, side, w);
      }
    }
  }

  /// \brief phi's ghost cells beyond the open ends, read by the FCT fluxes there.
  void fillOpenEndGhosts() {
    for (int side : {ZLow, ZHigh}) {
      if (_open.kind[side] != BoundaryKind::Wall) {
        fillEndGhosts(_space, _grid, side, _open.kind[side] == BoundaryKind::Inflow, _inflowPhi,
                      _phi);
      }
    }
  }

  ExecutionSpace _space;
  Grid _grid;
  Shape _shape;
  TwoPhaseParameters _params;
  OpenSides _open;
  bool _periodic[3] = {false, false, true};
  CutCellOptions _cutOptions;
  CutCells<memory_space> _cut;
  ScalarBoundaries _pressureBc, _heatBc;
  VelocityBoundaries _velocityBc;
  UnknownBox _cells;
  field_type _phi, _p, _pBed, _rho, _mu, _gammaDot, _div, _pAlpha;
  velocity_type _u, _uStar, _rhs;
  velocity_type _accel;           ///< the incremental projection's carried acceleration (step 4)
  velocity_type _predictorChange; ///< u* less its cold guess, last step (warmMomentumStart)
  field_type _zeroCells;          ///< stays 0: the pressure's cold start (project)
  std::unique_ptr<ViscousMultigrid<ExecutionSpace>> _momentumMg; ///< keptMultigrid()
  std::unique_ptr<CellMultigrid<ExecutionSpace>> _pressureMg, _heatMg;
  field_type _alpha[3], _rhoFace[3], _beta[3];
  FctWork<memory_space> _fct;
  field_type _T, _Tstar, _phiOld, _kappa, _tAlpha, _tRhs, _tBeta[3];
  struct TemperatureTracer {
    field_type temperature;
    ThermalParameters thermal;
    InflowTemperature inflow;
    double lastIn = 0.0, lastOut = 0.0;
  };
  std::vector<TemperatureTracer> _tracers;
  field_type _inflowW, _inflowPhi, _gasHead; ///< open ends only
  bool _inflowSet = false;
  InflowTemperature _inflowT;
  double _solidsIn = 0.0, _solidsOut = 0.0;
  double _time = 0.0;
  double _lastDt = 0.0;    ///< of the last step (shellTorque)
  ShellTorque _dragTorque; ///< the shell's drag on the last predicted velocity
};

// The members that reach the kernels and the multigrids are defined out of the class, so that
// the explicit instantiation declarations below keep them out of every file that uses the drum's
// or the kiln's solver: they are compiled once per backend in hikiln_cfd
// (solvers/cfd/CMakeLists.txt).

template <class ExecutionSpace, class Shape>
TwoPhaseSolver<ExecutionSpace, Shape>::TwoPhaseSolver(ExecutionSpace const& space, Grid const& grid,
                                                      Shape const& shape,
                                                      TwoPhaseParameters const& params,
                                                      CutCellOptions const& cutOptions,
                                                      OpenSides const& openSides)
    : _space(space), _grid(grid), _shape(shape), _params(params), _open(openSides) {
  params.validate();
  for (int a = 0; a < 3; ++a) {
    _periodic[a] = cutOptions.periodic[a] || (a == 2 && !grid.is3D());
  }
  validateOpenSides();
  CutCellOptions options = cutOptions;
  options.periodic[2] = _periodic[2];
  for (int side = 0; side < 6; ++side) {
    options.open[side] = _open.kind[side] != BoundaryKind::Wall;
  }
  _cutOptions = options;
  _cut = buildCutCells(space, grid, shape, options);
  for (int side = 0; side < 6; ++side) {
    const bool per = _periodic[side / 2];
    const BoundaryKind end = _open.kind[side];
    _pressureBc.kind[side] =
        per ? BoundaryKind::Periodic
            : (end == BoundaryKind::Outflow ? BoundaryKind::Value : BoundaryKind::Wall);
    _velocityBc.kind[side] = per ? BoundaryKind::Periodic : end;
    // heat leaves and enters an open end with the flow only: no diffusive flux there
    _heatBc.kind[side] = per ? BoundaryKind::Periodic : BoundaryKind::Wall;
  }
  _phi = cellField("hikiln::cfd::phi");
  _p = cellField("hikiln::cfd::p");
  _pBed = cellField("hikiln::cfd::pBed");
  _rho = cellField("hikiln::cfd::rho");
  _mu = cellField("hikiln::cfd::mu");
  _gammaDot = cellField("hikiln::cfd::gammaDot");
  _div = cellField("hikiln::cfd::div");
  _pAlpha = cellField("hikiln::cfd::pAlpha");
  if (params.energy) {
    params.thermal.validate("hikiln::cfd::TwoPhaseParameters");
    _T = cellField("hikiln::cfd::T");
    allocateHeatWork();
  }
  for (int a = 0; a < 3; ++a) {
    const Staggering s = faceStaggering(a);
    _u.comp[a] = makeField(space, grid, s, "hikiln::cfd::u");
    _uStar.comp[a] = makeField(space, grid, s, "hikiln::cfd::uStar");
    _rhs.comp[a] = makeField(space, grid, s, "hikiln::cfd::rhs");
    _alpha[a] = makeField(space, grid, s, "hikiln::cfd::alpha");
    _rhoFace[a] = makeField(space, grid, s, "hikiln::cfd::rhoFace");
    _beta[a] = makeField(space, grid, s, "hikiln::cfd::beta");
    if (params.incrementalProjection) {
      _accel.comp[a] = makeField(space, grid, s, "hikiln::cfd::accel");
    }
    if (params.warmStart) {
      _predictorChange.comp[a] = makeField(space, grid, s, "hikiln::cfd::predictorChange");
    }
  }
  if (params.warmStart) {
    _zeroCells = cellField("hikiln::cfd::zeroCells");
  }
  _fct = makeFctWork(space, grid);
  for (int a = 0; a < 3; ++a) {
    _cells.lo[a] = 0;
    _cells.hi[a] = grid.cells(a);
  }
  _cells.offsets = ghostOffsets(grid);
  if (_open.has(BoundaryKind::Inflow)) {
    _inflowW = makeField(space, grid, faceStaggering(2), "hikiln::cfd::inflowW");
    _inflowPhi = makeField(space, grid, faceStaggering(2), "hikiln::cfd::inflowPhi");
  }
  if (_open.has(BoundaryKind::Outflow)) {
    _gasHead = cellField("hikiln::cfd::gasHead");
    gasHead(space, grid, params.gasDensity, params.gravity, _gasHead);
  }
}

template <class ExecutionSpace, class Shape>
double TwoPhaseSolver<ExecutionSpace, Shape>::changeShape(Shape const& shape) {
  const double before = solids();
  _shape = shape;
  _cut = buildCutCells(_space, _grid, shape, _cutOptions);
  imposeInflow(_u.comp[2]);
  makeDivergenceFree();
  return before - solids();
}

template <class ExecutionSpace, class Shape>
void TwoPhaseSolver<ExecutionSpace, Shape>::setFlatBed(double level) {
  const Grid grid = _grid;
  const int g = grid.ghost, gz = grid.ghostZ();
  const double phiMax = _params.rheology.phiMax;
  const auto vol = _cut.capacity;
  const auto phi = _phi;
  Kokkos::parallel_for(
      "hikiln::cfd::setFlatBed", gridPolicy(_space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const double y0 = grid.y0 + j * grid.hy;
        const double below = math::fmin(math::fmax((level - y0) / grid.hy, 0.0), 1.0);
        phi(i + g, j + g, k + gz) = vol(i + g, j + g, k + gz) > 0.0 ? phiMax * below : 0.0;
      });
  for (int a = 0; a < 3; ++a) {
    Kokkos::deep_copy(_space, _u.comp[a], 0.0);
  }
  hydrostaticPressure();
  if (_inflowSet) {
    startInflow();
  }
}

template <class ExecutionSpace, class Shape>
void TwoPhaseSolver<ExecutionSpace, Shape>::hydrostaticPressure() {
  updateDensity();
  for (int c = 0; c < dims(); ++c) {
    Kokkos::deep_copy(_space, _uStar.comp[c], 0.0);
  }
  addGravity(_space, _cut, _params.gravity, 1.0, _uStar);
  Kokkos::deep_copy(_space, _p, 0.0);
  project(1.0, _uStar, _p, true, false);
}

template <class ExecutionSpace, class Shape>
TwoPhaseStepReport TwoPhaseSolver<ExecutionSpace, Shape>::step(double dt) {
  TwoPhaseStepReport report;
  report.dt = dt;
  report.limitedBy = "given";
  const RheologyView rh = rheologyView();
  report.solidsBefore = solidsContent(_space, _cut, _phi);
  if (_params.energy) {
    report.heatBefore = heat();
  }
  if (_phiOld.extent(0) > 0) {
    Kokkos::deep_copy(_space, _phiOld, _phi);
  }
  if (_open.has(BoundaryKind::Inflow) || _open.has(BoundaryKind::Outflow)) {
    fillOpenEndGhosts();
  }
  report.transportSubsteps = transportVolumeFractionInSubsteps(_space, _cut, _u, settling().v, dt,
                                                               rh.phiMax, _params.cfl, _phi, _fct);
  report.solidsAfter = solidsContent(_space, _cut, _phi);
  for (int side : {ZLow, ZHigh}) {
    if (_open.kind[side] == BoundaryKind::Wall) {
      continue;
    }
    // the flux along +z leaves the domain at the high side and enters it at the low side
    const double outward =
        (side == ZHigh ? 1.0 : -1.0) * boundarySolidsFlux(_space, _cut, _fct, side);
    if (_open.kind[side] == BoundaryKind::Outflow) {
      report.solidsOut += outward;
    } else {
      report.solidsIn -= outward;
    }
  }
  _solidsIn += report.solidsIn;
  _solidsOut += report.solidsOut;
  if (_params.energy) {
    const HeatStep h = energyStep(dt, _T, _params.thermal, _inflowT);
    report.energy = h.solve;
    report.heatSubsteps = h.substeps;
    report.heatIn = h.in;
    report.heatOut = h.out;
    report.heatFromShell = h.shell;
    report.heatAfter = heat();
  }
  for (TemperatureTracer& tracer : _tracers) {
    const HeatStep h = energyStep(dt, tracer.temperature, tracer.thermal, tracer.inflow);
    tracer.lastIn = h.in;
    tracer.lastOut = h.out;
  }
  updateDensity();
  updateViscosity();
  // momentum predictor with implicit viscosity
  for (int c = 0; c < dims(); ++c) {
    fillGhostsVelocity(_space, _grid, _velocityBc, c, _u.comp[c]);
  }
  const double muMax = maxAbsUnknowns(_space, _cells, _mu);
  const WallFriction friction = wallFriction();
  for (int c = 0; c < dims(); ++c) {
    momentumPredictor(_space, _cut, _shape, c, _u, _rhoFace[c], dt, _params.penalty, muMax,
                      friction, _pBed, _alpha[c], _rhs.comp[c], _uStar.comp[c]);
    if (_params.incrementalProjection) {
      addCarriedAcceleration(_space, _cut, c, _rhoFace[c], _accel.comp[c], _rhs.comp[c]);
    }
  }
  // the open ends' normal velocities are data of the solve: u^n's (inflow given, outflow
  // from the last projection)
  copyEndNodes(_u.comp[2], _uStar.comp[2]);
  const auto viscousStart = startSolveClock();
  ViscousMultigrid<ExecutionSpace>& viscous = keptMultigrid(_momentumMg, [&] {
    return std::make_unique<ViscousMultigrid<ExecutionSpace>>(
        _space, _grid, _velocityBc, _alpha, _mu, multigridOptions(_params.viscousTolerance),
        wallLawApertures());
  });
  const double coldResidual = warmMomentumStart(viscous, dt);
  report.viscous = viscous.solvePcg(_uStar, _rhs, coldResidual);
  if (_params.warmStart) {
    viscous.axpby(1.0, _uStar, 1.0, _predictorChange); // u* less the cold guess
  }
  report.viscous.seconds = elapsedSince(viscousStart);
  if (!_grid.is3D()) {
    _dragTorque = shellTorqueOf(_uStar, dt); // the shell's drag acts on the predicted velocity
  }
  if (!report.viscous.converged) {
    throw std::runtime_error("hikiln::cfd::TwoPhaseSolver: momentum solve did not converge (" +
                             std::to_string(report.viscous.iterations) + " iterations)");
  }
  if (_params.incrementalProjection) {
    for (int c = 0; c < dims(); ++c) {
      removeCarriedAcceleration(_space, _cut, c, dt, _accel.comp[c], _uStar.comp[c]);
    }
  }
  if (_open.has(BoundaryKind::Outflow)) {
    extrapolateOutflow(_uStar.comp[2]);
  }
  addGravity(_space, _cut, _params.gravity, dt, _uStar);
  report.pressure = project(dt, _uStar, _p);
  if (_params.incrementalProjection) {
    for (int c = 0; c < dims(); ++c) {
      updateCarriedAcceleration(_space, _cut, c, dt, _uStar.comp[c], _accel.comp[c]);
    }
  }
  for (int c = 0; c < dims(); ++c) {
    Kokkos::deep_copy(_space, _u.comp[c], _uStar.comp[c]);
  }
  apertureDivergence(_space, _cut, _u, _div);
  report.maxDivergence = maxAbsUnknowns(_space, _cells, _div);
  _time += dt;
  _lastDt = dt;
  return report;
}

template <class ExecutionSpace, class Shape>
double TwoPhaseSolver<ExecutionSpace, Shape>::wallSlip() {
  if constexpr (!HasAxis<Shape>::value) {
    return std::nan(""); // no axis (cx, cy, omega) to turn about
  } else {
    if (_shape.omega == 0.0) {
      return std::nan("");
    }
    const Grid grid = _grid;
    const int g = grid.ghost, gz = grid.ghostZ();
    const auto cap = _cut.capacity;
    const auto wall = _cut.wallLayer;
    const auto phi = _phi;
    const auto u = _u.comp[0], v = _u.comp[1];
    const auto au = _cut.aperture[0], av = _cut.aperture[1];
    const double half = 0.5 * _params.rheology.phiMax;
    const double cx = _shape.cx, cy = _shape.cy, omega = _shape.omega;
    double sum = 0.0, weight = 0.0;
    Kokkos::parallel_reduce(
        "hikiln::cfd::wallSlip", gridPolicy(_space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
        KOKKOS_LAMBDA(const int i, const int j, const int k, double& s, double& w) {
          const int I = i + g, J = j + g, K = k + gz;
          if (wall(I, J, K) <= 0.0 || phi(I, J, K) < half) {
            return;
          }
          const double openU = au(I, J, K) + au(I + 1, J, K);
          const double openV = av(I, J, K) + av(I, J + 1, K);
          if (openU <= 0.0 || openV <= 0.0) {
            return;
          }
          const double x = grid.coordinate(Staggering::Cell, 0, i) - cx;
          const double y = grid.coordinate(Staggering::Cell, 1, j) - cy;
          const double r = math::sqrt(x * x + y * y);
          const double uc = (au(I, J, K) * u(I, J, K) + au(I + 1, J, K) * u(I + 1, J, K)) / openU;
          const double vc = (av(I, J, K) * v(I, J, K) + av(I, J + 1, K) * v(I, J + 1, K)) / openV;
          const double bed = cap(I, J, K) * phi(I, J, K);
          s += bed * (-y * uc + x * vc) / (r * omega * r);
          w += bed;
        },
        sum, weight);
    return weight > 0.0 ? 1.0 - sum / weight : std::nan("");
  }
}

template <class ExecutionSpace, class Shape>
void TwoPhaseSolver<ExecutionSpace, Shape>::phiRange(double& lo, double& hi) {
  const Grid grid = _grid;
  const int g = grid.ghost, gz = grid.ghostZ();
  const auto vol = _cut.capacity;
  const auto phi = _phi;
  lo = 0.0;
  hi = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::phiRange", gridPolicy(_space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& mn, double& mx) {
        if (vol(i + g, j + g, k + gz) > 0.0) {
          mn = math::fmin(mn, phi(i + g, j + g, k + gz));
          mx = math::fmax(mx, phi(i + g, j + g, k + gz));
        }
      },
      Kokkos::Min<double>(lo), Kokkos::Max<double>(hi));
}

template <class ExecutionSpace, class Shape>
void TwoPhaseSolver<ExecutionSpace, Shape>::startInflow() {
  imposeInflow(_u.comp[2]);
  makeDivergenceFree();
}

#ifdef KOKKOS_ENABLE_SERIAL
extern template class TwoPhaseSolver<Kokkos::Serial, DrumShell>;
extern template class TwoPhaseSolver<Kokkos::Serial, KilnDomain>;
#endif
#ifdef KOKKOS_ENABLE_OPENMP
extern template class TwoPhaseSolver<Kokkos::OpenMP, DrumShell>;
extern template class TwoPhaseSolver<Kokkos::OpenMP, KilnDomain>;
#endif
#ifdef KOKKOS_ENABLE_CUDA
extern template class TwoPhaseSolver<Kokkos::Cuda, DrumShell>;
extern template class TwoPhaseSolver<Kokkos::Cuda, KilnDomain>;
#endif

} // namespace hikiln::cfd
