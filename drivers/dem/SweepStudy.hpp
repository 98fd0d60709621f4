#pragma once
/// \file SweepStudy.hpp
/// \brief A parameter study file for `hikiln sweep`: a base case plus one set of overrides per
/// case.
///
/// ```yaml
/// base: drum-base.yaml          # relative to the study file
/// defaults: {time.duration: 60} # overrides for every case (optional)
/// cases:                        # name -> overrides (dotted keys of the dem schema)
///   fill-10: {drum.fill: 0.10}
///   fill-30: {drum.fill: 0.30}
/// ```

#include <string>
#include <vector>

namespace hikiln::dem {

/// \brief One case of a study: its name (also its output folder) and its `--set` overrides.
struct SweepCase {
  std::string name;
  std::vector<std::string> overrides; ///< "key=value", defaults first, then the case's own
};

/// \brief A parsed study: the base case path (resolved against the study's folder) and its cases.
struct SweepStudy {
  std::string source;
  std::string baseCase;
  std::vector<SweepCase> cases;
};

/// \brief Reads and checks a study file; every case's overrides are validated against the dem
/// schema with the base case, so a typo fails before anything runs. Errors name file, line and key.
SweepStudy loadSweepStudy(const std::string& path, const std::vector<std::string>& extraOverrides);

} // namespace hikiln::dem
