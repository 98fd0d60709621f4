// Spot windows and map differences: the default spot of a 30-cell drum grid, the exact spot value
// of a linear field, zero difference for identical maps and the known difference of a scaled map.
#include "compare/AnalyticDrum.hpp"
#include "drivers/compare/CellStatistics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {
using namespace hikiln::compare;
using hikiln::compare::test::squareGrid;

std::vector<double> linearField(const CellGrid& g, double a, double b, double c) {
  std::vector<double> v;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      v.push_back(a + b * g.xCentre(i) + c * g.yCentre(j));
  return v;
}

TEST(CompareCellStatistics, DefaultSpotOfA30CellDrumGrid) {
  const double D = 2.0;
  const CellGrid g = squareGrid(30, 0.5 * D);
  const SpotWindow spot{0.0, -0.5 * D + 0.05 * D, 0.04 * D}; // compare's defaults
  const std::vector<std::size_t> cells = cellsInWindow(g, spot);
  ASSERT_EQ(cells.size(), 6u); // columns 14, 15 and rows 0, 1, 2
  for (std::size_t c : cells) {
    EXPECT_TRUE(c % 30 == 14 || c % 30 == 15);
    EXPECT_LE(c / 30, 2u);
  }
}

TEST(CompareCellStatistics, LinearFieldGivesTheExactSpotValue) {
  const CellGrid g = squareGrid(30, 1.0);
  const SpotWindow spot{0.0, -0.9, 0.08};
  const auto cells = cellsInWindow(g, spot);
  const auto pressure = [](double x, double y) { return 2700.0 * 9.81 * (-0.4 - y) + 50.0 * x; };
  const std::vector<double> dem = linearField(g, 2700.0 * 9.81 * -0.4, 50.0, -2700.0 * 9.81);
  const std::vector<double> model(dem.size(), 7.0);
  std::vector<std::uint8_t> mask(dem.size(), 1);
  PairedMean m = pairedMean(g, dem, model, mask, cells);
  EXPECT_EQ(m.cells, 6u);
  EXPECT_NEAR(m.reference, pressure(0.0, -0.9), 1e-9);
  EXPECT_NEAR(m.centroidX, 0.0, 1e-14);
  EXPECT_NEAR(m.centroidY, -0.9, 1e-14);
  EXPECT_DOUBLE_EQ(m.model, 7.0);
  // masked or missing cells leave the window: the mean is then the value at the new centroid
  mask[cells[0]] = 0;
  std::vector<double> holed = dem;
  holed[cells[1]] = NAN; // with cells[0], the window's bottom row
  m = pairedMean(g, holed, model, mask, cells);
  EXPECT_EQ(m.cells, 4u);
  EXPECT_NEAR(m.reference, pressure(m.centroidX, m.centroidY), 1e-9);
  EXPECT_GT(std::fabs(m.centroidY + 0.9) + std::fabs(m.centroidX), 1e-3);
}

TEST(CompareCellStatistics, IdenticalMapsDifferByZero) {
  const CellGrid g = squareGrid(12, 1.0);
  const std::vector<double> a = linearField(g, 3.0, 1.0, 2.0);
  std::vector<std::uint8_t> mask(a.size(), 1);
  mask[5] = 0;
  const MapDifference d = mapDifference(a, a, mask);
  EXPECT_EQ(d.cells, a.size() - 1);
  EXPECT_EQ(d.relativeL2, 0.0);
  EXPECT_EQ(d.rmsLog10Ratio, 0.0);
  EXPECT_DOUBLE_EQ(d.referenceMean, d.modelMean);
}

TEST(CompareCellStatistics, ScaledMapHasTheKnownDifference) {
  const CellGrid g = squareGrid(12, 1.0);
  const std::vector<double> a = linearField(g, 3.0, 1.0, 0.5); // positive everywhere
  std::vector<double> b = a;
  for (double& v : b)
    v *= 1.1;
  b[7] = NAN; // left out
  const MapDifference d = mapDifference(a, b, std::vector<std::uint8_t>(a.size(), 1));
  EXPECT_EQ(d.cells, a.size() - 1);
  EXPECT_NEAR(d.relativeL2, 0.1, 1e-12);
  EXPECT_NEAR(d.rmsLog10Ratio, std::log10(1.1), 1e-12);
  EXPECT_NEAR(d.modelMean, 1.1 * d.referenceMean, 1e-12);
}

} // namespace
