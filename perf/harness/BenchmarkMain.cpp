/// \file BenchmarkMain.cpp
/// \brief Entry point of hikiln_bench: Kokkos up, context recorded, benchmarks registered and run.

#include "perf/harness/Backends.hpp"
#include "perf/harness/RunContext.hpp"

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

int main(int argc, char** argv) {
  // Kokkos first: it consumes its own --kokkos-* arguments before Google Benchmark sees argv.
  Kokkos::ScopeGuard kokkos(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
    return 1;
  }
  hikiln::perf::addRunContext();
  hikiln::perf::registerAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
