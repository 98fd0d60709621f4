#pragma once
/// \file DemSystem.hpp
/// \brief Host-side owner of a 2D DEM run: particles, neighbour list, walls, parameters, clock.
///
/// Design
/// - Step (velocity Verlet, LAMMPS nve/sphere order), two launches without a rebuild:
///   1. initialIntegrate: v += dt/2 F/m, omega += dt/2 T/I, x += dt v, and a max-reduction of the
///      displacement since the last list build;
///   2. if that exceeds skin/2 (or a rebuild was asked for): rebuild the neighbour list;
///   3. computeForcesAndKick: contact + wall + gravity forces at the new positions with the
///      half-step velocities, fused with the second half kick. Neighbours' velocities are read
///      while a particle's own is updated, so the kick writes a second velocity buffer and the
///      two are swapped afterwards.
///   Between steps the state is x^n, v^n, omega^n, F^n, T^n (what diagnostics and exports see).
/// - Neighbour list: a uniform cell grid (cell >= largest diameter + skin) over the particle
///   bounds; a FULL list with fixed-capacity rows (overflow is an exception, never silent); each
///   row is sorted by neighbour id.
/// - History: one tangential displacement per row slot (and one per particle and wall). The two
///   copies of a pair's history evolve identically because every pair quantity is computed so
///   that it is bitwise the same from both sides. A rebuild carries each slot's history over by
///   neighbour id; a reorder (sortByCell, every sortEveryRebuilds rebuilds) permutes particles and
///   history rows together and then rebuilds.
/// - Determinism: each particle sums its own force in id order and writes only its own data, so
///   results are bitwise identical for any thread count, and independent of when rebuilds and
///   reorders happen (non-touching slots contribute nothing). Hence exportState()/importState()
///   continue bitwise identically even though the imported system rebuilds its list at once.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/CellGrid.hpp"
#include "kernels/dem/ContactLaw.hpp"
#include "kernels/dem/Diagnostics.hpp"
#include "kernels/dem/ForceKernel.hpp"
#include "kernels/dem/Integrator.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Periodic.hpp"
#include "kernels/dem/Reorder.hpp"
#include "kernels/dem/TimeStep.hpp"
#include "kernels/dem/Walls.hpp"
#include "solvers/dem/DemState.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hikiln::dem {

/// \brief Parameters of a DEM system. Defaults: physics.md base-case springs and friction, e = 0.5,
/// gravity 9.81 m/s^2 in -y (as the LAMMPS reference), dt from the contact time.
struct DemConfig {
  ContactParameters particleContact; ///< particle-particle law
  ContactParameters wallContact;     ///< particle-wall law
  double timeStep = 0.0;             ///< s; <= 0: recommendedTimeStep() times timeStepSafety
  double timeStepSafety = defaultTimeStepSafety;
  double gravityX = 0.0;
  double gravityY = -9.81;
  double skin = 0.0;          ///< neighbour skin (m); <= 0: 0.2 x the largest diameter
  int neighborCapacity = 12;  ///< slots per particle in the neighbour list
  int sortEveryRebuilds = 10; ///< reorder particles by cell every N rebuilds (0: only on request)
  WallSet walls;
  PeriodicX periodic;
};

