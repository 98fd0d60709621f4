#pragma once
/// \file DemHeat.hpp
/// \brief Host-side owner of the thermal state of a 2D DEM run (physics.md 6.1), driven by the
/// caller after the mechanical steps.
///
/// Design
/// - Model: N radial shells per particle (ShellModel.hpp), contact conduction through per-contact
///   boundary layers (ContactConduction.hpp), radiation to neighbours and optionally to a fixed
///   environment (Radiation.hpp). Heat capacity of a particle = its DEM mass x c, so the shells'
///   density is mass / volume of the chosen geometry.
/// - Use: `heat.initialize(system, field)` once the system has its particles, then
///   `heat.step(system, dt)` after every mechanical step (dt = system.timeStep()) or after every
///   k steps (dt = k x the mechanical step: contacts are then sampled every k steps). A step
///   splits dt into equal sub-steps no longer than timeStepSafety x the explicit limit
///   (stableHeatTimeStep(), computed at initialisation from the particles).
/// - The DEM system is read, never modified: positions, radii, masses, ids and its neighbour
///   rows (count and index only). The per-slot layer state is kept in this class, aligned with the
///   list: when the system's rebuildCount() or sortCount() changed since the last heat step, the
///   state is carried over (rows matched by particle id after a reorder, slots by neighbour id).
///   After setParticles()/importState() on the system, initialise or import the heat again.
/// - Conservation: every transfer between particles (contact, radiation) is computed once per
///   pair from the lower-id side and applied with opposite signs; intra-particle face fluxes
///   likewise; layers exchange capacity with their bulk by conservative mixing. energy() is
///   constant to round-off; heat from the environment (off by default) is summed apart.
/// - Determinism: each particle sums its fluxes in neighbour-row order and writes only its own
///   rows, so temperatures are bitwise identical for any thread count and any reorder schedule.
///   Radiation with a range > 0 takes the pairs the list holds within that gap; the list holds
///   every pair closer than skin - (displacements since its build), so pairs with a gap in
///   (0, skin) can depend on when the list was rebuilt (radiationRange 0: touching pairs only,
///   schedule independent).
/// - Shell count: the centre temperature of a particle with a convective surface (Bi = 1) at
///   Fo = 0.05, 0.2, 0.5, 1 (validation.md) converges at second order (tstHeatConduction.hpp);
///   the error (theta units) is 2.1e-2 / 5.7e-3 / 1.4e-3 / 3.6e-4 for spheres and 1.4e-2 /
///   3.1e-3 / 8.2e-4 / 2.1e-4 for discs at 2 / 4 / 8 / 16 shells: 8 shells by default.
/// - Cost (1714 particles, base drum, one core): a heat step with contact conduction costs about
///   4-5 mechanical steps (a Hertz area and a 2x2 layer solve per contact side), without it
///   about 1; stepping heat every 10 mechanical steps adds ~45 % (~5-20 % without contact
///   conduction). Contacts are then sampled every 10 steps: fine for the enduring contacts of a
///   slowly rotating bed.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/heat/HeatArrays.hpp"
#include "kernels/dem/heat/HeatCarryOver.hpp"
#include "kernels/dem/heat/HeatDiagnostics.hpp"
#include "kernels/dem/heat/HeatKernel.hpp"
#include "kernels/dem/heat/HeatParameters.hpp"
#include "kernels/dem/heat/ShellModel.hpp"
#include "solvers/dem/DemSystem.hpp"
#include "solvers/dem/heat/DemHeatState.hpp"
#include "solvers/dem/heat/InitialTemperature.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace hikiln::dem {

namespace detail {

/// \brief Whether a DEM system offers neighborRows(), the list as the step uses it.
template <class System, class = void> struct HasNeighborRows : std::false_type {};
template <class System>
struct HasNeighborRows<System, std::void_t<decltype(std::declval<const System&>().neighborRows())>>
    : std::true_type {};

/// \brief The system's neighbour rows (count, index; rows sorted by neighbour id). Systems
/// with neighborRows() publish extra views through neighborList() at the price of a force
/// evaluation, so the rows are taken from neighborRows() when it exists.
template <class System> decltype(auto) neighborRows(const System& system) {
  if constexpr (HasNeighborRows<System>::value) {
    return system.neighborRows();
  } else {
    return system.neighborList();
  }
}

} // namespace detail

