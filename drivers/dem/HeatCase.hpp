#pragma once
/// \file HeatCase.hpp
/// \brief The `heat.*` keys of the `hikiln dem` case file (physics.md 6.1, 6.2) and the settings
/// read from them. The keys are added to the dem schema by DemCase.cpp.

#include "drivers/case/CaseFile.hpp"
#include "drivers/case/CaseSchema.hpp"
#include "kernels/dem/heat/HeatParameters.hpp"
#include "solvers/dem/DrumFill.hpp"
#include "solvers/dem/heat/InitialTemperature.hpp"

#include <array>
#include <cstdint>

namespace hikiln::dem {

/// \brief How the particle temperatures start when the drum starts rotating.
enum class InitialTemperatureKind { Uniform, LeftRight, Region };

/// \brief Heat settings of a drum run, in SI units (K for temperatures).
struct DrumHeatSettings {
  bool enabled = false;
  HeatParameters parameters;   ///< material, mechanisms, shells (geometry from the particles)
  std::int64_t stepEvery = 10; ///< heat step every this many mechanical steps
  double equilibriumThreshold = 0.05; ///< mixing measure below which the bed counts as mixed
  InitialTemperatureKind initial = InitialTemperatureKind::Uniform;
  double baseTemperature = 293.15;                       ///< uniform: everywhere; region: outside
  double leftTemperature = 673.0;                        ///< left_right: centres with x < splitX
  double rightTemperature = 1073.0;                      ///< left_right: the others
  double splitX = 0.0;                                   ///< m, left_right split (0: the drum axis)
  double insideTemperature = 1073.0;                     ///< region: centres inside the box
  std::array<double, 4> regionBox{{0.0, 0.0, 0.0, 0.0}}; ///< x_min, y_min, x_max, y_max (m)

  /// \brief The initial temperature field these settings describe.
  TemperatureField initialField() const;
};

/// \brief Adds the `heat.*` keys and their cross-key checks to the dem schema.
void addHeatKeys(cases::CaseSchema& schema);

/// \brief Heat settings of a validated case; the shell geometry follows the particles' mass
/// convention (sphere or disc of the given thickness).
DrumHeatSettings heatSettingsFromCase(const cases::CaseFile& file, const FillSpec& fill);

} // namespace hikiln::dem
