#pragma once
/// \file TemperatureMaps.hpp
/// \brief DEM particle temperatures and continuum temperature fields on one comparison grid, and
/// the measures `hikiln fit-diffusivity` compares them by (docs/fit-diffusivity.md).
///
/// - Comparison grid: square blocks of `factor` x `factor` continuum cells (2 x 2 on the 64^2
///   drum grid: 6.7 cm cells for D = 2 m, about 3 particle diameters), so both models are seen at
///   the same resolution: a block straddling the initial hot/cold split is mixed in both.
/// - DEM: each free particle's mean temperature goes to the block holding its centre, weighted
///   by its area pi r^2; bed fraction = particle area / block area (about 0.8 in the dense bed).
/// - Continuum: the block's cells weighted by capacity x phi (heat capacity); bed fraction =
///   mean over the block of capacity x phi / phi_max (1 in the bed).
/// - Normalised temperature theta = (T - T_left) / (T_right - T_left) of the initial halves.
/// - Mixed fraction: the share of a model's bed blocks with 0.1 < theta < 0.9 (the thermal mixing
///   layer's area over the bed area; physics.md 6.3 fits "the width and growth" of that layer).
/// - Map misfit: the rms of theta_continuum - theta_dem over blocks that are bed in both.

#include "drivers/fit/DemTemperatures.hpp"

#include <vector>

namespace hikiln::fit {

/// \brief n x n square blocks of side h, the first at (x0, y0) (lower left corner).
struct BlockGrid {
  int n = 0;
  double x0 = 0.0, y0 = 0.0, h = 1.0;
  /// \brief Block holding (x, y) as i + n j, or -1 outside.
  int index(double x, double y) const;
  /// \brief Centre of block b.
  double centreX(int b) const { return x0 + (b % n + 0.5) * h; }
  double centreY(int b) const { return y0 + (b / n + 0.5) * h; }
};

/// \brief A temperature map on a BlockGrid (NaN temperature where nothing was deposited).
struct TemperatureMap {
  std::vector<double> temperature; ///< K
  std::vector<double> bedFraction; ///< see the file comment
};

/// \brief The free particles of a DEM snapshot on the blocks.
TemperatureMap binParticles(const BlockGrid& blocks, const ParticleTemperatureSnapshot& snapshot);

/// \brief A continuum field of nx x ny cells (x fastest, no ghosts) on blocks of factor x factor
/// cells (nx, ny multiples of factor): temperature, capacity and phi / phi_max per cell.
TemperatureMap coarsenCells(int nx, int ny, int factor, const std::vector<double>& temperature,
                            const std::vector<double>& capacity,
                            const std::vector<double>& relativePhi);

/// \brief Share of the bed blocks (bedFraction >= bedThreshold, finite temperature) with
/// 0.1 < theta < 0.9; NaN when there is no bed block.
double mixedFraction(const TemperatureMap& map, double cold, double hot, double bedThreshold);

/// \brief rms of theta_a - theta_b over blocks that are bed in both maps (thresholds as in
/// mixedFraction); NaN when there is none.
double thetaRms(const TemperatureMap& a, double thresholdA, const TemperatureMap& b,
                double thresholdB, double cold, double hot);

} // namespace hikiln::fit
