/// \file Blocky.cpp
/// \brief Throughput of blocky (superquadric) particles against the disc engine on the same
/// packing: full time steps of a rotating drum bed (DemSystem::advance (blocky) with N = 2, 4, 6
/// and DemSystem::advance with the same discs), 1e3 and 1e4 particles.
///
/// The bed: particles of bounding radius 10 mm (+-5 %) on a hexagonal lattice of pitch 2.05
/// bounding radii at the bottom of a drum whose radius grows with sqrt(N) for a 20 % fill, random
/// orientations, k_n = 1e5 N/m, k_t = 5e4 N/m, friction 0.5, e = 0.5, dt = 2.5e-5 s, 3 rpm, 300
/// warm-up steps. N = 2 blocky particles are circles and take the disc engine's exact contact
/// formula, so blocky_n2 measures the blocky kernel's overhead alone; blocky_n4/n6 add the
/// superquadric narrow phase. Counter: particle_steps/s.
///
/// HIKILN_BENCH_MAX_PARTICLES (default 1000000) drops the sizes above it.

#include "kernels/dem/BlockyArrays.hpp"
#include "perf/harness/Backends.hpp"
#include "perf/harness/Timing.hpp"
#include "solvers/dem/DemSystem.hpp"

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace hikiln::perf {
namespace {

constexpr double radius = 0.01;

dem::DemConfig blockyDrumConfig(double drumRadius) {
  dem::DemConfig cfg;
  cfg.timeStep = 2.5e-5;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = drumRadius;
  cfg.walls.drum.angularVelocity = 3.0 * 2.0 * constants::pi / 60.0;
  cfg.neighborCapacity = 24;
  return cfg;
}

double drumRadiusFor(std::size_t n) {
  return 2.5 * radius * std::sqrt(static_cast<double>(n));
}

/// \brief n particles on a hexagonal lattice at the bottom of the drum, shapes of blockiness
/// `blockiness` with bounding radius = the disc radius, random orientations.
struct Bed {
  dem::ParticleArrays<Kokkos::HostSpace> particles;
  dem::BlockyArrays<Kokkos::HostSpace> shapes;
};

Bed makeBed(std::size_t n, double blockiness) {
  const double drum = drumRadiusFor(n), pitch = 2.05 * 1.05 * radius;
  std::vector<std::pair<double, double>> sites;
  for (int row = 0; sites.size() < n; ++row) {
    const double y = -drum + pitch + row * pitch * std::sqrt(0.75);
    if (y > drum - pitch) {
      break;
    }
    const double half = std::sqrt(std::max(0.0, (drum - pitch) * (drum - pitch) - y * y));
    for (double x = -half + 0.5 * (row % 2) * pitch; x <= half && sites.size() < n; x += pitch) {
      sites.emplace_back(x, y);
    }
  }
  Bed bed{dem::ParticleArrays<Kokkos::HostSpace>(sites.size(), sites.size()),
          dem::BlockyArrays<Kokkos::HostSpace>(sites.size())};
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const dem::SuperquadricShape unit{1.0, 1.0, blockiness};
  const double reach = dem::isCircle(unit) ? 1.0 : dem::boundingRadius(unit);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const double r = radius * (1.0 + 0.05 * u(gen));
    bed.particles.id(i) = static_cast<std::int64_t>(i);
    bed.particles.position(i, 0) = sites[i].first;
    bed.particles.position(i, 1) = sites[i].second;
    bed.shapes.shape(i) = dem::SuperquadricShape{r / reach, r / reach, blockiness};
    bed.shapes.orientation(i) = dem::isCircle(unit) ? 0.0 : constants::pi * u(gen);
  }
  dem::assignBlockyMassPropertiesHost(bed.particles, bed.shapes, 2500.0, dem::MassConvention::Disc,
                                      2.0 * radius);
  return bed;
}

template <class System, class ExecutionSpace>
void timeSteps(System& system, ExecutionSpace const& space, benchmark::State& state) {
  system.advance(300); // warm-up: the lattice starts to settle and shear
  const auto n = static_cast<std::int64_t>(system.size());
  const std::int64_t steps = std::max<std::int64_t>(1, 200000 / n);
  const double seconds = timeIterations(state, space, [&] { system.advance(steps); });
  const auto particleSteps =
      static_cast<double>(n * steps) * static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<std::int64_t>(particleSteps));
  state.counters["particle_steps/s"] =
      benchmark::Counter(seconds > 0.0 ? particleSteps / seconds : 0.0);
  state.SetLabel(std::to_string(system.size()) + " particles");
  if (!std::isfinite(system.energy().kinetic())) {
    state.SkipWithError("the drum blew up (non-finite kinetic energy)");
  }
}

template <class ExecutionSpace>
void benchmarkBlocky(Backend<ExecutionSpace>, benchmark::State& state, double blockiness) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Bed bed = makeBed(n, blockiness);
  dem::DemSystem<ExecutionSpace> system(blockyDrumConfig(drumRadiusFor(n)));
  system.setParticles(bed.particles, bed.shapes);
  timeSteps(system, system.executionSpace(), state);
}

template <class ExecutionSpace>
void benchmarkDiscReference(Backend<ExecutionSpace>, benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Bed bed = makeBed(n, 2.0);
  dem::DemSystem<ExecutionSpace> system(blockyDrumConfig(drumRadiusFor(n)));
  system.setParticles(bed.particles);
  timeSteps(system, system.executionSpace(), state);
}

void registerBlocky() {
  std::vector<std::int64_t> counts;
  const char* cap = std::getenv("HIKILN_BENCH_MAX_PARTICLES");
  const std::int64_t maxCount = cap ? std::atoll(cap) : 1000000;
  for (const std::int64_t n : {1000, 10000}) {
    if (n <= maxCount) {
      counts.push_back(n);
    }
  }
  registerPerBackend("blocky_disc_reference", counts, [](auto backend, benchmark::State& state) {
    benchmarkDiscReference(backend, state);
  });
  registerPerBackend("blocky_n2", counts, [](auto backend, benchmark::State& state) {
    benchmarkBlocky(backend, state, 2.0);
  });
  registerPerBackend("blocky_n4", counts, [](auto backend, benchmark::State& state) {
    benchmarkBlocky(backend, state, 4.0);
  });
  registerPerBackend("blocky_n6", counts, [](auto backend, benchmark::State& state) {
    benchmarkBlocky(backend, state, 6.0);
  });
}

HIKILN_PERF_REGISTER(registerBlocky);

} // namespace
} // namespace hikiln::perf