/// \brief Per-particle temperatures on the host, in the particle order of the last heat step.
struct ParticleTemperatures {
  std::vector<std::int64_t> id;
  std::vector<double> mean;    ///< heat content / (m c) (K)
  std::vector<double> surface; ///< outer-shell bulk temperature (K)
  std::vector<double> centre;  ///< innermost shell (K)
};

/// \brief Thermal state of the particles of a DemSystem<ExecutionSpace> (see the file comment).
template <class ExecutionSpace> class DemHeat {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using system_type = DemSystem<ExecutionSpace>;

  /// \brief A heat model with the given parameters (validated at initialisation).
  explicit DemHeat(HeatParameters parameters) : _parameters(std::move(parameters)) {}

  // Views are shared handles: a copy would alias the state.
  DemHeat(const DemHeat&) = delete;
  DemHeat& operator=(const DemHeat&) = delete;
  DemHeat(DemHeat&&) = default;
  DemHeat& operator=(DemHeat&&) = default;
  ~DemHeat() = default;

  /// \brief Attaches to the system's current particles with every particle (all shells) at
  /// field(x, y, id); no contact layers yet; resets the clock and the energy reference.
  void initialize(const system_type& system, const TemperatureField& field) {
    const auto host = system.hostParticles();
    const std::size_t n = host.count();
    const int ns = _parameters.shells;
    std::vector<double> rows(n * static_cast<std::size_t>(std::max(ns, 1)));
    for (std::size_t i = 0; i < n; ++i) {
      const double t = field(host.position(i, 0), host.position(i, 1), host.id(i));
      requireTemperature(t);
      std::fill(rows.begin() + i * ns, rows.begin() + (i + 1) * ns, t);
    }
    attach(system, rows, std::vector<double>(n, 0.0));
    _time = 0.0;
    _subSteps = 0;
    _initialEnergy = energy();
  }

  /// \brief Advances the temperatures by dt (s) at the system's current configuration, in
  /// ceil(dt / stableTimeStep()) equal sub-steps.
  void step(const system_type& system, double dt) {
    requireReady();
    if (!(dt >= 0.0) || !std::isfinite(dt)) {
      throw std::invalid_argument("hikiln::dem::DemHeat: step length must be finite and >= 0");
    }
    if (dt == 0.0) {
      return;
    }
    synchronize(system);
    const auto subSteps =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(dt / _stableTimeStep)));
    const double h = dt / static_cast<double>(subSteps);
    const auto& p = system.particles();
    const auto& list = detail::neighborRows(system);
    const PeriodicX periodic = system.forceSettings().periodic;
    for (std::int64_t s = 0; s < subSteps; ++s) {
      heatSubStep(_space, p, list, _model, _coefficients, periodic, h, _state, _temperatureNext,
                  _slots);
      std::swap(_state.temperature, _temperatureNext);
    }
    _time += dt;
    _subSteps += subSteps;
  }

  /// \brief Heat content of the particles (J, relative to 0 K), layers included.
  double energy() const {
    requireReady();
    return heatContent(_space, _radius, _mass, _n, _state, _slots, _coefficients);
  }
  /// \brief Heat received from the environment since initialisation (J; 0 unless
  /// environmentExchange).
  double environmentHeat() const {
    requireReady();
    return environmentHeatTotal(_space, _state, _n);
  }
  /// \brief Heat content at initialisation (J).
  double initialEnergy() const { return _initialEnergy; }
  /// \brief (energy - environment heat - initial energy) / initial energy: round-off only.
  double energyDrift() const {
    return (energy() - environmentHeat() - _initialEnergy) / _initialEnergy;
  }
  /// \brief Heat-capacity weighted mean temperature of all particles (K).
  double meanTemperature() const { return energy() / _totalCapacity; }

  /// \brief Mean temperature of each particle (device View, rows in the order of the last heat
  /// step, which is the system's order when called right after step()).
  Kokkos::View<double*, memory_space> particleTemperatures() const {
    requireReady();
    Kokkos::View<double*, memory_space> out(
        Kokkos::view_alloc(_space, Kokkos::WithoutInitializing,
                           std::string("hikiln::dem::heat::particleTemperature")),
        _n);
    particleMeanTemperature(_space, _radius, _mass, _n, _state, _slots, _coefficients, out);
    return out;
  }

  /// \brief Ids with mean, surface and centre temperatures on the host (for output).
  ParticleTemperatures hostTemperatures() const {
    const auto mean =
        Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, particleTemperatures());
    const auto t = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _state.temperature);
    const auto ids = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _ids);
    ParticleTemperatures out;
    const int ns = _coefficients.shells;
    for (std::size_t i = 0; i < _n; ++i) {
      out.id.push_back(ids(i));
      out.mean.push_back(mean(i));
      out.surface.push_back(t(i, ns - 1));
      out.centre.push_back(t(i, 0));
    }
    return out;
  }

  /// \brief Copies the thermal state to the host, keyed by particle id.
  DemHeatState exportState() const {
    requireReady();
    _space.fence();
    const auto ids = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _ids);
    const auto t = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _state.temperature);
    const auto env =
        Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _state.environmentHeat);
    const auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.count);
    const auto nid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.neighborId);
    const auto area = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.area);
    const auto self = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.layerSelf);
    const auto other = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.layerOther);
    DemHeatState s;
    s.shells = _coefficients.shells;
    s.time = _time;
    s.subSteps = _subSteps;
    s.initialEnergy = _initialEnergy;
    s.stableTimeStep = _stableTimeStep;
    for (std::size_t i = 0; i < _n; ++i) {
      s.id.push_back(ids(i));
      for (int m = 0; m < s.shells; ++m) {
        s.temperature.push_back(t(i, m));
      }
      s.environmentHeat.push_back(env(i));
      for (int k = 0; k < std::min(count(i), _slots.capacity()); ++k) {
        if (area(i, k) != 0.0) {
          s.contactId.push_back(ids(i));
          s.contactNeighborId.push_back(nid(i, k));
          s.contactArea.push_back(area(i, k));
          s.contactLayer.push_back(self(i, k));
          s.contactLayerOther.push_back(other(i, k));
        }
      }
    }
    return s;
  }

  /// \brief Attaches to the system's current particles with an exported state (same particle
  /// ids, same shell count); continues the clock, the energy reference and the sub-step limit.
  void importState(const system_type& system, const DemHeatState& s) {
    const auto bad = [](const std::string& what) {
      throw std::invalid_argument("hikiln::dem::DemHeatState: " + what);
    };
    const std::size_t n = s.size();
    if (s.shells != _parameters.shells) {
      bad("shell count " + std::to_string(s.shells) + " differs from the parameters' " +
          std::to_string(_parameters.shells));
    }
    if (s.temperature.size() != n * static_cast<std::size_t>(s.shells) ||
        s.environmentHeat.size() != n || s.contactNeighborId.size() != s.contactId.size() ||
        s.contactArea.size() != s.contactId.size() || s.contactLayer.size() != s.contactId.size() ||
        s.contactLayerOther.size() != s.contactId.size()) {
      bad("inconsistent array sizes");
    }
    const auto host = system.hostParticles();
    if (host.count() != n) {
      bad("the system has " + std::to_string(host.count()) + " particles, the state " +
          std::to_string(n));
    }
    std::map<std::int64_t, std::size_t> rowOf;
    for (std::size_t r = 0; r < n; ++r) {
      rowOf[s.id[r]] = r;
    }
    const int ns = s.shells;
    std::vector<double> rows(n * ns), env(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto it = rowOf.find(host.id(i));
      if (it == rowOf.end()) {
        bad("particle " + std::to_string(host.id(i)) + " of the system is not in the state");
      }
      for (int m = 0; m < ns; ++m) {
        rows[i * ns + m] = s.temperature[it->second * ns + m];
        requireTemperature(rows[i * ns + m]);
      }
      env[i] = s.environmentHeat[it->second];
    }
    std::map<std::pair<std::int64_t, std::int64_t>, std::size_t> contactOf;
    for (std::size_t c = 0; c < s.contactId.size(); ++c) {
      contactOf[{s.contactId[c], s.contactNeighborId[c]}] = c;
    }
    attach(system, rows, env);
    // layers of the touching pairs into the (now aligned) slots
    auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.count);
    auto nid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.neighborId);
    auto area = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.area);
    auto self = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.layerSelf);
    auto other = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slots.layerOther);
    std::size_t matched = 0;
    for (std::size_t i = 0; i < n; ++i) {
      for (int k = 0; k < std::min(count(i), _slots.capacity()); ++k) {
        const auto it = contactOf.find({host.id(i), nid(i, k)});
        if (it != contactOf.end()) {
          area(i, k) = s.contactArea[it->second];
          self(i, k) = s.contactLayer[it->second];
          other(i, k) = s.contactLayerOther[it->second];
          requireTemperature(self(i, k));
          requireTemperature(other(i, k));
          ++matched;
        }
      }
    }
    if (matched != s.contactId.size()) {
      bad(std::to_string(s.contactId.size() - matched) +
          " contact layers name pairs the system's neighbour list does not hold");
    }
    Kokkos::deep_copy(_space, _slots.area, area);
    Kokkos::deep_copy(_space, _slots.layerSelf, self);
    Kokkos::deep_copy(_space, _slots.layerOther, other);
    _space.fence();
    _time = s.time;
    _subSteps = s.subSteps;
    _initialEnergy = s.initialEnergy;
    if (s.stableTimeStep > 0.0) {
      _stableTimeStep = s.stableTimeStep; // sub-steps as before the restart
    }
  }

  /// \brief Shell temperatures (n x shells, K; rows in the order of the last heat step).
  Kokkos::View<double**, memory_space> shellTemperatures() const { return _state.temperature; }
  /// \brief Boundary-layer state per neighbour slot.
  const HeatSlots<memory_space>& slots() const { return _slots; }
  /// \brief The heat sub-step limit in use (s): safety x the explicit stability limit.
  double stableTimeStep() const { return _stableTimeStep; }
  /// \brief Heat time advanced since initialisation (s).
  double time() const { return _time; }
  /// \brief Heat sub-steps taken since initialisation.
  std::int64_t subStepCount() const { return _subSteps; }
  /// \brief Number of particles.
  std::size_t size() const { return _n; }
  /// \brief The parameters.
  const HeatParameters& parameters() const { return _parameters; }
  /// \brief The kernel coefficients in use (radiation range resolved against the skin).
  const HeatCoefficients& coefficients() const { return _coefficients; }

