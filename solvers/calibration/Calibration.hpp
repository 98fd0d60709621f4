#pragma once
/// \file Calibration.hpp
/// \brief physics.md section 4: every fit of the calibration stage over the pooled cells of the
/// calibration runs (shear stress vs strain rate and pressure, viscosity vs pressure per run,
/// m(gamma_dot), the mu(I) form and the wall friction).

#include "solvers/calibration/CellSelection.hpp"
#include "solvers/calibration/CoulombFit.hpp"
#include "solvers/calibration/LinearFit.hpp"
#include "solvers/calibration/MuIFit.hpp"
#include "solvers/calibration/NewtonianTest.hpp"
#include "solvers/calibration/WallStatistics.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace hikiln::calibration {

/// \brief What a DEM run was (root attributes of its averaged-field file); NaN when unknown.
struct RunConditions {
  double fill = std::numeric_limits<double>::quiet_NaN();             ///< measured fill fraction
  double omega = std::numeric_limits<double>::quiet_NaN();            ///< drum speed [rad/s]
  double drumRadius = std::numeric_limits<double>::quiet_NaN();       ///< [m]
  double particleDiameter = std::numeric_limits<double>::quiet_NaN(); ///< mean d [m]
  double particleDensity = std::numeric_limits<double>::quiet_NaN();  ///< rho_p [kg/m3]
  double averageStart = std::numeric_limits<double>::quiet_NaN();     ///< [s]
  double averageEnd = std::numeric_limits<double>::quiet_NaN();       ///< [s]
  std::int64_t samples = 0;                                           ///< averaged snapshots
};

/// \brief One calibration run: its selected cells and wall values.
struct CalibrationRun {
  std::string label; ///< short unique name (legend, CSV)
  std::string path;  ///< the averaged-field file it came from
  RunConditions conditions;
  double muWall = 0.0;      ///< bed-shell friction coefficient
  double slipPercent = 0.0; ///< wall slip [%]
  CellSamples cells;        ///< the selected cells
  SelectionCounts counts;   ///< how the selection went
};

/// \brief Choices of the calibration.
struct CalibrationOptions {
  SelectionOptions selection;      ///< recorded in the outputs (the caller selects the cells)
  double newtonianTolerance = 0.1; ///< |n - 1| for a Newtonian verdict
  bool fitMuI = true;              ///< also fit the mu(I) form
  MuIFitOptions muI;
};

/// \brief Every fit with its quality.
struct CalibrationResult {
  LinearFit frictionLine;                     ///< m = m0 + m1 gamma_dot (the default law)
  CoulombFit coulomb;                         ///< q = c + mu_fr p
  NewtonianTest newtonian;                    ///< q = K gamma_dot^n
  std::vector<LinearFit> viscosityVsPressure; ///< per run, viscosity = a + b p
  std::optional<MuIFit> muI;                  ///< empty when not requested or when it failed
  std::string muIStatus;                      ///< "fitted", "not requested" or why it failed
  WallStatistics wall;
  std::size_t cellCount = 0;                       ///< pooled cells
  double strainRateMin = 0.0, strainRateMax = 0.0; ///< range of the fitted data [1/s]
  double pressureMin = 0.0, pressureMax = 0.0;     ///< [Pa]
  double inertialMin = 0.0, inertialMax = 0.0;     ///< range of I (NaN without particle data)
};

/// \brief Inertial number of every selected cell of `run` (uses its particle diameter/density).
std::vector<double> inertialNumbers(const CalibrationRun& run);

/// \brief Pools the runs' cells and fits everything. Throws std::invalid_argument when there are
/// no runs or a run has fewer than 2 cells; a failing mu(I) fit is reported in muIStatus instead.
CalibrationResult calibrate(const std::vector<CalibrationRun>& runs,
                            const CalibrationOptions& options);

} // namespace hikiln::calibration
