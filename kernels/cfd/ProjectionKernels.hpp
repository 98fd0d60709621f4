#pragma once
/// \file ProjectionKernels.hpp
/// \brief Per-cell and per-face kernels of the two-phase projection step on cut cells (see
/// solvers/cfd/TwoPhaseSolver.hpp): mixture and face densities, the momentum predictor's
/// coefficients and right-hand side (upwind advection, gravity, old pressure gradient, Brinkman
/// wall forcing), the aperture-weighted divergence, the pressure coefficients and the velocity
/// correction, and the granular (bed) pressure.
///
/// Faces of axis a between cells L (below) and R (above); pressure gradients (p_R - p_L) / h_a
/// only through open faces (aperture > 0); at a closed face the wall forcing holds the velocity.

#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/ShellGeometry.hpp"
#include "kernels/cfd/SplitLoop.hpp"
#include "kernels/cfd/ViscousOperator.hpp"

#include <Kokkos_Core.hpp>

#include <type_traits>

namespace hikiln::cfd {

/// \brief rho = phi rhoSolid + (1 - phi) rhoGas per cell.
template <class ExecutionSpace, class MemorySpace>
void mixtureDensity(ExecutionSpace const& space, Grid const& grid, double rhoSolid, double rhoGas,
                    Field<MemorySpace> const& phi, Field<MemorySpace> const& rho) {
  const int g = grid.ghost, gz = grid.ghostZ();
  Kokkos::parallel_for(
      "hikiln::cfd::mixtureDensity", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const double f = phi(i + g, j + g, k + gz);
        rho(i + g, j + g, k + gz) = f * rhoSolid + (1.0 - f) * rhoGas;
      });
}

/// \brief The two cells beside face `face` along an axis of n cells (wrapped when periodic,
/// clamped otherwise).
KOKKOS_INLINE_FUNCTION void cellsBesideFace(int face, int n, bool periodic, int& below,
                                            int& above) {
  below = face - 1;
  above = face;
  if (periodic) {
    below = below < 0 ? n - 1 : below;
    above = above >= n ? 0 : above;
  } else {
    below = below < 0 ? 0 : below;
    above = above >= n ? n - 1 : above;
  }
}

namespace detail {

/// faceDensities on the faces normal to axis A.
template <int A, class ExecutionSpace, class MemorySpace>
void faceDensitiesOnAxis(ExecutionSpace const& space, Grid const& grid, bool periodic,
                         Field<MemorySpace> const& rho, Field<MemorySpace> const& out) {
  const int g = grid.ghost, gz = grid.ghostZ();
  const int n = grid.cells(A);
  const int hi[3] = {grid.nx + (A == 0), grid.ny + (A == 1), grid.nz + (A == 2)};
  forEachBoxCell(
      space, "hikiln::cfd::faceDensities", {0, 0, 0}, hi,
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        int idx[3] = {i, j, k};
        int below, above;
        cellsBesideFace(idx[A], n, periodic, below, above);
        idx[A] = below;
        const double rb = rho(idx[0] + g, idx[1] + g, idx[2] + gz);
        idx[A] = above;
        const double ra = rho(idx[0] + g, idx[1] + g, idx[2] + gz);
        out(i + g, j + g, k + gz) = 0.5 * (rb + ra);
      });
}

} // namespace detail

/// \brief Face densities (arithmetic mean of the two cells) on every face of every axis.
template <class ExecutionSpace, class MemorySpace>
void faceDensities(ExecutionSpace const& space, Grid const& grid, bool const (&periodic)[3],
                   Field<MemorySpace> const& rho, Field<MemorySpace> const (&rhoFace)[3]) {
  for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
    withAxis(a, [&](auto axis) {
      detail::faceDensitiesOnAxis<decltype(axis)::value>(space, grid, periodic[a], rho, rhoFace[a]);
    });
  }
}

