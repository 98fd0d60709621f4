#pragma once
/// \file ViscousMultigrid.hpp
/// \brief Geometric multigrid for the implicit momentum (viscous) solve on the MAC grid,
///   alpha u - div(mu (grad u + grad u^T)) = f,
/// alpha = rho / dt on the faces (absent for a steady Stokes-like solve), mu > 0 in cells, with
/// the coupling of the components through grad u^T. Usable alone (V-cycles) and as the
/// preconditioner of conjugate gradients (the operator is symmetric positive definite).
///
/// Design (as CellMultigrid, per component):
/// - the same grid hierarchy; per level alpha is full-weighted onto the coarse faces (with
///   `open`, over the open children only: averageDown says why), mu
///   averaged over the children, and the edge viscosities recomputed from the coarse mu;
/// - smoother: red-black Gauss-Seidel one component at a time with the others fixed
///   (u red, u black, v red, v black, ... before the coarse correction, the reverse after, so
///   the V-cycle is symmetric); each component's colours are independent of thread count;
/// - transfers per component: along its own axis (face-normal) linear interpolation and full
///   weighting, along the others constant interpolation and the mean (see Transfer.hpp);
/// - boundaries: the boundary nodes of the normal components and the wall velocities of the
///   tangential ones come from VelocityBoundaries (filled into the solution before iterating);
/// - null space: without alpha and with every axis periodic, constants per component (the
///   right-hand side and the solution are projected to zero mean per component).

#include "kernels/cfd/AxisClosure.hpp"
#include "kernels/cfd/FieldOps.hpp"
#include "kernels/cfd/GhostFill.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/Transfer.hpp"
#include "kernels/cfd/ViscousOperator.hpp"
#include "solvers/cfd/Coarsening.hpp"
#include "solvers/cfd/DenseCoarseSolver.hpp"
#include "solvers/cfd/SolveStats.hpp"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace hikiln::cfd {

