#pragma once
/// \file CellMultigrid.hpp
/// \brief Matrix-free geometric multigrid for A x = alpha x - div(beta grad x) = f on a cell grid
/// (pressure Poisson with beta = 1/rho and alpha = 0; implicit scalar diffusion), usable alone
/// (V-cycle iteration) and as the preconditioner of conjugate gradients (one V-cycle per step).
///
/// Design
/// - Levels from coarsenGrids (factor 2 per axis where possible, semi-coarsening for flat
///   domains); coefficients coarsened by averages: alpha over the 2^d children, beta over the
///   fine faces that make up a coarse face (the coarse operator is rediscretised, not Galerkin).
///   With an `open` mask (cut cells: the capacity) alpha is averaged over the open children
///   only, so the alpha that just decouples the cells outside a shell does not reach the coarse
///   cells that straddle it (setupLevels). Where that leaves the open cells singular (no alpha
///   on them, no side with a given value), their mean is kept out of the right-hand side and of
///   every residual (setupOpenNullVector).
/// - V(pre, post)-cycle: red-black Gauss-Seidel (red then black before, black then red after),
///   residual, restriction by the mean of the children, piecewise-constant interpolation of the
///   correction (options: linear, P^T restriction; see Transfer.hpp for the measured reasons),
///   and a dense pseudo-inverse on the coarsest level. With the defaults R = P^T / 2^d and the
///   V-cycle is a symmetric operator.
/// - Boundaries through AxisClosure: wall = zero normal gradient, Value = Dirichlet (its value
///   enters only on the finest level of a solve, "affine"), periodic.
/// - Null space: with alpha absent and no Dirichlet side the operator is singular (constants):
///   the right-hand side is projected to zero mean (the nearest consistent problem) and the
///   solution is returned with zero mean.
/// - Determinism: no atomics; red-black updates of one colour read only the other colour, so
///   fixed-count V-cycles are bitwise identical for any thread count. Residual norms and (in
///   the singular case) means are parallel reductions whose rounding depends on the backend.

#include "kernels/cfd/AxisClosure.hpp"
#include "kernels/cfd/CellOperator.hpp"
#include "kernels/cfd/FieldOps.hpp"
#include "kernels/cfd/Grid.hpp"
#include "kernels/cfd/Transfer.hpp"
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