/// \brief Coulomb friction of the bed on the shell, applied on the cut faces.
///
/// The cap is the granular stress's: gas does not obey it. A cut face in the gas is held at the
/// shell velocity (no slip, the full penalty forcing), a face with a solids fraction of
/// `dilutePhi` or more is capped, and in between the two forcings are blended by the solids
/// fraction. Without that the freeboard gas slid freely along the shell: in the inclined kiln
/// (kramers-inclined.yaml, incremental projection, harmonic edge viscosities) a jet of gas
/// ran up the shell's cut cells along the whole kiln and sped up steadily (2.4 m/s at 30 s)
/// until the step collapsed.
struct WallFriction {
  bool enabled = false;
  double muWall = 0.0;
  double slipFloor = 1e-3;   ///< m/s: regularises the drag at zero slip (stick below)
  double gasDensity = 0.0;   ///< [kg/m3], with solidDensity: a face's solids fraction
  double solidDensity = 0.0; ///< [kg/m3]
  double dilutePhi = 0.0;    ///< solids fraction from which a face is all bed; 0: every cut face is
                             ///< bed (shell_gas slip)

  /// \brief The share of a face (mixture density rhoFace) that the shell holds as gas:
  /// 1 - phi / dilutePhi clamped to [0, 1]; 0 everywhere when dilutePhi is 0.
  KOKKOS_INLINE_FUNCTION double gasShare(double rhoFace) const {
    if (!(dilutePhi > 0.0)) {
      return 0.0;
    }
    const double phi = (rhoFace - gasDensity) / (solidDensity - gasDensity);
    return math::fmin(1.0, math::fmax(0.0, 1.0 - phi / dilutePhi));
  }

  /// \brief The largest wall force on one cut face of component c per unit depth,
  /// mu_wall sigma_n h: sigma_n ~ the larger bed pressure of the two cells beside the face, h the
  /// wall length per cut cell (~ a cell edge across c). ShellTorque.hpp sums it as a bound.
  KOKKOS_INLINE_FUNCTION double capForce(Grid const& grid, int c, double pBedHere,
                                         double pBedBelow) const {
    return muWall * math::fmax(pBedHere, pBedBelow) * grid.spacing(c == 0 ? 1 : 0);
  }
};

