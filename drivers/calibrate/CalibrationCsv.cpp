#include "drivers/calibrate/CalibrationCsv.hpp"

#include <fmt/format.h>

namespace hikiln::calibrate {

namespace {
// Labels come from directory names: keep the CSV unambiguous without a quoting dialect.
std::string csvField(std::string text) {
  for (char& ch : text)
    if (ch == ',' || ch == '"' || ch == '\n' || ch == '\r')
      ch = '_';
  return text;
}
} // namespace

std::string formatCalibrationCsv(const std::vector<calibration::CalibrationRun>& runs) {
  std::string out =
      "run,r,theta,volume_fraction,pressure,shear_stress,strain_rate,viscosity,m,inertial_number\n";
  for (const calibration::CalibrationRun& run : runs) {
    const calibration::CellSamples& c = run.cells;
    const std::vector<double> inertial = calibration::inertialNumbers(run);
    const std::string label = csvField(run.label);
    for (std::size_t i = 0; i < c.size(); ++i)
      out += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", label, c.r[i], c.theta[i],
                         c.volumeFraction[i], c.pressure[i], c.shearStress[i], c.strainRate[i],
                         c.viscosity[i], c.frictionM[i], inertial[i]);
  }
  return out;
}

std::string formatWallProfileCsv(const std::vector<calibration::CalibrationRun>& runs,
                                 const std::vector<WallProfile>& walls) {
  std::string out = "run,theta_deg,normal_stress,shear_stress,friction_ratio,slip_percent\n";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const WallProfile& w = walls.at(r);
    const std::string label = csvField(runs[r].label);
    for (std::size_t i = 0; i < w.thetaDeg.size(); ++i)
      out += fmt::format("{},{},{},{},{},{}\n", label, w.thetaDeg[i], w.normalStress[i],
                         w.shearStress[i], w.ratio[i], w.slipPercent[i]);
  }
  return out;
}

} // namespace hikiln::calibrate
