#pragma once
/// \file ContinuumCase.hpp
/// \brief The `hikiln continuum` case file: its schema and the run settings read from it.

#include "drivers/case/CaseFile.hpp"
#include "drivers/case/CaseSchema.hpp"
#include "solvers/cfd/TwoPhaseSolver.hpp"

#include <string>

namespace hikiln::cfd {

/// \brief Everything a 2D continuum drum run needs, in SI units.
struct ContinuumSettings {
  double diameter = 2.0;        ///< m
  double rpm = 3.0;             ///< rev/min, counter-clockwise
  double fill = 0.2;            ///< bed area over drum area
  int cells = 64;               ///< cells across the (square) domain
  double duration = 10.0;       ///< s
  double outputInterval = 1.0;  ///< s between field outputs
  double slipAfter = 0.0;       ///< s: wall slip is averaged over outputs after this time
  double initialLeft = 673.0;   ///< K, initial temperature of the left half (heat on)
  double initialRight = 1073.0; ///< K, right half
  std::string rheologySource;   ///< "case file" or the rheology file read
  TwoPhaseParameters params;
  /// \brief Drum angular velocity (rad/s).
  double omega() const { return rpm * 2.0 * constants::pi / 60.0; }
};

/// \brief Height above the drum centre of a flat bed filling `fill` of a circle of radius R (the
/// bed at rest at t = 0).
double flatBedLevel(double R, double fill);

/// \brief Schema of the `hikiln continuum` case file (physics.md 3, 5, 6.3).
const cases::CaseSchema& continuumSchema();

/// \brief Run settings from a validated case file; a `rheology.file` is read (relative paths
/// from the case file's folder) and overrides the case's m0, m1, strain-rate floor and mu_wall.
ContinuumSettings continuumSettingsFromCase(const cases::CaseFile& file);

} // namespace hikiln::cfd
