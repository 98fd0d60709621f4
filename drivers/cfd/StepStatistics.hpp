#pragma once
/// \file StepStatistics.hpp
/// \brief Bookkeeping of a continuum run's time steps shared by `hikiln continuum` and
/// `hikiln kiln`: landing on output times, and the counts, extremes and solver iterations of the
/// steps that go into the log and summary.json.

#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>

namespace hikiln::cfd {

/// \brief The step dt from `time`, shortened to land on `target` when it would pass it (a
/// shorter step is always stable); the reason then says so.
inline double landOn(double time, double dt, double target, std::string& reason) {
  if (time + dt > target) {
    reason += ", shortened to an output time";
    return target - time;
  }
  return dt;
}

/// \brief Counts and extremes of the steps taken.
struct StepStatistics {
  std::int64_t steps = 0;
  std::int64_t viscousIterations = 0;
  std::int64_t pressureIterations = 0;
  double viscousSeconds = 0.0;  ///< in the momentum solves (hierarchy set-up included)
  double pressureSeconds = 0.0; ///< in the pressure solves (likewise)
  std::int64_t transportSubsteps = 0;
  int mostTransportSubsteps = 0;
  double minDt = std::numeric_limits<double>::infinity(); ///< of the steps not shortened
  double maxDt = 0.0;
  double maxDivergence = 0.0;
  std::map<std::string, std::int64_t> limits; ///< steps per limiting reason

  /// \brief Adds one step of length dt taken for `reason` ("advection (CFL), shortened ...").
  void add(double dt, std::string const& reason, TwoPhaseStepReport const& r) {
    ++steps;
    ++limits[reason.substr(0, reason.find(','))];
    if (reason.find("shortened") == std::string::npos) { // a landing step says nothing
      minDt = std::min(minDt, dt);
    }
    maxDt = std::max(maxDt, dt);
    maxDivergence = std::max(maxDivergence, r.maxDivergence);
    viscousIterations += r.viscous.iterations;
    pressureIterations += r.pressure.iterations;
    viscousSeconds += r.viscous.seconds;
    pressureSeconds += r.pressure.seconds;
    transportSubsteps += r.transportSubsteps;
    mostTransportSubsteps = std::max(mostTransportSubsteps, r.transportSubsteps);
  }

  /// \brief Writes steps, dt_min (of the steps not shortened to land on an output time), dt_max,
  /// dt_limited_by, max_divergence, the mean iterations, seconds_per_step, the share of it in the
  /// momentum and pressure solves, and cell_updates_per_second (loopSeconds of stepping over
  /// `cells`).
  void writeTo(nlohmann::json& summary, double loopSeconds, std::int64_t cells) const {
    const double n = static_cast<double>(steps);
    summary["steps"] = steps;
    summary["dt_min"] = std::isfinite(minDt) ? minDt : maxDt;
    summary["dt_max"] = maxDt;
    summary["dt_limited_by"] = limits;
    summary["max_divergence"] = maxDivergence;
    summary["mean_viscous_iterations"] = steps > 0 ? double(viscousIterations) / n : 0.0;
    summary["mean_pressure_iterations"] = steps > 0 ? double(pressureIterations) / n : 0.0;
    summary["transport_substeps_mean"] = steps > 0 ? double(transportSubsteps) / n : 0.0;
    summary["transport_substeps_max"] = mostTransportSubsteps;
    summary["seconds_per_step"] = steps > 0 ? loopSeconds / n : 0.0;
    summary["share_in_momentum_solves"] = loopSeconds > 0.0 ? viscousSeconds / loopSeconds : 0.0;
    summary["share_in_pressure_solves"] = loopSeconds > 0.0 ? pressureSeconds / loopSeconds : 0.0;
    summary["cell_updates_per_second"] = loopSeconds > 0.0 ? double(cells) * n / loopSeconds : 0.0;
  }
};

} // namespace hikiln::cfd
