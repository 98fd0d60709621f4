// Cell selection, wall statistics, the pooled calibration and the rheology file round trip.
#include "solvers/calibration/Calibration.hpp"
#include "solvers/calibration/CalibrationJson.hpp"
#include "solvers/calibration/RheologyFile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace {
using namespace hikiln::calibration;
const double notANumber = std::numeric_limits<double>::quiet_NaN();

// One cell with everything finite and usable.
void addCell(GridFields& g, double p, double rate, double m, std::uint8_t valid = 1) {
  CellSamples& c = g.cells;
  c.r.push_back(0.1);
  c.theta.push_back(4.0);
  c.volumeFraction.push_back(0.7);
  c.pressure.push_back(p);
  c.shearStress.push_back(m * p);
  c.strainRate.push_back(rate);
  c.viscosity.push_back(m * p / rate);
  c.frictionM.push_back(m);
  g.valid.push_back(valid);
}

// A run whose cells follow m = m0 + m1 gamma_dot exactly and viscosity = a + b p exactly
// (independent columns: calibrate() fits each pair on its own).
CalibrationRun syntheticRun(const std::string& label, double a, double b, double muWall,
                            double slip, std::uint64_t seed) {
  CalibrationRun run;
  run.label = label;
  run.path = label + "/averages.h5";
  run.conditions.particleDiameter = 0.02;
  run.conditions.particleDensity = 2500.0;
  run.muWall = muWall;
  run.slipPercent = slip;
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 40; ++i) {
    const double p = 100.0 + 2000.0 * u(random);
    const double rate = 0.1 + 15.0 * u(random);
    const double m = 0.35 + 0.012 * rate;
    CellSamples& c = run.cells;
    c.r.push_back(0.3);
    c.theta.push_back(4.5);
    c.volumeFraction.push_back(0.7);
    c.pressure.push_back(p);
    c.shearStress.push_back(m * p);
    c.strainRate.push_back(rate);
    c.viscosity.push_back(a + b * p);
    c.frictionM.push_back(m);
  }
  run.counts.total = run.counts.selected = run.cells.size();
  return run;
}
} // namespace

TEST(calibration_selection, each_rejection_counted_once) {
  GridFields g;
  addCell(g, 100.0, 1.0, 0.4);        // selected
  addCell(g, 100.0, 1.0, 0.4, 0);     // not valid
  addCell(g, 100.0, 1.0, 0.4, 2);     // valid must be exactly 1
  addCell(g, 100.0, 1.0, notANumber); // non-finite m
  addCell(g, 100.0, 0.01, 0.4);       // at the floor: excluded (strictly above is required)
  addCell(g, 100.0, 0.005, 0.4);      // below the floor
  addCell(g, -5.0, 1.0, 0.4);         // tension
  addCell(g, 0.0, 1.0, 0.4);          // no pressure
  addCell(g, 200.0, 2.0, 0.5);        // selected
  g.cells.viscosity[1] = notANumber;  // an invalid cell with NaN counts as invalid, not non-finite
  SelectionCounts counts;
  const CellSamples s = selectCells(g, SelectionOptions{0.01}, &counts);
  EXPECT_EQ(counts.total, 9u);
  EXPECT_EQ(counts.invalid, 2u);
  EXPECT_EQ(counts.nonFinite, 1u);
  EXPECT_EQ(counts.belowStrainRate, 2u);
  EXPECT_EQ(counts.nonPositivePressure, 2u);
  EXPECT_EQ(counts.selected, 2u);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.pressure[1], 200.0);
  EXPECT_EQ(s.frictionM[1], 0.5);
  EXPECT_EQ(s.strainRate[0], 1.0);
  // A lower floor admits the two slow cells.
  selectCells(g, SelectionOptions{0.001}, &counts);
  EXPECT_EQ(counts.selected, 4u);

  g.cells.theta.pop_back();
  EXPECT_THROW(selectCells(g, SelectionOptions{}), std::invalid_argument);
}

TEST(calibration_wall, mean_and_sample_spread) {
  const WallStatistics w = summarizeWall({0.30, 0.33, 0.36}, {12.0, 10.0, 8.0});
  EXPECT_NEAR(w.muWall, 0.33, 1e-15);
  EXPECT_NEAR(w.muWallStd, 0.03, 1e-15);
  EXPECT_NEAR(w.meanSlipPercent, 10.0, 1e-14);
  EXPECT_EQ(w.slipPercent, (std::vector<double>{12.0, 10.0, 8.0}));
  EXPECT_EQ(summarizeWall({0.4}, {5.0}).muWallStd, 0.0);
  EXPECT_THROW(summarizeWall({}, {}), std::invalid_argument);
  EXPECT_THROW(summarizeWall({0.3, notANumber}, {1.0, 2.0}), std::invalid_argument);
}

