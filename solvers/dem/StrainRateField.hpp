#pragma once
/// \file StrainRateField.hpp
/// \brief Strain-rate invariant gamma_dot = sqrt(2 D':D') of a cell-averaged velocity field by
/// finite differences: central where both neighbours along a direction have a velocity,
/// one-sided where one has, NaN where none has (or the cell itself has none).

#include "kernels/dem/CoarseGrainGrid.hpp"

#include <cstdint>
#include <vector>

namespace hikiln::dem {

/// \brief gamma_dot per cell of a Cartesian grid from velocities at the cell centres (arrays in
/// [ny][nx] order); `available` marks cells whose velocity may be used.
std::vector<double> cartesianStrainRate(const cg::CartesianGrid& grid,
                                        const std::vector<double>& ux,
                                        const std::vector<double>& uy,
                                        const std::vector<std::uint8_t>& available);

/// \brief gamma_dot per cell of a polar grid (arrays in [ntheta][nr] order), in polar
/// coordinates: D_rr = du_r/dr, D_tt = (du_t/dtheta + u_r) / r,
/// D_rt = (du_t/dr - u_t/r + du_r/dtheta / r) / 2, with each cell's value located at its area
/// centroid (radius PolarGrid::centroidRadius, mid angle), where a cell average of a linear field
/// is exact; periodic in theta.
std::vector<double> polarStrainRate(const cg::PolarGrid& grid, const std::vector<double>& ux,
                                    const std::vector<double>& uy,
                                    const std::vector<std::uint8_t>& available);

} // namespace hikiln::dem
