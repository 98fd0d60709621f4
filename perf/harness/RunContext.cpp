/// \file RunContext.cpp
/// \brief Build and machine description for the benchmark JSON context.

#include "perf/harness/RunContext.hpp"

#include "kernels/common/Compat.hpp"
#include "perf/harness/Backends.hpp"

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

#ifndef HIKILN_VERSION
#define HIKILN_VERSION "unknown"
#endif
#ifndef HIKILN_BUILD_TYPE
#define HIKILN_BUILD_TYPE "unknown"
#endif

namespace hikiln::perf {
namespace {

/// \brief The environment variable's value, or "(unset)".
std::string environmentValue(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? std::string(value) : std::string("(unset)");
}

/// \brief This machine's host name.
std::string hostName() {
  char buffer[256] = {};
  if (gethostname(buffer, sizeof(buffer) - 1) != 0) {
    return "unknown";
  }
  return buffer;
}

/// \brief The first "model name" in /proc/cpuinfo (Linux), else "unknown".
std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        const auto start = line.find_first_not_of(" \t", colon + 1);
        return start == std::string::npos ? std::string() : line.substr(start);
      }
    }
  }
  return "unknown";
}

/// \brief The compiler that built the harness.
std::string compilerName() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("gcc ") + __VERSION__;
#else
  return "unknown";
#endif
}

} // namespace

void addRunContext() {
  benchmark::AddCustomContext("hikiln_version", HIKILN_VERSION);
  benchmark::AddCustomContext("hikiln_build_type", HIKILN_BUILD_TYPE);
  benchmark::AddCustomContext("compiler", compilerName());
  benchmark::AddCustomContext("kokkos_version", hikiln::kokkosVersionString());
  benchmark::AddCustomContext("kokkos_backends", enabledBackendNames());
  benchmark::AddCustomContext("kokkos_default_execution_space",
                              Kokkos::DefaultExecutionSpace::name());
#if defined(KOKKOS_ENABLE_OPENMP)
  benchmark::AddCustomContext("openmp_threads", std::to_string(Kokkos::OpenMP{}.concurrency()));
#endif
  benchmark::AddCustomContext("omp_num_threads", environmentValue("OMP_NUM_THREADS"));
  benchmark::AddCustomContext("omp_proc_bind", environmentValue("OMP_PROC_BIND"));
  benchmark::AddCustomContext("omp_places", environmentValue("OMP_PLACES"));
  benchmark::AddCustomContext("hostname", hostName());
  benchmark::AddCustomContext("cpu_model", cpuModel());
}

} // namespace hikiln::perf
