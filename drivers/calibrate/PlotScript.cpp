#include "drivers/calibrate/PlotScript.hpp"

#include <spdlog/spdlog.h>

#include <cstdlib>
#include <filesystem>

#ifndef HIKILN_SOURCE_DIR
#define HIKILN_SOURCE_DIR "."
#endif

namespace hikiln::calibrate {

namespace fs = std::filesystem;

std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char ch : text)
    quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

std::string plotScriptPath(const std::string& name) {
  const char* overridden = std::getenv("HIKILN_PLOT_SCRIPTS");
  const fs::path dir = overridden != nullptr && *overridden != '\0'
                           ? fs::path(overridden)
                           : fs::path(HIKILN_SOURCE_DIR) / "drivers" / "plots";
  return (dir / name).string();
}

std::string calibrationPlotScript() {
  return plotScriptPath("plot_calibration.py");
}

bool runPlotScript(const std::string& script, const std::string& arguments,
                   const std::string& modules, const std::string& what) {
  const std::string command = std::string(plotPython) + " " + shellQuote(script) + " " + arguments;
  if (!fs::is_regular_file(script)) {
    spdlog::warn("plot script '{}' not found (set HIKILN_PLOT_SCRIPTS); no {}. Later: {}", script,
                 what, command);
    return false;
  }
  const std::string probe =
      std::string(plotPython) + " -c 'import " + modules + "' >/dev/null 2>&1";
  if (std::system(probe.c_str()) != 0) {
    spdlog::warn("{} cannot import {} (apt-get install python3-matplotlib python3-h5py); no {}. "
                 "Later: {}",
                 plotPython, modules, what, command);
    return false;
  }
  spdlog::info("{}: {}", what, command);
  if (std::system((command + " >/dev/null").c_str()) != 0) {
    spdlog::warn("the {} script failed; rerun: {}", what, command);
    return false;
  }
  return true;
}

namespace {
std::string calibrationPlotArguments(const std::string& outputDir, const std::string& plotDir) {
  const fs::path out(outputDir);
  return "--csv " + shellQuote((out / "calibration.csv").string()) + " --json " +
         shellQuote((out / "calibration.json").string()) + " --out " + shellQuote(plotDir);
}
} // namespace

std::string calibrationPlotCommand(const std::string& outputDir, const std::string& plotDir) {
  return std::string(plotPython) + " " + shellQuote(calibrationPlotScript()) + " " +
         calibrationPlotArguments(outputDir, plotDir);
}

bool drawCalibrationPlots(const std::string& outputDir, const std::string& plotDir) {
  return runPlotScript(calibrationPlotScript(), calibrationPlotArguments(outputDir, plotDir),
                       "matplotlib, numpy", "calibration plots");
}

} // namespace hikiln::calibrate
