#pragma once
/// \file KilnCase.hpp
/// \brief The `hikiln kiln` case file (physics.md 7): its schema and the run settings read from it.

#include "drivers/case/CaseFile.hpp"
#include "drivers/case/CaseSchema.hpp"
#include "kernels/cfd/KilnGeometry.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <string>
#include <vector>

namespace hikiln::cfd {

/// \brief Everything a 3D kiln run needs, in SI units.
struct KilnSettings {
  double length = 15.0;              ///< m
  double diameter = 5.0;             ///< m
  double rpm = 3.0;                  ///< rev/min, counter-clockwise seen from the discharge end
  double slopeDegrees = 0.0;         ///< inclination, discharge end lower
  double fill = 0.24;                ///< initial bed area over the cross-section, uniform along z
  double feedFraction = 0.046;       ///< feed patch: lowest part of the inlet face
  double feedVelocity = 0.05;        ///< m/s
  double feedPacking = 1.0;          ///< feed phi over phi_max
  double airFraction = 0.35;         ///< air patch: highest part of the inlet face
  double airVelocity = 2.0;          ///< m/s
  double damHeight = 0.0;            ///< m, radial; 0: no dam ring
  double damWidth = 0.0;             ///< m, axial
  double damOnAt = 0.0;              ///< s: the ring is switched on at this time
  int cellsAcross = 32;              ///< cells across the square cross-section
  int cellsAlong = 48;               ///< cells along the kiln
  double duration = 49.0;            ///< s
  double outputInterval = 1.0;       ///< s between field outputs
  std::vector<double> snapshots;     ///< extra output times (rendered bed surfaces)
  double initialTemperature = 300.0; ///< K, bed and gas at the start (heat on)
  double feedTemperature = 300.0;    ///< K, the solids fed
  double airTemperature = 300.0;     ///< K, the air blown in
  double tracerStart = 0.0;          ///< s, the residence-time pulse in the feed starts
  double tracerDuration = 0.0;       ///< s; 0: no tracer
  double kramersFrom = 0.0;          ///< s: steady-state window start; 0: no comparison
  std::string rheologySource;
  TwoPhaseParameters params;
  double omega() const { return rpm * 2.0 * constants::pi / 60.0; }
};

/// \brief Schema of the `hikiln kiln` case file.
const cases::CaseSchema& kilnSchema();

/// \brief Run settings from a validated case file (rheology file as for `hikiln continuum`).
KilnSettings kilnSettingsFromCase(const cases::CaseFile& file);

/// \brief The grid of a kiln run: cellsAcross^2 cells over the diameter plus 2 cells each side,
/// cellsAlong cells over the length (z from 0 at the inlet face).
Grid kilnGrid(KilnSettings const& s);

/// \brief The kiln's shape (shell, inlet patches, open discharge), the dam ring included when
/// withDam.
KilnDomain kilnDomain(KilnSettings const& s, bool withDam);

} // namespace hikiln::cfd
