// The kiln's bed per cross-section: the depth of a flat bed and the surface angle of a tilted
// one, from exact cell fractions (tests/compare/AnalyticDrum.hpp), with the cut cells' volume
// fractions as the solver stores them (phi per open volume).
#include "compare/AnalyticDrum.hpp"
#include "drivers/cfd/KilnBedProfile.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {
using hikiln::cfd::BedSection;
using hikiln::cfd::Grid;
using hikiln::compare::test::AnalyticBed;

constexpr double radius = 0.2, phiMax = 0.57;
constexpr double degree = 3.14159265358979323846 / 180.0;

struct Sections {
  Grid grid;
  std::vector<double> phi, open;
};

// Three sections along z holding the beds `beds` on a 24 x 24 grid over the kiln's square.
Sections kilnOf(std::vector<AnalyticBed> const& beds) {
  Sections s;
  const int n = 24;
  s.grid.nx = s.grid.ny = n;
  s.grid.nz = static_cast<int>(beds.size());
  s.grid.hx = s.grid.hy = 2.0 * radius / n;
  s.grid.hz = 0.1;
  s.grid.x0 = s.grid.y0 = -radius;
  const auto columns = hikiln::compare::test::squareGrid(n, radius);
  AnalyticBed full;
  full.radius = radius;
  full.level = 2.0 * radius;
  const auto unity = [](double, double) { return 1.0; };
  const std::vector<double> open = full.cellAverages(columns, unity);
  for (AnalyticBed const& bed : beds) {
    const std::vector<double> inBed = bed.cellAverages(columns, unity);
    for (std::size_t c = 0; c < open.size(); ++c) {
      s.open.push_back(open[c]);
      s.phi.push_back(open[c] > 0.0 ? phiMax * inBed[c] / open[c] : 0.0);
    }
  }
  return s;
}

AnalyticBed bed(double level, double slope) {
  AnalyticBed b;
  b.radius = radius;
  b.level = level;
  b.slope = slope;
  return b;
}

TEST(KilnBedProfile, FlatBedsHaveTheirDepth) {
  const Sections s = kilnOf({bed(-0.15, 0.0), bed(-0.1, 0.0), bed(0.02, 0.0)});
  const std::vector<BedSection> sections = bedSections(s.grid, s.phi, s.open, phiMax, radius);
  ASSERT_EQ(sections.size(), 3u);
  const double depths[] = {0.05, 0.1, 0.22};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(sections[k].z, 0.05 + 0.1 * k, 1e-12);
    EXPECT_NEAR(sections[k].depth, depths[k], 1e-4 * radius) << "section " << k;
    EXPECT_NEAR(sections[k].angleDeg, 0.0, 0.05) << "section " << k;
  }
}

TEST(KilnBedProfile, TiltedSurfaceGivesItsAngle) {
  const Sections s =
      kilnOf({bed(-0.08, std::tan(31.0 * degree)), bed(-0.05, -std::tan(20 * degree))});
  const std::vector<BedSection> sections = bedSections(s.grid, s.phi, s.open, phiMax, radius);
  EXPECT_NEAR(sections[0].angleDeg, 31.0, 0.2);
  EXPECT_NEAR(sections[1].angleDeg, 20.0, 0.2);
}

TEST(KilnBedProfile, MismatchedArraysAreRefused) {
  Sections s = kilnOf({bed(-0.1, 0.0)});
  s.open.pop_back();
  EXPECT_THROW(bedSections(s.grid, s.phi, s.open, phiMax, radius), std::invalid_argument);
}

} // namespace
