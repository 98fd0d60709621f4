#include "solvers/calibration/RheologyFile.hpp"

#include "solvers/calibration/YamlText.hpp"

#include <cmath>

namespace hikiln::calibration {

namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

void writeQuality(YamlText& y, const FitQuality& quality) {
  y.entry("n", std::to_string(quality.n));
  y.entry("r_squared", yamlNumber(quality.rSquared));
  y.entry("rms_residual", yamlNumber(quality.rmsResidual));
}

void writeHeader(YamlText& y, const std::vector<CalibrationRun>& runs,
                 const CalibrationOptions& options, const RheologyProvenance& provenance) {
  y.comment("hikiln rheology file: the granular-bed law of the continuum stage, fitted by");
  y.comment("`hikiln calibrate` to the averaged DEM fields of the calibration runs.");
  y.comment("hikiln version: " + provenance.hikilnVersion);
  y.comment("created: " + provenance.created);
  y.comment("grid: " + provenance.grid + "; cells with valid = 1, finite values, p > 0 and");
  y.comment("      strain rate > " + yamlNumber(options.selection.minStrainRate) + " 1/s");
  y.comment("inputs:");
  for (const CalibrationRun& run : runs)
    y.comment("  " + run.path);
  y.comment("");
  y.comment("SI units. Drucker-Prager convention (2D): p = sigma_ii / 2 (compressive positive),");
  y.comment("q = sqrt(s_ij s_ij / 2) with s = sigma - p I; yield at q = m p; in simple shear");
  y.comment("q / p = tau / sigma_n, so m = tan(phi). Continuum closure:");
  y.comment("mu_eff = m(gamma_dot) p / max(gamma_dot, strain_rate_floor). Inertial number:");
  y.comment("I = gamma_dot d / sqrt(p / rho_p).");
}

void writeLaws(YamlText& y, const CalibrationResult& r, const CalibrationOptions& options,
               const std::vector<CalibrationRun>& runs) {
  y.entry("format_version", "1");
  y.open("rheology", "the default law: m(gamma_dot) = m0 + m1 gamma_dot");
  y.entry("model", "drucker-prager-rate");
  y.entry("m0", yamlNumber(r.frictionLine.intercept), "[1] m at zero strain rate");
  y.entry("m1", yamlNumber(r.frictionLine.slope), "[s] dm / d gamma_dot");
  y.entry("strain_rate_floor", yamlNumber(options.selection.minStrainRate),
          "[1/s] regularisation; data below were not fitted");
  y.entry("strain_rate_range", yamlNumberList({r.strainRateMin, r.strainRateMax}),
          "[1/s] fitted data; beyond is extrapolation");
  y.entry("pressure_range", yamlNumberList({r.pressureMin, r.pressureMax}), "[Pa]");
  y.close();

  double diameter = 0.0, density = 0.0;
  for (const CalibrationRun& run : runs) {
    diameter += run.conditions.particleDiameter / static_cast<double>(runs.size());
    density += run.conditions.particleDensity / static_cast<double>(runs.size());
  }
  y.open("mu_i", "alternative: m = m_s + (m_2 - m_s) / (1 + I0 / I)");
  y.entry("fitted", r.muI ? "true" : "false");
  y.entry("status", yamlString(r.muIStatus));
  if (r.muI) {
    y.entry("m_s", yamlNumber(r.muI->parameters.staticFriction), "[1]");
    y.entry("m_2", yamlNumber(r.muI->parameters.limitFriction), "[1]");
    y.entry("I0", yamlNumber(r.muI->parameters.inertialScale), "[1]");
  }
  y.entry("particle_diameter", yamlNumber(diameter), "[m] mean over runs");
  y.entry("particle_density", yamlNumber(density), "[kg/m3] mean over runs");
  y.entry("inertial_range", yamlNumberList({r.inertialMin, r.inertialMax}), "[1] fitted data");
  y.close();

  y.open("coulomb", "tau = cohesion + mu_fr p, tan(phi) = mu_fr");
  y.entry("mu_fr", yamlNumber(r.coulomb.frictionCoefficient), "[1]");
  y.entry("cohesion", yamlNumber(r.coulomb.cohesion), "[Pa]");
  y.entry("phi_deg", yamlNumber(r.coulomb.frictionAngleDeg), "[degrees]");
  y.close();

  y.open("newtonian", "tau = K gamma_dot^n; n = 1 would be a Newtonian fluid");
  y.entry("exponent", yamlNumber(r.newtonian.fit.exponent), "[1] n");
  y.entry("consistency", yamlNumber(r.newtonian.fit.coefficient), "[Pa s^n] K");
  y.entry("newtonian", r.newtonian.newtonian ? "true" : "false",
          "|n - 1| <= " + yamlNumber(r.newtonian.tolerance));
  y.close();

  y.open("wall", "tau_wall = mu_wall sigma_n where the bed slips");
  y.entry("mu_wall", yamlNumber(r.wall.muWall), "[1] mean over runs");
  y.entry("mu_wall_std", yamlNumber(r.wall.muWallStd), "[1] sample standard deviation");
  y.entry("mu_wall_runs", yamlNumberList(r.wall.muWallRuns), "[1] per run");
  y.entry("slip_percent", yamlNumberList(r.wall.slipPercent), "[%] per run");
  y.close();
}

void writeFitQuality(YamlText& y, const CalibrationResult& r,
                     const std::vector<CalibrationRun>& runs) {
  y.open("fit_quality", "n points, R^2, RMS residual (units of the fitted quantity), std errors");
  y.open("m_line", "m against gamma_dot");
  writeQuality(y, r.frictionLine.quality);
  y.entry("m0_stderr", yamlNumber(r.frictionLine.interceptStdError));
  y.entry("m1_stderr", yamlNumber(r.frictionLine.slopeStdError));
  y.close();
  y.open("mu_i", "m against I");
  if (r.muI) {
    writeQuality(y, r.muI->quality);
    y.entry("m_s_stderr", yamlNumber(r.muI->standardErrors.staticFriction));
    y.entry("m_2_stderr", yamlNumber(r.muI->standardErrors.limitFriction));
    y.entry("I0_stderr", yamlNumber(r.muI->standardErrors.inertialScale));
    y.entry("iterations", std::to_string(r.muI->iterations));
    y.entry("converged", r.muI->converged ? "true" : "false");
  } else {
    y.entry("n", "0");
  }
  y.close();
  y.open("coulomb", "shear stress [Pa] against pressure");
  writeQuality(y, r.coulomb.quality);
  y.entry("mu_fr_stderr", yamlNumber(r.coulomb.frictionCoefficientStdError));
  y.entry("cohesion_stderr", yamlNumber(r.coulomb.cohesionStdError));
  y.entry("phi_deg_stderr", yamlNumber(r.coulomb.frictionAngleDegStdError));
  y.close();
  y.open("newtonian", "ln shear stress against ln strain rate");
  writeQuality(y, r.newtonian.fit.quality);
  y.entry("exponent_stderr", yamlNumber(r.newtonian.fit.exponentStdError));
  y.close();
  y.open("viscosity_vs_pressure", "per run: viscosity [Pa s] = intercept + slope p");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const LinearFit& fit = r.viscosityVsPressure[i];
    y.openListItem();
    y.entry("run", yamlString(runs[i].label));
    y.entry("intercept", yamlNumber(fit.intercept), "[Pa s]");
    y.entry("slope", yamlNumber(fit.slope), "[s]");
    writeQuality(y, fit.quality);
    y.close();
  }
  y.close();
  y.close();
}