/// \brief Geometric multigrid for the MAC viscous operator (see the file comment).
template <class ExecutionSpace> class ViscousMultigrid {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using field_type = Field<memory_space>;
  using velocity_type = VelocityFields<memory_space>;
  using operator_type = ViscousOperator<memory_space>;

  /// \brief Builds the hierarchy for alpha (per component on its faces; empty Views for
  /// alpha = 0) and cell viscosity mu on grid with velocity boundary conditions bc. The fields
  /// are referenced, not copied (the edge viscosities are computed here): change them and call
  /// refresh(). `open` (face apertures, optional): the fine operator leaves out the stresses
  /// that read closed faces (ViscousOperator.hpp); the coarse levels, a preconditioner only,
  /// keep them.
  ViscousMultigrid(ExecutionSpace const& space, Grid const& grid, VelocityBoundaries const& bc,
                   field_type const (&alpha)[3], field_type const& mu,
                   MultigridOptions const& options = MultigridOptions(),
                   velocity_type const& open = velocity_type());

  /// \brief Takes the current values of the referenced fine alpha, mu and open: recomputes the
  /// edge viscosities and the coarse coefficients and rebuilds the coarsest level's solve, in
  /// the fields allocated at construction (as CellMultigrid::refresh).
  void refresh();

  /// \brief Solves A u = f by V-cycles from the initial guess u. The boundary nodes and ghosts
  /// of u are set from the boundary conditions first (and again at the end); stops at
  /// ||f - A u|| <= tolerance * ||f - A u_0|| or after maxIterations cycles.
  SolveStats solve(velocity_type const& u, velocity_type const& f);

  /// \brief Solves A u = f by conjugate gradients preconditioned with one V-cycle per
  /// iteration (flexible Polak-Ribiere update), from the initial guess u. Stops at
  /// ||f - A u|| <= tolerance * reference, where reference is the initial residual, or the
  /// given one when > 0: a warm start then stops where a colder start would have (the caller
  /// measures that start's residual with residualNorm).
  SolveStats solvePcg(velocity_type const& u, velocity_type const& f, double reference = 0.0);

  /// \brief One V-cycle on A u = f (affine: boundary values included; the boundary nodes of u
  /// must hold them, see fillBoundaries).
  void vcycle(velocity_type const& u, velocity_type const& f, bool affine);

  /// \brief z = M^-1 r: one V-cycle from zero on the linear operator.
  void precondition(velocity_type const& r, velocity_type const& z);

  /// \brief Sets the boundary nodes (given normal velocities) and ghost layers of u from the
  /// boundary conditions.
  void fillBoundaries(velocity_type const& u) const;

  /// \brief ||f - A u|| over all unknowns (affine; f as the solves take it), using an internal
  /// buffer. The boundary nodes of u must hold their values (fillBoundaries).
  double residualNorm(velocity_type const& u, velocity_type const& f);

  /// \brief y = a x + b y over the finest level's unknowns (every component).
  void axpby(double a, velocity_type const& x, double b, velocity_type const& y) const;

  /// \brief Number of levels.
  int numLevels() const { return static_cast<int>(_levels.size()); }
  /// \brief Operator of a level, 0 = finest.
  operator_type const& levelOperator(int level) const { return _levels.at(level).op; }
  /// \brief Unknowns of the dense coarsest-level solve (all components).
  int coarseUnknowns() const { return _coarse.size(); }
  /// \brief Operator applications that probed the coarsest level's matrix.
  int coarseProbes() const { return _coarse.probes(); }
  /// \brief True when the operator has constant null vectors (no alpha, all axes periodic).
  bool singular() const { return _singular; }
  /// \brief Velocity components (2 or 3).
  int numComponents() const { return _levels.front().op.numComponents(); }

private:
  struct Level {
    operator_type op;
    UnknownBox box[3];
    velocity_type x, rhs, res;
    velocity_type alphaOpen; ///< where alpha is averaged from (coarsenCoefficients); may be empty
    Transfer fromFiner[3];   ///< per component, between the next finer level and this one
  };

  velocity_type makeVelocity(Grid const& g, const char* label) const {
    velocity_type v;
    for (int c = 0; c < (g.is3D() ? 3 : 2); ++c) {
      v.comp[c] = makeField(_space, g, faceStaggering(c), label);
    }
    return v;
  }

  /// The hierarchy's grids, closures and fields; the fine level references the caller's
  /// coefficients.
  void setupLevels(Grid const& grid, field_type const (&alpha)[3], field_type const& mu,
                   velocity_type const& open) {
    const bool periodic[3] = {_bc.periodic(0), _bc.periodic(1), _bc.periodic(2)};
    const std::vector<LevelGeometry> geometry = coarsenGrids(grid, periodic, _options.coarsening);
    const bool hasAlpha = alpha[0].extent(0) > 0;
    const int numComps = grid.is3D() ? 3 : 2;
    _singular = !hasAlpha;
    for (int a = 0; a < numComps; ++a) {
      _singular = _singular && periodic[a];
    }
    // with `open`, alpha is coarsened over the open faces of the next finer level (averageDown)
    const bool overOpen = hasAlpha && open.comp[0].extent(0) > 0;
    for (std::size_t l = 0; l < geometry.size(); ++l) {
      Level level;
      Grid const& g = geometry[l].grid;
      level.op.grid = g;
      for (int c = 0; c < 3; ++c) {
        velocityClosures(g, _bc, c, level.op.axis[c]);
        level.box[c] = unknownBox(g, level.op.axis[c]);
      }
      level.res = makeVelocity(g, "hikiln::cfd::viscous::res");
      for (int s = 0; s < (g.is3D() ? 3 : 1); ++s) {
        level.op.muEdge[s] =
            makeField(_space, g, edgeStaggering(s), "hikiln::cfd::viscous::muEdge");
      }
      if (l == 0) {
        level.op.mu = mu;
        level.op.open = open;
        for (int c = 0; c < 3; ++c) {
          level.op.alpha[c] = alpha[c];
        }
        if (overOpen) {
          level.alphaOpen = open;
        }
      } else {
        level.x = makeVelocity(g, "hikiln::cfd::viscous::x");
        level.rhs = makeVelocity(g, "hikiln::cfd::viscous::rhs");
        Level const& finer = _levels.back();
        for (int c = 0; c < numComps; ++c) {
          level.fromFiner[c] = makeTransfer(finer, level, c, geometry[l].ratio);
        }
        level.op.mu = makeField(_space, g, Staggering::Cell, "hikiln::cfd::viscous::mu");
        if (hasAlpha) {
          for (int c = 0; c < numComps; ++c) {
            level.op.alpha[c] =
                makeField(_space, g, faceStaggering(c), "hikiln::cfd::viscous::alpha");
          }
        }
        if (overOpen) {
          level.alphaOpen = makeVelocity(g, "hikiln::cfd::viscous::open");
        }
      }
      _levels.push_back(level);
    }
  }

  /// Per level the edge viscosities; on the coarse levels mu averaged over the children and
  /// alpha full-weighted (over the open faces of the finer level where there is a mask).
  void coarsenCoefficients() {
    const bool periodic[3] = {_bc.periodic(0), _bc.periodic(1), _bc.periodic(2)};
    for (std::size_t l = 0; l < _levels.size(); ++l) {
      Level& level = _levels[l];
      if (l > 0) {
        Level const& finer = _levels[l - 1];
        Transfer cells = level.fromFiner[0];
        cells.axis[0].fine.node = cells.axis[0].coarse.node = false;
        averageDown(_space, cells, NodeAverage::Inject, finer.op.mu, level.op.mu);
        for (int c = 0; c < level.op.numComponents() && level.op.alpha[0].extent(0) > 0; ++c) {
          averageDown(_space, level.fromFiner[c], NodeAverage::FullWeighting, finer.op.alpha[c],
                      level.op.alpha[c], finer.alphaOpen.comp[c], level.alphaOpen.comp[c]);
        }
      }
      edgeViscosities(_space, level.op.grid, periodic, level.op.mu, level.op.muEdge, level.op.open,
                      _options.harmonicEdgeViscosity ? EdgeViscosity::Harmonic
                                                     : EdgeViscosity::Arithmetic);
    }
  }

  Transfer makeTransfer(Level const& fine, Level const& coarse, int c,
                        int const (&ratio)[3]) const {
    Transfer t;
    for (int a = 0; a < 3; ++a) {
      t.axis[a].fine = fine.op.axis[c][a];
      t.axis[a].coarse = coarse.op.axis[c][a];
      t.axis[a].ratio = ratio[a];
      t.axis[a].linear = _options.interpolation == Interpolation::Linear;
      t.axis[a].transpose = _options.restriction == Restriction::Transpose;
    }
    t.fineOffsets = ghostOffsets(fine.op.grid);
    t.coarseOffsets = ghostOffsets(coarse.op.grid);
    return t;
  }

  void setupCoarseSolve() {
    Level& last = _levels.back();
    const int numComps = last.op.numComponents();
    std::int64_t offsets[4] = {0, 0, 0, 0};
    for (int c = 0; c < numComps; ++c) {
      offsets[c + 1] = offsets[c] + last.box[c].size();
    }
    const std::int64_t n = offsets[numComps];
    if (n > _options.maxDirectUnknowns) {
      throw std::runtime_error(
          "hikiln::cfd::ViscousMultigrid: the coarsest level has " + std::to_string(n) +
          " unknowns, more than maxDirectUnknowns = " + std::to_string(_options.maxDirectUnknowns) +
          "; use cell counts with more factors of 2 (periodic axes: even counts)");
    }
    for (int c = 0; c < 4; ++c) {
      _coarseOffsets[c] = offsets[c];
    }
    if (last.x.comp[0].extent(0) == 0) {
      last.x = makeVelocity(last.op.grid, "hikiln::cfd::viscous::x");
    }
    const velocity_type probeIn = last.x;
    const velocity_type probeOut = last.res;
    const operator_type op = last.op;
    ExecutionSpace const space = _space;
    CoarseUnknowns unknowns;
    unknowns.numComponents = numComps;
    for (int a = 0; a < 3; ++a) {
      unknowns.box[a] = last.box[a];
      unknowns.periodic[a] = _bc.periodic(a);
    }
    _coarse.build(
        _space, unknowns, _options.colouredProbe,
        [&](auto const& unit, auto const& column) {
          for (int c = 0; c < numComps; ++c) {
            unpackUnknowns(space, last.box[c], unit, offsets[c], probeIn.comp[c]);
          }
          applyViscousOperator(space, op, probeIn, probeOut, false);
          for (int c = 0; c < numComps; ++c) {
            packUnknowns(space, last.box[c], probeOut.comp[c], column, offsets[c]);
          }
        },
        _options.pseudoInverseTolerance);
    for (int c = 0; c < numComps; ++c) {
      Kokkos::deep_copy(_space, last.x.comp[c], 0.0);
    }
  }

  void smooth(Level& level, velocity_type const& u, velocity_type const& f, bool affine,
              bool forward) {
    const int numComps = level.op.numComponents();
    for (int step = 0; step < numComps; ++step) {
      const int c = forward ? step : numComps - 1 - step;
      smoothViscousRedBlack(_space, level.op, u, f, c, forward ? 0 : 1, affine);
    }
  }

  void cycle(int l, velocity_type const& u, velocity_type const& f, bool affine) {
    Level& level = _levels[l];
    if (l + 1 == static_cast<int>(_levels.size())) {
      coarseSolve(level, u, f, affine);
      return;
    }
    for (int s = 0; s < _options.preSmooth; ++s) {
      smooth(level, u, f, affine, true);
    }
    viscousResidual(_space, level.op, u, f, level.res, affine);
    Level& coarse = _levels[l + 1];
    const int numComps = level.op.numComponents();
    for (int c = 0; c < numComps; ++c) {
      restrictField(_space, coarse.fromFiner[c], level.res.comp[c], coarse.rhs.comp[c]);
      Kokkos::deep_copy(_space, coarse.x.comp[c], 0.0);
    }
    cycle(l + 1, coarse.x, coarse.rhs, false);
    for (int c = 0; c < numComps; ++c) {
      prolongateAdd(_space, coarse.fromFiner[c], coarse.x.comp[c], u.comp[c]);
    }
    for (int s = 0; s < _options.postSmooth; ++s) {
      smooth(level, u, f, affine, false);
    }
  }

  void coarseSolve(Level& level, velocity_type const& u, velocity_type const& f, bool affine) {
    viscousResidual(_space, level.op, u, f, level.res, affine);
    const int numComps = level.op.numComponents();
    for (int c = 0; c < numComps; ++c) {
      packUnknowns(_space, level.box[c], level.res.comp[c], _coarse.rhs, _coarseOffsets[c]);
    }
    _coarse.apply(_space);
    for (int c = 0; c < numComps; ++c) {
      unpackUnknowns(_space, level.box[c], _coarse.solution, _coarseOffsets[c], level.res.comp[c]);
      axpbyUnknowns(_space, level.box[c], 1.0, level.res.comp[c], 1.0, u.comp[c]);
    }
  }

  void removeMeans(Level const& level, velocity_type const& v) const {
    for (int c = 0; c < level.op.numComponents(); ++c) {
      removeMean(_space, level.box[c], v.comp[c]);
    }
  }

  void finish(velocity_type const& u) {
    if (_singular) {
      removeMeans(_levels.front(), u);
    }
    fillBoundaries(u);
  }

  velocity_type consistentRhs(velocity_type const& f) {
    if (!_singular) {
      return f;
    }
    Level& fine = _levels.front();
    if (_rhs0.comp[0].extent(0) == 0) {
      _rhs0 = makeVelocity(fine.op.grid, "hikiln::cfd::viscous::rhs0");
    }
    for (int c = 0; c < numComponents(); ++c) {
      Kokkos::deep_copy(_space, _rhs0.comp[c], f.comp[c]);
    }
    removeMeans(fine, _rhs0);
    return _rhs0;
  }

  double dot(velocity_type const& a, velocity_type const& b) const {
    double sum = 0.0;
    Level const& fine = _levels.front();
    for (int c = 0; c < numComponents(); ++c) {
      sum += dotUnknowns(_space, fine.box[c], a.comp[c], b.comp[c]);
    }
    return sum;
  }

  void allocateKrylov() {
    if (_r.comp[0].extent(0) > 0) {
      return;
    }
    Grid const& g = _levels.front().op.grid;
    _r = makeVelocity(g, "hikiln::cfd::viscous::pcg::r");
    _z = makeVelocity(g, "hikiln::cfd::viscous::pcg::z");
    _p = makeVelocity(g, "hikiln::cfd::viscous::pcg::p");
    _q = makeVelocity(g, "hikiln::cfd::viscous::pcg::q");
  }

  ExecutionSpace _space;
  VelocityBoundaries _bc;
  MultigridOptions _options;
  std::vector<Level> _levels;
  DenseCoarseSolver<ExecutionSpace> _coarse;
  std::int64_t _coarseOffsets[4] = {0, 0, 0, 0};
  bool _singular = false;
  velocity_type _rhs0, _r, _z, _p, _q;
};

