#pragma once
/// \file DrumHeat.hpp
/// \brief The heat transfer of `hikiln dem` (physics.md 6.1, 6.2; docs/heat.md): a DemHeat that
/// starts with the rotation, stepped every heat.step_every mechanical steps, with its time series,
/// snapshot fields, checkpoint entries, summary and temperature maps.
///
/// - Schedule: heat steps fall on ABSOLUTE mechanical step counts divisible by step_every (the
///   first one covers the steps since the start), so a restart steps at the same counts with the
///   same lengths and continues bitwise.
/// - Measures (heat_timeseries.csv, summary.json) are host sums over the particles in id order
///   of their mean temperatures, so they are bitwise the same for any thread count or particle
///   order: heat energy E = sum m c T_i, drift (E - environment heat - E_0) / E_0, and the mixing
///   measure std(T_i) / std(T_i at the start) (unweighted over particles). Energy sums every
///   particle (glued shell discs exchange heat too); the mean, std, min and max describe the bed,
///   the free particles only. The bed counts as
///   thermally equilibrated at the first sample with mixing below heat.equilibrium_threshold.
/// - Temperatures written with a sample or snapshot are those of the last heat step (at most
///   step_every - 1 mechanical steps old).

#include "drivers/dem/HeatCase.hpp"
#include "drivers/dem/ParticleSnapshots.hpp"
#include "drivers/dem/TimeSeries.hpp"
#include "drivers/io/Checkpoint.hpp"
#include "solvers/dem/DemSystem.hpp"
#include "solvers/dem/heat/DemHeat.hpp"

#include <Kokkos_Core.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace hikiln::dem {

/// \brief Thermal measures of the bed at one sample (see the file comment).
struct BedHeatMeasures {
  double energy = 0.0;          ///< J
  double drift = 0.0;           ///< relative to the initial energy
  double environmentHeat = 0.0; ///< J received from the environment
  double meanTemperature = 0.0; ///< heat-capacity weighted (K)
  double stdTemperature = 0.0;  ///< of the particle mean temperatures (K)
  double mixing = std::numeric_limits<double>::quiet_NaN(); ///< std / initial std
  double minTemperature = 0.0, maxTemperature = 0.0;        ///< K
};

/// \brief Heat of one drum run (see the file comment); does nothing when heat is disabled.
class DrumHeat {
public:
  using Space = Kokkos::DefaultExecutionSpace;

  /// \brief Heat of a run with `settings`, writing into `outputDirectory`.
  DrumHeat(DrumHeatSettings settings, std::string outputDirectory);

  /// \brief Whether heat is on.
  bool enabled() const { return _settings.enabled; }
  /// \brief Names of the per-particle snapshot fields (empty when disabled).
  std::vector<std::string> snapshotFieldNames() const;

  /// \brief Starts the temperatures (heat.initial) on the system's particles now, and takes the
  /// first sample at rotation time `time`.
  void start(const DemSystem<Space>& system, double time);
  /// \brief Continues from a checkpoint (the system already imported it); keeps the time series
  /// up to the checkpoint's time. Throws when the checkpoint holds no heat state.
  void resume(const io::Checkpoint& checkpoint, const DemSystem<Space>& system);
  /// \brief Advances the system by `steps` mechanical steps with the heat steps due on the way.
  void advance(DemSystem<Space>& system, std::int64_t steps);
  /// \brief Adds a row to heat_timeseries.csv at rotation time `time`.
  void sample(const DemSystem<Space>& system, double time);
  /// \brief Mean temperature of each particle in the order of `particles` (K; empty when
  /// disabled).
  std::vector<double> meanTemperatures(const ParticleArrays<Kokkos::HostSpace>& particles) const;
  /// \brief Mean and surface-shell temperatures in the order of `particles`, for a snapshot.
  std::vector<ParticleField>
  snapshotFields(const ParticleArrays<Kokkos::HostSpace>& particles) const;
  /// \brief Stores the heat state and the measures' references in `checkpoint`.
  void save(io::Checkpoint& checkpoint) const;
  /// \brief Writes heat_timeseries.csv.
  void flush() const;
  /// \brief The `heat` section of summary.json (`{"enabled": false}` when disabled).
  nlohmann::json summary() const;
  /// \brief Draws the temperature maps and the mixing curve into `outputDirectory`/plots.
  bool plot(double drumRadius) const;

private:
  void capacities(const DemSystem<Space>& system);
  BedHeatMeasures measure() const;
  ParticleTemperatures inParticleOrder(const ParticleArrays<Kokkos::HostSpace>& particles) const;

  DrumHeatSettings _settings;
  std::string _directory;
  TimeSeries _series;
  std::unique_ptr<DemHeat<Space>> _heat;
  std::vector<std::int64_t> _ids; ///< particle ids, sorted
  std::vector<double> _capacity;  ///< m c of those particles (J/K)
  std::vector<char> _inBed;       ///< 1 for free particles (not glued/fixed), same order
  std::int64_t _lastHeatStep = 0; ///< mechanical step of the last heat step
  double _initialEnergy = 0.0;    ///< E_0 (host sum, J)
  double _initialStd = 0.0;       ///< std of the particle temperatures at the start (K)
  double _equilibriumTime = std::numeric_limits<double>::quiet_NaN(); ///< rotation time (s)
  double _maxDrift = 0.0;                                             ///< largest |drift| sampled
  double _wallSeconds = 0.0; ///< spent in heat steps (this process)
  BedHeatMeasures _last;
};

} // namespace hikiln::dem
