/// \file DemBatch.cpp
/// \brief Batched DEM slices (solvers/dem/DemBatch.hpp) against the same slices advanced one after
/// another: K drums of 1000 particles (the dem_step drum, each turning at its own speed between
/// 1.5 and 6 rpm), K = 4, 16, 64 (those within HIKILN_BENCH_MAX_PARTICLES; below 4000 the four
/// slices get fewer particles). Each benchmark
/// iteration advances every slice by the same number of steps (about 1e6 particle-steps in all)
/// twice, once batched and once slice by slice, alternating, so that both rates are measured under
/// the same machine load. Counters: particle_steps/s (batched, summed over the slices),
/// sequential_particle_steps/s and speedup = their ratio.

#include "solvers/dem/DemBatch.hpp"
#include "perf/bench/DrumSetup.hpp"
#include "perf/harness/Backends.hpp"

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hikiln::perf {
namespace {

using namespace drum;

inline constexpr std::int64_t particlesPerSlice = 1000;

/// \brief Particles per slice for `slices` slices: 1000, fewer under a small
/// HIKILN_BENCH_MAX_PARTICLES (the smoke test).
std::size_t sliceSize(std::int64_t slices) {
  return static_cast<std::size_t>(std::min(particlesPerSlice, particleCounts().back() / slices));
}

template <class ExecutionSpace>
void benchmarkBatch(Backend<ExecutionSpace>, benchmark::State& state) {
  const auto slices = static_cast<int>(state.range(0));
  std::vector<dem::DemSystem<ExecutionSpace>> alone;
  dem::DemBatch<ExecutionSpace> batch;
  for (int k = 0; k < slices; ++k) {
    alone.push_back(warmDrum<ExecutionSpace>(sliceSize(slices)));
    const double rpm = 1.5 + 4.5 * k / std::max(1, slices - 1);
    alone.back().setDrumAngularVelocity(rpm * 2.0 * constants::pi / 60.0);
    batch.add(alone.back());
  }
  batch.start();
  const auto n = static_cast<std::int64_t>(batch.size());
  const std::int64_t steps = std::max<std::int64_t>(1, 1000000 / n);
  const ExecutionSpace space;
  double batchedSeconds = 0.0, sequentialSeconds = 0.0;
  for (auto _ : state) {
    space.fence();
    Kokkos::Timer timer;
    batch.advance(steps);
    space.fence();
    const double batched = timer.seconds();
    timer.reset();
    for (auto& system : alone) {
      system.advance(steps);
    }
    space.fence();
    const double sequential = timer.seconds();
    state.SetIterationTime(batched);
    batchedSeconds += batched;
    sequentialSeconds += sequential;
  }
  const double particleSteps =
      static_cast<double>(n * steps) * static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<std::int64_t>(particleSteps));
  state.SetLabel(std::to_string(slices) + " slices, " + std::to_string(n) + " particles");
  state.counters["particle_steps/s"] =
      benchmark::Counter(batchedSeconds > 0.0 ? particleSteps / batchedSeconds : 0.0);
  state.counters["sequential_particle_steps/s"] =
      benchmark::Counter(sequentialSeconds > 0.0 ? particleSteps / sequentialSeconds : 0.0);
  state.counters["speedup"] =
      benchmark::Counter(batchedSeconds > 0.0 ? sequentialSeconds / batchedSeconds : 0.0);
}

void registerDemBatch() {
  std::vector<std::int64_t> sliceCounts = {4}; // more within HIKILN_BENCH_MAX_PARTICLES
  for (const std::int64_t k : {16, 64}) {
    if (k * particlesPerSlice <= particleCounts().back()) {
      sliceCounts.push_back(k);
    }
  }
  registerPerBackend("dem_batch", sliceCounts,
                     [](auto backend, benchmark::State& state) { benchmarkBatch(backend, state); });
}

HIKILN_PERF_REGISTER(registerDemBatch);

} // namespace
} // namespace hikiln::perf
