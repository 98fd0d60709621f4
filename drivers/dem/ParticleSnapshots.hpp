#pragma once
/// \file ParticleSnapshots.hpp
/// \brief Particle snapshots of a DEM run: one HDF5 file per snapshot (written atomically, so a
/// killed run keeps every finished snapshot) and one XDMF series `particles.xmf` for ParaView.

#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Xdmf.hpp"
#include "kernels/dem/BlockyArrays.hpp"
#include "kernels/dem/ParticleArrays.hpp"

#include <string>
#include <vector>

namespace hikiln::dem {

/// \brief An extra per-particle scalar of a snapshot (e.g. a temperature), one value per particle
/// in the order of the particle arrays written with it.
struct ParticleField {
  std::string name; ///< dataset and ParaView name
  std::string unit;
  std::vector<double> values;
};

/// \brief Shape fields of blocky particles, in the order of `shapes`: orientation (rad, body x axis
/// from x), semi_axis_a, semi_axis_b (m) and blockiness (N); none for discs (capacity 0). With
/// position they let ParaView draw each outline (e.g. a glyph scaled by the semi-axes, turned by
/// the orientation).
std::vector<ParticleField> shapeFields(const BlockyArrays<Kokkos::HostSpace>& shapes,
                                       std::size_t count);

/// \brief Names of the fields shapeFields() writes for blocky particles.
std::vector<std::string> shapeFieldNames();

/// \brief Writes snapshots into DIR/snapshots/ and keeps DIR/particles.xmf listing them.
class ParticleSnapshots {
public:
  /// \brief Snapshots of a run in `directory`; existing snapshots later than `keepUntil` (a restart
  /// time) are dropped from the series, earlier ones are kept (with those of `extraFields` they
  /// hold).
  ParticleSnapshots(std::string directory, io::RunInfo info, double keepUntil = -1.0,
                    const std::vector<std::string>& extraFields = {});

  /// \brief Writes one snapshot (position, velocity, angular velocity, radius, id and `extra`) and
  /// the series.
  void write(std::int64_t step, double time, const ParticleArrays<Kokkos::HostSpace>& particles,
             const std::vector<ParticleField>& extra = {});

  /// \brief Number of snapshots in the series.
  std::size_t size() const { return _steps.size(); }

private:
  std::string _directory;
  io::RunInfo _info;
  std::vector<io::XdmfParticleStep> _steps;
};

} // namespace hikiln::dem