namespace detail {

/// The momentum predictor's coefficients on one face of component C (momentumPredictor). Dims
/// and C are template arguments so that the loop over the advecting components unrolls and the
/// index arrays stay in registers (with run-time counts ~18 ns a face on two threads, 256 x 256
/// drum: 1.19 ms a component).
template <int Dims, int C, class MemorySpace, class Shape> struct MomentumPredictor {
  Grid grid;
  int off[3];
  Shape shape;
  Field<MemorySpace> ap, cx, cy, cz; ///< aperture and open-part centroid of the C faces
  Field<MemorySpace> u[3];
  Field<MemorySpace> rhoFace, pBed, alpha, rhs, guess;
  double dt, penalty, viscousScale;
  double h; ///< wall length per cut cell ~ a cell edge
  WallFriction friction;

  KOKKOS_FORCEINLINE_FUNCTION void operator()(const int i, const int j, const int k) const {
    const int I = i + off[0], J = j + off[1], K = k + off[2];
    const auto& uc = u[C];
    const double open = ap(I, J, K);
    const double rf = rhoFace(I, J, K);
    const double wall = shape.wallVelocity(C, cx(I, J, K), cy(I, J, K), cz(I, J, K));
    const double here = uc(I, J, K);
    double forcing = penalty * (rf / dt + viscousScale) * (1.0 - open);
    if (friction.enabled && open > 0.0 && open < 1.0) {
      // Coulomb wall friction on the cut faces: the drag per unit volume reaches at most
      // mu_wall sigma_n / h (sigma_n ~ the bed pressure beside the face)
      int q[3] = {I, J, K};
      q[C] -= 1;
      const double slip = math::fmax(math::fabs(here - wall), friction.slipFloor);
      const double cap = friction.capForce(grid, C, pBed(I, J, K), pBed(q[0], q[1], q[2]));
      const double gas = friction.gasShare(rf);
      forcing = gas * forcing + (1.0 - gas) * math::fmin(forcing, cap / (h * h * slip));
    }
    alpha(I, J, K) = rf / dt + forcing;
    double value = rf * here / dt + forcing * wall;
    if (open > 0.0) {
      double advection = 0.0;
      for (int b = 0; b < Dims; ++b) {
        int q[3] = {I, J, K};
        double vb;
        if (b == C) {
          vb = here;
        } else {
          // u_b at the four (b-node, C-cell) positions around this C-face
          const auto& ub = u[b];
          int s[3] = {I, J, K};
          vb = ub(s[0], s[1], s[2]);
          s[b] += 1;
          vb += ub(s[0], s[1], s[2]);
          s[C] -= 1;
          vb += ub(s[0], s[1], s[2]);
          s[b] -= 1;
          vb += ub(s[0], s[1], s[2]);
          vb *= 0.25;
        }
        q[b] += vb >= 0.0 ? -1 : 1;
        // with the Coulomb wall a closed (shell-held) face upwind carries no momentum in
        // (zero gradient): the shell acts on the fluid only through the capped forcing.
        // Ghost faces (apertures not stored) keep their boundary-filled values.
        const int upwind[3] = {q[0] - off[0], q[1] - off[1], q[2] - off[2]};
        const bool shellHeld = friction.enabled && shellHeldFaceOf<Dims>(ap, grid, C, upwind);
        const double neighbour = shellHeld ? here : uc(q[0], q[1], q[2]);
        advection += vb * (vb >= 0.0 ? here - neighbour : neighbour - here) / grid.spacing(b);
      }
      value -= rf * advection;
    }
    rhs(I, J, K) = value;
    guess(I, J, K) = open < 1.0 ? wall : here;
  }
};

template <int Dims, int C, class ExecutionSpace, class MemorySpace, class Shape>
void momentumPredictorOf(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                         Shape const& shape, VelocityFields<MemorySpace> const& u,
                         Field<MemorySpace> const& rhoFace, double dt, double penalty, double muMax,
                         WallFriction const& friction, Field<MemorySpace> const& pBed,
                         Field<MemorySpace> const& alpha, Field<MemorySpace> const& rhs,
                         Field<MemorySpace> const& guess) {
  const Grid grid = cc.grid;
  MomentumPredictor<Dims, C, MemorySpace, Shape> predictor;
  predictor.grid = grid;
  predictor.off[0] = predictor.off[1] = grid.ghost;
  predictor.off[2] = grid.ghostZ();
  predictor.shape = shape;
  predictor.ap = cc.aperture[C];
  predictor.cx = cc.centroid[C][0];
  predictor.cy = cc.centroid[C][1];
  predictor.cz = cc.centroid[C][2];
  for (int b = 0; b < Dims; ++b) {
    predictor.u[b] = u.comp[b];
  }
  predictor.rhoFace = rhoFace;
  predictor.pBed = pBed;
  predictor.alpha = alpha;
  predictor.rhs = rhs;
  predictor.guess = guess;
  predictor.dt = dt;
  predictor.penalty = penalty;
  double hMin = grid.hx < grid.hy ? grid.hx : grid.hy;
  hMin = Dims == 3 && grid.hz < hMin ? grid.hz : hMin;
  predictor.viscousScale = 2.0 * Dims * muMax / (hMin * hMin);
  predictor.h = grid.spacing(C == 0 ? 1 : 0);
  predictor.friction = friction;
  const int hi[3] = {grid.nx + (C == 0), grid.ny + (C == 1), grid.nz + (C == 2)};
  forEachBoxCell(space, "hikiln::cfd::momentumPredictor", {0, 0, 0}, hi, predictor);
}

} // namespace detail

