// compareRuns end to end on synthetic runs: a DEM map and a continuum map on a grid twice as fine,
// both the exact cell averages of the same analytic bed (a tilted surface in the drum, hydrostatic
// pressure, a linear velocity field, a linear shear stress). Regridding, validity, spot values,
// surfaces and map differences must then agree to round-off, and the surface must be the
// analytic one. Also: the drum checks and the resolved-case reader.
#include "compare/AnalyticDrum.hpp"
#include "drivers/compare/FieldComparison.hpp"
#include "solvers/dem/StrainRateField.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {
using namespace hikiln::compare;
using hikiln::compare::test::AnalyticBed;
using hikiln::compare::test::squareGrid;

constexpr double rho = 2700.0, g = 9.81;

struct Synthetic {
  AnalyticBed bed;
  double pressure(double x, double y) const { return 0.6 * rho * g * (bed.surface(x) - y); }
  double shear(double x, double y) const { return 200.0 + 30.0 * x - 80.0 * y; }
  double u(double, double y) const { return 0.1 - 0.3 * y; }
  double v(double x, double) const { return 0.2 * x; }
};

DemRun demRun(const Synthetic& s, double phiBed) {
  DemRun run;
  run.drum = {2.0 * s.bed.radius, 3.0, 0.2};
  run.minVolumeFraction = 0.5;
  CellMaps& m = run.maps;
  m.grid = squareGrid(30, s.bed.radius);
  const auto area = s.bed.cellAverages(m.grid, [](double, double) { return 1.0; });
  const auto px = s.bed.cellAverages(m.grid, [&](double x, double y) { return s.u(x, y); });
  const auto py = s.bed.cellAverages(m.grid, [&](double x, double y) { return s.v(x, y); });
  const std::size_t n = area.size();
  std::vector<double>& phi = m.fields["volume_fraction"];
  std::vector<double>& ux = m.fields["velocity_x"];
  std::vector<double>& uy = m.fields["velocity_y"];
  std::vector<std::uint8_t> present(n);
  for (std::size_t c = 0; c < n; ++c) {
    phi.push_back(phiBed * area[c]);
    ux.push_back(area[c] > 0.0 ? px[c] / area[c] : NAN);
    uy.push_back(area[c] > 0.0 ? py[c] / area[c] : NAN);
    present[c] = area[c] >= solidsPresentFraction ? 1 : 0;
  }
  m.fields["pressure"] =
      s.bed.cellAverages(m.grid, [&](double x, double y) { return s.pressure(x, y); });
  m.fields["shear_stress"] =
      s.bed.cellAverages(m.grid, [&](double x, double y) { return s.shear(x, y); });
  m.fields["strain_rate"] = hikiln::dem::cartesianStrainRate(m.grid, ux, uy, present);
  m.valid.resize(n);
  std::vector<double>& viscosity = m.fields["viscosity"];
  for (std::size_t c = 0; c < n; ++c) {
    m.valid[c] = phi[c] >= run.minVolumeFraction ? 1 : 0;
    viscosity.push_back(m.valid[c] ? m.fields["shear_stress"][c] / m.fields["strain_rate"][c]
                                   : NAN);
  }
  return run;
}

// A continuum run on a grid twice as fine, with one extra cell of margin around the drum, open
// (capacity 1) everywhere: its cell values are the exact averages over the bed part.
ContinuumRun continuumRun(const Synthetic& s, double phiBed) {
  ContinuumRun run;
  run.drum = {2.0 * s.bed.radius, 3.0, 0.2};
  const double h = s.bed.radius / 30.0;
  run.grid.nx = run.grid.ny = 62;
  run.grid.dx = run.grid.dy = h;
  run.grid.x0 = run.grid.y0 = -s.bed.radius - h;
  const auto area = s.bed.cellAverages(run.grid, [](double, double) { return 1.0; });
  run.means["volume_fraction"] = area;
  run.means["momentum_x"] =
      s.bed.cellAverages(run.grid, [&](double x, double y) { return s.u(x, y); });
  run.means["momentum_y"] =
      s.bed.cellAverages(run.grid, [&](double x, double y) { return s.v(x, y); });
  for (const char* key : {"volume_fraction", "momentum_x", "momentum_y"})
    for (double& value : run.means[key])
      value *= phiBed;
  // stresses per open area of a fine cell: the continuum's point values times its bed share
  run.means["bed_pressure"] =
      s.bed.cellAverages(run.grid, [&](double x, double y) { return s.pressure(x, y); });
  run.means["shear_stress"] =
      s.bed.cellAverages(run.grid, [&](double x, double y) { return s.shear(x, y); });
  run.means["capacity"].assign(area.size(), 1.0);
  return run;
}

