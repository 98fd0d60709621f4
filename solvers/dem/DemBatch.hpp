#pragma once
/// \file DemBatch.hpp
/// \brief Several independent DEM slices (the cases of a parameter study) advanced as one system:
/// one set of kernel launches per step over all their particles, so that tens of slices of a
/// few thousand particles fill a GPU (or amortise launch and thread start-up costs on a CPU)
/// where one slice cannot.
///
/// Each slice keeps its own drum, walls, coefficients and gravity (the force kernel reads them
/// per particle, SliceTable in ForceKernel.hpp) and never meets another slice: the cell grid has
/// one layer per slice (CellGrid.hpp). Positions are not shifted (a shift would change their
/// round-off), ids are offset per slice so that they stay unique and keep their order within a
/// slice, which is the order every particle sums its contact forces in. A slice's trajectory is
/// therefore bitwise the one its own DemSystem would follow (tests/dem/tstDemBatch.hpp): the
/// engine's results do not depend on rebuild and reorder times, thread counts or particle order.
///
/// All slices share the time step (a batch of slices with different steps could only run at the
/// smallest, and would no longer match the slices run alone: add() refuses it). Disc particles
/// only, without shell-attached particles or periodic boundaries (DemSystem::importSlices()).
///
/// Use: add() each slice's set-up system, start(), then advance() and exportSlices() (to sample,
/// checkpoint or continue a slice on its own DemSystem with importState()).

#include "solvers/dem/DemState.hpp"
#include "solvers/dem/DemSystem.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace hikiln::dem {

template <class ExecutionSpace> class DemBatch {
public:
  using system_type = DemSystem<ExecutionSpace>;

  explicit DemBatch(ExecutionSpace space = ExecutionSpace()) : _space(std::move(space)) {}

  /// \brief Adds a copy of a system's current state and settings as the next slice; returns its
  /// index. Throws std::invalid_argument for a system that cannot join (see the file comment).
  int add(const system_type& system) {
    if (_system) {
      throw std::logic_error("hikiln::dem::DemBatch: add() after start()");
    }
    const int k = static_cast<int>(_slices.size());
    const std::string who = "hikiln::dem::DemBatch: slice " + std::to_string(k);
    if (const std::string why = refusal(system); !why.empty()) {
      throw std::invalid_argument(who + " cannot be batched: " + why);
    }
    if (!_slices.empty() && system.timeStep() != _slices.front().settings.dt) {
      throw std::invalid_argument(who + " has the time step " + std::to_string(system.timeStep()) +
                                  " s, slice 0 " + std::to_string(_slices.front().settings.dt) +
                                  " s: the slices of a batch need the same time step");
    }
    Slice s{system.exportState(), system.forceSettings(), system.config(), system.skin(), 0};
    _slices.push_back(std::move(s));
    return k;
  }

  /// \brief Why a system cannot join a batch (empty: it can).
  static std::string refusal(const system_type& system) {
    if (system.size() == 0) {
      return "no particles";
    }
    if (system.blocky()) {
      return "blocky particles";
    }
    if (system.config().periodic.enabled) {
      return "a periodic boundary";
    }
    const auto kind =
        Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, system.particles().kind);
    for (std::size_t i = 0; i < system.size(); ++i) {
      if (kind(i) == static_cast<std::uint8_t>(ParticleKind::Shell)) {
        return "shell-attached particles (each slice's shell turns on its own)";
      }
    }
    return "";
  }

  /// \brief Builds the combined system from the slices added (their states as they were then).
  void start() {
    if (_slices.empty() || _system) {
      throw std::logic_error("hikiln::dem::DemBatch: start() needs slices, once");
    }
    DemState all;
    std::vector<ForceSettings> settings;
    std::int64_t nextId = 0;
    for (std::size_t k = 0; k < _slices.size(); ++k) {
      Slice& s = _slices[k];
      const auto [lo, hi] = std::minmax_element(s.state.id.begin(), s.state.id.end());
      _firstId.push_back(nextId); // the slice's ids [lo, hi] become [nextId, nextId + hi - lo]
      s.idOffset = nextId - *lo;
      nextId += *hi - *lo + 1;
      appendSlice(s, static_cast<int>(k), all);
      settings.push_back(s.settings);
    }
    DemConfig config = _slices.front().config;
    config.timeStep = _slices.front().settings.dt;
    for (const Slice& s : _slices) {
      config.neighborCapacity = std::max(config.neighborCapacity, s.config.neighborCapacity);
      config.skin = std::max(config.skin, s.skin);
    }
    _system = std::make_unique<system_type>(config, _space);
    _system->importSlices(all, settings);
  }

  /// \brief Advances every slice by `steps` time steps.
  void advance(std::int64_t steps) {
    requireStarted();
    _system->advance(steps);
    for (Slice& s : _slices) {
      s.state.step += steps;
      for (std::int64_t n = 0; n < steps; ++n) {
        s.state.time += s.settings.dt; // as each slice's own clock adds it up
      }
    }
  }

  /// \brief The current state of every slice, as its own DemSystem would export it (ids as added;
  /// particle order may differ).
  std::vector<DemState> exportSlices() const {
    requireStarted();
    const DemState all = _system->exportState();
    std::vector<DemState> out(_slices.size());
    for (std::size_t k = 0; k < _slices.size(); ++k) {
      out[k].step = _slices[k].state.step;
      out[k].time = _slices[k].state.time;
    }
    const std::size_t n = all.size();
    for (std::size_t i = 0; i < n; ++i) {
      const int k = all.slice[i];
      DemState& s = out[static_cast<std::size_t>(k)];
      s.id.push_back(all.id[i] - _slices[static_cast<std::size_t>(k)].idOffset);
      s.kind.push_back(all.kind[i]);
      for (int c = 0; c < 2; ++c) {
        s.position.push_back(all.position[2 * i + c]);
        s.velocity.push_back(all.velocity[2 * i + c]);
        s.force.push_back(all.force[2 * i + c]);
      }
      s.angularVelocity.push_back(all.angularVelocity[i]);
      s.torque.push_back(all.torque[i]);
      s.radius.push_back(all.radius[i]);
      s.mass.push_back(all.mass[i]);
      s.inertia.push_back(all.inertia[i]);
      for (int m = 0; m < wallSlotCount; ++m) {
        s.wallShear.push_back(all.wallShear[wallSlotCount * i + m]);
      }
    }
    for (std::size_t c = 0; c < all.contactId.size(); ++c) {
      const std::size_t k = sliceOfId(all.contactId[c]);
      const std::int64_t offset = _slices[k].idOffset;
      out[k].contactId.push_back(all.contactId[c] - offset);
      out[k].contactNeighborId.push_back(all.contactNeighborId[c] - offset);
      out[k].contactShear.push_back(all.contactShear[c]);
    }
    return out;
  }

  /// \brief Number of slices.
  int sliceCount() const { return static_cast<int>(_slices.size()); }
  /// \brief Particles over all slices.
  std::size_t size() const { return _system ? _system->size() : 0; }
  /// \brief The common time step (s).
  double timeStep() const { return _slices.empty() ? 0.0 : _slices.front().settings.dt; }
  /// \brief The combined system (after start()).
  const system_type& system() const {
    requireStarted();
    return *_system;
  }

