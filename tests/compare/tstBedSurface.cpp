// Bed scale and surface shape: median of the dense cells, the surface height of a flat and of a
// tilted bed computed from exact cell volume fractions, and the surface angle.
#include "compare/AnalyticDrum.hpp"
#include "drivers/compare/BedSurface.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {
using namespace hikiln::compare;
using hikiln::compare::test::AnalyticBed;
using hikiln::compare::test::squareGrid;

TEST(CompareBedSurface, BedFractionIsTheMedianOfTheDenseCells) {
  EXPECT_DOUBLE_EQ(bedVolumeFraction({0.0, 0.1, 0.3, 0.80, 0.82, 0.84, NAN}), 0.82);
  EXPECT_DOUBLE_EQ(bedVolumeFraction({0.0, 0.80, 0.82, 0.84, 0.86}), 0.83);
  EXPECT_TRUE(std::isnan(bedVolumeFraction({0.0, 0.0, NAN})));
}

// Surface heights of columns whose whole width lies under the surface and above the shell.
void expectSurface(const AnalyticBed& bed, int cells, double phiBed) {
  const CellGrid g = squareGrid(cells, bed.radius);
  std::vector<double> phi = bed.cellAverages(g, [](double, double) { return 1.0; });
  for (double& v : phi)
    v *= phiBed;
  const DrumCircle drum{0.0, 0.0, bed.radius};
  const std::vector<double> h = surfaceHeights(g, phi, phiBed, drum, 0.5 * g.dy);
  int checked = 0;
  for (int i = 0; i < g.nx; ++i) {
    const double a = g.x0 + i * g.dx, b = a + g.dx;
    const double shellA = -std::sqrt(bed.radius * bed.radius - a * a);
    const double shellB = -std::sqrt(bed.radius * bed.radius - b * b);
    // the surface crosses the whole column between the lower and the upper shell
    const bool covered = bed.surface(a) > shellA + 1e-9 && bed.surface(b) > shellB + 1e-9 &&
                         bed.surface(a) < -shellA - 1e-9 && bed.surface(b) < -shellB - 1e-9;
    if (covered) {
      ++checked;
      EXPECT_NEAR(h[static_cast<std::size_t>(i)], bed.surface(g.xCentre(i)), 2e-6)
          << "column " << i;
    } else if (std::isfinite(h[static_cast<std::size_t>(i)])) {
      EXPECT_GT(h[static_cast<std::size_t>(i)], -bed.radius); // a partial column: above the shell
    }
  }
  EXPECT_GT(checked, cells / 2);
}

TEST(CompareBedSurface, FlatBedOfKnownHeight) {
  AnalyticBed bed;
  bed.level = -0.4;
  expectSurface(bed, 30, 0.82);
  bed.radius = 0.3;
  bed.level = -0.05;
  expectSurface(bed, 24, 0.6);
}

TEST(CompareBedSurface, TiltedBedAndItsAngle) {
  AnalyticBed bed;
  bed.level = -0.35;
  bed.slope = std::tan(30.0 * M_PI / 180.0);
  expectSurface(bed, 30, 0.82);
  const CellGrid g = squareGrid(30, 1.0);
  std::vector<double> line;
  for (int i = 0; i < g.nx; ++i)
    line.push_back(i % 7 == 3 ? NAN : bed.surface(g.xCentre(i)));
  EXPECT_NEAR(surfaceAngleDeg(g, line, DrumCircle{0.0, 0.0, 1.0}, 0.5), 30.0, 1e-10);
  EXPECT_TRUE(std::isnan(surfaceAngleDeg(g, std::vector<double>(30, NAN), {0.0, 0.0, 1.0}, 0.5)));
}

TEST(CompareBedSurface, NoSurfaceWhereTheColumnHoldsNoBed) {
  const CellGrid g = squareGrid(10, 1.0);
  std::vector<double> phi(100, 0.0);
  phi[0 * 10 + 5] = 0.8; // one cell of bed in column 5, bottom row
  const std::vector<double> h = surfaceHeights(g, phi, 0.8, {0.0, 0.0, 1.0}, 0.5 * g.dy);
  for (int i = 0; i < 10; ++i)
    EXPECT_EQ(std::isfinite(h[static_cast<std::size_t>(i)]), i == 5) << "column " << i;
}

} // namespace