TEST(calibration_pipeline, pooled_fits_and_per_run_viscosity_lines) {
  const std::vector<CalibrationRun> runs = {syntheticRun("fill10", 5.0, 0.2, 0.30, 12.0, 1),
                                            syntheticRun("fill20", 8.0, 0.1, 0.33, 10.0, 2),
                                            syntheticRun("fill30", -2.0, 0.3, 0.36, 8.0, 3)};
  const CalibrationResult r = calibrate(runs, CalibrationOptions{});
  EXPECT_EQ(r.cellCount, 120u);
  EXPECT_NEAR(r.frictionLine.intercept, 0.35, 1e-12);
  EXPECT_NEAR(r.frictionLine.slope, 0.012, 1e-12);
  ASSERT_EQ(r.viscosityVsPressure.size(), 3u);
  EXPECT_NEAR(r.viscosityVsPressure[0].intercept, 5.0, 1e-10);
  EXPECT_NEAR(r.viscosityVsPressure[0].slope, 0.2, 1e-13);
  EXPECT_NEAR(r.viscosityVsPressure[1].intercept, 8.0, 1e-10);
  EXPECT_NEAR(r.viscosityVsPressure[1].slope, 0.1, 1e-13);
  EXPECT_NEAR(r.viscosityVsPressure[2].intercept, -2.0, 1e-10);
  EXPECT_NEAR(r.viscosityVsPressure[2].slope, 0.3, 1e-13);
  EXPECT_NEAR(r.wall.muWall, 0.33, 1e-15);
  EXPECT_NEAR(r.wall.muWallStd, 0.03, 1e-15);
  // q = (0.35 + 0.012 gamma_dot) p with gamma_dot independent of p: the Coulomb slope is the
  // mean m, 0.35 + 0.012 * 7.55 = 0.4406 (uniform 0.1..15.1), to sampling error.
  EXPECT_NEAR(r.coulomb.frictionCoefficient, 0.4406, 0.02);
  EXPECT_FALSE(r.newtonian.newtonian);
  ASSERT_TRUE(r.muI.has_value());
  EXPECT_EQ(r.muIStatus, "fitted");
  EXPECT_GT(r.strainRateMax, r.strainRateMin);

  CalibrationOptions noMuI;
  noMuI.fitMuI = false;
  EXPECT_FALSE(calibrate(runs, noMuI).muI.has_value());
  EXPECT_THROW(calibrate({}, CalibrationOptions{}), std::invalid_argument);
}

TEST(calibration_pipeline, missing_particle_data_reports_mu_i_failure) {
  CalibrationRun run = syntheticRun("nodata", 1.0, 0.1, 0.3, 5.0, 9);
  run.conditions.particleDiameter = notANumber;
  const CalibrationResult r = calibrate({run}, CalibrationOptions{});
  EXPECT_FALSE(r.muI.has_value());
  EXPECT_NE(r.muIStatus.find("finite"), std::string::npos) << r.muIStatus;
  EXPECT_NEAR(r.frictionLine.slope, 0.012, 1e-12); // the default law does not need d
}

TEST(calibration_rheology_file, yaml_round_trips_exactly) {
  const std::vector<CalibrationRun> runs = {syntheticRun("a,\"odd\" name", 5.0, 0.2, 0.31, 9.5, 4),
                                            syntheticRun("b", 8.0, 0.1, 0.35, 10.25, 5)};
  CalibrationOptions options;
  options.selection.minStrainRate = 0.05;
  const CalibrationResult r = calibrate(runs, options);
  const std::string text =
      formatRheologyYaml(r, runs, options, {"0.1.0", "2025-01-01T00:00:00Z", "polar"});
  EXPECT_NE(text.find("# hikiln version: 0.1.0"), std::string::npos);
  EXPECT_NE(text.find("# created: 2025-01-01T00:00:00Z"), std::string::npos);
  const RheologyParameters p = parseRheologyYaml(text, "test");
  EXPECT_EQ(p.model, "drucker-prager-rate");
  EXPECT_EQ(p.m0, r.frictionLine.intercept); // bit-exact: shortest round-trip printing
  EXPECT_EQ(p.m1, r.frictionLine.slope);
  EXPECT_EQ(p.strainRateFloor, 0.05);
  EXPECT_EQ(p.strainRateMin, r.strainRateMin);
  EXPECT_EQ(p.frictionCoefficient, r.coulomb.frictionCoefficient);
  EXPECT_EQ(p.cohesion, r.coulomb.cohesion);
  EXPECT_EQ(p.frictionAngleDeg, r.coulomb.frictionAngleDeg);
  EXPECT_EQ(p.muWall, r.wall.muWall);
  EXPECT_EQ(p.muWallStd, r.wall.muWallStd);
  EXPECT_EQ(p.slipPercent, (std::vector<double>{9.5, 10.25}));
  ASSERT_TRUE(p.muI.has_value());
  EXPECT_EQ(p.muI->inertialScale, r.muI->parameters.inertialScale);
  EXPECT_EQ(p.particleDiameter, 0.02);

  // The JSON view carries the same numbers.
  const nlohmann::json j = calibrationToJson(r, runs, options);
  EXPECT_EQ(j["m_line"]["slope"].get<double>(), r.frictionLine.slope);
  EXPECT_EQ(j["runs"][0]["label"].get<std::string>(), "a,\"odd\" name");
  EXPECT_EQ(j["runs"].size(), 2u);
}

TEST(calibration_rheology_file, parse_errors_name_the_key_and_source) {
  auto errorOf = [](const std::string& text) {
    try {
      parseRheologyYaml(text, "my.yaml");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(errorOf("coulomb: {}\n").find("'rheology'"), std::string::npos);
  EXPECT_NE(errorOf("rheology: {model: drucker-prager-rate, m0: 0.3}\n").find("rheology.m1"),
            std::string::npos);
  EXPECT_NE(errorOf("rheology: {model: drucker-prager-rate, m0: abc}\n").find("malformed"),
            std::string::npos);
  EXPECT_NE(errorOf("rheology: {model: bingham}\n").find("bingham"), std::string::npos);
  EXPECT_NE(errorOf("rheology: [unclosed\n").find("my.yaml"), std::string::npos);
  EXPECT_THROW(loadRheologyFile("/nonexistent/rheology.yaml"), std::runtime_error);
}
