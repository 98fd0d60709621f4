#pragma once
/// \file DemSystem.hpp
/// \brief Host-side owner of a 2D DEM run: particles, neighbour list, walls, parameters, clock.
///
/// Design
/// - Step (velocity Verlet, LAMMPS nve/sphere order), two launches without a rebuild:
///   1. initialIntegrate: the previous step's deferred second half kick, then v += dt/2 F/m,
///      omega += dt/2 T/I, x += dt v, and a max-reduction of the displacement since the last list
///      build;
///   2. if that exceeds skin/2 (or a rebuild was asked for): rebuild the neighbour list;
///   3. computeForces: contact + wall + gravity forces at the new positions with the half-step
///      velocities.
///   The second half kick v += dt/2 F/m of step n is deferred into step n+1's first launch (the
///   force kernel reads neighbours' velocities, so kicking there needs a second velocity buffer).
///   Every accessor that exposes the state applies a pending kick first (finishHalfKick), so
///   between steps callers see x^n, v^n, omega^n, F^n, T^n as before; the arithmetic is the same
///   in both paths, so the trajectory is bitwise the same whether or not anyone looked.
/// - Neighbour list: a uniform cell grid (cell >= largest diameter + skin) over the particle
///   bounds; a FULL list of rows sorted by neighbour id, rebuilt in place (NeighborList.hpp).
///   Rows are as wide as the longest row needs; the configured neighborCapacity is the limit
///   (overflow is an exception, never silent).
/// - History: one tangential displacement per row slot (and one per particle and wall). The two
///   copies of a pair's history evolve identically because every pair quantity is computed so
///   that it is bitwise the same from both sides. A rebuild carries each slot's history over by
///   neighbour id; a reorder (sortByCell, every sortEveryRebuilds rebuilds) permutes particles and
///   history rows together (indices remapped) and then rebuilds.
/// - Memory (about 250-300 bytes per particle): particles 120, list 4 + 12 per slot, wall history
///   40, build positions 16, cell bins ~10-20. Per-contact forces are not kept by the step; the
///   compatibility views of neighborList()/wallContacts() (neighbour ids, contact forces) are
///   allocated and filled on first use, forces re-evaluated for the current state
///   (computeContactForces()). Reordering permutes one field at a time (no second particle set).
/// - Determinism: each particle sums its own force in id order and writes only its own data, so
///   results are bitwise identical for any thread count, and independent of when rebuilds and
///   reorders happen (non-touching slots contribute nothing). Hence exportState()/importState()
///   continue bitwise identically even though the imported system rebuilds its list at once.
/// - Particle kinds (ParticleKind): fixed particles never move; shell particles (ids consecutive)
///   are rotated rigidly with the drum from their home positions (their positions at
///   setParticles) by the shell angle, the sum of omega dt over the steps (kept on the host, so
///   the same on every backend). Both act on free particles as bodies of infinite mass.
/// - Blocky particles (setParticles() with shapes): each particle is a superquadric with an
///   orientation (BlockyArrays next to the particle arrays, radius = bounding radius); the step
///   then also turns the orientations (theta += dt omega^(n+1/2)) and takes the forces of
///   BlockyForceKernel.hpp; the list keeps each pair's last normal or separating axis
///   (NeighborList::normalAngle) as the history, carried over rebuilds, reorders and checkpoints.
///   Shell-attached particles must be circles then. An all-circle blocky system follows the disc
///   system bitwise.
/// - Batches (importSlices(), used by DemBatch.hpp): several independent systems ("slices", disc
///   particles, no shell particles, no periodic boundary) in one set of arrays and one set of
///   launches. Each particle carries its slice; the cell grid has one layer per slice, so
///   particles of different slices never become neighbours, and the force kernel takes each
///   particle's coefficients, walls and gravity from its slice's ForceSettings. dt is common.

#include "kernels/common/Compat.hpp"
#include "kernels/dem/BlockyArrays.hpp"
#include "kernels/dem/BlockyForceKernel.hpp"
#include "kernels/dem/CellGrid.hpp"
#include "kernels/dem/ContactLaw.hpp"
#include "kernels/dem/Diagnostics.hpp"
#include "kernels/dem/ForceKernel.hpp"
#include "kernels/dem/Integrator.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/PairOnceForces.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Periodic.hpp"
#include "kernels/dem/PrescribedMotion.hpp"
#include "kernels/dem/Reorder.hpp"
#include "kernels/dem/Superquadric.hpp"
#include "kernels/dem/TimeStep.hpp"
#include "kernels/dem/Walls.hpp"
#include "solvers/dem/DemState.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
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
  /// evaluate each disc pair once, adding the partner's side into exact integer sums
  /// (PairOnceForces.hpp): the same guarantees, the partners' side rounded to 2^-50 of k_n times
  /// the largest diameter (torques: times the largest radius too); host backends only (a device
  /// keeps the full-row kernel)
  bool pairOnceForces = false;
  WallSet walls;
  PeriodicX periodic;
};

