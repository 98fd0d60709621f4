/// \file Launch.cpp
/// \brief The cost of a kernel launch itself: a run of back-to-back parallel_for over a few
/// elements (a(i) += 1), timed per launch. On the OpenMP backend of Kokkos 3.4 every launch opens
/// a parallel region (a fork and a join of the threads), so a solver that makes thousands of
/// small launches per time step (the coarse multigrid levels, the shell cells, the Krylov
/// vector operations) pays this per launch; perf/README.md counts them with the launch counter
/// (perf/tools/LaunchCounter.cpp).

#include "perf/harness/Backends.hpp"
#include "perf/harness/Timing.hpp"

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hikiln::perf {

/// Launches per timed iteration: enough that the fences around the run do not count.
constexpr int launchesPerIteration = 1000;

/// launchesPerIteration launches of a(i) += 1 over a's elements.
template <class ExecutionSpace>
void launchRun(ExecutionSpace const& space,
               Kokkos::View<double*, typename ExecutionSpace::memory_space> const& a) {
  for (int n = 0; n < launchesPerIteration; ++n) {
    Kokkos::parallel_for(
        "hikiln::perf::launch", Kokkos::RangePolicy<ExecutionSpace>(space, 0, a.extent(0)),
        KOKKOS_LAMBDA(const std::int64_t i) { a(i) += 1.0; });
  }
}

namespace {

/// Benchmark body: state.range(0) is the elements per launch.
template <class ExecutionSpace>
void benchmarkLaunch(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const auto n = static_cast<std::size_t>(state.range(0));
  Kokkos::View<double*, typename ExecutionSpace::memory_space> a(
      Kokkos::view_alloc(space, "hikiln::perf::launch::a"), n);
  const double seconds = timeIterations(state, space, [&] { launchRun(space, a); });
  // every element was incremented once per launch
  const double expected = static_cast<double>(state.iterations()) * launchesPerIteration;
  double wrong = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::perf::launch::check", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(const std::int64_t i, double& count) { count += a(i) != expected ? 1.0 : 0.0; },
      wrong);
  if (wrong != 0.0) {
    state.SkipWithError("a launch was lost");
    return;
  }
  state.SetLabel(std::to_string(n) + " elements");
  const double launches = static_cast<double>(state.iterations()) * launchesPerIteration;
  state.counters["us/launch"] = benchmark::Counter(launches > 0.0 ? 1e6 * seconds / launches : 0.0);
}

void registerLaunch() {
  registerPerBackend("kokkos_launch", {2, 64, 1024}, [](auto backend, benchmark::State& state) {
    benchmarkLaunch(backend, state);
  });
}

} // namespace

HIKILN_PERF_REGISTER(registerLaunch);

} // namespace hikiln::perf
