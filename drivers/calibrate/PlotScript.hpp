#pragma once
/// \file PlotScript.hpp
/// \brief Runs drivers/plots/plot_calibration.py with Debian's python3 (which has matplotlib),
/// or says how to run it later.

#include <string>

namespace hikiln::calibrate {

/// \brief The interpreter the plot scripts are written for.
inline constexpr const char* plotPython = "/usr/bin/python3";

/// \brief Path of the plot script `name` (e.g. "plot_fields.py"): in $HIKILN_PLOT_SCRIPTS when
/// set, else in the source tree this program was built from (drivers/plots).
std::string plotScriptPath(const std::string& name);

/// \brief Path of plot_calibration.py (plotScriptPath()).
std::string calibrationPlotScript();

/// \brief Single-quotes `text` for /bin/sh (safe for any path).
std::string shellQuote(const std::string& text);

/// \brief Runs `plotPython script arguments` (arguments already quoted) when the script exists
/// and plotPython can import `modules` (comma-separated); otherwise, or when the script fails,
/// logs a warning naming `what` with the command to run later. Returns true when it ran cleanly.
bool runPlotScript(const std::string& script, const std::string& arguments,
                   const std::string& modules, const std::string& what);

/// \brief The shell command that draws the calibration plots into `plotDir` from
/// calibration.csv and calibration.json in `outputDir`.
std::string calibrationPlotCommand(const std::string& outputDir, const std::string& plotDir);

/// \brief Runs the plot command when the script exists and plotPython can import matplotlib;
/// otherwise logs a warning with the command to run later. Returns true when the plots were made.
bool drawCalibrationPlots(const std::string& outputDir, const std::string& plotDir);

} // namespace hikiln::calibrate