/// \brief Geometric multigrid for the cell-centred operator (see the file comment).
template <class ExecutionSpace> class CellMultigrid {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using field_type = Field<memory_space>;
  using operator_type = CellOperator<memory_space>;

  /// \brief Builds the hierarchy for the operator with cell coefficient alpha (an empty View
  /// for alpha = 0) and face coefficients beta (FaceX, FaceY, FaceZ; beta[2] unused in 2D) on
  /// grid with boundary conditions bc. The fields are referenced, not copied: change them and
  /// call refresh() (or build a new solver). Throws if the coarsest level is too large for the
  /// direct solve. With `open` (> 0 in the cells that belong to the problem, e.g. a cut-cell
  /// capacity), alpha is coarsened over the open children only: see coarsenCoefficients.
  CellMultigrid(ExecutionSpace const& space, Grid const& grid, ScalarBoundaries const& bc,
                field_type const& alpha, field_type const (&beta)[3],
                MultigridOptions const& options = MultigridOptions(),
                field_type const& open = field_type());

  /// \brief Takes the current values of the referenced fine coefficients (alpha, beta, open):
  /// coarsens them again and rebuilds the coarsest level's solve, in the fields allocated at
  /// construction. A solver kept across time steps (TwoPhaseSolver) saves allocating and
  /// zeroing its hierarchy every step.
  void refresh();

  /// \brief Solves A x = f by V-cycles from the initial guess x (boundary values included);
  /// stops at ||f - A x|| <= tolerance * ||f - A x_0|| or after maxIterations cycles.
  SolveStats solve(field_type const& x, field_type const& f);

  /// \brief Solves A x = f by conjugate gradients preconditioned with one V-cycle per
  /// iteration (flexible Polak-Ribiere update, as the default V-cycle is not exactly
  /// symmetric), from the initial guess x. Stops at ||f - A x|| <= tolerance * reference, where
  /// reference is the initial residual, or the given one when > 0: a warm start then stops
  /// where a colder start would have (the caller measures that start's residual with
  /// residualNorm).
  SolveStats solvePcg(field_type const& x, field_type const& f, double reference = 0.0);

  /// \brief One V-cycle on A x = f (affine: boundary values included, as in a solve).
  void vcycle(field_type const& x, field_type const& f, bool affine);

  /// \brief z = M^-1 r: one V-cycle from zero on the linear operator (zero mean if singular).
  void precondition(field_type const& r, field_type const& z);

  /// \brief ||f - A x|| over the cells (affine; f as the solves take it), using an internal
  /// buffer.
  double residualNorm(field_type const& x, field_type const& f);

  /// \brief Number of levels (1 when the finest grid is solved directly).
  int numLevels() const { return static_cast<int>(_levels.size()); }
  /// \brief Operator (grid, closures, coefficients) of a level, 0 = finest.
  operator_type const& levelOperator(int level) const { return _levels.at(level).op; }
  /// \brief Unknowns of the dense coarsest-level solve.
  int coarseUnknowns() const { return _coarse.size(); }
  /// \brief Operator applications that probed the coarsest level's matrix.
  int coarseProbes() const { return _coarse.probes(); }
  /// \brief True when the operator has a constant null space (no alpha, no Dirichlet side).
  bool singular() const { return _singular; }
  /// \brief The execution space instance the solver runs on.
  ExecutionSpace const& space() const { return _space; }

private:
  struct Level {
    operator_type op;
    UnknownBox box;
    field_type x, rhs, res;
    field_type open;    ///< where alpha is averaged from (coarsenCoefficients); may be empty
    Transfer fromFiner; ///< transfer between the next finer level and this one
  };

  /// The hierarchy's grids, closures and fields; the fine level references the caller's
  /// coefficients.
  void setupLevels(Grid const& grid, field_type const& alpha, field_type const (&beta)[3],
                   field_type const& open) {
    const bool periodic[3] = {_bc.periodic(0), _bc.periodic(1), _bc.periodic(2)};
    const std::vector<LevelGeometry> geometry = coarsenGrids(grid, periodic, _options.coarsening);
    const bool hasAlpha = alpha.extent(0) > 0;
    _singular = !hasAlpha;
    for (int side = 0; side < 6; ++side) {
      _singular = _singular && _bc.kind[side] != BoundaryKind::Value;
    }
    const int numAxes = grid.is3D() ? 3 : 2;
    for (std::size_t l = 0; l < geometry.size(); ++l) {
      Level level;
      Grid const& g = geometry[l].grid;
      level.op.grid = g;
      scalarClosures(g, _bc, level.op.axis);
      level.box = unknownBox(g, level.op.axis);
      level.res = makeField(_space, g, Staggering::Cell, "hikiln::cfd::mg::res");
      if (l == 0) {
        level.op.alpha = alpha;
        level.open = hasAlpha ? open : field_type();
        for (int a = 0; a < 3; ++a) {
          level.op.beta[a] = beta[a];
        }
        _levels.push_back(level);
        continue;
      }
      level.x = makeField(_space, g, Staggering::Cell, "hikiln::cfd::mg::x");
      level.rhs = makeField(_space, g, Staggering::Cell, "hikiln::cfd::mg::rhs");
      Level const& finer = _levels.back();
      level.fromFiner = makeTransfer(finer.op, level.op, geometry[l].ratio, _options);
      if (hasAlpha) {
        level.op.alpha = makeField(_space, g, Staggering::Cell, "hikiln::cfd::mg::alpha");
        if (finer.open.extent(0) > 0) {
          level.open = makeField(_space, g, Staggering::Cell, "hikiln::cfd::mg::open");
        }
      }
      for (int a = 0; a < numAxes; ++a) {
        level.op.beta[a] = makeField(_space, g, faceStaggering(a), "hikiln::cfd::mg::beta");
      }
      _levels.push_back(level);
    }
  }

  /// Coefficients of the coarse levels (see the file comment). With `open`, a coarse cell takes
  /// the mean of alpha over its open children and is open when one of them is: the alpha that
  /// only decouples the cells outside a shell (they have no open face) then stays out of the
  /// coarse cells that straddle the shell, where it would be a sink the fine problem lacks.
  void coarsenCoefficients() {
    for (std::size_t l = 1; l < _levels.size(); ++l) {
      Level const& finer = _levels[l - 1];
      Level& level = _levels[l];
      if (level.op.alpha.extent(0) > 0) {
        averageDown(_space, level.fromFiner, NodeAverage::Inject, finer.op.alpha, level.op.alpha,
                    finer.open, level.open);
      }
      for (int a = 0; a < (level.op.grid.is3D() ? 3 : 2); ++a) {
        Transfer faces = level.fromFiner;
        faces.axis[a].fine.node = true;
        faces.axis[a].coarse.node = true;
        averageDown(_space, faces, NodeAverage::Inject, finer.op.beta[a], level.op.beta[a]);
      }
    }
  }

  /// With `open`, no alpha on the open cells and no side with a given value, the operator is
  /// singular on the open cells (p up to a constant there; the others are decoupled by their
  /// alpha): its null vector is their indicator. The coarse levels, which keep alpha off them,
  /// are singular the same way, so the V-cycle cannot correct that mode, and round-off in the
  /// Krylov recursion would feed it until the iteration diverges (a 256 x 256 drum at t = 3 s,
  /// perf/README.md). The right-hand side and every residual and preconditioned residual are
  /// therefore kept orthogonal to it (removeNullComponent, as the constant of a singular
  /// operator).
  void setupOpenNullVector() {
    Level const& fine = _levels.front();
    _openCount = 0.0;
    if (fine.open.extent(0) == 0 || fine.op.alpha.extent(0) == 0 || _singular) {
      return;
    }
    for (int side = 0; side < 6; ++side) {
      if (_bc.kind[side] == BoundaryKind::Value) {
        return;
      }
    }
    if (_openCells.extent(0) == 0) {
      _openCells = makeField(_space, fine.op.grid, Staggering::Cell, "hikiln::cfd::mg::openCells");
    }
    indicatorUnknowns(_space, fine.box, fine.open, _openCells);
    const double count = sumUnknowns(_space, fine.box, _openCells);
    if (count > 0.0 && dotUnknowns(_space, fine.box, fine.op.alpha, _openCells) == 0.0) {
      _openCount = count;
    }
  }

  /// True when the operator has a null vector: the constant (_singular) or the open cells'
  /// indicator (setupOpenNullVector).
  bool hasNullSpace() const { return _singular || _openCount > 0.0; }

  /// Removes from v its component along the null vector, if any: the mean over all cells, or
  /// over the open cells on them.
  void removeNullComponent(field_type const& v) {
    const UnknownBox& box = _levels.front().box;
    if (_singular) {
      removeMean(_space, box, v);
    } else if (_openCount > 0.0) {
      const double mean = dotUnknowns(_space, box, v, _openCells) / _openCount;
      axpbyUnknowns(_space, box, -mean, _openCells, 1.0, v);
    }
  }

  static Transfer makeTransfer(operator_type const& fine, operator_type const& coarse,
                               int const (&ratio)[3], MultigridOptions const& options) {
    Transfer t;
    for (int a = 0; a < 3; ++a) {
      t.axis[a].fine = fine.axis[a];
      t.axis[a].coarse = coarse.axis[a];
      t.axis[a].ratio = ratio[a];
      t.axis[a].linear = options.interpolation == Interpolation::Linear;
      t.axis[a].transpose = options.restriction == Restriction::Transpose;
    }
    t.fineOffsets = ghostOffsets(fine.grid);
    t.coarseOffsets = ghostOffsets(coarse.grid);
    return t;
  }

  void setupCoarseSolve() {
    Level& last = _levels.back();
    const std::int64_t n = last.box.size();
    if (n > _options.maxDirectUnknowns) {
      throw std::runtime_error(
          "hikiln::cfd::CellMultigrid: the coarsest level has " + std::to_string(n) +
          " cells, more than maxDirectUnknowns = " + std::to_string(_options.maxDirectUnknowns) +
          "; use cell counts with more factors of 2 (periodic axes: even counts)");
    }
    if (last.x.extent(0) == 0) {
      last.x = makeField(_space, last.op.grid, Staggering::Cell, "hikiln::cfd::mg::x");
    }
    field_type probeIn = last.x;
    field_type probeOut = last.res;
    const operator_type op = last.op;
    const UnknownBox box = last.box;
    ExecutionSpace const space = _space;
    CoarseUnknowns unknowns;
    unknowns.box[0] = box;
    for (int a = 0; a < 3; ++a) {
      unknowns.periodic[a] = _bc.periodic(a);
    }
    _coarse.build(
        _space, unknowns, _options.colouredProbe,
        [&](auto const& unit, auto const& column) {
          unpackUnknowns(space, box, unit, 0, probeIn);
          applyCellOperator(space, op, probeIn, probeOut, false);
          packUnknowns(space, box, probeOut, column, 0);
        },
        _options.pseudoInverseTolerance);
    Kokkos::deep_copy(_space, last.x, 0.0);
  }

  void cycle(int l, field_type const& x, field_type const& f, bool affine) {
    Level& level = _levels[l];
    if (l + 1 == static_cast<int>(_levels.size())) {
      coarseSolve(level, x, f, affine);
      return;
    }
    for (int s = 0; s < _options.preSmooth; ++s) {
      smoothCellRedBlack(_space, level.op, x, f, 0, affine);
    }
    cellResidual(_space, level.op, x, f, level.res, affine);
    Level& coarse = _levels[l + 1];
    restrictField(_space, coarse.fromFiner, level.res, coarse.rhs);
    Kokkos::deep_copy(_space, coarse.x, 0.0);
    cycle(l + 1, coarse.x, coarse.rhs, false);
    prolongateAdd(_space, coarse.fromFiner, coarse.x, x);
    for (int s = 0; s < _options.postSmooth; ++s) {
      smoothCellRedBlack(_space, level.op, x, f, 1, affine);
    }
  }

  void coarseSolve(Level& level, field_type const& x, field_type const& f, bool affine) {
    cellResidual(_space, level.op, x, f, level.res, affine);
    packUnknowns(_space, level.box, level.res, _coarse.rhs, 0);
    _coarse.apply(_space);
    unpackUnknowns(_space, level.box, _coarse.solution, 0, level.res);
    axpbyUnknowns(_space, level.box, 1.0, level.res, 1.0, x);
  }

  field_type consistentRhs(field_type const& f) {
    if (!hasNullSpace()) {
      return f;
    }
    Level& fine = _levels.front();
    if (_rhs0.extent(0) == 0) {
      _rhs0 = makeField(_space, fine.op.grid, Staggering::Cell, "hikiln::cfd::mg::rhs0");
    }
    Kokkos::deep_copy(_space, _rhs0, f);
    removeNullComponent(_rhs0);
    return _rhs0;
  }

  void allocateKrylov() {
    if (_r.extent(0) > 0) {
      return;
    }
    Grid const& g = _levels.front().op.grid;
    _r = makeField(_space, g, Staggering::Cell, "hikiln::cfd::pcg::r");
    _z = makeField(_space, g, Staggering::Cell, "hikiln::cfd::pcg::z");
    _p = makeField(_space, g, Staggering::Cell, "hikiln::cfd::pcg::p");
    _q = makeField(_space, g, Staggering::Cell, "hikiln::cfd::pcg::q");
  }

  ExecutionSpace _space;
  ScalarBoundaries _bc;
  MultigridOptions _options;
  std::vector<Level> _levels;
  DenseCoarseSolver<ExecutionSpace> _coarse;
  bool _singular = false;
  field_type _openCells;   ///< indicator of the open cells (used when _openCount > 0)
  double _openCount = 0.0; ///< their number when singular on them, else 0
  field_type _rhs0, _r, _z, _p, _q;
};

