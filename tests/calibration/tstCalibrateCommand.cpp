// `hikiln calibrate` end to end on synthetic averages.h5 files written in the exact layout of
// docs/averaged-fields.md: the rheology file reproduces the generating law, and bad input gives
// errors that name the file.
#include "calibration/SyntheticAverages.hpp"
#include "drivers/calibrate/CalibrateCommand.hpp"
#include "drivers/calibrate/PlotScript.hpp"
#include "io/IoTestSupport.hpp"
#include "solvers/calibration/RheologyFile.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace {
using hikiln::calibrate::CalibrateOptions;
using hikiln::calibrate::runCalibrate;
using hikiln::calibration::test::SyntheticRun;
using hikiln::calibration::test::writeSyntheticRun;
using hikiln::io::test::ScratchDir;
namespace fs = std::filesystem;

std::string errorOf(const CalibrateOptions& options) {
  try {
    runCalibrate(options);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

std::size_t lineCount(const std::string& path) {
  std::ifstream in(path);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);)
    ++n;
  return n;
}

// Three calibration runs with one law and different wall friction and slip.
struct ThreeRuns {
  explicit ThreeRuns(const ScratchDir& dir, SyntheticRun base = {}) {
    const double muWall[] = {0.30, 0.33, 0.36};
    const double slip[] = {12.0, 10.0, 8.0};
    for (int i = 0; i < 3; ++i) {
      SyntheticRun run = base;
      run.muWall = muWall[i];
      run.slipPercent = slip[i];
      run.fill = 0.1 * (i + 1);
      run.seed = static_cast<std::uint64_t>(i + 1);
      const fs::path path = dir.path() / ("fill" + std::to_string(10 * (i + 1)));
      const auto usable = writeSyntheticRun(path, run);
      polarCells += usable.first;
      cartesianCells += usable.second;
      paths.push_back(path.string());
    }
  }
  std::vector<std::string> paths;
  std::size_t polarCells = 0, cartesianCells = 0;
};
} // namespace