/// \brief Validates a configuration (normalising the flat-wall normals in place) and returns the
/// kernel settings it gives (dt is set later, from the particles).
inline ForceSettings prepareForceSettings(DemConfig& config) {
  if (config.neighborCapacity < 1 || config.neighborCapacity > maxNeighborCapacity) {
    throw std::invalid_argument("hikiln::dem::DemConfig: neighborCapacity must be in [1, " +
                                std::to_string(maxNeighborCapacity) + "]");
  }
  if (config.walls.drum.enabled && !(config.walls.drum.radius > 0.0)) {
    throw std::invalid_argument("hikiln::dem::DemConfig: drum radius must be > 0");
  }
  if (config.walls.numFlat < 0 || config.walls.numFlat > maxFlatWalls) {
    throw std::invalid_argument("hikiln::dem::DemConfig: at most " + std::to_string(maxFlatWalls) +
                                " flat walls");
  }
  for (int k = 0; k < config.walls.numFlat; ++k) {
    FlatWall& w = config.walls.flat[k];
    const double len = std::hypot(w.normalX, w.normalY);
    if (!(len > 0.0)) {
      throw std::invalid_argument("hikiln::dem::FlatWall: zero normal");
    }
    w.normalX /= len;
    w.normalY /= len;
  }
  if (config.periodic.enabled && !(config.periodic.length > 0.0)) {
    throw std::invalid_argument("hikiln::dem::DemConfig: periodic length must be > 0");
  }
  ForceSettings settings;
  settings.particle = prepareContact(config.particleContact);
  settings.wall = prepareContact(config.wallContact);
  settings.walls = config.walls;
  settings.periodic = config.periodic;
  settings.gravityX = config.gravityX;
  settings.gravityY = config.gravityY;
  return settings;
}

