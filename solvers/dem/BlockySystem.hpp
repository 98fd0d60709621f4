#pragma once
/// \file BlockySystem.hpp
/// \brief Host-side owner of a 2D DEM run of blocky (superquadric) particles: DemSystem's time
/// loop (velocity Verlet with the deferred second half kick, neighbour list with skin, contact
/// history carried over by id) with the orientation integrated as theta += dt omega^(n+1/2) and
/// the forces of BlockyForceKernel.hpp.
///
/// Differences from DemSystem: particles are never reordered by cell (the order only affects
/// memory locality, never the results), there is no export/import of the state, no contact-force
/// sampling and no shell-attached particles (fixed ones are supported). An all-circle system
/// (N = 2, a = b) follows DemSystem bitwise.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/BlockyArrays.hpp"
#include "kernels/dem/BlockyForceKernel.hpp"
#include "kernels/dem/CellGrid.hpp"
#include "kernels/dem/Diagnostics.hpp"
#include "kernels/dem/Integrator.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/TimeStep.hpp"
#include "kernels/dem/Walls.hpp"
#include "solvers/dem/DemSystem.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace hikiln::dem {

/// \brief A 2D system of blocky particles advanced on ExecutionSpace (see the file comment).
template <class ExecutionSpace> class BlockySystem {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using host_particles_type = ParticleArrays<Kokkos::HostSpace>;
  using host_blocky_type = BlockyArrays<Kokkos::HostSpace>;

  /// \brief A system with no particles yet; validates the configuration as DemSystem does.
  explicit BlockySystem(DemConfig config, ExecutionSpace space = ExecutionSpace())
      : _config(std::move(config)), _space(std::move(space)),
        _settings(prepareForceSettings(_config)) {}

  BlockySystem(const BlockySystem&) = delete;
  BlockySystem& operator=(const BlockySystem&) = delete;
  BlockySystem(BlockySystem&&) = default;
  BlockySystem& operator=(BlockySystem&&) = default;
  ~BlockySystem() = default;

  /// \brief Takes the live particles (radius = bounding radius, mass and inertia set, e.g. by
  /// assignBlockyMassPropertiesHost(); unique ids) and their shapes and orientations; clears the
  /// contact history, resets the clock, builds the list and evaluates the initial forces.
  void setParticles(const host_particles_type& given, const host_blocky_type& shapes) {
    const std::size_t n = given.count();
    if (shapes.capacity() < n) {
      throw std::invalid_argument("hikiln::dem::BlockySystem: fewer shapes than particles");
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::string who = "hikiln::dem::BlockySystem: particle " + std::to_string(given.id(i));
      validateShape(shapes.shape(i), who);
      if (given.kind(i) == static_cast<std::uint8_t>(ParticleKind::Shell)) {
        throw std::invalid_argument(who + ": shell-attached blocky particles are not supported");
      }
      if (!(given.mass(i) > 0.0) || !(given.inertia(i) > 0.0) || !(given.radius(i) > 0.0)) {
        throw std::invalid_argument(who + " needs radius, mass and inertia > 0");
      }
    }
    _particles = copyParticles<memory_space>(given);
    _blocky = copyBlocky<memory_space>(shapes);
    updateOrientationAxes(_space, _blocky, n);
    updateInverseMassProperties(_space, _particles);
    placeFixed();
    const std::size_t cap = _particles.capacity();
    _list = NeighborList<memory_space>::lean(cap, std::min(_config.neighborCapacity, 8), _space);
    _list.allocateNormalAngle(_space); // warm starts of the pair search
    _walls = WallContactState<memory_space>();
    _walls.shear = Kokkos::View<double* [wallSlotCount], memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::wallShear")), cap);
    _buildPosition = Kokkos::View<double* [2], memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::buildPosition")), cap);
    _step = 0;
    _time = 0.0;
    _pendingHalfDt = 0.0;
    _rebuildCount = 0;
    configure(given);
    rebuild();
    ForceSettings setup = _settings;
    setup.updateHistory = false;
    computeBlockyForces(_space, _particles, _blocky, _list, _walls, setup);
    _space.fence();
    _ready = true;
  }

  /// \brief Advances one time step.
  void step() {
    require();
    const double d2 = initialIntegrate(_space, _particles, _settings.dt, _settings.periodic,
                                       _buildPosition, _pendingHalfDt);
    advanceOrientation(_space, _particles, _blocky, _settings.dt);
    _pendingHalfDt = 0.0;
    if (d2 > 0.25 * _skin * _skin) {
      rebuild();
    }
    computeBlockyForces(_space, _particles, _blocky, _list, _walls, _settings);
    _pendingHalfDt = 0.5 * _settings.dt;
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

  /// \brief Energies of the current state (elastic parts from the blocky contact geometry).
  EnergyReport energy() const {
    require();
    synchronize();
    EnergyReport e = computeEnergy(_space, _particles, _list, _walls, _settings);
    const auto elastic = blockyElasticEnergy(_space, _particles, _blocky, _list, _walls, _settings);
    e.elasticPair = elastic.first;
    e.elasticWall = elastic.second;
    return e;
  }
  /// \brief Linear and angular momentum of the current state.
  MomentumReport momentum() const {
    require();
    synchronize();
    return computeMomentum(_space, _particles);
  }
  /// \brief Host copy of the particle arrays.
  host_particles_type hostParticles() const {
    synchronize();
    _space.fence();
    return copyParticles<Kokkos::HostSpace>(_particles);
  }
  /// \brief Host copy of the shapes and orientations (same order as hostParticles()).
  host_blocky_type hostBlocky() const {
    _space.fence();
    return copyBlocky<Kokkos::HostSpace>(_blocky);
  }
  /// \brief Time step (s).
  double timeStep() const { return _settings.dt; }
  /// \brief Simulated time (s).
  double time() const { return _time; }
  /// \brief Steps taken since setParticles.
  std::int64_t stepCount() const { return _step; }
  /// \brief Neighbour-list builds so far.
  std::int64_t rebuildCount() const { return _rebuildCount; }
  /// \brief Number of live particles.
  std::size_t size() const { return _particles.count(); }
  /// \brief Coefficients, walls, gravity and dt as the kernels see them.
  const ForceSettings& forceSettings() const { return _settings; }
  /// \brief The execution space instance.
  const execution_space& executionSpace() const { return _space; }

private:
  void require() const {
    if (!_ready) {
      throw std::logic_error("hikiln::dem::BlockySystem: no particles set");
    }
  }

  void synchronize() const {
    if (_pendingHalfDt != 0.0) {
      finishHalfKick(_space, _particles, _pendingHalfDt);
      _pendingHalfDt = 0.0;
    }
  }

  // Fixed particles start (and stay) at rest.
  void placeFixed() {
    auto host = copyParticles<Kokkos::HostSpace>(_particles);
    bool any = false;
    for (std::size_t i = 0; i < host.count(); ++i) {
      if (host.kind(i) == static_cast<std::uint8_t>(ParticleKind::Fixed)) {
        host.velocity(i, 0) = host.velocity(i, 1) = host.angularVelocity(i) = 0.0;
        any = true;
      }
    }
    if (any) {
      Kokkos::deep_copy(_particles.velocity, host.velocity);
      Kokkos::deep_copy(_particles.angularVelocity, host.angularVelocity);
    }
  }

  // Skin, cell size and time step as DemSystem sets them (the bounding radius plays the radius;
  // I / (m r_bound^2) bounds the lever arms, so the tangential time scale stays conservative).
  void configure(const host_particles_type& h) {
    double rmax = 0.0, mmin = 1.0e300, inertiaFactor = 1.0e300;
    for (std::size_t i = 0; i < h.count(); ++i) {
      rmax = std::max(rmax, h.radius(i));
      mmin = std::min(mmin, h.mass(i));
      inertiaFactor =
          std::min(inertiaFactor, h.inertia(i) / (h.mass(i) * h.radius(i) * h.radius(i)));
    }
    _skin = _config.skin > 0.0 ? _config.skin : 0.4 * rmax;
    _cellSize = 2.0 * rmax + _skin;
    _settings.dt =
        _config.timeStep > 0.0
            ? _config.timeStep
            : (h.count() > 0 ? recommendedTimeStep(_settings.particle, _settings.wall, mmin,
                                                   inertiaFactor, _config.timeStepSafety)
                             : 0.0);
  }

  void rebuild() {
    const std::size_t n = _particles.count();
    const Bounds b = particleBounds(_space, _particles.position, n);
    const CellGrid grid =
        makeCellGrid(b.xmin, b.xmax, b.ymin, b.ymax, _cellSize, _settings.periodic, 4 * n + 4096);
    binParticles(_space, grid, _particles.position, n, _bins);
    for (;;) { // rows that did not fit are left as they were: widen and repeat
      const int maxCount =
          rebuildNeighborList(_space, _bins, _particles.position, _particles.radius, _particles.id,
                              n, _skin, _settings.periodic, _list);
      if (maxCount > _config.neighborCapacity) {
        throw std::runtime_error(neighborOverflowMessage(maxCount, _config.neighborCapacity));
      }
      if (maxCount <= _list.capacity()) {
        break;
      }
      auto wider = NeighborList<memory_space>::lean(
          _list.rows(), std::min(_config.neighborCapacity, maxCount + 2), _space);
      wider.allocateNormalAngle(_space);
      copyNeighborRows(_space, n, _list, wider);
      _list = wider;
    }
    copyPositions(_space, _particles.position, _buildPosition, n);
    ++_rebuildCount;
  }

  DemConfig _config;
  ExecutionSpace _space;
  ForceSettings _settings;
  ParticleArrays<memory_space> _particles;
  BlockyArrays<memory_space> _blocky;
  NeighborList<memory_space> _list;
  WallContactState<memory_space> _walls;
  CellBins<memory_space> _bins;
  Kokkos::View<double* [2], memory_space> _buildPosition;
  mutable double _pendingHalfDt = 0.0; // deferred second half kick of the last step (0: none)
  double _skin = 0.0;
  double _cellSize = 0.0;
  double _time = 0.0;
  std::int64_t _step = 0;
  std::int64_t _rebuildCount = 0;
  bool _ready = false;
};

} // namespace hikiln::dem