/// \brief Coefficients of the momentum predictor of component c on its faces:
///   alpha = rho_f / dt + K (1 - aperture),
///   rhs = rho_f (u / dt - (u . grad) u) [advection on open faces] + K (1 - aperture) u_wall,
/// with first-order upwind advection (advecting velocities averaged to the face), u_wall at the
/// centroid of the open part of the face, and the initial guess `guess` = u_wall on forced
/// faces, u elsewhere. u's ghosts must be filled.
/// K = penalty x (rho_f / dt + 2 d muMax / h_min^2) dominates inertia and viscous coupling.
/// Gravity and pressure act in the projection (balanced on the same faces, see
/// addGravity and correctVelocity).
template <class ExecutionSpace, class MemorySpace, class Shape>
void momentumPredictor(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                       Shape const& shape, int c, VelocityFields<MemorySpace> const& u,
                       Field<MemorySpace> const& rhoFace, double dt, double penalty, double muMax,
                       WallFriction const& friction, Field<MemorySpace> const& pBed,
                       Field<MemorySpace> const& alpha, Field<MemorySpace> const& rhs,
                       Field<MemorySpace> const& guess) {
  const auto launch = [&](auto dims, auto component) {
    detail::momentumPredictorOf<decltype(dims)::value, decltype(component)::value>(
        space, cc, shape, u, rhoFace, dt, penalty, muMax, friction, pBed, alpha, rhs, guess);
  };
  using Two = std::integral_constant<int, 2>;
  using Three = std::integral_constant<int, 3>;
  if (!cc.grid.is3D()) {
    c == 0 ? launch(Two(), std::integral_constant<int, 0>())
           : launch(Two(), std::integral_constant<int, 1>());
  } else if (c == 0) {
    launch(Three(), std::integral_constant<int, 0>());
  } else if (c == 1) {
    launch(Three(), std::integral_constant<int, 1>());
  } else {
    launch(Three(), std::integral_constant<int, 2>());
  }
}

/// \brief u += dt g on the open faces of every axis (gravity enters with the pressure gradient
/// of the projection, so a layered bed at rest is in exact discrete balance).
template <class ExecutionSpace, class MemorySpace>
void addGravity(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                double const (&gravity)[3], double dt, VelocityFields<MemorySpace> const& u) {
  const Grid grid = cc.grid;
  const int g = grid.ghost, gz = grid.ghostZ();
  for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
    const auto ap = cc.aperture[a];
    const auto ua = u.comp[a];
    const double dv = dt * gravity[a];
    const int hi[3] = {grid.nx + (a == 0), grid.ny + (a == 1), grid.nz + (a == 2)};
    Kokkos::parallel_for(
        "hikiln::cfd::addGravity", gridPolicy(space, {0, 0, 0}, hi),
        KOKKOS_LAMBDA(const int i, const int j, const int k) {
          if (ap(i + g, j + g, k + gz) > 0.0) {
            ua(i + g, j + g, k + gz) += dv;
          }
        });
  }
}

/// \brief div = sum over axes of (aperture u)(high face) - (aperture u)(low face), over h.
template <class ExecutionSpace, class MemorySpace>
void apertureDivergence(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                        VelocityFields<MemorySpace> const& u, Field<MemorySpace> const& div) {
  const Grid grid = cc.grid;
  const int dims = grid.is3D() ? 3 : 2;
  const int g = grid.ghost, gz = grid.ghostZ();
  const auto a0 = cc.aperture[0], a1 = cc.aperture[1], a2 = cc.aperture[2];
  const auto u0 = u.comp[0], u1 = u.comp[1], u2 = dims == 3 ? u.comp[2] : u.comp[0];
  Kokkos::parallel_for(
      "hikiln::cfd::apertureDivergence", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const int I = i + g, J = j + g, K = k + gz;
        double d = (a0(I + 1, J, K) * u0(I + 1, J, K) - a0(I, J, K) * u0(I, J, K)) / grid.hx +
                   (a1(I, J + 1, K) * u1(I, J + 1, K) - a1(I, J, K) * u1(I, J, K)) / grid.hy;
        if (dims == 3) {
          d += (a2(I, J, K + 1) * u2(I, J, K + 1) - a2(I, J, K) * u2(I, J, K)) / grid.hz;
        }
        div(I, J, K) = d;
      });
}

