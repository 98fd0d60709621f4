#pragma once
/// \file Timing.hpp
/// \brief Manual timing of Kokkos kernels for Google Benchmark (asynchronous backends need a
/// fence on both sides, so the library's own wall clock would be wrong on CUDA).

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <cstdint>

namespace hikiln::perf {

/// \brief Runs kernel() once per benchmark iteration between two fences of space, reports each
/// run's wall time with SetIterationTime and returns the summed seconds.
template <class ExecutionSpace, class Kernel>
double timeIterations(benchmark::State& state, ExecutionSpace const& space, Kernel&& kernel) {
  double totalSeconds = 0.0;
  for (auto _ : state) {
    space.fence();
    Kokkos::Timer timer;
    kernel();
    space.fence();
    const double seconds = timer.seconds();
    state.SetIterationTime(seconds);
    totalSeconds += seconds;
  }
  return totalSeconds;
}

/// \brief Reports bytesPerIteration moved per iteration as bytes_per_second and as a decimal
/// "GB/s" counter computed from the measured (manual) time.
inline void reportBandwidth(benchmark::State& state, double bytesPerIteration,
                            double totalSeconds) {
  const auto iterations = static_cast<double>(state.iterations());
  state.SetBytesProcessed(static_cast<std::int64_t>(bytesPerIteration * iterations));
  state.counters["GB/s"] = benchmark::Counter(
      totalSeconds > 0.0 ? bytesPerIteration * iterations / totalSeconds / 1e9 : 0.0);
}

} // namespace hikiln::perf
