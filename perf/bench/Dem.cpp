/// \file Dem.cpp
/// \brief 2D DEM throughput: the full time step (DemSystem::advance) of a rotating drum at 20 %
/// fill and the neighbour-list rebuild alone, for 1e3 to 1e6 particles.
///
/// The drum is the physics.md base case scaled up: 20 mm discs (+-5 %), k_n = 1e5 N/m,
/// k_t = 5e4 N/m, friction 0.5, LAMMPS-style rate damping (gamma_n 1813/s, gamma_t 906/s),
/// dt = 2.5e-5 s, 3 rpm, the drum diameter growing with sqrt(N) so that the bed fills 20 % of
/// it. Settling a 1e6-particle bed would take longer than the benchmark, so the bed starts as a
/// dense hexagonal lattice (pitch = mean diameter: about half the pairs overlap slightly) at the
/// bottom of the drum and gets a few hundred warm-up steps; the bed then jostles, somewhat more
/// than a settled bed (more rebuilds), so the timings are on the safe side. Counters:
/// particle_steps/s, bytes/particle (DemSystem::memoryBytes() / N) and contacts/particle
/// (touching neighbour slots / N, both sides counted).
///
/// HIKILN_BENCH_MAX_PARTICLES (default 1000000) drops the sizes above it (CI: 10000).

