#pragma once
/// \file AveragedFields.hpp
/// \brief Time-averaged continuum fields of a DEM drum slice (physics.md 2), on the host: the
/// accumulated sums a FieldAverager collects, and their finalisation into the fields of
/// docs/averaged-fields.md.

#include "kernels/dem/CoarseGrainGrid.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace hikiln::dem {

/// \brief Grids, slice thickness and validity filter of the averaging.
struct AveragingSettings {
  double drumRadius = 1.0; ///< R (m); grids cover r < R and [-R, R]^2
  /// \brief Slice thickness (m) that turns cell areas into volumes, as the mass convention
  /// implies: the mean particle diameter for MassConvention::Sphere (a sphere of diameter d in a
  /// slice d thick), the disc thickness for MassConvention::Disc.
  double thickness = 0.02;
  int radialCells = 15;  ///< the paper's 30 cells across the diameter
  int angularCells = 60; ///< polar sectors, and the shell's angular bins
  int cartesianCellsX = 30;
  int cartesianCellsY = 30;
  double minVolumeFraction = 0.5;       ///< valid: area fraction at least this ...
  std::int64_t minParticleSamples = 20; ///< ... and at least this many particle-samples
  double touchGap = 0.002;              ///< shell "touching" gap of wallSlip() (m)

  /// \brief The polar grid these settings describe.
  cg::PolarGrid polarGrid() const;
  /// \brief The Cartesian grid over [-R, R]^2.
  cg::CartesianGrid cartesianGrid() const;
  /// \brief Throws std::invalid_argument naming the first unusable setting.
  void validate() const;
};

/// \brief Everything accumulated so far (what a checkpoint stores to continue the averages).
/// Arrays are row-major: polar cells x CellSum::Size, Cartesian cells x CellSum::Size, shell bins
/// x WallSum::Size.
struct AveragingSums {
  std::vector<double> polar, cartesian, wall;
  std::int64_t samples = 0;
  double slipSum = 0.0;         ///< sum of per-sample wallSlip() fractions that were finite
  std::int64_t slipSamples = 0; ///< how many
  double firstTime = std::numeric_limits<double>::quiet_NaN(); ///< time of the first sample (s)
  double lastTime = std::numeric_limits<double>::quiet_NaN();  ///< time of the last sample (s)
};

/// \brief Finalised fields of one grid, arrays in its [slow][fast] cell order (docs).
struct CellFields {
  std::size_t slow = 0, fast = 0; ///< [ntheta][nr] or [ny][nx]
  std::vector<double> volumeFraction, velocityX, velocityY;
  std::vector<double> kineticXX, kineticXY, kineticYY;
  std::vector<double> contactXX, contactXY, contactYX, contactYY;
  std::vector<double> granularTemperature, strainRate, pressure, shearStress, viscosity, frictionM;
  std::vector<double> particlesPerSample; ///< mean number of particle centres in the cell
  /// Mass-weighted mean particle temperature (K) over the samples, NaN where no particle was
  /// seen; empty without heat (filled by the heat driver, not by finalizeAverages()).
  std::vector<double> temperature;
  std::vector<std::uint8_t> valid;
  /// \brief Number of cells.
  std::size_t size() const { return slow * fast; }
};

/// \brief Finalised shell fields, per angular bin.
struct WallFields {
  std::vector<double> thetaCentres;       ///< rad
  std::vector<double> normalStress;       ///< Pa, time average
  std::vector<double> shearStress;        ///< Pa, positive along the shell motion
  std::vector<double> tangentialVelocity; ///< m/s, counter-clockwise v_theta of touching particles
  std::vector<double> contactsPerSample;  ///< mean number of particles in drum contact
  double muWall = std::numeric_limits<double>::quiet_NaN();
  double slipPercent = std::numeric_limits<double>::quiet_NaN();
};

/// \brief All averaged fields of a run.
struct AveragedFields {
  cg::PolarGrid polarGrid;
  cg::CartesianGrid cartesianGrid;
  CellFields polar, cartesian;
  WallFields wall;
  std::int64_t samples = 0;
  double averageStart = std::numeric_limits<double>::quiet_NaN();
  double averageEnd = std::numeric_limits<double>::quiet_NaN();
  double thickness = 0.0;         ///< slice thickness of the cell volumes (m)
  double minVolumeFraction = 0.0; ///< validity filter in use
  std::int64_t minParticleSamples = 0;
};

/// \brief Turns accumulated sums into fields (docs/averaged-fields.md): volume fraction = area /
/// cell area; velocity = momentum / mass; kinetic stress = (sum m v v - M u u) / (S V); contact
/// stress = -(virial sum) / (S V), compressive positive; total = kinetic + contact; strain rate
/// from the averaged velocities (StrainRateField.hpp); p, q, viscosity = q / gamma_dot,
/// m = q / p (NaN where not valid). V = cell area x thickness, S = samples. Throws
/// std::invalid_argument when the array sizes do not match the settings.
AveragedFields finalizeAverages(const AveragingSettings& settings, const AveragingSums& sums);

/// \brief Bed-averaged invariants over the valid cells of a grid (for convergence checks).
struct BedAverage {
  double pressure = std::numeric_limits<double>::quiet_NaN();    ///< mean p (Pa)
  double shearStress = std::numeric_limits<double>::quiet_NaN(); ///< mean q (Pa)
  double frictionM = std::numeric_limits<double>::quiet_NaN();   ///< mean q / mean p
  std::size_t validCells = 0;
};

/// \brief Means of p and q over the valid cells of `fields`, and their ratio.
BedAverage bedAverage(const CellFields& fields);

} // namespace hikiln::dem
