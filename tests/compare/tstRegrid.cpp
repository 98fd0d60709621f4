// Overlap-area regridding: identity on the same grid, exact cell averages of a linear field on an
// aligned 2:1 grid, conservation onto a misaligned grid, and weights.
#include "drivers/compare/Regrid.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {
using namespace hikiln::compare;

CellGrid grid(int nx, int ny, double x0, double y0, double dx, double dy) {
  CellGrid g;
  g.nx = nx;
  g.ny = ny;
  g.x0 = x0;
  g.y0 = y0;
  g.dx = dx;
  g.dy = dy;
  return g;
}

std::vector<double> sampled(const CellGrid& g, double a, double b, double c) {
  std::vector<double> v;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      v.push_back(a + b * g.xCentre(i) + c * g.yCentre(j));
  return v;
}

TEST(CompareRegrid, SameGridIsTheIdentity) {
  const CellGrid g = grid(7, 5, -0.3, 0.2, 0.1, 0.15);
  const std::vector<double> v = sampled(g, 1.0, 2.0, -3.0);
  const std::vector<double> ones(v.size(), 1.0);
  const OverlapSums s = overlapSums(g, v, ones, g);
  const std::vector<double> mean = weightedMean(s), density = perCellArea(s, g);
  for (std::size_t c = 0; c < v.size(); ++c) {
    EXPECT_NEAR(mean[c], v[c], 1e-13);
    EXPECT_NEAR(density[c], v[c], 1e-13);
  }
}

TEST(CompareRegrid, AlignedRefinementGivesExactAveragesOfALinearField) {
  const CellGrid coarse = grid(6, 4, -1.0, -0.5, 0.2, 0.25);
  const CellGrid fine = grid(16, 12, -1.2, -0.75, 0.1, 0.125); // one extra cell around
  const std::vector<double> v = sampled(fine, 0.5, -1.5, 4.0);
  const std::vector<double> mean =
      weightedMean(overlapSums(fine, v, std::vector<double>(v.size(), 1.0), coarse));
  const std::vector<double> exact = sampled(coarse, 0.5, -1.5, 4.0);
  for (std::size_t c = 0; c < exact.size(); ++c)
    EXPECT_NEAR(mean[c], exact[c], 1e-12) << "cell " << c;
}

TEST(CompareRegrid, MisalignedGridConservesTheIntegral) {
  const CellGrid target = grid(9, 9, -1.0, -1.0, 2.0 / 9, 2.0 / 9);
  const CellGrid source = grid(23, 21, -1.13, -1.07, 0.1, 0.105); // covers the target
  std::vector<double> v;
  for (int c = 0; c < source.cellCount(); ++c)
    v.push_back(std::sin(0.37 * c) + 2.0);
  const std::vector<double> ones(v.size(), 1.0);
  const OverlapSums s = overlapSums(source, v, ones, target);
  double total = 0.0, expected = 0.0, area = 0.0;
  for (double x : s.weighted)
    total += x;
  for (double x : s.weight)
    area += x;
  for (int j = 0; j < source.ny; ++j)
    for (int i = 0; i < source.nx; ++i) {
      const double lx = std::max(0.0, std::min(source.x0 + (i + 1) * source.dx, 1.0) -
                                          std::max(source.x0 + i * source.dx, -1.0));
      const double ly = std::max(0.0, std::min(source.y0 + (j + 1) * source.dy, 1.0) -
                                          std::max(source.y0 + j * source.dy, -1.0));
      expected += v[static_cast<std::size_t>(j) * source.nx + i] * lx * ly;
    }
  EXPECT_NEAR(area, 4.0, 1e-12);
  EXPECT_NEAR(total, expected, 1e-12 * std::fabs(expected));
}

TEST(CompareRegrid, WeightsSelectAndNonFiniteCellsAreSkipped) {
  const CellGrid fine = grid(4, 2, 0.0, 0.0, 0.5, 0.5);
  const CellGrid coarse = grid(2, 1, 0.0, 0.0, 1.0, 1.0);
  // coarse cell 0 holds fine cells (0,1) in row 0 and (4,5) in row 1
  const std::vector<double> v = {1.0, 3.0, 10.0, 20.0, 5.0, NAN, 30.0, 40.0};
  const std::vector<double> w = {1.0, 3.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0};
  const OverlapSums s = overlapSums(fine, v, w, coarse);
  const std::vector<double> mean = weightedMean(s), density = perCellArea(s, coarse);
  EXPECT_NEAR(mean[0], (1.0 * 1.0 + 3.0 * 3.0) / 4.0, 1e-14); // the NaN cell is left out
  EXPECT_NEAR(mean[1], (20.0 + 30.0 + 40.0) / 3.0, 1e-14);
  EXPECT_NEAR(density[0], 0.25 * (1.0 + 9.0), 1e-14);
  EXPECT_TRUE(
      std::isnan(weightedMean(overlapSums(fine, v, std::vector<double>(8, 0.0), coarse))[0]));
}

} // namespace