TEST(calibrate_command, rheology_file_reproduces_the_generating_law) {
  ScratchDir dir("calibrate-law");
  const ThreeRuns runs(dir);
  CalibrateOptions options;
  options.runs = runs.paths;
  options.output = dir.file("out/rheology.yaml");
  EXPECT_EQ(runCalibrate(options), 0);

  const auto p = hikiln::calibration::loadRheologyFile(options.output);
  EXPECT_EQ(p.model, "drucker-prager-rate");
  EXPECT_NEAR(p.m0, 0.35, 1e-12);
  EXPECT_NEAR(p.m1, 0.012, 1e-13);
  EXPECT_EQ(p.strainRateFloor, 1e-2);
  EXPECT_NEAR(p.muWall, 0.33, 1e-15);
  EXPECT_NEAR(p.muWallStd, 0.03, 1e-15);
  EXPECT_EQ(p.slipPercent, (std::vector<double>{12.0, 10.0, 8.0}));
  EXPECT_GE(p.strainRateMin, 0.1);
  EXPECT_LE(p.strainRateMax, 20.0 + 1e-9);
  EXPECT_EQ(p.particleDiameter, 0.02);

  const YAML::Node yaml = YAML::LoadFile(options.output);
  EXPECT_NEAR(yaml["fit_quality"]["m_line"]["r_squared"].as<double>(), 1.0, 1e-12);
  EXPECT_EQ(yaml["fit_quality"]["m_line"]["n"].as<std::size_t>(), runs.polarCells);
  EXPECT_FALSE(yaml["newtonian"]["newtonian"].as<bool>());
  ASSERT_EQ(yaml["runs"].size(), 3u);
  EXPECT_EQ(yaml["runs"][1]["label"].as<std::string>(), "fill20");
  EXPECT_NEAR(yaml["runs"][1]["fill"].as<double>(), 0.2, 1e-15);
  EXPECT_NEAR(yaml["runs"][0]["rpm"].as<double>(), 0.314159 * 30.0 / 3.141592653589793, 1e-12);
  EXPECT_EQ(yaml["fit_quality"]["viscosity_vs_pressure"].size(), 3u);

  // Side outputs: one CSV row per selected cell, the fits, the summary.
  const fs::path out = dir.path() / "out";
  EXPECT_EQ(lineCount((out / "calibration.csv").string()), runs.polarCells + 1);
  const nlohmann::json fits = hikiln::io::readSummaryJson((out / "calibration.json").string());
  EXPECT_NEAR(fits["m_line"]["slope"].get<double>(), 0.012, 1e-13);
  EXPECT_EQ(fits["runs"][2]["selection"]["selected"].get<std::size_t>() +
                fits["runs"][1]["selection"]["selected"].get<std::size_t>() +
                fits["runs"][0]["selection"]["selected"].get<std::size_t>(),
            runs.polarCells);
  const nlohmann::json summary = hikiln::io::readSummaryJson((out / "summary.json").string());
  EXPECT_EQ(summary["stage"], "calibrate");
  EXPECT_EQ(summary["cells"].get<std::size_t>(), runs.polarCells);
  EXPECT_NEAR(summary["mu_wall"].get<double>(), 0.33, 1e-15);
  EXPECT_FALSE(summary["inputs"][0]["dem_summary"].is_null());
  EXPECT_EQ(summary["outputs"]["wall_profile"], "wall_profile.csv");
  // The wall profile: per shell bin of every run, the generating ratio and slip.
  std::ifstream wall((out / "wall_profile.csv").string());
  std::string line;
  std::getline(wall, line);
  EXPECT_EQ(line, "run,theta_deg,normal_stress,shear_stress,friction_ratio,slip_percent");
  const std::map<std::string, std::pair<double, double>> law = {
      {"fill10", {0.30, 12.0}}, {"fill20", {0.33, 10.0}}, {"fill30", {0.36, 8.0}}};
  std::size_t rows = 0;
  while (std::getline(wall, line)) {
    std::istringstream fields(line);
    std::string run, value;
    std::getline(fields, run, ',');
    std::vector<double> v;
    while (std::getline(fields, value, ','))
      v.push_back(std::stod(value));
    ASSERT_EQ(v.size(), 5u) << line;
    ASSERT_EQ(law.count(run), 1u) << line;
    EXPECT_NEAR(v[3], law.at(run).first, 1e-12) << line;
    EXPECT_NEAR(v[4], law.at(run).second, 1e-9) << line;
    EXPECT_GT(v[0], 0.0);
    EXPECT_LT(v[0], 360.0);
    ++rows;
  }
  EXPECT_EQ(rows, 3u * 36u);
  // Nothing but the five outputs (no temporaries left behind).
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out))
    ++entries;
  EXPECT_EQ(entries, 5u);
}

TEST(calibrate_command, cartesian_grid_gives_the_same_law) {
  ScratchDir dir("calibrate-cartesian");
  const ThreeRuns runs(dir);
  CalibrateOptions options;
  options.runs = runs.paths;
  options.output = dir.file("rheology.yaml");
  options.grid = hikiln::calibrate::AveragesGrid::Cartesian;
  runCalibrate(options);
  const auto p = hikiln::calibration::loadRheologyFile(options.output);
  EXPECT_NEAR(p.m0, 0.35, 1e-12);
  EXPECT_NEAR(p.m1, 0.012, 1e-13);
  const YAML::Node yaml = YAML::LoadFile(options.output);
  EXPECT_EQ(yaml["fit_quality"]["m_line"]["n"].as<std::size_t>(), runs.cartesianCells);
}

TEST(calibrate_command, mu_i_law_recovered_from_glass_bead_data) {
  ScratchDir dir("calibrate-mu-i");
  SyntheticRun base;
  base.useMuI = true;
  const ThreeRuns runs(dir, base);
  CalibrateOptions options;
  options.runs = runs.paths;
  options.output = dir.file("rheology.yaml");
  runCalibrate(options);
  const auto p = hikiln::calibration::loadRheologyFile(options.output);
  ASSERT_TRUE(p.muI.has_value());
  EXPECT_NEAR(p.muI->staticFriction, 0.383, 1e-9);
  EXPECT_NEAR(p.muI->limitFriction, 0.643, 1e-9);
  EXPECT_NEAR(p.muI->inertialScale, 0.279, 1e-9);
}