TEST(CompareRuns, IdenticalAnalyticFieldsGiveZeroDifference) {
  Synthetic s;
  s.bed.level = -0.38;
  s.bed.slope = std::tan(25.0 * M_PI / 180.0);
  const DemRun dem = demRun(s, 0.82);
  const CellMaps continuum = continuumOnGrid(continuumRun(s, 0.6), dem.maps.grid, 0.0, 0.0);
  const Comparison c = compareRuns(dem, continuum, CompareOptions{});

  EXPECT_NEAR(c.demBedFraction, 0.82, 1e-12);
  EXPECT_NEAR(c.continuumBedFraction, 0.6, 1e-12);
  for (std::size_t k = 0; k < c.dem.valid.size(); ++k)
    EXPECT_EQ(c.dem.valid[k], c.continuum.valid[k]) << "cell " << k;
  for (const auto& [name, d] : c.maps) {
    EXPECT_GT(d.cells, 100u) << name;
    // raw volume fractions differ by their definitions (0.82 vs 0.6 in the bed), nothing else
    EXPECT_NEAR(d.relativeL2, name == "volume_fraction" ? (0.82 - 0.6) / 0.82 : 0.0, 1e-10) << name;
  }
  ASSERT_EQ(c.spotCells.size(), 6u);
  for (const auto& [name, m] : c.spotValues) {
    EXPECT_GE(m.cells, 4u) << name;
    EXPECT_NEAR(m.model, m.reference, 1e-9 * std::fabs(m.reference) + 1e-12) << name;
  }
  // the spot's velocity is the linear field's at the window's centroid, but for the bottom row's
  // cells, cut by the shell, whose bed centroid lies slightly above their centre
  EXPECT_NEAR(c.spotValues.at("velocity_x").reference,
              s.u(0.0, c.spotValues.at("velocity_x").centroidY), 1e-4);
  int columns = 0;
  for (int i = 0; i < 30; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    if (!std::isfinite(c.demSurface[k]))
      continue;
    ++columns;
    EXPECT_NEAR(c.continuumSurface[k], c.demSurface[k], 1e-9);
    if (std::fabs(c.dem.grid.xCentre(i)) < 0.5) {
      EXPECT_NEAR(c.demSurface[k], s.bed.surface(c.dem.grid.xCentre(i)), 2e-6);
    }
  }
  EXPECT_GT(columns, 15);
  EXPECT_NEAR(c.demSurfaceAngleDeg, 25.0, 1e-3);
  EXPECT_NEAR(c.continuumSurfaceAngleDeg, 25.0, 1e-3);
}

TEST(CompareRuns, DifferentFlowsShowInTheMaps) {
  Synthetic s;
  const DemRun dem = demRun(s, 0.82);
  Synthetic faster = s;
  faster.bed.level = s.bed.level + 0.1; // a fuller, higher bed
  const CellMaps continuum = continuumOnGrid(continuumRun(faster, 0.6), dem.maps.grid, 0.0, 0.0);
  const Comparison c = compareRuns(dem, continuum, CompareOptions{});
  EXPECT_GT(c.maps.at("pressure").relativeL2, 0.05);
  EXPECT_GT(c.maps.at("volume_fraction_normalised").relativeL2, 0.05);
  EXPECT_NEAR(c.continuumSurface[15] - c.demSurface[15], 0.1, 2e-6);
  // 0.1 m more bed above the spot: 0.6 rho g x 0.1 more pressure over the bed part of its cells
  const PairedMean& p = c.spotValues.at("pressure");
  ASSERT_EQ(p.cells, c.spotCells.size());
  const auto area = s.bed.cellAverages(dem.maps.grid, [](double, double) { return 1.0; });
  double share = 0.0;
  for (std::size_t k : c.spotCells)
    share += area[k] / static_cast<double>(c.spotCells.size());
  EXPECT_GT(share, 0.98);
  EXPECT_NEAR(p.model - p.reference, 0.6 * rho * g * 0.1 * share, 1e-9 * p.model);
}

TEST(CompareRuns, DifferentDrumsAreRefusedWithEveryDifference) {
  DemRun dem;
  dem.directory = "dem-run";
  dem.drum = {2.0, 3.0, 0.2};
  ContinuumRun continuum;
  continuum.directory = "continuum-run";
  continuum.drum = {2.0, 3.0, 0.2};
  EXPECT_NO_THROW(requireSameDrum(dem, continuum));
  continuum.drum = {1.5, 6.0, 0.2};
  try {
    requireSameDrum(dem, continuum);
    FAIL() << "different drums accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'dem-run' and continuum run 'continuum-run' are not the same drum"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("drum.diameter 2 m (DEM) vs 1.5 m (continuum)"), std::string::npos) << what;
    EXPECT_NE(what.find("drum.rpm 3 rpm (DEM) vs 6 rpm (continuum)"), std::string::npos) << what;
    EXPECT_EQ(what.find("drum.fill"), std::string::npos) << what;
  }
}

TEST(CompareRuns, DrumOfAResolvedCase) {
  const DrumConditions d = drumOfResolvedCase(
      "# comment\ndrum:\n  diameter: 2.0   # [m]\n  rpm: 1.5\n  fill: 0.3\n", "test case");
  EXPECT_DOUBLE_EQ(d.diameter, 2.0);
  EXPECT_DOUBLE_EQ(d.rpm, 1.5);
  EXPECT_DOUBLE_EQ(d.fill, 0.3);
  EXPECT_THROW(drumOfResolvedCase("drum: {diameter: 2}\n", "test case"), std::runtime_error);
}

} // namespace