private:
  void requireReady() const {
    if (!_ready) {
      throw std::logic_error("hikiln::dem::DemHeat: not initialised");
    }
  }

  static void requireTemperature(double t) {
    if (!(t > 0.0) || !std::isfinite(t)) {
      throw std::invalid_argument("hikiln::dem::DemHeat: temperatures must be finite and > 0 K");
    }
  }

  // Allocates the state for the system's particles with the given shell temperatures
  // (particle-major, system order) and environment heat; empty layers aligned with its list.
  void attach(const system_type& system, const std::vector<double>& rows,
              const std::vector<double>& env) {
    _space = system.executionSpace();
    _coefficients = prepareHeat(_parameters, system.forceSettings().particle.kn, system.skin());
    const auto host = system.hostParticles();
    _n = host.count();
    const int ns = _coefficients.shells;
    const int capacity = detail::neighborRows(system).capacity();
    const std::size_t rowsAlloc = std::max<std::size_t>(_n, 1);
    _state = HeatParticles<memory_space>(rowsAlloc, ns, _space);
    _spare = HeatParticles<memory_space>(rowsAlloc, ns, _space);
    _temperatureNext = Kokkos::View<double**, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::heat::temperatureNext")), rowsAlloc,
        ns);
    _slots = HeatSlots<memory_space>(rowsAlloc, capacity, _space);
    _spareSlots = HeatSlots<memory_space>(rowsAlloc, capacity, _space);
    _origin = Kokkos::View<int*, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::heat::origin")), rowsAlloc);
    _ids = Kokkos::View<std::int64_t*, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::heat::ids")), rowsAlloc);
    _radius = Kokkos::View<double*, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::heat::radius")), rowsAlloc);
    _mass = Kokkos::View<double*, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::heat::mass")), rowsAlloc);
    _model = makeHeatModelViews<memory_space>(_space, _coefficients, rowsAlloc);
    auto t = Kokkos::create_mirror_view(Kokkos::HostSpace{}, _spare.temperature);
    auto q = Kokkos::create_mirror_view(Kokkos::HostSpace{}, _spare.environmentHeat);
    double temperatureMax =
        _coefficients.environmentExchange ? _coefficients.environmentTemperature : 0.0;
    _totalCapacity = 0.0;
    _stableTimeStep = 1.0e300;
    for (std::size_t i = 0; i < _n; ++i) {
      for (int m = 0; m < ns; ++m) {
        t(i, m) = rows[i * ns + m];
        temperatureMax = std::max(temperatureMax, t(i, m));
      }
      q(i) = env[i];
      _totalCapacity += host.mass(i) * _coefficients.specificHeat;
    }
    for (std::size_t i = 0; i < _n; ++i) {
      _stableTimeStep =
          std::min(_stableTimeStep, stableHeatTimeStep(_coefficients, host.radius(i), host.mass(i),
                                                       capacity, temperatureMax));
    }
    if (!(_stableTimeStep > 0.0)) {
      throw std::invalid_argument(
          "hikiln::dem::HeatParameters: contact layers could exceed a particle's outer shell "
          "(lower maxContactAreaFraction or use more shells)");
    }
    _stableTimeStep *= _parameters.timeStepSafety;
    Kokkos::deep_copy(_space, _spare.temperature, t);
    Kokkos::deep_copy(_space, _spare.environmentHeat, q);
    // slots of the current list, all without layers: carry over from empty rows
    const auto& p = system.particles();
    carryHeatState(_space, p, detail::neighborRows(system), _coefficients,
                   Kokkos::View<int*, memory_space>(), _spare, _spareSlots, _state, _slots);
    copyParticleRows(p);
    _seenRebuild = system.rebuildCount();
    _seenSort = system.sortCount();
    _space.fence();
    _ready = true;
  }

  void copyParticleRows(const typename system_type::particles_type& p) {
    const auto live = Kokkos::make_pair(std::size_t(0), _n);
    Kokkos::deep_copy(_space, Kokkos::subview(_ids, live), Kokkos::subview(p.id, live));
    Kokkos::deep_copy(_space, Kokkos::subview(_radius, live), Kokkos::subview(p.radius, live));
    Kokkos::deep_copy(_space, Kokkos::subview(_mass, live), Kokkos::subview(p.mass, live));
    computeParticleHeat(_space, _radius, _mass, _n, _coefficients, _model.particle);
  }

  // Carries the state over when the system rebuilt its list or reordered its particles.
  void synchronize(const system_type& system) {
    if (system.size() != _n) {
      throw std::logic_error("hikiln::dem::DemHeat: the system's particle count changed; "
                             "initialise the heat model again");
    }
    const bool sorted = system.sortCount() != _seenSort;
    if (!sorted && system.rebuildCount() == _seenRebuild) {
      return;
    }
    const auto& p = system.particles();
    const auto& list = detail::neighborRows(system);
    if (_spareSlots.capacity() != list.capacity()) {
      _spareSlots = HeatSlots<memory_space>(_slots.rows(), list.capacity(), _space);
    }
    Kokkos::View<int*, memory_space> origin;
    if (sorted) {
      matchRowsById(_space, _ids, p.id, _n, _origin);
      origin = _origin;
    }
    carryHeatState(_space, p, list, _coefficients, origin, _state, _slots, _spare, _spareSlots);
    std::swap(_state, _spare);
    std::swap(_slots, _spareSlots);
    if (sorted) {
      copyParticleRows(p);
    }
    _seenRebuild = system.rebuildCount();
    _seenSort = system.sortCount();
  }

  HeatParameters _parameters;
  HeatCoefficients _coefficients;
  ExecutionSpace _space;
  HeatParticles<memory_space> _state;
  HeatParticles<memory_space> _spare;
  Kokkos::View<double**, memory_space> _temperatureNext;
  HeatSlots<memory_space> _slots;
  HeatSlots<memory_space> _spareSlots;
  Kokkos::View<int*, memory_space> _origin;
  Kokkos::View<std::int64_t*, memory_space> _ids;
  Kokkos::View<double*, memory_space> _radius;
  Kokkos::View<double*, memory_space> _mass;
  HeatModelViews<memory_space> _model;
  std::size_t _n = 0;
  double _stableTimeStep = 0.0;
  double _totalCapacity = 0.0;
  double _initialEnergy = 0.0;
  double _time = 0.0;
  std::int64_t _subSteps = 0;
  std::int64_t _seenRebuild = -1;
  std::int64_t _seenSort = -1;
  bool _ready = false;
};

} // namespace hikiln::dem
