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

#include "perf/bench/DrumSetup.hpp"
#include "perf/harness/Backends.hpp"
#include "perf/harness/Timing.hpp"

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

using namespace drum;

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