/// \brief A 2D DEM system advanced on ExecutionSpace (see the file comment for the algorithm).
template <class ExecutionSpace> class DemSystem {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using particles_type = ParticleArrays<memory_space>;
  using host_particles_type = ParticleArrays<Kokkos::HostSpace>;

  /// \brief A system with no particles yet; validates the configuration.
  explicit DemSystem(DemConfig config, ExecutionSpace space = ExecutionSpace())
      : _config(std::move(config)), _space(std::move(space)) {
    if (_config.neighborCapacity < 1) {
      throw std::invalid_argument("hikiln::dem::DemConfig: neighborCapacity must be >= 1");
    }
    if (_config.walls.drum.enabled && !(_config.walls.drum.radius > 0.0)) {
      throw std::invalid_argument("hikiln::dem::DemConfig: drum radius must be > 0");
    }
    if (_config.walls.numFlat < 0 || _config.walls.numFlat > maxFlatWalls) {
      throw std::invalid_argument("hikiln::dem::DemConfig: at most " +
                                  std::to_string(maxFlatWalls) + " flat walls");
    }
    for (int k = 0; k < _config.walls.numFlat; ++k) {
      FlatWall& w = _config.walls.flat[k];
      const double len = std::hypot(w.normalX, w.normalY);
      if (!(len > 0.0)) {
        throw std::invalid_argument("hikiln::dem::FlatWall: zero normal");
      }
      w.normalX /= len;
      w.normalY /= len;
      if (w.roughness != 0.0) {
        throw std::invalid_argument("hikiln::dem::FlatWall: roughness is a hook for a future "
                                    "rough-wall model and is not implemented; leave it 0");
      }
    }
    if (_config.periodic.enabled && !(_config.periodic.length > 0.0)) {
      throw std::invalid_argument("hikiln::dem::DemConfig: periodic length must be > 0");
    }
    _settings.particle = prepareContact(_config.particleContact);
    _settings.wall = prepareContact(_config.wallContact);
    _settings.walls = _config.walls;
    _settings.periodic = _config.periodic;
    _settings.gravityX = _config.gravityX;
    _settings.gravityY = _config.gravityY;
  }

  // Views are shared handles: a copy would alias the state, so systems are move-only.
  DemSystem(const DemSystem&) = delete;
  DemSystem& operator=(const DemSystem&) = delete;
  DemSystem(DemSystem&&) = default;
  DemSystem& operator=(DemSystem&&) = default;
  ~DemSystem() = default;

  /// \brief Takes the live particles of a host container (radius, mass and inertia set, unique
  /// ids), clears all contact history, resets the clock, builds the list and evaluates the initial
  /// forces (history not advanced, as LAMMPS's set-up).
  void setParticles(const host_particles_type& host) {
    validateHost(host);
    _particles = copyParticles<memory_space>(host);
    updateInverseMassProperties(_space, _particles);
    allocateContactState(
        NeighborList<memory_space>(_particles.capacity(), _config.neighborCapacity, _space));
    Kokkos::deep_copy(_space, _particles.force, 0.0);
    Kokkos::deep_copy(_space, _particles.torque, 0.0);
    _step = 0;
    _time = 0.0;
    configureFromParticles(host);
    rebuild(sortDue());
    ForceSettings setup = _settings;
    setup.updateHistory = false;
    computeForces(_space, _particles, _list, _walls, setup);
    _space.fence();
  }

  /// \brief Advances one time step.
  void step() {
    requireParticles();
    const double d2 =
        initialIntegrate(_space, _particles, _settings.dt, _settings.periodic, _buildPosition);
    if (_rebuildRequested || d2 > 0.25 * _skin * _skin) {
      rebuild(sortDue());
    }
    computeForcesAndKick(_space, _particles, _list, _walls, _settings, _velocityNext,
                         _angularVelocityNext);
    std::swap(_particles.velocity, _velocityNext);
    std::swap(_particles.angularVelocity, _angularVelocityNext);
    ++_step;
    _time += _settings.dt;
  }

  /// \brief Advances nSteps time steps.
  void advance(std::int64_t nSteps) {
    for (std::int64_t s = 0; s < nSteps; ++s) {
      step();
    }
    _space.fence();
  }

  /// \brief Rebuilds the neighbour list now (history carried over).
  void forceRebuild() {
    requireParticles();
    rebuild(false);
  }

  /// \brief Reorders the particles by cell now (history rows follow) and rebuilds the list.
  void sortByCell() {
    requireParticles();
    rebuild(true);
  }

  /// \brief Sets the drum's angular velocity (rad/s, counter-clockwise positive) from now on.
  void setDrumAngularVelocity(double omega) {
    _config.walls.drum.angularVelocity = omega;
    _settings.walls.drum.angularVelocity = omega;
  }

  /// \brief Sets the gravity vector (m/s^2) from now on.
  void setGravity(double gx, double gy) {
    _config.gravityX = _settings.gravityX = gx;
    _config.gravityY = _settings.gravityY = gy;
  }

  /// \brief Sets the time step (s) from now on (velocity Verlet may change dt between steps).
  void setTimeStep(double dt) {
    if (!(dt > 0.0)) {
      throw std::invalid_argument("hikiln::dem::DemSystem: time step must be > 0");
    }
    _config.timeStep = _settings.dt = dt;
  }

  /// \brief Copies the state needed to continue the run bitwise identically to the host.
  DemState exportState() const {
    requireParticles();
    _space.fence();
    const std::size_t n = _particles.count();
    const auto p = copyParticles<Kokkos::HostSpace>(_particles);
    const auto wallShear = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _walls.shear);
    const auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _list.count);
    const auto nid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _list.neighborId);
    const auto shear = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _list.shear);
    DemState s;
    s.step = _step;
    s.time = _time;
    for (std::size_t i = 0; i < n; ++i) {
      s.id.push_back(p.id(i));
      for (int c = 0; c < 2; ++c) {
        s.position.push_back(p.position(i, c));
        s.velocity.push_back(p.velocity(i, c));
        s.force.push_back(p.force(i, c));
      }
      s.angularVelocity.push_back(p.angularVelocity(i));
      s.torque.push_back(p.torque(i));
      s.radius.push_back(p.radius(i));
      s.mass.push_back(p.mass(i));
      s.inertia.push_back(p.inertia(i));
      for (int m = 0; m < wallSlotCount; ++m) {
        s.wallShear.push_back(wallShear(i, m));
      }
      const int rowCount = std::min(count(i), _list.capacity());
      for (int k = 0; k < rowCount; ++k) {
        if (shear(i, k) != 0.0) {
          s.contactId.push_back(p.id(i));
          s.contactNeighborId.push_back(nid(i, k));
          s.contactShear.push_back(shear(i, k));
        }
      }
    }
    return s;
  }

  /// \brief Replaces the whole state by an exported one (no force evaluation: the exported forces
  /// are used), then rebuilds the list with the imported history. Stepping on continues bitwise as
  /// the exporting system would have. Slot/wall forces read zero until the next step.
  void importState(const DemState& s) {
    const std::size_t n = s.size();
    const auto bad = [](const char* what) {
      throw std::invalid_argument(std::string("hikiln::dem::DemState: ") + what);
    };
    if (s.position.size() != 2 * n || s.velocity.size() != 2 * n || s.force.size() != 2 * n ||
        s.angularVelocity.size() != n || s.torque.size() != n || s.radius.size() != n ||
        s.mass.size() != n || s.inertia.size() != n || s.wallShear.size() != wallSlotCount * n) {
      bad("inconsistent array sizes");
    }
    if (s.contactNeighborId.size() != s.contactId.size() ||
        s.contactShear.size() != s.contactId.size()) {
      bad("inconsistent contact history sizes");
    }
    host_particles_type host(n, n);
    for (std::size_t i = 0; i < n; ++i) {
      host.id(i) = s.id[i];
      for (int c = 0; c < 2; ++c) {
        host.position(i, c) = s.position[2 * i + c];
        host.velocity(i, c) = s.velocity[2 * i + c];
        host.force(i, c) = s.force[2 * i + c];
      }
      host.angularVelocity(i) = s.angularVelocity[i];
      host.torque(i) = s.torque[i];
      host.radius(i) = s.radius[i];
      host.mass(i) = s.mass[i];
      host.inertia(i) = s.inertia[i];
    }
    validateHost(host);
    // pair history rows keyed by the particle's index here, sorted by neighbour id
    std::vector<std::int64_t> sortedIds(s.id);
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) {
      order[i] = i;
    }
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return s.id[a] < s.id[b]; });
    std::sort(sortedIds.begin(), sortedIds.end());
    const auto rowOf = [&](std::int64_t pid) {
      const auto it = std::lower_bound(sortedIds.begin(), sortedIds.end(), pid);
      if (it == sortedIds.end() || *it != pid) {
        bad("contact history names an unknown particle");
      }
      return order[static_cast<std::size_t>(it - sortedIds.begin())];
    };
    std::vector<std::vector<std::pair<std::int64_t, double>>> rows(n);
    for (std::size_t c = 0; c < s.contactId.size(); ++c) {
      rows[rowOf(s.contactId[c])].emplace_back(s.contactNeighborId[c], s.contactShear[c]);
    }
    std::size_t seedCapacity = 1;
    for (auto& r : rows) {
      std::sort(r.begin(), r.end());
      seedCapacity = std::max(seedCapacity, r.size());
    }
    NeighborList<Kokkos::HostSpace> seedHost(n, static_cast<int>(seedCapacity));
    for (std::size_t i = 0; i < n; ++i) {
      seedHost.count(i) = static_cast<int>(rows[i].size());
      for (std::size_t k = 0; k < rows[i].size(); ++k) {
        seedHost.neighborId(i, k) = rows[i][k].first;
        seedHost.shear(i, k) = rows[i][k].second;
      }
    }
    NeighborList<memory_space> seed(n, static_cast<int>(seedCapacity), _space);
    Kokkos::deep_copy(seed.count, seedHost.count);
    Kokkos::deep_copy(seed.neighborId, seedHost.neighborId);
    Kokkos::deep_copy(seed.shear, seedHost.shear);

    _particles = copyParticles<memory_space>(host);
    updateInverseMassProperties(_space, _particles);
    allocateContactState(seed);
    Kokkos::View<double* [wallSlotCount], Kokkos::HostSpace> wallHost("hikiln::dem::wallShearHost",
                                                                      n);
    for (std::size_t i = 0; i < n; ++i) {
      for (int m = 0; m < wallSlotCount; ++m) {
        wallHost(i, m) = s.wallShear[wallSlotCount * i + m];
      }
    }
    Kokkos::deep_copy(_walls.shear, wallHost);
    _step = s.step;
    _time = s.time;
    configureFromParticles(host);
    rebuild(sortDue());
    _space.fence();
  }

  /// \brief Energies of the current state.
  EnergyReport energy() const {
    requireParticles();
    return computeEnergy(_space, _particles, _list, _walls, _settings);
  }
  /// \brief Linear and angular momentum of the current state.
  MomentumReport momentum() const {
    requireParticles();
    return computeMomentum(_space, _particles);
  }

  /// \brief Device particle arrays (View handles change on every step: do not keep them).
  const particles_type& particles() const { return _particles; }
  /// \brief Host copy of the particle arrays.
  host_particles_type hostParticles() const {
    _space.fence();
    return copyParticles<Kokkos::HostSpace>(_particles);
  }
  /// \brief The neighbour list with per-slot history and last contact forces.
  const NeighborList<memory_space>& neighborList() const { return _list; }
  /// \brief Per-particle wall history and last wall forces.
  const WallContactState<memory_space>& wallContacts() const { return _walls; }
  /// \brief Coefficients, walls, gravity and dt as the kernels see them.
  const ForceSettings& forceSettings() const { return _settings; }
  /// \brief The configuration (with normalised wall normals and current omega, gravity, dt).
  const DemConfig& config() const { return _config; }
  /// \brief The execution space instance.
  const execution_space& executionSpace() const { return _space; }
  /// \brief Number of live particles.
  std::size_t size() const { return _particles.count(); }
  /// \brief Time step (s).
  double timeStep() const { return _settings.dt; }
  /// \brief Neighbour skin in use (m).
  double skin() const { return _skin; }
  /// \brief Simulated time (s).
  double time() const { return _time; }
  /// \brief Steps taken since setParticles (or the imported step count).
  std::int64_t stepCount() const { return _step; }
  /// \brief Neighbour-list builds so far (all causes).
  std::int64_t rebuildCount() const { return _rebuildCount; }
  /// \brief Particle reorderings so far.
  std::int64_t sortCount() const { return _sortCount; }

