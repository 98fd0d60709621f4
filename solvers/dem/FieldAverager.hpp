#pragma once
/// \file FieldAverager.hpp
/// \brief Accumulates samples of a DEM drum slice into time-averaged continuum fields on a polar
/// and a Cartesian grid and in angular bins of the shell (physics.md 2). Sampling runs on the
/// system's execution space (kernels/dem/CoarseGrain*.hpp); finalisation is on the host
/// (AveragedFields.hpp).

#include "kernels/dem/CoarseGrainDeposit.hpp"
#include "kernels/dem/CoarseGrainGrid.hpp"
#include "kernels/dem/CoarseGrainShell.hpp"
#include "solvers/dem/AveragedFields.hpp"
#include "solvers/dem/DemSystem.hpp"
#include "solvers/dem/DrumAnalysis.hpp"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace hikiln::dem {

/// \brief Cumulative time averages of a drum slice: sample() adds the current state, sums() and
/// restore() carry the accumulators through checkpoints, result() finalises the fields.
template <class ExecutionSpace> class FieldAverager {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using sums_view = Kokkos::View<double**, memory_space>;

  /// \brief Zeroed accumulators for the grids of `settings` (validated).
  explicit FieldAverager(AveragingSettings settings, ExecutionSpace space = ExecutionSpace())
      : _settings(std::move(settings)), _space(std::move(space)) {
    _settings.validate();
    _polar = sums_view(Kokkos::view_alloc(_space, std::string("hikiln::dem::cg::polarSums")),
                       _settings.polarGrid().cellCount(), cg::CellSum::Size);
    _cartesian =
        sums_view(Kokkos::view_alloc(_space, std::string("hikiln::dem::cg::cartesianSums")),
                  _settings.cartesianGrid().cellCount(), cg::CellSum::Size);
    _wall = sums_view(Kokkos::view_alloc(_space, std::string("hikiln::dem::cg::wallSums")),
                      _settings.angularCells, cg::WallSum::Size);
  }

  /// \brief Adds the current state of `system` (positions, velocities and the contact forces of
  /// its last step) as one sample taken at `time` (the caller's clock, e.g. rotation time). The
  /// shell bins use the drum's current angular velocity for the sign of the shear; the wall slip
  /// of the sample is wallSlip() of the same particles.
  void sample(const DemSystem<ExecutionSpace>& system, double time) {
    const auto& p = system.particles();
    const ForceSettings& f = system.forceSettings();
    // blocky particles bring their own contact virials and areas (empty Views for discs)
    Kokkos::View<double* [4], typename ExecutionSpace::memory_space> virial;
    if (system.blocky()) {
      virial = system.contactVirial();
    }
    const auto area = system.particleAreas();
    cg::depositCells(_space, _settings.polarGrid(), p, system.neighborList(), system.wallContacts(),
                     f.walls, f.periodic, _polar, virial, area);
    cg::depositCells(_space, _settings.cartesianGrid(), p, system.neighborList(),
                     system.wallContacts(), f.walls, f.periodic, _cartesian, virial, area);
    const double omega = f.walls.drum.angularVelocity;
    const auto host = system.hostParticles();
    cg::ShellBins bins;
    bins.radius = shellInnerRadius(host, _settings.drumRadius); // a rough shell's bump tops
    bins.ntheta = _settings.angularCells;
    bins.touchGap = _settings.touchGap;
    bins.shearSign = cg::shellMotionSign(omega);
    cg::depositShell(_space, bins, p, system.wallContacts(), _wall);
    _space.fence();
    const double slip = wallSlip(host, _settings.drumRadius, omega, _settings.touchGap);
    if (std::isfinite(slip)) {
      _slipSum += slip;
      ++_slipSamples;
    }
    if (_samples == 0) {
      _firstTime = time;
    }
    _lastTime = time;
    ++_samples;
  }

  /// \brief Number of samples so far.
  std::int64_t samples() const { return _samples; }
  /// \brief The settings in use.
  const AveragingSettings& settings() const { return _settings; }

  /// \brief Host copy of everything accumulated.
  AveragingSums sums() const {
    AveragingSums s;
    s.polar = toHost(_polar);
    s.cartesian = toHost(_cartesian);
    s.wall = toHost(_wall);
    s.samples = _samples;
    s.slipSum = _slipSum;
    s.slipSamples = _slipSamples;
    s.firstTime = _firstTime;
    s.lastTime = _lastTime;
    return s;
  }

  /// \brief Replaces the accumulators by `s` (from sums(), e.g. through a checkpoint); throws
  /// std::invalid_argument when its sizes do not fit the grids.
  void restore(const AveragingSums& s) {
    fromHost(s.polar, _polar, "polar");
    fromHost(s.cartesian, _cartesian, "Cartesian");
    fromHost(s.wall, _wall, "shell");
    _samples = s.samples;
    _slipSum = s.slipSum;
    _slipSamples = s.slipSamples;
    _firstTime = s.firstTime;
    _lastTime = s.lastTime;
  }

  /// \brief The finalised fields of everything accumulated so far.
  AveragedFields result() const { return finalizeAverages(_settings, sums()); }

private:
  std::vector<double> toHost(const sums_view& v) const {
    const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, v);
    std::vector<double> out(v.extent(0) * v.extent(1));
    for (std::size_t i = 0; i < v.extent(0); ++i) {
      for (std::size_t k = 0; k < v.extent(1); ++k) {
        out[i * v.extent(1) + k] = h(i, k);
      }
    }
    return out;
  }

  void fromHost(const std::vector<double>& values, const sums_view& v, const char* what) {
    if (values.size() != v.extent(0) * v.extent(1)) {
      throw std::invalid_argument(std::string("hikiln::dem::FieldAverager: restored ") + what +
                                  " sums have " + std::to_string(values.size()) +
                                  " values, the grid needs " +
                                  std::to_string(v.extent(0) * v.extent(1)));
    }
    auto h = Kokkos::create_mirror_view(v);
    for (std::size_t i = 0; i < v.extent(0); ++i) {
      for (std::size_t k = 0; k < v.extent(1); ++k) {
        h(i, k) = values[i * v.extent(1) + k];
      }
    }
    Kokkos::deep_copy(v, h);
  }

  AveragingSettings _settings;
  ExecutionSpace _space;
  sums_view _polar, _cartesian, _wall;
  std::int64_t _samples = 0;
  double _slipSum = 0.0;
  std::int64_t _slipSamples = 0;
  double _firstTime = std::numeric_limits<double>::quiet_NaN();
  double _lastTime = std::numeric_limits<double>::quiet_NaN();
};

} // namespace hikiln::dem
