#include "drivers/calibrate/PlotScript.hpp"

#include <spdlog/spdlog.h>

#include <cstdlib>
#include <filesystem>

#ifndef HIKILN_SOURCE_DIR
#define HIKILN_SOURCE_DIR "."
#endif

namespace hikiln::calibrate {

namespace fs = std::filesystem;

namespace {
// Single-quoted for /bin/sh: safe for any path.
std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char ch : text)
    quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}
} // namespace

std::string calibrationPlotScript() {
  const char* overridden = std::getenv("HIKILN_PLOT_SCRIPTS");
  const fs::path dir = overridden != nullptr && *overridden != '\0'
                           ? fs::path(overridden)
                           : fs::path(HIKILN_SOURCE_DIR) / "drivers" / "plots";
  return (dir / "plot_calibration.py").string();
}

std::string calibrationPlotCommand(const std::string& outputDir, const std::string& plotDir) {
  const fs::path out(outputDir);
  return std::string(plotPython) + " " + shellQuote(calibrationPlotScript()) + " --csv " +
         shellQuote((out / "calibration.csv").string()) + " --json " +
         shellQuote((out / "calibration.json").string()) + " --out " + shellQuote(plotDir);
}

bool drawCalibrationPlots(const std::string& outputDir, const std::string& plotDir) {
  const std::string command = calibrationPlotCommand(outputDir, plotDir);
  if (!fs::is_regular_file(calibrationPlotScript())) {
    spdlog::warn("plot script '{}' not found (set HIKILN_PLOT_SCRIPTS); no plots. Later: {}",
                 calibrationPlotScript(), command);
    return false;
  }
  const std::string probe =
      std::string(plotPython) + " -c 'import matplotlib, numpy' >/dev/null 2>&1";
  if (std::system(probe.c_str()) != 0) {
    spdlog::warn("{} cannot import matplotlib and numpy (apt-get install python3-matplotlib); "
                 "no plots. Run later: {}",
                 plotPython, command);
    return false;
  }
  spdlog::info("plotting: {}", command);
  if (std::system(command.c_str()) != 0) {
    spdlog::warn("the plot script failed; rerun: {}", command);
    return false;
  }
  return true;
}

} // namespace hikiln::calibrate