/// \brief A 2D DEM system advanced on ExecutionSpace (see the file comment for the algorithm).
template <class ExecutionSpace> class DemSystem {
public:
  using execution_space = ExecutionSpace;
  using memory_space = typename ExecutionSpace::memory_space;
  using particles_type = ParticleArrays<memory_space>;
  using host_particles_type = ParticleArrays<Kokkos::HostSpace>;
  using host_blocky_type = BlockyArrays<Kokkos::HostSpace>;

  /// \brief A system with no particles yet; validates the configuration.
  explicit DemSystem(DemConfig config, ExecutionSpace space = ExecutionSpace())
      : _config(std::move(config)), _space(std::move(space)),
        _settings(prepareForceSettings(_config)) {}

  // Views are shared handles: a copy would alias the state, so systems are move-only.
  DemSystem(const DemSystem&) = delete;
  DemSystem& operator=(const DemSystem&) = delete;
  DemSystem(DemSystem&&) = default;
  DemSystem& operator=(DemSystem&&) = default;
  ~DemSystem() = default;

  /// \brief Takes the live particles of a host container (radius, mass and inertia set, unique
  /// ids), clears all contact history, resets the clock, builds the list and evaluates the initial
  /// forces (history not advanced, as LAMMPS's set-up). Fixed particles get v = omega = 0, shell
  /// particles the shell's motion; their positions now are their home positions (shell angle 0).
  void setParticles(const host_particles_type& given) { setParticlesAndShapes(given, nullptr); }

  /// \brief setParticles() for blocky particles: `shapes` holds each particle's outline and
  /// orientation in the same order (radius = bounding radius, mass and inertia set to match, e.g.
  /// by assignBlockyMassPropertiesHost()).
  void setParticles(const host_particles_type& given, const host_blocky_type& shapes) {
    setParticlesAndShapes(given, &shapes);
  }

  /// \brief Advances one time step (its second half kick is applied by the next step or the next
  /// accessor that exposes the state, see the file comment).
  void step() {
    requireParticles();
    if (_shellHome.extent(0) > 0) {
      _shellAngle += _config.walls.drum.angularVelocity * _settings.dt;
      updateShellMotion();
    }
    const double d2 = initialIntegrate(_space, _particles, _settings.dt, _settings.periodic,
                                       _buildPosition, _pendingHalfDt, _shell, _shellHome);
    if (_isBlocky) {
      advanceOrientation(_space, _particles, _blocky, _settings.dt);
    }
    _pendingHalfDt = 0.0;
    if (_rebuildRequested || d2 > 0.25 * _skin * _skin) {
      rebuild(sortDue());
    }
    evaluateForces(_settings);
    _pendingHalfDt = 0.5 * _settings.dt;
    ++_step;
    ++_version;
    _time += _settings.dt;
  }

  /// \brief Advances nSteps time steps.
  void advance(std::int64_t nSteps) {
    for (std::int64_t s = 0; s < nSteps; ++s) {
      step();
    }
    _space.fence();
  }

  /// \brief Multiplies the velocities and spins of the free particles by `factor` in [0, 1]
  /// (the settling of a drum removes motion this way; positions, forces and contact history stay).
  void scaleFreeMotion(double factor) {
    requireParticles();
    if (!(factor >= 0.0 && factor <= 1.0)) {
      throw std::invalid_argument("hikiln::dem::DemSystem: motion scale factor must be in [0, 1]");
    }
    synchronize(); // the pending half kick belongs to the motion being scaled
    hikiln::dem::scaleFreeMotion(_space, _particles, factor); // the kernel, not this member
    ++_version;
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
    requireSingle("setDrumAngularVelocity");
    _config.walls.drum.angularVelocity = omega;
    _settings.walls.drum.angularVelocity = omega;
    updateShellMotion(); // shell particles take the new speed from the next step on
    ++_version;
  }

  /// \brief Sets the gravity vector (m/s^2) from now on.
  void setGravity(double gx, double gy) {
    requireSingle("setGravity");
    _config.gravityX = _settings.gravityX = gx;
    _config.gravityY = _settings.gravityY = gy;
    ++_version;
  }

  /// \brief Sets the time step (s) from now on (velocity Verlet may change dt between steps).
  void setTimeStep(double dt) {
    if (!(dt > 0.0)) {
      throw std::invalid_argument("hikiln::dem::DemSystem: time step must be > 0");
    }
    synchronize(); // the pending half kick belongs to the old step size
    _config.timeStep = _settings.dt = dt;
    updateSliceTable(); // a batch's slices step with it
  }

  /// \brief Copies the state needed to continue the run bitwise identically to the host.
  DemState exportState() const {
    requireParticles();
    synchronize();
    _space.fence();
    const std::size_t n = _particles.count();
    const auto p = copyParticles<Kokkos::HostSpace>(_particles);
    const auto wallShear = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _walls.shear);
    const auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _list.count);
    const auto index = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _list.index);
    const auto shear = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _list.shear);
    const auto angle = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _list.normalAngle);
    DemState s;
    s.step = _step;
    s.time = _time;
    s.shellAngle = _shellAngle;
    const auto home = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _shellHome);
    for (std::size_t k = 0; k < home.extent(0); ++k) {
      s.shellHome.push_back(home(k, 0));
      s.shellHome.push_back(home(k, 1));
    }
    for (std::size_t i = 0; i < n; ++i) {
      s.id.push_back(p.id(i));
      s.kind.push_back(p.kind(i));
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
        const double a = _isBlocky ? angle(i, k) : 0.0;
        if (shear(i, k) != 0.0 || a != 0.0) {
          s.contactId.push_back(p.id(i));
          s.contactNeighborId.push_back(p.id(index(i, k)));
          s.contactShear.push_back(shear(i, k));
          if (_isBlocky) {
            s.contactAngle.push_back(a);
          }
        }
      }
    }
    if (batched()) {
      const auto slice = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, _slice);
      s.slice.assign(slice.data(), slice.data() + n);
    }
    if (_isBlocky) {
      const auto b = copyBlocky<Kokkos::HostSpace>(_blocky);
      for (std::size_t i = 0; i < n; ++i) {
        s.orientation.push_back(b.orientation(i));
        s.shapeA.push_back(b.shape(i).a);
        s.shapeB.push_back(b.shape(i).b);
        s.shapeN.push_back(b.shape(i).n);
      }
    }
    return s;
  }

  /// \brief Replaces the whole state by an exported one (no force evaluation: the exported forces
  /// are used), then rebuilds the list with the imported history. Stepping on continues bitwise as
  /// the exporting system would have.
  void importState(const DemState& s) { importSlices(s, {}); }

  /// \brief importState() for a batch: `s.slice` names each particle's slice in [0,
  /// sliceSettings.size()), whose coefficients, walls and gravity it then feels (their dt is
  /// replaced by this system's). Disc particles only, free or fixed, no periodic boundary; ids
  /// unique over the batch. A state without slices imports as one system (sliceSettings empty).
  void importSlices(const DemState& s, const std::vector<ForceSettings>& sliceSettings) {
    const std::size_t n = s.size();
    const auto bad = [](const char* what) {
      throw std::invalid_argument(std::string("hikiln::dem::DemState: ") + what);
    };
    if (s.position.size() != 2 * n || s.velocity.size() != 2 * n || s.force.size() != 2 * n ||
        s.angularVelocity.size() != n || s.torque.size() != n || s.radius.size() != n ||
        s.mass.size() != n || s.inertia.size() != n || s.wallShear.size() != wallSlotCount * n) {
      bad("inconsistent array sizes");
    }
    if (!s.kind.empty() && s.kind.size() != n) {
      bad("inconsistent array sizes (kind)");
    }
    if (s.contactNeighborId.size() != s.contactId.size() ||
        s.contactShear.size() != s.contactId.size()) {
      bad("inconsistent contact history sizes");
    }
    const bool blocky = !s.orientation.empty();
    if (blocky && (s.orientation.size() != n || s.shapeA.size() != n || s.shapeB.size() != n ||
                   s.shapeN.size() != n || s.contactAngle.size() != s.contactId.size())) {
      bad("inconsistent blocky shape or contact direction sizes");
    }
    checkSlices(s, sliceSettings.size());
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
      host.kind(i) = s.kind.empty() ? std::uint8_t(0) : s.kind[i]; // older states: all free
    }
    validateHost(host);
    setShellHome(host, s.shellAngle, s.shellHome);
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
    // (neighbour id, shear, direction) per row
    std::vector<std::vector<std::tuple<std::int64_t, double, double>>> rows(n);
    for (std::size_t c = 0; c < s.contactId.size(); ++c) {
      rows[rowOf(s.contactId[c])].emplace_back(s.contactNeighborId[c], s.contactShear[c],
                                               blocky ? s.contactAngle[c] : 0.0);
    }
    std::size_t seedWidth = static_cast<std::size_t>(initialWidth());
    for (auto& r : rows) {
      std::sort(r.begin(), r.end());
      seedWidth = std::max(seedWidth, r.size());
    }
    if (seedWidth > static_cast<std::size_t>(maxNeighborCapacity)) {
      bad("a particle has more contacts than a neighbour row can hold");
    }
    // rows hold indices in this (the imported) particle order, sorted by neighbour id
    auto seedHost = NeighborList<Kokkos::HostSpace>::lean(n, static_cast<int>(seedWidth));
    if (blocky) {
      seedHost.allocateNormalAngle();
    }
    for (std::size_t i = 0; i < n; ++i) {
      seedHost.count(i) = static_cast<int>(rows[i].size());
      for (std::size_t k = 0; k < rows[i].size(); ++k) {
        seedHost.index(i, k) = static_cast<int>(rowOf(std::get<0>(rows[i][k])));
        seedHost.shear(i, k) = std::get<1>(rows[i][k]);
        if (blocky) {
          seedHost.normalAngle(i, k) = std::get<2>(rows[i][k]);
        }
      }
    }
    host_blocky_type shapes;
    if (blocky) {
      shapes = host_blocky_type(n);
      for (std::size_t i = 0; i < n; ++i) {
        shapes.orientation(i) = s.orientation[i];
        shapes.shape(i) = SuperquadricShape{s.shapeA[i], s.shapeB[i], s.shapeN[i]};
      }
    }
    adoptShapes(host, blocky ? &shapes : nullptr);
    auto seed = leanList(n, static_cast<int>(seedWidth));
    Kokkos::deep_copy(seed.count, seedHost.count);
    Kokkos::deep_copy(seed.index, seedHost.index);
    Kokkos::deep_copy(seed.shear, seedHost.shear);
    if (blocky) {
      Kokkos::deep_copy(seed.normalAngle, seedHost.normalAngle);
    }

    _particles = copyParticles<memory_space>(host);
    updateInverseMassProperties(_space, _particles);
    adoptSlices(s.slice, sliceSettings);
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
    updateSliceTable();
    rebuild(sortDue());
    _space.fence();
  }

  /// \brief Energies of the current state.
  EnergyReport energy() const {
    requireParticles();
    requireSingle("energy"); // its potential and elastic parts need one set of coefficients
    synchronize();
    EnergyReport e = computeEnergy(_space, _particles, _list, _walls, _settings);
    if (_isBlocky) { // elastic parts from the blocky contact geometry
      const auto elastic =
          blockyElasticEnergy(_space, _particles, _blocky, _list, _walls, _settings);
      e.elasticPair = elastic.first;
      e.elasticWall = elastic.second;
    }
    return e;
  }
  /// \brief Linear and angular momentum of the current state.
  MomentumReport momentum() const {
    requireParticles();
    synchronize();
    return computeMomentum(_space, _particles);
  }

  /// \brief Device particle arrays of the current state (View handles change when particles are
  /// reordered: do not keep them across steps).
  const particles_type& particles() const {
    synchronize();
    return _particles;
  }
  /// \brief Host copy of the particle arrays.
  host_particles_type hostParticles() const {
    synchronize();
    _space.fence();
    return copyParticles<Kokkos::HostSpace>(_particles);
  }
  /// \brief The neighbour list with per-slot history, plus the optional views filled for the
  /// current state: neighbour ids and the contact forces of computeContactForces() (allocated on
  /// first use, ids refreshed after rebuilds, forces re-evaluated once per step that asks: a force
  /// evaluation; samplers call it at sample times). Per-step users wanting only rows and history
  /// take neighborRows().
  const NeighborList<memory_space>& neighborList() const {
    requireParticles();
    refreshContactViews();
    return _published;
  }
  /// \brief Per-particle wall history and the wall contact forces of the current state (as
  /// neighborList(), evaluated on demand).
  const WallContactState<memory_space>& wallContacts() const {
    requireParticles();
    refreshContactViews();
    return _publishedWalls;
  }
  /// \brief The neighbour list as the step uses it (count, index, shear; no optional views).
  /// Indices refer to particles() order; ids are particles().id(index(i, k)).
  const NeighborList<memory_space>& neighborRows() const {
    mirrorHistoryIfPending();
    return _list;
  }
  /// \brief True for a system of blocky particles (setParticles() with shapes).
  bool blocky() const { return _isBlocky; }
  /// \brief True for a batch of slices (importSlices()).
  bool batched() const { return _slice.extent(0) > 0; }
  /// \brief Slices of a batch (1 otherwise).
  int sliceCount() const { return _sliceCount; }
  /// \brief Host copy of the shapes and orientations, in hostParticles() order (capacity 0 for a
  /// disc system).
  host_blocky_type hostShapes() const {
    _space.fence();
    return _isBlocky ? copyBlocky<Kokkos::HostSpace>(_blocky) : host_blocky_type();
  }
  /// \brief Blocky systems: each particle's contact virial sum (x_c - x_i) (x) f_i (n x 4: xx, xy,
  /// yx, yy) of the current state, evaluated with neighborList()'s forces. Empty for discs (their
  /// virial follows from the stored forces and the centres, CoarseGrainContact.hpp).
  const Kokkos::View<double* [4], memory_space>& contactVirial() const {
    requireParticles();
    refreshContactViews();
    return _publishedVirial;
  }
  /// \brief Blocky systems: each particle's true area (m^2), in particles() order; empty for discs
  /// (pi r^2).
  const Kokkos::View<double*, memory_space>& particleAreas() const {
    return _area;
  }
  /// \brief Bytes held by the system's Views (particles, list, walls, bins, build positions and
  /// any optional views allocated by neighborList()/wallContacts()).
  std::size_t memoryBytes() const {
    const auto bytes = [](const auto& v) {
      return v.span() * sizeof(typename std::decay_t<decltype(v)>::value_type);
    };
    const particles_type& p = _particles;
    std::size_t total = bytes(p.position) + bytes(p.velocity) + bytes(p.angularVelocity) +
                        bytes(p.force) + bytes(p.torque) + bytes(p.radius) + bytes(p.mass) +
                        bytes(p.inertia) + bytes(p.inverseMass) + bytes(p.inverseInertia) +
                        bytes(p.id) + bytes(p.kind);
    total += bytes(_shellHome) + bytes(_slice) + bytes(_sliceSettings);
    total += bytes(_buildPosition) + _list.bytes() + bytes(_walls.shear);
    total += bytes(_bins.cellOfParticle) + bytes(_bins.cellCount) + bytes(_bins.cellOffset) +
             bytes(_bins.cellParticles);
    total += bytes(_published.neighborId) + bytes(_published.normalForce) +
             bytes(_published.tangentialForce) + bytes(_publishedWalls.normalForce) +
             bytes(_publishedWalls.tangentialForce);
    total += bytes(_blocky.orientation) + bytes(_blocky.shape) + bytes(_blocky.axis) +
             bytes(_area) + bytes(_publishedVirial) + bytes(_pairOutcomes);
    total += bytes(_pairOnce.partner.sums) + bytes(_pairOnce.firstHigher);
    return total;
  }
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
  /// \brief Rotation angle of the shell particles since their home positions (rad).
  double shellAngle() const { return _shellAngle; }
  /// \brief Simulated time (s).
  double time() const { return _time; }
  /// \brief Steps taken since setParticles (or the imported step count).
  std::int64_t stepCount() const { return _step; }
  /// \brief Neighbour-list builds so far (all causes).
  std::int64_t rebuildCount() const { return _rebuildCount; }
  /// \brief Particle reorderings so far.
  std::int64_t sortCount() const { return _sortCount; }

