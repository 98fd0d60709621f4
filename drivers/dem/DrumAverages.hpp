#pragma once
/// \file DrumAverages.hpp
/// \brief The averaged fields of `hikiln dem` (physics.md 2): sampling during rotation, periodic
/// writes of the cumulative averages.h5 with a convergence log, checkpointing of the sums, the
/// `averages` section of summary.json and the PNG maps.

#include "drivers/dem/DemCase.hpp"
#include "drivers/io/Checkpoint.hpp"
#include "drivers/io/Hdf5File.hpp"
#include "solvers/dem/FieldAverager.hpp"

#include <Kokkos_Core.hpp>
#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

namespace hikiln::dem {

/// \brief One write of the cumulative averages: bed-averaged invariants over the valid Cartesian
/// cells, and their relative change since the previous write (NaN for the first).
struct AveragesConvergence {
  double time = 0.0;
  std::int64_t samples = 0;
  double pressure = 0.0, shearStress = 0.0, frictionM = 0.0, muWall = 0.0;
  double pressureChange = 0.0, shearStressChange = 0.0, frictionMChange = 0.0;
};

/// \brief Averaged fields of one drum run (see the file comment).
class DrumAverages {
public:
  using Space = Kokkos::DefaultExecutionSpace;

  /// \brief Averages for the run `settings`, written into `outputDirectory`.
  DrumAverages(const DrumRunSettings& settings, std::string outputDirectory, io::RunInfo info);

  /// \brief Starts empty averages for the settled bed: its mean particle diameter is the slice
  /// thickness of the sphere convention; `fill` is the measured fill.
  void start(const ParticleArrays<Kokkos::HostSpace>& bed, double fill);
  /// \brief Continues the averages saved in `checkpoint` (start() with `bed` if it has none).
  void resume(const io::Checkpoint& checkpoint, const ParticleArrays<Kokkos::HostSpace>& bed,
              double fill);

  /// \brief Adds the current state as one sample at rotation time `time`.
  void sample(const DemSystem<Space>& system, double time);
  /// \brief Adds the particles' temperatures (K, in the order of `particles`) to the
  /// mass-weighted cell temperatures (with each sample() of a heated run).
  void sampleTemperature(const ParticleArrays<Kokkos::HostSpace>& particles,
                         const std::vector<double>& temperature);
  /// \brief Writes averages.h5 / averages.xmf with everything so far and logs the convergence
  /// (nothing without samples).
  void write(double time);
  /// \brief Stores the sums and the convergence history in `checkpoint`.
  void save(io::Checkpoint& checkpoint) const;
  /// \brief The `averages` section of summary.json.
  nlohmann::json summary() const;
  /// \brief Draws the PNG maps of averages.h5 into `outputDirectory`/plots (warns if it cannot).
  bool plot() const;

private:
  void create(double thickness, double meanDiameter, double fill);

  DrumRunSettings _run;
  std::string _directory;
  io::RunInfo _info;
  double _meanDiameter = 0.0, _fill = 0.0;
  std::unique_ptr<FieldAverager<Space>> _averager;
  std::vector<AveragesConvergence> _history;
  AveragedFields _last; ///< fields of the last write
  /// Cells x {sum m, sum m T} of the polar and the Cartesian grid (empty until a temperature
  /// sample).
  std::vector<double> _temperaturePolar, _temperatureCartesian;
  bool _written = false;
};

} // namespace hikiln::dem