/// \brief Pressure-equation coefficients: beta = aperture / rho_f on the faces, and alpha in
/// cells = `removedAlpha` in solid cells (no open face, capacity 0: decoupled, pressure 0), 0 in
/// fluid ones.
template <class ExecutionSpace, class MemorySpace>
void pressureCoefficients(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                          Field<MemorySpace> const (&rhoFace)[3], double removedAlpha,
                          Field<MemorySpace> const& alpha, Field<MemorySpace> const (&beta)[3]) {
  const Grid grid = cc.grid;
  const int g = grid.ghost, gz = grid.ghostZ();
  for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
    const auto ap = cc.aperture[a];
    const auto rf = rhoFace[a];
    const auto b = beta[a];
    const int hi[3] = {grid.nx + (a == 0), grid.ny + (a == 1), grid.nz + (a == 2)};
    Kokkos::parallel_for(
        "hikiln::cfd::pressureBeta", gridPolicy(space, {0, 0, 0}, hi),
        KOKKOS_LAMBDA(const int i, const int j, const int k) {
          b(i + g, j + g, k + gz) = ap(i + g, j + g, k + gz) / rf(i + g, j + g, k + gz);
        });
  }
  const auto vol = cc.capacity;
  Kokkos::parallel_for(
      "hikiln::cfd::pressureAlpha", gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        alpha(i + g, j + g, k + gz) = vol(i + g, j + g, k + gz) > 0.0 ? 0.0 : removedAlpha;
      });
}

/// \brief u -= dt / rho_f dq/dx on the open faces of every axis. An open boundary face of a
/// non-periodic axis (a kiln's end) reads q's ghost cell: fill q's ghosts first there.
template <class ExecutionSpace, class MemorySpace>
void correctVelocity(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                     Field<MemorySpace> const (&rhoFace)[3], double dt, Field<MemorySpace> const& q,
                     VelocityFields<MemorySpace> const& u) {
  const Grid grid = cc.grid;
  const int off[3] = {grid.ghost, grid.ghost, grid.ghostZ()};
  for (int a = 0; a < (grid.is3D() ? 3 : 2); ++a) {
    const auto ap = cc.aperture[a];
    const auto rf = rhoFace[a];
    const auto ua = u.comp[a];
    const int n = grid.cells(a);
    const bool periodic = cc.periodic[a];
    const double h = grid.spacing(a);
    const int hi[3] = {grid.nx + (a == 0), grid.ny + (a == 1), grid.nz + (a == 2)};
    Kokkos::parallel_for(
        "hikiln::cfd::correctVelocity", gridPolicy(space, {0, 0, 0}, hi),
        KOKKOS_LAMBDA(const int i, const int j, const int k) {
          const int I = i + off[0], J = j + off[1], K = k + off[2];
          if (ap(I, J, K) <= 0.0) {
            return;
          }
          int idx[3] = {i, j, k};
          int below = idx[a] - 1, above = idx[a];
          if (periodic) {
            cellsBesideFace(idx[a], n, true, below, above);
          }
          idx[a] = below;
          const double qb = q(idx[0] + off[0], idx[1] + off[1], idx[2] + off[2]);
          idx[a] = above;
          const double qa = q(idx[0] + off[0], idx[1] + off[1], idx[2] + off[2]);
          ua(I, J, K) -= dt / rf(I, J, K) * (qa - qb) / h;
        });
  }
}