TEST(calibrate_command, missing_run_directory_or_file_is_named) {
  ScratchDir dir("calibrate-missing");
  fs::create_directories(dir.path() / "empty");
  CalibrateOptions options;
  options.output = dir.file("out/rheology.yaml");
  options.runs = {dir.file("empty")};
  std::string error = errorOf(options);
  EXPECT_NE(error.find(dir.file("empty")), std::string::npos) << error;
  EXPECT_NE(error.find("averages.h5"), std::string::npos) << error;
  options.runs = {dir.file("nowhere")};
  error = errorOf(options);
  EXPECT_NE(error.find(dir.file("nowhere")), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(options.output));
}

TEST(calibrate_command, missing_dataset_or_attribute_is_named) {
  ScratchDir dir("calibrate-dataset");
  SyntheticRun run;
  run.omit = {"/polar/strain_rate"};
  writeSyntheticRun(dir.path() / "run", run);
  CalibrateOptions options;
  options.output = dir.file("out/rheology.yaml");
  options.runs = {dir.file("run")};
  std::string error = errorOf(options);
  EXPECT_NE(error.find(dir.file("run/averages.h5")), std::string::npos) << error;
  EXPECT_NE(error.find("'/polar/strain_rate'"), std::string::npos) << error;
  // The cartesian grid is complete, so the same file calibrates from it.
  options.grid = hikiln::calibrate::AveragesGrid::Cartesian;
  EXPECT_EQ(errorOf(options), "");

  // A run without a wall attribute or a wall dataset: the file and the missing piece are named.
  const auto expectNamed = [&](const std::string& omitted, const std::string& folder,
                               const std::string& named) {
    run.omit = {omitted};
    writeSyntheticRun(dir.path() / folder, run);
    options.runs = {dir.file(folder)};
    const std::string message = errorOf(options);
    EXPECT_NE(message.find(dir.file(folder + "/averages.h5")), std::string::npos) << message;
    EXPECT_NE(message.find(named), std::string::npos) << message;
  };
  expectNamed("/wall@mu_wall", "nowall", "mu_wall");
  expectNamed("/wall/shear_stress", "noprofile", "'/wall/shear_stress'");
}

TEST(calibrate_command, too_few_valid_cells_is_named) {
  ScratchDir dir("calibrate-invalid");
  SyntheticRun good;
  writeSyntheticRun(dir.path() / "good", good);
  SyntheticRun bad;
  bad.allInvalid = true;
  writeSyntheticRun(dir.path() / "bad", bad);
  CalibrateOptions options;
  options.output = dir.file("out/rheology.yaml");
  options.runs = {dir.file("good"), dir.file("bad")};
  const std::string error = errorOf(options);
  EXPECT_NE(error.find(dir.file("bad/averages.h5")), std::string::npos) << error;
  EXPECT_NE(error.find("only 0 usable cells"), std::string::npos) << error;
  EXPECT_FALSE(fs::exists(options.output));
  // A raised floor can also leave too few: every generated strain rate is <= 20 1/s.
  options.runs = {dir.file("good")};
  options.minStrainRate = 25.0;
  EXPECT_NE(errorOf(options).find("at or below the strain-rate floor"), std::string::npos);
}

TEST(calibrate_command, refuses_to_write_into_a_run_directory) {
  ScratchDir dir("calibrate-clobber");
  writeSyntheticRun(dir.path() / "run", SyntheticRun{});
  CalibrateOptions options;
  options.runs = {dir.file("run")};
  options.output = dir.file("run/rheology.yaml");
  EXPECT_NE(errorOf(options).find("would overwrite"), std::string::npos);
  const nlohmann::json demSummary = hikiln::io::readSummaryJson(dir.file("run/summary.json"));
  EXPECT_EQ(demSummary["stage"], "dem");
}

TEST(calibrate_command, plot_command_uses_debian_python_and_the_script_override) {
  ::setenv("HIKILN_PLOT_SCRIPTS", "/opt/my scripts", 1);
  EXPECT_EQ(hikiln::calibrate::calibrationPlotScript(), "/opt/my scripts/plot_calibration.py");
  const std::string command = hikiln::calibrate::calibrationPlotCommand("/out", "/out/plots");
  EXPECT_EQ(command, "/usr/bin/python3 '/opt/my scripts/plot_calibration.py' --csv "
                     "'/out/calibration.csv' --json '/out/calibration.json' --out '/out/plots'");
  ::unsetenv("HIKILN_PLOT_SCRIPTS");
  EXPECT_TRUE(fs::is_regular_file(hikiln::calibrate::calibrationPlotScript()))
      << hikiln::calibrate::calibrationPlotScript();
}