// The members that reach the kernels are defined out of the class, so that the explicit
// instantiation declarations below keep them out of every file that uses the solver: they are
// compiled once per backend in hikiln_cfd (solvers/cfd/CMakeLists.txt).

template <class ExecutionSpace>
ViscousMultigrid<ExecutionSpace>::ViscousMultigrid(ExecutionSpace const& space, Grid const& grid,
                                                   VelocityBoundaries const& bc,
                                                   field_type const (&alpha)[3],
                                                   field_type const& mu,
                                                   MultigridOptions const& options,
                                                   velocity_type const& open)
    : _space(space), _bc(bc), _options(options) {
  checkBoundaries(grid, bc);
  setupLevels(grid, alpha, mu, open);
  refresh();
}

template <class ExecutionSpace> void ViscousMultigrid<ExecutionSpace>::refresh() {
  coarsenCoefficients();
  setupCoarseSolve();
}

template <class ExecutionSpace>
SolveStats ViscousMultigrid<ExecutionSpace>::solve(velocity_type const& u, velocity_type const& f) {
  fillBoundaries(u);
  const velocity_type rhs = consistentRhs(f);
  Level& fine = _levels.front();
  SolveStats stats;
  stats.initialResidual = std::sqrt(viscousResidual(_space, fine.op, u, rhs, fine.res, true));
  stats.referenceResidual = stats.initialResidual;
  stats.history.push_back(stats.initialResidual);
  double residual = stats.initialResidual;
  while (residual > _options.tolerance * stats.initialResidual &&
         stats.iterations < _options.maxIterations) {
    cycle(0, u, rhs, true);
    residual = std::sqrt(viscousResidual(_space, fine.op, u, rhs, fine.res, true));
    stats.history.push_back(residual);
    ++stats.iterations;
  }
  finish(u);
  stats.finalResidual = residual;
  stats.converged = residual <= _options.tolerance * stats.initialResidual;
  return stats;
}