// The members that reach the kernels are defined out of the class, so that the explicit
// instantiation declarations below keep them out of every file that uses the solver: they are
// compiled once per backend in hikiln_cfd (solvers/cfd/CMakeLists.txt).

template <class ExecutionSpace>
CellMultigrid<ExecutionSpace>::CellMultigrid(ExecutionSpace const& space, Grid const& grid,
                                             ScalarBoundaries const& bc, field_type const& alpha,
                                             field_type const (&beta)[3],
                                             MultigridOptions const& options,
                                             field_type const& open)
    : _space(space), _bc(bc), _options(options) {
  checkBoundaries(grid, bc);
  setupLevels(grid, alpha, beta, open);
  refresh();
}

template <class ExecutionSpace> void CellMultigrid<ExecutionSpace>::refresh() {
  coarsenCoefficients();
  setupOpenNullVector();
  setupCoarseSolve();
}

template <class ExecutionSpace>
SolveStats CellMultigrid<ExecutionSpace>::solve(field_type const& x, field_type const& f) {
  const field_type rhs = consistentRhs(f);
  Level& fine = _levels.front();
  SolveStats stats;
  stats.initialResidual = std::sqrt(cellResidualNorm2(_space, fine.op, x, rhs, fine.res, true));
  stats.referenceResidual = stats.initialResidual;
  stats.history.push_back(stats.initialResidual);
  double residual = stats.initialResidual;
  while (residual > _options.tolerance * stats.initialResidual &&
         stats.iterations < _options.maxIterations) {
    cycle(0, x, rhs, true);
    residual = std::sqrt(cellResidualNorm2(_space, fine.op, x, rhs, fine.res, true));
    stats.history.push_back(residual);
    ++stats.iterations;
  }
  if (_singular) {
    removeMean(_space, fine.box, x);
  }
  stats.finalResidual = residual;
  stats.converged = residual <= _options.tolerance * stats.initialResidual;
  return stats;
}

