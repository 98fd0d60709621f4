/// \file Bandwidth.cpp
/// \brief STREAM-like memory bandwidth: copy (b = a) and triad (a = b + s c) on Views of doubles.
/// This is the roofline for every bandwidth-bound kernel in hikiln (STREAM byte counting: copy
/// moves 2 arrays per iteration, triad 3; write-allocate traffic is not counted).

#include "perf/harness/Backends.hpp"
#include "perf/harness/Timing.hpp"

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace hikiln::perf {
namespace {

constexpr std::int64_t bytesPerMiB = 1024 * 1024;
constexpr double triadScalar = 3.0;

/// \brief Array sizes in bytes: 8, 64 and 512 MiB, where HIKILN_BENCH_MAX_MIB replaces the
/// largest (smaller defaults are kept), so CI smoke runs stay small.
std::vector<std::int64_t> arraySizesBytes() {
  std::int64_t maxMiB = 512;
  if (const char* text = std::getenv("HIKILN_BENCH_MAX_MIB")) {
    char* end = nullptr;
    const long long value = std::strtoll(text, &end, 10);
    if (end != text && *end == '\0' && value >= 1) {
      maxMiB = value;
    } else {
      std::cerr << "hikiln_bench: ignoring HIKILN_BENCH_MAX_MIB='" << text
                << "' (want an integer >= 1)\n";
    }
  }
  std::vector<std::int64_t> sizes;
  for (const std::int64_t mib : {std::int64_t{8}, std::int64_t{64}}) {
    if (mib < maxMiB) {
      sizes.push_back(mib * bytesPerMiB);
    }
  }
  sizes.push_back(maxMiB * bytesPerMiB);
  return sizes;
}

/// \brief A 1D array of doubles in the execution space's memory space.
template <class ExecutionSpace>
using ArrayView = Kokkos::View<double*, typename ExecutionSpace::memory_space>;

/// \brief Allocates an uninitialised array and fills it with value using the same execution
/// space, so pages are first touched by the threads that will stream them.
template <class ExecutionSpace>
ArrayView<ExecutionSpace> firstTouchArray(ExecutionSpace const& space, std::string const& label,
                                          std::size_t n, double value) {
  ArrayView<ExecutionSpace> array(Kokkos::view_alloc(space, Kokkos::WithoutInitializing, label), n);
  Kokkos::parallel_for(
      "hikiln::perf::bandwidth::firstTouch", Kokkos::RangePolicy<ExecutionSpace>(space, 0, n),
      KOKKOS_LAMBDA(const std::size_t i) { array(i) = value; });
  return array;
}

/// \brief STREAM copy: target = source.
template <class ExecutionSpace, class SourceView, class TargetView>
void streamCopy(ExecutionSpace const& space, SourceView const& source, TargetView const& target) {
  static_assert(
      Kokkos::SpaceAccessibility<ExecutionSpace, typename SourceView::memory_space>::accessible,
      "source must be accessible from the execution space");
  static_assert(
      Kokkos::SpaceAccessibility<ExecutionSpace, typename TargetView::memory_space>::accessible,
      "target must be accessible from the execution space");
  Kokkos::parallel_for(
      "hikiln::perf::bandwidth::copy",
      Kokkos::RangePolicy<ExecutionSpace>(space, 0, source.extent(0)),
      KOKKOS_LAMBDA(const std::size_t i) { target(i) = source(i); });
}

/// \brief STREAM triad: a = b + scalar * c.
template <class ExecutionSpace, class ViewA, class ViewB, class ViewC>
void streamTriad(ExecutionSpace const& space, ViewA const& a, ViewB const& b, ViewC const& c,
                 double scalar) {
  static_assert(
      Kokkos::SpaceAccessibility<ExecutionSpace, typename ViewA::memory_space>::accessible,
      "a must be accessible from the execution space");
  static_assert(
      Kokkos::SpaceAccessibility<ExecutionSpace, typename ViewB::memory_space>::accessible,
      "b must be accessible from the execution space");
  static_assert(
      Kokkos::SpaceAccessibility<ExecutionSpace, typename ViewC::memory_space>::accessible,
      "c must be accessible from the execution space");
  Kokkos::parallel_for(
      "hikiln::perf::bandwidth::triad", Kokkos::RangePolicy<ExecutionSpace>(space, 0, a.extent(0)),
      KOKKOS_LAMBDA(const std::size_t i) { a(i) = b(i) + scalar * c(i); });
}

/// \brief How many elements of array differ from expected (checked after timing, not timed).
template <class ExecutionSpace, class View>
std::size_t countMismatches(ExecutionSpace const& space, View const& array, double expected) {
  static_assert(Kokkos::SpaceAccessibility<ExecutionSpace, typename View::memory_space>::accessible,
                "array must be accessible from the execution space");
  std::size_t mismatches = 0;
  Kokkos::parallel_reduce(
      "hikiln::perf::bandwidth::check",
      Kokkos::RangePolicy<ExecutionSpace>(space, 0, array.extent(0)),
      KOKKOS_LAMBDA(const std::size_t i, std::size_t& count) {
        count += array(i) != expected ? 1 : 0;
      },
      mismatches);
  return mismatches;
}

/// \brief Labels the result with the array size in MiB (the name carries it in bytes).
void labelArraySize(benchmark::State& state) {
  state.SetLabel(std::to_string(state.range(0) / bytesPerMiB) + " MiB");
}

/// \brief Benchmark body for copy on one backend; state.range(0) is the bytes per array.
template <class ExecutionSpace>
void benchmarkCopy(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const auto n = static_cast<std::size_t>(state.range(0)) / sizeof(double);
  const auto a = firstTouchArray(space, "hikiln::perf::bandwidth::a", n, 1.0);
  const auto b = firstTouchArray(space, "hikiln::perf::bandwidth::b", n, 0.0);
  const double seconds = timeIterations(state, space, [&] { streamCopy(space, a, b); });
  if (countMismatches(space, b, 1.0) != 0) {
    state.SkipWithError("copy produced a wrong value");
    return;
  }
  labelArraySize(state);
  reportBandwidth(state, 2.0 * static_cast<double>(n * sizeof(double)), seconds);
}

/// \brief Benchmark body for triad on one backend; state.range(0) is the bytes per array.
template <class ExecutionSpace>
void benchmarkTriad(Backend<ExecutionSpace>, benchmark::State& state) {
  const ExecutionSpace space{};
  const auto n = static_cast<std::size_t>(state.range(0)) / sizeof(double);
  const auto a = firstTouchArray(space, "hikiln::perf::bandwidth::a", n, 0.0);
  const auto b = firstTouchArray(space, "hikiln::perf::bandwidth::b", n, 1.0);
  const auto c = firstTouchArray(space, "hikiln::perf::bandwidth::c", n, 2.0);
  const double seconds =
      timeIterations(state, space, [&] { streamTriad(space, a, b, c, triadScalar); });
  if (countMismatches(space, a, 1.0 + triadScalar * 2.0) != 0) {
    state.SkipWithError("triad produced a wrong value");
    return;
  }
  labelArraySize(state);
  reportBandwidth(state, 3.0 * static_cast<double>(n * sizeof(double)), seconds);
}

/// \brief Registers copy and triad for every backend and array size.
void registerBandwidth() {
  const auto sizes = arraySizesBytes();
  registerPerBackend("copy", sizes,
                     [](auto backend, benchmark::State& state) { benchmarkCopy(backend, state); });
  registerPerBackend("triad", sizes,
                     [](auto backend, benchmark::State& state) { benchmarkTriad(backend, state); });
}

HIKILN_PERF_REGISTER(registerBandwidth);

} // namespace
} // namespace hikiln::perf
