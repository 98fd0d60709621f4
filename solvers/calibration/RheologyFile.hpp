#pragma once
/// \file RheologyFile.hpp
/// \brief The rheology file: the calibration stage's output and the continuum stage's input.
/// A commented YAML document; see formatRheologyYaml for its sections.

#include "solvers/calibration/Calibration.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hikiln::calibration {

/// \brief Where a rheology file came from (its comment header).
struct RheologyProvenance {
  std::string hikilnVersion; ///< e.g. "0.1.0"
  std::string created;       ///< UTC, ISO 8601
  std::string grid;          ///< "polar" or "cartesian"
};

/// \brief The values the continuum stage needs, as read back from a rheology file.
struct RheologyParameters {
  std::string model;            ///< "drucker-prager-rate"
  double m0 = 0.0;              ///< m at zero strain rate [1]
  double m1 = 0.0;              ///< dm / d gamma_dot [s]
  double strainRateFloor = 0.0; ///< [1/s]
  double strainRateMin = 0.0;   ///< fitted data range [1/s]
  double strainRateMax = 0.0;
  std::optional<MuIParameters> muI; ///< present when the mu(I) fit succeeded
  double particleDiameter = 0.0;    ///< mean over runs [m] (for I)
  double particleDensity = 0.0;     ///< mean over runs [kg/m3]
  double frictionCoefficient = 0.0; ///< Coulomb mu_fr
  double cohesion = 0.0;            ///< [Pa]
  double frictionAngleDeg = 0.0;    ///< [degrees]
  double muWall = 0.0;
  double muWallStd = 0.0;
  std::vector<double> slipPercent;
};

/// \brief The rheology file's YAML text: a comment header (version, date, inputs, conventions)
/// and sections rheology (m0, m1, floor: the default law), mu_i, coulomb, newtonian, wall,
/// fit_quality (n, R^2, RMS residual, standard errors of every fit) and runs.
std::string formatRheologyYaml(const CalibrationResult& result,
                               const std::vector<CalibrationRun>& runs,
                               const CalibrationOptions& options,
                               const RheologyProvenance& provenance);

/// \brief Parses rheology YAML text; throws std::runtime_error naming the first missing or
/// malformed key. `source` names the text in messages (usually its file path).
RheologyParameters parseRheologyYaml(const std::string& text, const std::string& source = "");

/// \brief Reads and parses the rheology file at `path`; errors name the path.
RheologyParameters loadRheologyFile(const std::string& path);

} // namespace hikiln::calibration