template <class ExecutionSpace>
SolveStats CellMultigrid<ExecutionSpace>::solvePcg(field_type const& x, field_type const& f,
                                                   double reference) {
  allocateKrylov();
  const field_type rhs = consistentRhs(f);
  Level& fine = _levels.front();
  const UnknownBox& box = fine.box;
  SolveStats stats;
  stats.initialResidual = std::sqrt(cellResidualNorm2(_space, fine.op, x, rhs, _r, true));
  stats.history.push_back(stats.initialResidual);
  stats.referenceResidual = reference > 0.0 ? reference : stats.initialResidual;
  const double target = _options.tolerance * stats.referenceResidual;
  double residual = stats.initialResidual;
  removeNullComponent(_r);
  if (residual > target) {
    precondition(_r, _z);
    axpbyUnknowns(_space, box, 1.0, _z, 0.0, _p);
    double rz = dotUnknowns(_space, box, _r, _z);
    while (residual > target && stats.iterations < _options.maxIterations) {
      applyCellOperator(_space, fine.op, _p, _q, false);
      const double step = rz / dotUnknowns(_space, box, _p, _q);
      axpbyUnknowns(_space, box, step, _p, 1.0, x);
      axpbyUnknowns(_space, box, -step, _q, 1.0, _r);
      removeNullComponent(_r);
      residual = std::sqrt(dotUnknowns(_space, box, _r, _r));
      stats.history.push_back(residual);
      ++stats.iterations;
      if (residual <= target) {
        break;
      }
      // flexible (Polak-Ribiere) beta: robust when the V-cycle is not exactly symmetric
      const double rzOld = dotUnknowns(_space, box, _r, _z);
      precondition(_r, _z);
      const double rzNew = dotUnknowns(_space, box, _r, _z);
      axpbyUnknowns(_space, box, 1.0, _z, (rzNew - rzOld) / rz, _p);
      rz = rzNew;
    }
  }
  if (_singular) {
    removeMean(_space, box, x);
  }
  stats.converged = residual <= target;
  stats.finalResidual = std::sqrt(cellResidualNorm2(_space, fine.op, x, rhs, _q, true));
  return stats;
}

template <class ExecutionSpace>
void CellMultigrid<ExecutionSpace>::vcycle(field_type const& x, field_type const& f, bool affine) {
  cycle(0, x, f, affine);
}

template <class ExecutionSpace>
void CellMultigrid<ExecutionSpace>::precondition(field_type const& r, field_type const& z) {
  Kokkos::deep_copy(_space, z, 0.0);
  cycle(0, z, r, false);
  removeNullComponent(z);
}

template <class ExecutionSpace>
double CellMultigrid<ExecutionSpace>::residualNorm(field_type const& x, field_type const& f) {
  Level& fine = _levels.front();
  return std::sqrt(cellResidualNorm2(_space, fine.op, x, consistentRhs(f), fine.res, true));
}

#ifdef KOKKOS_ENABLE_SERIAL
extern template class CellMultigrid<Kokkos::Serial>;
#endif
#ifdef KOKKOS_ENABLE_OPENMP
extern template class CellMultigrid<Kokkos::OpenMP>;
#endif
#ifdef KOKKOS_ENABLE_CUDA
extern template class CellMultigrid<Kokkos::Cuda>;
#endif

} // namespace hikiln::cfd