void writeRuns(YamlText& y, const std::vector<CalibrationRun>& runs) {
  y.open("runs", "the calibration runs");
  for (const CalibrationRun& run : runs) {
    const RunConditions& c = run.conditions;
    y.openListItem();
    y.entry("label", yamlString(run.label));
    y.entry("path", yamlString(run.path));
    y.entry("fill", yamlNumber(c.fill), "[1] measured fill fraction");
    y.entry("omega", yamlNumber(c.omega), "[rad/s]");
    y.entry("rpm", yamlNumber(c.omega * 30.0 / pi), "[1/min]");
    y.entry("drum_radius", yamlNumber(c.drumRadius), "[m]");
    y.entry("particle_diameter", yamlNumber(c.particleDiameter), "[m]");
    y.entry("particle_density", yamlNumber(c.particleDensity), "[kg/m3]");
    y.entry("average_window", yamlNumberList({c.averageStart, c.averageEnd}), "[s]");
    y.entry("mu_wall", yamlNumber(run.muWall), "[1]");
    y.entry("slip_percent", yamlNumber(run.slipPercent), "[%]");
    y.entry("cells", std::to_string(run.counts.selected),
            "selected of " + std::to_string(run.counts.total));
    y.close();
  }
  y.close();
}

} // namespace

std::string formatRheologyYaml(const CalibrationResult& result,
                               const std::vector<CalibrationRun>& runs,
                               const CalibrationOptions& options,
                               const RheologyProvenance& provenance) {
  YamlText y;
  writeHeader(y, runs, options, provenance);
  writeLaws(y, result, options, runs);
  writeFitQuality(y, result, runs);
  writeRuns(y, runs);
  return y.str();
}

} // namespace hikiln::calibration