private:
  struct Slice {
    DemState state; // as added; step and time then follow the batch
    ForceSettings settings;
    DemConfig config;
    double skin = 0.0;
    std::int64_t idOffset = 0; // batch id = slice id + idOffset
  };

  // Appends slice k's particles and history (ids offset) to the combined state.
  static void appendSlice(const Slice& s, int k, DemState& all) {
    const DemState& from = s.state;
    for (std::size_t i = 0; i < from.size(); ++i) {
      all.id.push_back(from.id[i] + s.idOffset);
      all.kind.push_back(from.kind.empty() ? std::uint8_t(0) : from.kind[i]);
      all.slice.push_back(k);
    }
    const auto append = [](std::vector<double>& to, const std::vector<double>& v) {
      to.insert(to.end(), v.begin(), v.end());
    };
    append(all.position, from.position);
    append(all.velocity, from.velocity);
    append(all.force, from.force);
    append(all.angularVelocity, from.angularVelocity);
    append(all.torque, from.torque);
    append(all.radius, from.radius);
    append(all.mass, from.mass);
    append(all.inertia, from.inertia);
    append(all.wallShear, from.wallShear);
    append(all.contactShear, from.contactShear);
    for (std::size_t c = 0; c < from.contactId.size(); ++c) {
      all.contactId.push_back(from.contactId[c] + s.idOffset);
      all.contactNeighborId.push_back(from.contactNeighborId[c] + s.idOffset);
    }
  }

  // The slice a batch id belongs to (slices hold consecutive id ranges).
  std::size_t sliceOfId(std::int64_t id) const {
    const auto it = std::upper_bound(_firstId.begin(), _firstId.end(), id);
    return static_cast<std::size_t>(it - _firstId.begin()) - 1;
  }

  void requireStarted() const {
    if (!_system) {
      throw std::logic_error("hikiln::dem::DemBatch: start() first");
    }
  }

  ExecutionSpace _space;
  std::vector<Slice> _slices;
  std::vector<std::int64_t> _firstId; // smallest batch id of each slice
  std::unique_ptr<system_type> _system;
};

} // namespace hikiln::dem