private:
  void requireParticles() const {
    if (!_ready) {
      throw std::logic_error("hikiln::dem::DemSystem: no particles set");
    }
  }

  static void validateHost(const host_particles_type& h) {
    std::vector<std::int64_t> ids;
    for (std::size_t i = 0; i < h.count(); ++i) {
      if (!(h.radius(i) > 0.0) || !(h.mass(i) > 0.0) || !(h.inertia(i) > 0.0)) {
        throw std::invalid_argument("hikiln::dem::DemSystem: particle " + std::to_string(h.id(i)) +
                                    " needs radius, mass and inertia > 0");
      }
      if (!std::isfinite(h.position(i, 0)) || !std::isfinite(h.position(i, 1))) {
        throw std::invalid_argument("hikiln::dem::DemSystem: non-finite position");
      }
      ids.push_back(h.id(i));
    }
    std::sort(ids.begin(), ids.end());
    if (std::adjacent_find(ids.begin(), ids.end()) != ids.end()) {
      throw std::invalid_argument("hikiln::dem::DemSystem: particle ids must be unique");
    }
  }

  // Scratch buffers, list and wall state sized like _particles; `previous` seeds the history.
  void allocateContactState(NeighborList<memory_space> previous) {
    const std::size_t cap = _particles.capacity();
    _scratch = particles_type(_space, cap, _particles.count());
    _velocityNext = Kokkos::View<double* [2], memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::velocityNext")), cap);
    _angularVelocityNext = Kokkos::View<double*, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::spinNext")), cap);
    _buildPosition = Kokkos::View<double* [2], memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::buildPosition")), cap);
    _list = std::move(previous);
    _listSpare = NeighborList<memory_space>(cap, _config.neighborCapacity, _space);
    _walls = WallContactState<memory_space>(cap, _space);
    _wallsSpare = WallContactState<memory_space>(cap, _space);
    _bins = CellBins<memory_space>();
    _rebuildCount = 0;
    _sortCount = 0;
    _rebuildRequested = false;
    _ready = true;
  }

  // Skin, cell size and time step from the particle set (host copy).
  void configureFromParticles(const host_particles_type& h) {
    double rmax = 0.0, mmin = 1.0e300, inertiaFactor = 1.0e300;
    for (std::size_t i = 0; i < h.count(); ++i) {
      rmax = std::max(rmax, h.radius(i));
      mmin = std::min(mmin, h.mass(i));
      inertiaFactor =
          std::min(inertiaFactor, h.inertia(i) / (h.mass(i) * h.radius(i) * h.radius(i)));
    }
    _skin = _config.skin > 0.0 ? _config.skin : 0.4 * rmax;
    _cellSize = 2.0 * rmax + _skin;
    if (_config.timeStep > 0.0) {
      _settings.dt = _config.timeStep;
    } else if (h.count() > 0) {
      _settings.dt = recommendedTimeStep(_settings.particle, _settings.wall, mmin, inertiaFactor,
                                         _config.timeStepSafety);
    } else {
      _settings.dt = 0.0;
    }
  }

  bool sortDue() const {
    return _config.sortEveryRebuilds > 0 && _rebuildCount % _config.sortEveryRebuilds == 0;
  }

  void rebuild(bool sort) {
    const std::size_t n = _particles.count();
    const Bounds b = particleBounds(_space, _particles.position, n);
    const CellGrid grid =
        makeCellGrid(b.xmin, b.xmax, b.ymin, b.ymax, _cellSize, _settings.periodic, 4 * n + 4096);
    binParticles(_space, grid, _particles.position, n, _bins);
    if (sort) {
      if (_listSpare.capacity() != _list.capacity() || _listSpare.rows() != _list.rows()) {
        _listSpare = NeighborList<memory_space>(_list.rows(), _list.capacity(), _space);
      }
      permuteParticles(_space, _bins.cellParticles, _particles, _scratch);
      permuteContactRows(_space, _bins.cellParticles, n, _list, _listSpare, _walls, _wallsSpare);
      _particles.swap(_scratch);
      std::swap(_list, _listSpare);
      std::swap(_walls, _wallsSpare);
      binParticles(_space, grid, _particles.position, n, _bins);
      ++_sortCount;
    }
    if (_listSpare.capacity() != _config.neighborCapacity || _listSpare.rows() < n) {
      _listSpare =
          NeighborList<memory_space>(_particles.capacity(), _config.neighborCapacity, _space);
    }
    const int maxCount =
        buildNeighborList(_space, _bins, _particles.position, _particles.radius, _particles.id, n,
                          _skin, _settings.periodic, _list, _listSpare);
    if (maxCount > _listSpare.capacity()) {
      _rebuildRequested = true; // the old list is intact; stepping on would retry and fail again
      throw std::runtime_error(neighborOverflowMessage(maxCount, _listSpare.capacity()));
    }
    std::swap(_list, _listSpare);
    Kokkos::deep_copy(_space, _buildPosition, _particles.position);
    _rebuildRequested = false;
    ++_rebuildCount;
  }

  DemConfig _config;
  ExecutionSpace _space;
  ForceSettings _settings;
  particles_type _particles;
  particles_type _scratch;
  Kokkos::View<double* [2], memory_space> _velocityNext;
  Kokkos::View<double*, memory_space> _angularVelocityNext;
  Kokkos::View<double* [2], memory_space> _buildPosition;
  NeighborList<memory_space> _list;
  NeighborList<memory_space> _listSpare;
  WallContactState<memory_space> _walls;
  WallContactState<memory_space> _wallsSpare;
  CellBins<memory_space> _bins;
  double _skin = 0.0;
  double _cellSize = 0.0;
  double _time = 0.0;
  std::int64_t _step = 0;
  std::int64_t _rebuildCount = 0;
  std::int64_t _sortCount = 0;
  bool _rebuildRequested = false;
  bool _ready = false;
};

} // namespace hikiln::dem
