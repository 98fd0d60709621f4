#pragma once
/// \file RunContext.hpp
/// \brief Describes the build and the machine in the "context" block of the benchmark JSON.

namespace hikiln::perf {

/// \brief Adds hikiln and Kokkos versions, enabled backends, thread count, OpenMP binding, host
/// name and CPU model to the benchmark context (call after Kokkos::initialize).
void addRunContext();

} // namespace hikiln::perf
