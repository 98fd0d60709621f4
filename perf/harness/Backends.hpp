#pragma once
/// \file Backends.hpp
/// \brief Registers each benchmark once per Kokkos backend compiled in ("copy/OpenMP/1048576").
///
/// Benchmark files call HIKILN_PERF_REGISTER(function) at namespace scope; the functions run from
/// main() after Kokkos is initialised, so they may read the environment and the Kokkos setup.

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace hikiln::perf {

/// \brief Type tag for one backend: names the execution space without constructing an instance
/// (which is not allowed before Kokkos::initialize).
template <class ExecutionSpace> struct Backend { using execution_space = ExecutionSpace; };

/// \brief Calls f(Backend<Space>{}) for every backend this Kokkos was built with.
template <class Function> void forEachBackend(Function&& f) {
#if defined(KOKKOS_ENABLE_SERIAL)
  f(Backend<Kokkos::Serial>{});
#endif
#if defined(KOKKOS_ENABLE_OPENMP)
  f(Backend<Kokkos::OpenMP>{});
#endif
#if defined(KOKKOS_ENABLE_CUDA)
  f(Backend<Kokkos::Cuda>{});
#endif
}

/// \brief Names of the backends forEachBackend visits, comma separated ("Serial,OpenMP").
inline std::string enabledBackendNames() {
  std::string names;
  forEachBackend([&names](auto backend) {
    using execution_space = typename decltype(backend)::execution_space;
    names += (names.empty() ? "" : ",") + std::string(execution_space::name());
  });
  return names;
}

/// \brief Registers body once per enabled backend as "<name>/<Backend>/<arg>" for each of args,
/// with manual timing (body must call timeIterations) and results in milliseconds.
/// body is callable as body(Backend<ExecutionSpace>{}, benchmark::State&).
template <class Body>
void registerPerBackend(std::string const& name, std::vector<std::int64_t> const& args, Body body) {
  forEachBackend([&](auto backend) {
    using execution_space = typename decltype(backend)::execution_space;
    const std::string fullName = name + "/" + execution_space::name();
    auto* bench = benchmark::RegisterBenchmark(fullName.c_str(), [body](benchmark::State& state) {
      body(Backend<execution_space>{}, state);
    });
    for (const std::int64_t arg : args) {
      bench->Arg(arg);
    }
    bench->UseManualTime()->Unit(benchmark::kMillisecond);
  });
}

/// \brief The registration functions collected by HIKILN_PERF_REGISTER, in link order.
inline std::vector<void (*)()>& registrationFunctions() {
  static std::vector<void (*)()> functions;
  return functions;
}

/// \brief Queues a registration function to be run by registerAll(); returns true.
inline bool addRegistration(void (*function)()) {
  registrationFunctions().push_back(function);
  return true;
}

/// \brief Runs every queued registration function (call once, after Kokkos is initialised).
inline void registerAll() {
  for (auto* function : registrationFunctions()) {
    function();
  }
}

} // namespace hikiln::perf

#define HIKILN_PERF_CONCAT_INNER(a, b) a##b
#define HIKILN_PERF_CONCAT(a, b) HIKILN_PERF_CONCAT_INNER(a, b)
/// \brief Queues function (a `void()` that calls registerPerBackend) to run from main().
#define HIKILN_PERF_REGISTER(function)                                                             \
  [[maybe_unused]] static const bool HIKILN_PERF_CONCAT(hikilnPerfRegistered_, __LINE__) =         \
      ::hikiln::perf::addRegistration(&(function))
