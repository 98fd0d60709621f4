#pragma once
/// \file AveragesFile.hpp
/// \brief Writes the averaged-field file averages.h5 (layout: docs/averaged-fields.md) and its
/// XDMF sidecar averages.xmf (the Cartesian fields, for ParaView).

#include "drivers/io/Hdf5File.hpp"
#include "solvers/dem/AveragedFields.hpp"

#include <string>

namespace hikiln::dem {

/// \brief Run conditions stored as root attributes of averages.h5.
struct AveragesConditions {
  double omega = 0.0;            ///< drum angular velocity (rad/s, counter-clockwise positive)
  double particleDiameter = 0.0; ///< mean particle diameter (m)
  double particleDensity = 0.0;  ///< kg/m3
  double fill = 0.0;             ///< measured fill fraction
};

/// \brief Writes `directory`/averages.h5 atomically (a reader never sees a partial file) and
/// `directory`/averages.xmf; returns the path of the .h5.
std::string writeAveragesFile(const std::string& directory, const AveragedFields& fields,
                              const AveragesConditions& conditions, const io::RunInfo& info);

} // namespace hikiln::dem