template <class ExecutionSpace>
SolveStats ViscousMultigrid<ExecutionSpace>::solvePcg(velocity_type const& u,
                                                      velocity_type const& f, double reference) {
  fillBoundaries(u);
  allocateKrylov();
  const velocity_type rhs = consistentRhs(f);
  Level& fine = _levels.front();
  SolveStats stats;
  stats.initialResidual = std::sqrt(viscousResidual(_space, fine.op, u, rhs, _r, true));
  stats.history.push_back(stats.initialResidual);
  stats.referenceResidual = reference > 0.0 ? reference : stats.initialResidual;
  const double target = _options.tolerance * stats.referenceResidual;
  double residual = stats.initialResidual;
  if (residual > target) {
    precondition(_r, _z);
    axpby(1.0, _z, 0.0, _p);
    double rz = dot(_r, _z);
    while (residual > target && stats.iterations < _options.maxIterations) {
      applyViscousOperator(_space, fine.op, _p, _q, false);
      const double step = rz / dot(_p, _q);
      axpby(step, _p, 1.0, u);
      axpby(-step, _q, 1.0, _r);
      residual = std::sqrt(dot(_r, _r));
      stats.history.push_back(residual);
      ++stats.iterations;
      if (residual <= target) {
        break;
      }
      const double rzOld = dot(_r, _z);
      precondition(_r, _z);
      const double rzNew = dot(_r, _z);
      axpby(1.0, _z, (rzNew - rzOld) / rz, _p);
      rz = rzNew;
    }
  }
  finish(u);
  stats.converged = residual <= target;
  stats.finalResidual = std::sqrt(viscousResidual(_space, fine.op, u, rhs, _q, true));
  return stats;
}