#include "perf/harness/Backends.hpp"
#include "perf/harness/Timing.hpp"
#include "solvers/dem/DemSystem.hpp"
#include "solvers/dem/SplitMix.hpp"

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace hikiln::perf {
namespace {

constexpr double meanDiameter = 0.02;
constexpr double sizeRange = 0.05;
constexpr double fill = 0.20;
constexpr double rpm = 3.0;

/// \brief Particle counts to run: 1e3 .. 1e6, capped by HIKILN_BENCH_MAX_PARTICLES.
std::vector<std::int64_t> particleCounts() {
  std::int64_t maxCount = 1000000;
  if (const char* text = std::getenv("HIKILN_BENCH_MAX_PARTICLES")) {
    char* end = nullptr;
    const long long value = std::strtoll(text, &end, 10);
    if (end != text && *end == '\0' && value >= 1000) {
      maxCount = value;
    } else {
      std::cerr << "hikiln_bench: ignoring HIKILN_BENCH_MAX_PARTICLES='" << text
                << "' (want an integer >= 1000)\n";
    }
  }
  std::vector<std::int64_t> counts;
  for (std::int64_t n = 1000; n <= maxCount; n *= 10) {
    counts.push_back(n);
  }
  return counts;
}

/// \brief Drum radius whose lower 20 % holds n lattice sites of the given pitch.
double drumRadiusFor(std::size_t n, double pitch) {
  const double siteArea = 0.5 * std::sqrt(3.0) * pitch * pitch;
  return std::sqrt(static_cast<double>(n) * siteArea / (fill * constants::pi)) + pitch;
}

/// \brief n discs on the lowest sites of a hexagonal lattice inside a drum of radius `radius`.
dem::ParticleArrays<Kokkos::HostSpace> latticeBed(std::size_t n, double radius) {
  const double pitch = meanDiameter;
  const double inner = radius - 0.6 * pitch * (1.0 + sizeRange);
  const double rowHeight = 0.5 * std::sqrt(3.0) * pitch;
  std::vector<std::pair<double, double>> sites;
  int row = 0;
  for (double y = -inner; sites.size() < n && y < inner; y += rowHeight, ++row) {
    const double half = std::sqrt(std::max(0.0, inner * inner - y * y));
    const double shift = (row % 2) * 0.5 * pitch; // rows share one x lattice
    for (double x = shift - std::floor((half + shift) / pitch) * pitch; x <= half; x += pitch) {
      sites.emplace_back(x, y);
    }
  }
  sites.resize(std::min(n, sites.size()));
  dem::ParticleArrays<Kokkos::HostSpace> p(sites.size(), sites.size());
  dem::SplitMix64 random(2024);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    p.position(i, 0) = sites[i].first;
    p.position(i, 1) = sites[i].second;
    p.radius(i) = 0.5 * meanDiameter * (1.0 - sizeRange + 2.0 * sizeRange * random.uniform());
    p.id(i) = static_cast<std::int64_t>(i);
  }
  dem::assignMassPropertiesHost(p, 2700.0, dem::MassConvention::Sphere);
  return p;
}

/// \brief The base-case contact law with LAMMPS gran/hooke/history damping (as perf/lammps).
dem::DemConfig drumConfig(double radius) {
  dem::DemConfig cfg;
  cfg.particleContact.dampingMode = dem::DampingMode::Rate;
  cfg.particleContact.normalDampingRate = 1813.0;
  cfg.particleContact.tangentialDampingRate = 906.0;
  cfg.particleContact.limitDamping = false;
  cfg.wallContact = cfg.particleContact;
  cfg.timeStep = 2.5e-5;
  cfg.skin = 0.2 * meanDiameter * (1.0 + sizeRange);
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = radius;
  return cfg;
}

/// \brief A drum of n particles after warm-up, rotating at 3 rpm.
template <class ExecutionSpace> dem::DemSystem<ExecutionSpace> warmDrum(std::size_t n) {
  const double radius = drumRadiusFor(n, meanDiameter);
  dem::DemSystem<ExecutionSpace> system(drumConfig(radius));
  system.setParticles(latticeBed(n, radius));
  system.setDrumAngularVelocity(rpm * 2.0 * constants::pi / 60.0);
  system.advance(n >= 100000 ? 100 : 300);
  return system;
}

/// \brief Touching neighbour slots (both sides of a pair counted) of the current state.
template <class ExecutionSpace>
std::int64_t touchingSlots(dem::DemSystem<ExecutionSpace> const& system) {
  const auto& p = system.particles();
  const auto& list = system.neighborRows();
  auto x = p.position;
  auto radius = p.radius;
  auto count = list.count;
  auto index = list.index;
  std::int64_t touching = 0;
  Kokkos::parallel_reduce(
      "hikiln::perf::dem::touching",
      Kokkos::RangePolicy<ExecutionSpace>(system.executionSpace(), 0, p.count()),
      KOKKOS_LAMBDA(int i, std::int64_t& sum) {
        for (int k = 0; k < count(i); ++k) {
          const int j = index(i, k);
          const double dx = x(j, 0) - x(i, 0), dy = x(j, 1) - x(i, 1);
          const double rs = radius(i) + radius(j);
          sum += dx * dx + dy * dy < rs * rs ? 1 : 0;
        }
      },
      touching);
  return touching;
}

/// \brief Counters common to both benchmarks.
template <class ExecutionSpace>
void reportDrum(benchmark::State& state, dem::DemSystem<ExecutionSpace> const& system) {
  const auto n = static_cast<double>(system.size());
  state.SetLabel(std::to_string(system.size()) + " particles");
  state.counters["bytes/particle"] =
      benchmark::Counter(static_cast<double>(system.memoryBytes()) / n);
  state.counters["contacts/particle"] =
      benchmark::Counter(static_cast<double>(touchingSlots(system)) / n);
  state.counters["rebuilds"] = benchmark::Counter(static_cast<double>(system.rebuildCount()));
}

/// \brief Full time steps; one iteration advances about 1e6 particle-steps.
template <class ExecutionSpace>
void benchmarkStep(Backend<ExecutionSpace>, benchmark::State& state) {
  auto system = warmDrum<ExecutionSpace>(static_cast<std::size_t>(state.range(0)));
  const auto n = static_cast<std::int64_t>(system.size());
  const std::int64_t steps = std::max<std::int64_t>(1, 1000000 / n);
  const double seconds =
      timeIterations(state, system.executionSpace(), [&] { system.advance(steps); });
  const auto particleSteps =
      static_cast<double>(n * steps) * static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<std::int64_t>(particleSteps));
  state.counters["particle_steps/s"] =
      benchmark::Counter(seconds > 0.0 ? particleSteps / seconds : 0.0);
  if (!std::isfinite(system.energy().kinetic())) {
    state.SkipWithError("the drum blew up (non-finite kinetic energy)");
    return;
  }
  reportDrum(state, system);
}

/// \brief The neighbour-list rebuild alone (bounds, binning, in-place list build with history).
template <class ExecutionSpace>
void benchmarkRebuild(Backend<ExecutionSpace>, benchmark::State& state) {
  auto system = warmDrum<ExecutionSpace>(static_cast<std::size_t>(state.range(0)));
  const double n = static_cast<double>(system.size());
  const double seconds =
      timeIterations(state, system.executionSpace(), [&] { system.forceRebuild(); });
  const double particles = n * static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<std::int64_t>(particles));
  state.counters["particles/s"] = benchmark::Counter(seconds > 0.0 ? particles / seconds : 0.0);
  reportDrum(state, system);
}

void registerDem() {
  const auto counts = particleCounts();
  registerPerBackend("dem_step", counts,
                     [](auto backend, benchmark::State& state) { benchmarkStep(backend, state); });
  registerPerBackend("dem_rebuild", counts, [](auto backend, benchmark::State& state) {
    benchmarkRebuild(backend, state);
  });
}

HIKILN_PERF_REGISTER(registerDem);

} // namespace
} // namespace hikiln::perf