private:
  void setParticlesAndShapes(const host_particles_type& given, const host_blocky_type* shapes) {
    host_particles_type host = copyParticles<Kokkos::HostSpace>(given); // placeNonFree edits it
    validateHost(host);
    adoptShapes(host, shapes);
    adoptSlices({}, {});
    setShellHome(host, 0.0, {});
    placeNonFree(host);
    _particles = copyParticles<memory_space>(host);
    updateInverseMassProperties(_space, _particles);
    allocateContactState(leanList(_particles.capacity(), initialWidth()));
    Kokkos::deep_copy(_space, _particles.force, 0.0);
    Kokkos::deep_copy(_space, _particles.torque, 0.0);
    _step = 0;
    _time = 0.0;
    configureFromParticles(host);
    rebuild(sortDue());
    ForceSettings setup = _settings;
    setup.updateHistory = false;
    evaluateForces(setup);
    _space.fence();
  }

  // Takes the shapes of the host set h (nullptr: discs): device copy sized like h, axes, areas.
  void adoptShapes(const host_particles_type& h, const host_blocky_type* shapes) {
    _isBlocky = shapes != nullptr;
    _publishedVirial = Kokkos::View<double* [4], memory_space>();
    if (!_isBlocky) {
      _blocky = BlockyArrays<memory_space>();
      _area = Kokkos::View<double*, memory_space>();
      return;
    }
    const std::size_t n = h.count();
    _circlesOnly = true;
    if (shapes->capacity() < n) {
      throw std::invalid_argument("hikiln::dem::DemSystem: fewer shapes than particles");
    }
    host_blocky_type b(h.capacity());
    Kokkos::View<double*, Kokkos::HostSpace> area("hikiln::dem::particleAreaHost", h.capacity());
    for (std::size_t i = 0; i < n; ++i) {
      const SuperquadricShape& s = shapes->shape(i);
      const std::string who = "hikiln::dem::DemSystem: particle " + std::to_string(h.id(i));
      validateShape(s, who);
      if (h.kind(i) == static_cast<std::uint8_t>(ParticleKind::Shell) && !isCircle(s)) {
        throw std::invalid_argument(who + ": shell-attached particles must be circles");
      }
      b.shape(i) = s;
      b.orientation(i) = shapes->orientation(i);
      area(i) = superquadricArea(s);
      _circlesOnly = _circlesOnly && isCircle(s);
    }
    _blocky = copyBlocky<memory_space>(b);
    updateOrientationAxes(_space, _blocky, n);
    _area = Kokkos::View<double*, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::particleArea")), h.capacity());
    Kokkos::deep_copy(_space, _area, area);
  }

  // Checks a state's slice tags against a batch of `slices` slices (0: not a batch).
  void checkSlices(const DemState& s, std::size_t slices) const {
    const auto bad = [](const std::string& what) {
      throw std::invalid_argument("hikiln::dem::DemSystem::importSlices: " + what);
    };
    if (s.slice.empty() != (slices == 0)) {
      bad("a batch needs both the particles' slices and the slices' settings");
    }
    if (slices == 0) {
      return;
    }
    if (s.slice.size() != s.size()) {
      bad("inconsistent array sizes (slice)");
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s.slice[i] < 0 || static_cast<std::size_t>(s.slice[i]) >= slices) {
        bad("particle " + std::to_string(s.id[i]) + " names slice " + std::to_string(s.slice[i]) +
            " of " + std::to_string(slices));
      }
      if (!s.kind.empty() && s.kind[i] == static_cast<std::uint8_t>(ParticleKind::Shell)) {
        bad("shell-attached particles cannot be batched (each slice's shell turns on its own)");
      }
    }
    if (!s.orientation.empty()) {
      bad("blocky particles cannot be batched");
    }
    if (_config.periodic.enabled) {
      bad("periodic systems cannot be batched");
    }
  }

  // Device copies of the particles' slices and the slices' settings (empty: a single system).
  void adoptSlices(const std::vector<int>& slice, const std::vector<ForceSettings>& settings) {
    _sliceCount = settings.empty() ? 1 : static_cast<int>(settings.size());
    _sliceTableHost = settings;
    if (slice.empty()) {
      _slice = Kokkos::View<int*, memory_space>();
      _sliceSettings = Kokkos::View<ForceSettings*, memory_space>();
      return;
    }
    _slice = Kokkos::View<int*, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::slice")), _particles.capacity());
    Kokkos::View<const int*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged> given(slice.data(),
                                                                               slice.size());
    Kokkos::deep_copy(_space, Kokkos::subview(_slice, std::make_pair(std::size_t(0), slice.size())),
                      given);
    _sliceSettings = Kokkos::View<ForceSettings*, memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::sliceSettings")), settings.size());
  }

  // The slices' settings on the device, with this system's time step.
  void updateSliceTable() {
    if (!batched()) {
      return;
    }
    auto host = Kokkos::create_mirror_view(_sliceSettings);
    for (std::size_t k = 0; k < _sliceTableHost.size(); ++k) {
      host(k) = _sliceTableHost[k];
      host(k).dt = _settings.dt;
      host(k).updateHistory = true;
    }
    Kokkos::deep_copy(_space, _sliceSettings, host);
    _space.fence();
  }

  SliceTable<memory_space> sliceTable() const { return {_slice, _sliceSettings}; }

  void requireSingle(const char* what) const {
    if (batched()) {
      throw std::logic_error(std::string("hikiln::dem::DemSystem::") + what +
                             ": not available for a batch of slices (export the slices)");
    }
  }

  // An empty list of `rows` rows `width` wide (with the pair directions for blocky systems).
  NeighborList<memory_space> leanList(std::size_t rows, int width) const {
    auto list = NeighborList<memory_space>::lean(rows, width, _space);
    if (_isBlocky) {
      list.allocateNormalAngle(_space);
    }
    return list;
  }

  // Contact, wall and gravity forces of the current state into the particle arrays. Blocky
  // systems of circles only take the disc kernel: the same forces at its cost
  // (computeBlockyForces()).
  void evaluateForces(const ForceSettings& settings) {
    if (_isBlocky && !_circlesOnly) {
      computeBlockyForces(_space, _particles, _blocky, _list, _walls, settings, _pairOutcomes);
    } else if (usesPairOnce()) {
      computeForcesPairOnce(_space, _particles, _list, _walls, settings, sliceTable(), _pairOnce);
      _historyMirrorPending = true;
    } else {
      computeForces(_space, _particles, _list, _walls, settings, sliceTable());
    }
  }

  // The pair-once disc kernel: asked for, and on a host backend.
  bool usesPairOnce() const {
    return _config.pairOnceForces &&
           Kokkos::SpaceAccessibility<Kokkos::HostSpace, memory_space>::accessible;
  }

  void requireParticles() const {
    if (!_ready) {
      throw std::logic_error("hikiln::dem::DemSystem: no particles set");
    }
  }

  void validateHost(const host_particles_type& h) const {
    std::vector<std::int64_t> ids;
    for (std::size_t i = 0; i < h.count(); ++i) {
      if (h.kind(i) > static_cast<std::uint8_t>(ParticleKind::Shell)) {
        throw std::invalid_argument("hikiln::dem::DemSystem: particle " + std::to_string(h.id(i)) +
                                    " has an unknown kind " + std::to_string(h.kind(i)));
      }
      if (h.kind(i) == static_cast<std::uint8_t>(ParticleKind::Shell) &&
          !_config.walls.drum.enabled) {
        throw std::invalid_argument("hikiln::dem::DemSystem: shell-attached particle " +
                                    std::to_string(h.id(i)) + " needs a drum wall");
      }
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

  // Shell home positions from a host set: `home` (2 per shell particle in id order) when given,
  // else the current positions (at shell angle 0). Shell ids must be consecutive.
  void setShellHome(const host_particles_type& h, double angle, const std::vector<double>& home) {
    std::vector<std::pair<std::int64_t, std::size_t>> shell;
    for (std::size_t i = 0; i < h.count(); ++i) {
      if (h.kind(i) == static_cast<std::uint8_t>(ParticleKind::Shell)) {
        shell.emplace_back(h.id(i), i);
      }
    }
    std::sort(shell.begin(), shell.end());
    for (std::size_t k = 1; k < shell.size(); ++k) {
      if (shell[k].first != shell[0].first + static_cast<std::int64_t>(k)) {
        throw std::invalid_argument("hikiln::dem::DemSystem: shell-attached particles need "
                                    "consecutive ids");
      }
    }
    if (!home.empty() && home.size() != 2 * shell.size()) {
      throw std::invalid_argument("hikiln::dem::DemState: shell home positions do not match the "
                                  "shell-attached particles");
    }
    Kokkos::View<double* [2], Kokkos::HostSpace> hostHome("hikiln::dem::shellHomeHost",
                                                          shell.size());
    for (std::size_t k = 0; k < shell.size(); ++k) {
      for (int c = 0; c < 2; ++c) {
        hostHome(k, c) = home.empty() ? h.position(shell[k].second, c) : home[2 * k + c];
      }
    }
    _shellHome = Kokkos::View<double* [2], memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::shellHome")), shell.size());
    Kokkos::deep_copy(_space, _shellHome, hostHome);
    _shell.firstId = shell.empty() ? 0 : shell[0].first;
    _shellAngle = angle;
    updateShellMotion();
  }

  void updateShellMotion() {
    _shell.cosAngle = std::cos(_shellAngle);
    _shell.sinAngle = std::sin(_shellAngle);
    _shell.angularVelocity = _config.walls.drum.angularVelocity;
  }

  // Prescribed state of a new set: fixed particles at rest, shell ones moving with the shell.
  void placeNonFree(const host_particles_type& h) const {
    for (std::size_t i = 0; i < h.count(); ++i) {
      if (h.kind(i) == static_cast<std::uint8_t>(ParticleKind::Fixed)) {
        h.velocity(i, 0) = h.velocity(i, 1) = h.angularVelocity(i) = 0.0;
      } else if (h.kind(i) == static_cast<std::uint8_t>(ParticleKind::Shell)) {
        h.velocity(i, 0) = -_shell.angularVelocity * h.position(i, 1);
        h.velocity(i, 1) = _shell.angularVelocity * h.position(i, 0);
        h.angularVelocity(i) = _shell.angularVelocity;
      }
    }
  }

  // List, wall history and build positions sized like _particles; `previous` seeds the history.
  void allocateContactState(NeighborList<memory_space> previous) {
    const std::size_t cap = _particles.capacity();
    _buildPosition = Kokkos::View<double* [2], memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::buildPosition")), cap);
    _list = std::move(previous);
    _walls = leanWallState(cap);
    _bins = CellBins<memory_space>();
    _published = NeighborList<memory_space>();
    _publishedWalls = WallContactState<memory_space>();
    _pendingHalfDt = 0.0;
    _historyMirrorPending = false; // a new list: nothing of the old one to copy
    ++_version;
    _rebuildCount = 0;
    _sortCount = 0;
    _rebuildRequested = false;
    _ready = true;
  }

  // Wall history only (the force views stay empty until wallContacts() asks for them).
  WallContactState<memory_space> leanWallState(std::size_t capacity) const {
    WallContactState<memory_space> w;
    w.shear = Kokkos::View<double* [wallSlotCount], memory_space>(
        Kokkos::view_alloc(_space, std::string("hikiln::dem::wallShear")), capacity);
    return w;
  }

  // Replaces list and wall state; the published views drop their handles to the old ones (so the
  // old allocations are released now) and are refreshed on their next use.
  void adoptContactState(NeighborList<memory_space> list, WallContactState<memory_space> walls) {
    _list = std::move(list);
    _walls = std::move(walls);
    _published.count = _list.count;
    _published.index = _list.index;
    _published.shear = _list.shear;
    _publishedWalls.shear = _walls.shear;
    ++_version;
  }

  // Row width to start with: rows grow on demand up to the configured limit.
  int initialWidth() const { return std::min(_config.neighborCapacity, 8); }

  // Applies the pending second half kick of the last step (see the file comment).
  void synchronize() const {
    if (_pendingHalfDt != 0.0) {
      finishHalfKick(_space, _particles, _pendingHalfDt);
      _pendingHalfDt = 0.0;
    }
    mirrorHistoryIfPending();
  }

  // The pair-once kernel updates each pair's history in the owner's row only: copied into the
  // partner's slot before anything reads both rows. A rebuild needs no copy: each row carries its
  // own slots across it, and the step reads the owner's only.
  void mirrorHistoryIfPending() const {
    if (_historyMirrorPending) {
      mirrorPairOnceHistory(_space, _list, _particles.count(), _pairOnce);
      _historyMirrorPending = false;
    }
  }

  // Fills the optional views of _published/_publishedWalls for the current state.
  void refreshContactViews() const {
    synchronize();
    if (_publishedVersion == _version) {
      return;
    }
    const bool reshaped = _published.normalForce.extent(0) != _list.rows() ||
                          _published.normalForce.extent(1) != _list.index.extent(1);
    _published.count = _list.count;
    _published.index = _list.index;
    _published.shear = _list.shear;
    if (reshaped) {
      _published.allocateOptional(_space);
    }
    _publishedWalls.shear = _walls.shear;
    if (_publishedWalls.normalForce.extent(0) != _walls.shear.extent(0)) {
      const std::size_t cap = _walls.shear.extent(0);
      using WallView = Kokkos::View<double* [wallSlotCount], memory_space>;
      _publishedWalls.normalForce =
          WallView(Kokkos::view_alloc(_space, std::string("hikiln::dem::wallNormalForce")), cap);
      _publishedWalls.tangentialForce = WallView(
          Kokkos::view_alloc(_space, std::string("hikiln::dem::wallTangentialForce")), cap);
    }
    // a free kernel function: CUDA extended lambdas may not sit in a private member function
    fillNeighborIds(_space, _particles.count(), _list, _particles.id, _published.neighborId);
    if (_isBlocky) {
      if (_publishedVirial.extent(0) != _list.rows()) {
        _publishedVirial = Kokkos::View<double* [4], memory_space>(
            Kokkos::view_alloc(_space, std::string("hikiln::dem::contactVirial")), _list.rows());
      }
      _published.normalAngle = _list.normalAngle;
      computeBlockyContactForces(_space, _particles, _blocky, _published, _publishedWalls,
                                 _settings, _publishedVirial);
    } else {
      computeContactForces(_space, _particles, _published, _publishedWalls, _settings,
                           sliceTable());
    }
    _publishedVersion = _version;
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
    _pairOnce.partner.forceScale = pairOnceScale(_settings.particle.kn * 2.0 * rmax);
    _pairOnce.partner.torqueScale = pairOnceScale(_settings.particle.kn * 2.0 * rmax * rmax);
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
    const CellGrid grid = makeCellGrid(b.xmin, b.xmax, b.ymin, b.ymax, _cellSize,
                                       _settings.periodic, 4 * n + 4096, _sliceCount);
    binParticles(_space, grid, _particles.position, n, _bins, _slice);
    ++_version;
    if (sort) {
      // one field at a time; the rows follow with their indices remapped
      permuteParticlesInPlace(_space, _bins.cellParticles, _particles);
      if (_isBlocky) {
        permuteView(_space, _bins.cellParticles, n, _blocky.orientation);
        permuteView(_space, _bins.cellParticles, n, _blocky.shape);
        permuteView(_space, _bins.cellParticles, n, _blocky.axis);
        permuteView(_space, _bins.cellParticles, n, _area);
      }
      if (batched()) {
        permuteView(_space, _bins.cellParticles, n, _slice);
      }
      auto list = leanList(_list.rows(), _list.capacity());
      auto walls = leanWallState(_walls.shear.extent(0));
      permuteContactRows(_space, _bins.cellParticles, n, _list, list, _walls, walls);
      adoptContactState(list, walls);
      binParticles(_space, grid, _particles.position, n, _bins, _slice);
      ++_sortCount;
    }
    for (;;) { // rows that did not fit are left as they were: widen and repeat
      const int maxCount =
          rebuildNeighborList(_space, _bins, _particles.position, _particles.radius, _particles.id,
                              n, _skin, _settings.periodic, _list);
      if (maxCount > _config.neighborCapacity) {
        _rebuildRequested = true; // rows are still valid; stepping on would retry and fail again
        throw std::runtime_error(neighborOverflowMessage(maxCount, _config.neighborCapacity));
      }
      if (maxCount <= _list.capacity()) {
        break;
      }
      auto wider = leanList(_list.rows(), std::min(_config.neighborCapacity, maxCount + 2));
      copyNeighborRows(_space, n, _list, wider);
      adoptContactState(wider, _walls);
    }
    // a kernel, not deep_copy: a host deep_copy may run on the default host space's threads
    // (a free function: CUDA extended lambdas may not sit in a private member function)
    copyPositions(_space, _particles.position, _buildPosition, n);
    if (usesPairOnce()) {
      layOutPairOnce(_space, _list, _particles.id, n, _pairOnce);
    }
    _rebuildRequested = false;
    ++_rebuildCount;
  }

  DemConfig _config;
  ExecutionSpace _space;
  ForceSettings _settings;
  particles_type _particles;
  Kokkos::View<double* [2], memory_space> _buildPosition;
  Kokkos::View<double* [2], memory_space> _shellHome; // shell particle k: id _shell.firstId + k
  ShellMotion _shell;
  double _shellAngle = 0.0;
  NeighborList<memory_space> _list;
  WallContactState<memory_space> _walls;
  CellBins<memory_space> _bins;
  BlockyArrays<memory_space> _blocky;             // blocky systems: shapes and orientations
  Kokkos::View<double*, memory_space> _area;      // blocky systems: true particle areas
  BlockyPairOutcomes<memory_space> _pairOutcomes; // blocky systems: force pass scratch
  PairOnceState<memory_space> _pairOnce;          // DemConfig::pairOnceForces
  bool _circlesOnly = false; // blocky systems: every shape a circle (the disc force kernel)
  bool _isBlocky = false;
  Kokkos::View<int*, memory_space> _slice;                   // batches: each particle's slice
  Kokkos::View<ForceSettings*, memory_space> _sliceSettings; // batches: per-slice settings
  std::vector<ForceSettings> _sliceTableHost;
  int _sliceCount = 1;
  mutable Kokkos::View<double* [4], memory_space> _publishedVirial; // see contactVirial()
  // what neighborList()/wallContacts() hand out: the live rows plus the optional views
  mutable NeighborList<memory_space> _published;
  mutable WallContactState<memory_space> _publishedWalls;
  mutable std::int64_t _publishedVersion = -1;
  mutable double _pendingHalfDt = 0.0; // deferred second half kick of the last step (0: none)
  mutable bool _historyMirrorPending = false; // pair-once history not yet in the partners' slots
  std::int64_t _version = 0; // bumped whenever state the published views show changes
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