template <class ExecutionSpace>
void ViscousMultigrid<ExecutionSpace>::vcycle(velocity_type const& u, velocity_type const& f,
                                              bool affine) {
  cycle(0, u, f, affine);
}

template <class ExecutionSpace>
void ViscousMultigrid<ExecutionSpace>::precondition(velocity_type const& r,
                                                    velocity_type const& z) {
  for (int c = 0; c < numComponents(); ++c) {
    Kokkos::deep_copy(_space, z.comp[c], 0.0);
  }
  cycle(0, z, r, false);
  if (_singular) {
    removeMeans(_levels.front(), z);
  }
}

template <class ExecutionSpace>
void ViscousMultigrid<ExecutionSpace>::fillBoundaries(velocity_type const& u) const {
  Grid const& g = _levels.front().op.grid;
  for (int c = 0; c < numComponents(); ++c) {
    fillGhostsVelocity(_space, g, _bc, c, u.comp[c]);
  }
}

template <class ExecutionSpace>
double ViscousMultigrid<ExecutionSpace>::residualNorm(velocity_type const& u,
                                                      velocity_type const& f) {
  Level& fine = _levels.front();
  return std::sqrt(viscousResidual(_space, fine.op, u, consistentRhs(f), fine.res, true));
}

template <class ExecutionSpace>
void ViscousMultigrid<ExecutionSpace>::axpby(double a, velocity_type const& x, double b,
                                             velocity_type const& y) const {
  Level const& fine = _levels.front();
  for (int c = 0; c < numComponents(); ++c) {
    axpbyUnknowns(_space, fine.box[c], a, x.comp[c], b, y.comp[c]);
  }
}

#ifdef KOKKOS_ENABLE_SERIAL
extern template class ViscousMultigrid<Kokkos::Serial>;
#endif
#ifdef KOKKOS_ENABLE_OPENMP
extern template class ViscousMultigrid<Kokkos::OpenMP>;
#endif
#ifdef KOKKOS_ENABLE_CUDA
extern template class ViscousMultigrid<Kokkos::Cuda>;
#endif

} // namespace hikiln::cfd
