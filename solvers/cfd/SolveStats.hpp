#pragma once
/// \file SolveStats.hpp
/// \brief Options and convergence record shared by the grid solvers (multigrid, PCG, baseline).

#include "solvers/cfd/Coarsening.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace hikiln::cfd {

/// \brief Interpolation of corrections along cell-centred axes (see kernels/cfd/Transfer.hpp).
enum class Interpolation : int {
  Constant = 0, ///< the parent's value (robust across coefficient jumps)
  Linear = 1    ///< bi/tri-linear
};

/// \brief Restriction along cell-centred axes.
enum class Restriction : int {
  Average = 0,  ///< mean of the children (= P^T / 2^d for constant interpolation)
  Transpose = 1 ///< P^T / 2^d of the chosen interpolation
};

/// \brief Multigrid set-up and iteration controls.
struct MultigridOptions {
  int preSmooth = 2;  ///< red-black Gauss-Seidel sweeps before the coarse correction
  int postSmooth = 2; ///< sweeps after it (reverse colour order: the V-cycle stays symmetric)
  Interpolation interpolation = Interpolation::Constant;
  Restriction restriction = Restriction::Average;
  CoarseningOptions coarsening;
  std::int64_t maxDirectUnknowns = 1024; ///< largest coarsest level solved densely
  double pseudoInverseTolerance = 1e-12; ///< relative eigenvalue cut of the coarse solve
  bool colouredProbe = true; ///< probe the coarse matrix many columns at a time (DenseCoarseSolver)
  double tolerance = 1e-10;  ///< stop at ||r|| <= tolerance * ||r_0||
  int maxIterations = 100;   ///< V-cycles or PCG iterations
  bool harmonicEdgeViscosity = false; ///< viscous solves: EdgeViscosity::Harmonic on every level
};

/// \brief What an iterative solve did: residual 2-norms over the unknowns.
struct SolveStats {
  int iterations = 0;
  bool converged = false;       ///< the iteration's residual reached tolerance * referenceResidual
  double initialResidual = 0.0; ///< ||f - A x_0||
  double referenceResidual = 0.0; ///< what the tolerance refers to: initialResidual, or the
                                  ///< residual of a colder start the caller gave (solvePcg)
  double finalResidual = 0.0;     ///< true residual at the end (recomputed, not the recursion)
  std::vector<double> history;    ///< residual before the first and after every iteration
  double seconds = 0.0; ///< wall time of the solve with its set-up, where the caller timed it

  /// \brief Geometric mean of the residual reduction per iteration.
  double meanReduction() const {
    if (iterations == 0 || initialResidual <= 0.0 || history.size() < 2) {
      return 0.0;
    }
    return std::pow(history.back() / history.front(), 1.0 / (history.size() - 1));
  }
  /// \brief Largest residual reduction of a single iteration.
  double worstReduction() const {
    double worst = 0.0;
    for (std::size_t i = 1; i < history.size(); ++i) {
      if (history[i - 1] > 0.0) {
        worst = history[i] / history[i - 1] > worst ? history[i] / history[i - 1] : worst;
      }
    }
    return worst;
  }
};

} // namespace hikiln::cfd
