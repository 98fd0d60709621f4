#include "solvers/calibration/CalibrationJson.hpp"

namespace hikiln::calibration {

nlohmann::json toJson(const FitQuality& quality) {
  return {{"n", quality.n}, {"r_squared", quality.rSquared}, {"rms_residual", quality.rmsResidual}};
}

nlohmann::json toJson(const LinearFit& fit) {
  return {{"intercept", fit.intercept},
          {"slope", fit.slope},
          {"intercept_stderr", fit.interceptStdError},
          {"slope_stderr", fit.slopeStdError},
          {"quality", toJson(fit.quality)}};
}

nlohmann::json toJson(const PowerLawFit& fit) {
  return {{"coefficient", fit.coefficient},
          {"exponent", fit.exponent},
          {"coefficient_stderr", fit.coefficientStdError},
          {"exponent_stderr", fit.exponentStdError},
          {"dropped", fit.dropped},
          {"quality_log", toJson(fit.quality)}};
}

nlohmann::json toJson(const CoulombFit& fit) {
  return {
      {"mu_fr", fit.frictionCoefficient},        {"cohesion", fit.cohesion},
      {"phi_deg", fit.frictionAngleDeg},         {"mu_fr_stderr", fit.frictionCoefficientStdError},
      {"cohesion_stderr", fit.cohesionStdError}, {"phi_deg_stderr", fit.frictionAngleDegStdError},
      {"quality", toJson(fit.quality)}};
}

nlohmann::json toJson(const MuIFit& fit) {
  return {{"m_s", fit.parameters.staticFriction},
          {"m_2", fit.parameters.limitFriction},
          {"I0", fit.parameters.inertialScale},
          {"m_s_stderr", fit.standardErrors.staticFriction},
          {"m_2_stderr", fit.standardErrors.limitFriction},
          {"I0_stderr", fit.standardErrors.inertialScale},
          {"iterations", fit.iterations},
          {"converged", fit.converged},
          {"quality", toJson(fit.quality)}};
}

nlohmann::json toJson(const SelectionCounts& counts) {
  return {{"total", counts.total},
          {"invalid", counts.invalid},
          {"non_finite", counts.nonFinite},
          {"below_strain_rate", counts.belowStrainRate},
          {"non_positive_pressure", counts.nonPositivePressure},
          {"selected", counts.selected}};
}

nlohmann::json calibrationToJson(const CalibrationResult& result,
                                 const std::vector<CalibrationRun>& runs,
                                 const CalibrationOptions& options) {
  nlohmann::json j;
  j["selection"] = {{"min_strain_rate", options.selection.minStrainRate}};
  j["cells"] = result.cellCount;
  j["ranges"] = {{"strain_rate", {result.strainRateMin, result.strainRateMax}},
                 {"pressure", {result.pressureMin, result.pressureMax}},
                 {"inertial_number", {result.inertialMin, result.inertialMax}}};
  j["m_line"] = toJson(result.frictionLine);
  j["mu_i"] = result.muI ? toJson(*result.muI) : nlohmann::json::object();
  j["mu_i"]["status"] = result.muIStatus;
  j["coulomb"] = toJson(result.coulomb);
  j["newtonian"] = toJson(result.newtonian.fit);
  j["newtonian"]["tolerance"] = result.newtonian.tolerance;
  j["newtonian"]["newtonian"] = result.newtonian.newtonian;
  j["wall"] = {{"mu_wall", result.wall.muWall},
               {"mu_wall_std", result.wall.muWallStd},
               {"mu_wall_runs", result.wall.muWallRuns},
               {"slip_percent", result.wall.slipPercent},
               {"mean_slip_percent", result.wall.meanSlipPercent}};
  nlohmann::json runList = nlohmann::json::array();
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const CalibrationRun& run = runs[i];
    const RunConditions& c = run.conditions;
    runList.push_back({{"label", run.label},
                       {"path", run.path},
                       {"fill", c.fill},
                       {"omega", c.omega},
                       {"drum_radius", c.drumRadius},
                       {"particle_diameter", c.particleDiameter},
                       {"particle_density", c.particleDensity},
                       {"average_start", c.averageStart},
                       {"average_end", c.averageEnd},
                       {"samples", c.samples},
                       {"mu_wall", run.muWall},
                       {"slip_percent", run.slipPercent},
                       {"selection", toJson(run.counts)},
                       {"viscosity_vs_pressure", toJson(result.viscosityVsPressure.at(i))}});
  }
  j["runs"] = runList;
  return j;
}

} // namespace hikiln::calibration