/// \brief q = rho_gas g.x in every cell, ghosts included: the pressure of the gas at rest (up to
/// a constant). Its gradient on any face is exactly rho_gas g.
template <class ExecutionSpace, class MemorySpace>
void gasHead(ExecutionSpace const& space, Grid const& grid, double rhoGas,
             double const (&gravity)[3], Field<MemorySpace> const& q) {
  const int g = grid.ghost, gz = grid.ghostZ();
  const double g0 = gravity[0], g1 = gravity[1], g2 = gravity[2];
  Kokkos::parallel_for(
      "hikiln::cfd::gasHead",
      gridPolicy(space, {-g, -g, -gz}, {grid.nx + g, grid.ny + g, grid.nz + gz}),
      KOKKOS_LAMBDA(const int i, const int j, const int k) {
        const double x = grid.coordinate(Staggering::Cell, 0, i);
        const double y = grid.coordinate(Staggering::Cell, 1, j);
        const double z = grid.coordinate(Staggering::Cell, 2, k);
        q(i + g, j + g, k + gz) = rhoGas * (g0 * x + g1 * y + g2 * z);
      });
}

/// \brief p - rho_gas g.x at a cell: constant through a gas at rest.
template <class MemorySpace> struct GasHeadRemoved {
  Grid grid;
  Field<MemorySpace> p;
  double rhoGas;
  double gravity[3];
  KOKKOS_INLINE_FUNCTION double operator()(int i, int j, int k) const {
    const double x = grid.coordinate(Staggering::Cell, 0, i);
    const double y = grid.coordinate(Staggering::Cell, 1, j);
    const double z = grid.coordinate(Staggering::Cell, 2, k);
    return p(i + grid.ghost, j + grid.ghost, k + grid.ghostZ()) -
           rhoGas * (gravity[0] * x + gravity[1] * y + gravity[2] * z);
  }
};

/// \brief The granular (bed) pressure p_bed = max(0, p - p_gas(x)), p_gas(x) = C + rho_gas g.x
/// the gas pressure extrapolated hydrostatically through the bed, C = the mean of p - rho_gas g.x
/// over the gas cells (phi <= gasPhi, fluid); without gas cells (a full drum) the smallest
/// p - rho_gas g.x over fluid cells. So p_bed is gauge-free and 0 at the bed surface, the
/// confining pressure of the grains (the mixture's total pressure less the gas pressure).
/// Returns C.
template <class ExecutionSpace, class MemorySpace>
double bedPressure(ExecutionSpace const& space, CutCells<MemorySpace> const& cc,
                   Field<MemorySpace> const& phi, Field<MemorySpace> const& p, double rhoGas,
                   double const (&gravity)[3], double gasPhi, Field<MemorySpace> const& pBed) {
  const Grid grid = cc.grid;
  const int g = grid.ghost, gz = grid.ghostZ();
  const auto vol = cc.capacity;
  const double g0 = gravity[0], g1 = gravity[1], g2 = gravity[2];
  const auto cells = gridPolicy(space, {0, 0, 0}, {grid.nx, grid.ny, grid.nz});
  const GasHeadRemoved<MemorySpace> reduced{grid, p, rhoGas, {g0, g1, g2}};
  double sum = 0.0, count = 0.0, lowest = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::cfd::gasReference", cells,
      KOKKOS_LAMBDA(const int i, const int j, const int k, double& s, double& c) {
        if (vol(i + g, j + g, k + gz) > 0.0 && phi(i + g, j + g, k + gz) <= gasPhi) {
          s += reduced(i, j, k);
          c += 1.0;
        }
      },
      sum, count);
  double reference = 0.0;
  if (count > 0.0) {
    reference = sum / count;
  } else {
    Kokkos::parallel_reduce(
        "hikiln::cfd::lowestPressure", cells,
        KOKKOS_LAMBDA(const int i, const int j, const int k, double& m) {
          if (vol(i + g, j + g, k + gz) > 0.0) {
            m = math::fmin(m, reduced(i, j, k));
          }
        },
        Kokkos::Min<double>(lowest));
    reference = lowest;
  }
  Kokkos::parallel_for(
      "hikiln::cfd::bedPressure", cells, KOKKOS_LAMBDA(const int i, const int j, const int k) {
        pBed(i + g, j + g, k + gz) =
            vol(i + g, j + g, k + gz) > 0.0 ? math::fmax(reduced(i, j, k) - reference, 0.0) : 0.0;
      });
  return reference;
}

} // namespace hikiln::cfd
