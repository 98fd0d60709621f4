/// \file LaunchCounter.cpp
/// \brief A Kokkos profiling tool that counts the kernel launches of a run and times them, per
/// kernel label: where a run's time goes, and how many launches (each a fork and join on the
/// OpenMP backend) a time step makes.
///
/// Load it through Kokkos' tools interface and name the output file:
///
///     export KOKKOS_PROFILE_LIBRARY=build/perf/libhikiln_launch_counter.so
///     HIKILN_LAUNCH_COUNTS=counts.txt hikiln -q continuum CASE ...
///
/// At Kokkos::finalize() it writes one line per label, the longest total first:
/// seconds, launches, microseconds per launch, label; after a first line with the run's wall
/// time, the time inside kernels and the launch count. Without HIKILN_LAUNCH_COUNTS it writes
/// to standard error. The time of a launch is from its begin to its end callback on the
/// launching thread: on the host that is the launch itself, on CUDA only the enqueue (fence
/// first, e.g. CUDA_LAUNCH_BLOCKING=1, to time the kernels). It adds about a microsecond to
/// each launch, so compare runs that both load it.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct LabelTotals {
  std::int64_t launches = 0;
  double seconds = 0.0;
};

struct OpenLaunch {
  std::string label;
  Clock::time_point start;
};

Clock::time_point runStart;
std::map<std::string, LabelTotals> totals;
std::unordered_map<std::uint64_t, OpenLaunch> open;
std::uint64_t nextId = 1;

void begin(const char* label, std::uint64_t* id) {
  *id = nextId++;
  open[*id] = OpenLaunch{label, Clock::now()};
}

void end(std::uint64_t id) {
  const auto found = open.find(id);
  if (found == open.end()) {
    return;
  }
  LabelTotals& label = totals[found->second.label];
  ++label.launches;
  label.seconds += std::chrono::duration<double>(Clock::now() - found->second.start).count();
  open.erase(found);
}

void writeCounts(std::FILE* out) {
  std::vector<std::pair<std::string, LabelTotals>> rows(totals.begin(), totals.end());
  std::sort(rows.begin(), rows.end(),
            [](auto const& a, auto const& b) { return a.second.seconds > b.second.seconds; });
  double inKernels = 0.0;
  std::int64_t launches = 0;
  for (auto const& row : rows) {
    inKernels += row.second.seconds;
    launches += row.second.launches;
  }
  const double wall = std::chrono::duration<double>(Clock::now() - runStart).count();
  std::fprintf(out, "total %.3f s, in kernels %.3f s, launches %lld\n", wall, inKernels,
               static_cast<long long>(launches));
  for (auto const& row : rows) {
    std::fprintf(out, "%10.4f s %9lld %10.2f us  %s\n", row.second.seconds,
                 static_cast<long long>(row.second.launches),
                 1e6 * row.second.seconds / static_cast<double>(row.second.launches),
                 row.first.c_str());
  }
}

} // namespace

// The entry points Kokkos looks up by name (Kokkos_Profiling_C_Interface.h).
extern "C" {

void kokkosp_init_library(int, std::uint64_t, std::uint32_t, void*) {
  runStart = Clock::now();
}

void kokkosp_begin_parallel_for(const char* label, std::uint32_t, std::uint64_t* id) {
  begin(label, id);
}
void kokkosp_end_parallel_for(std::uint64_t id) {
  end(id);
}
void kokkosp_begin_parallel_reduce(const char* label, std::uint32_t, std::uint64_t* id) {
  begin(label, id);
}
void kokkosp_end_parallel_reduce(std::uint64_t id) {
  end(id);
}
void kokkosp_begin_parallel_scan(const char* label, std::uint32_t, std::uint64_t* id) {
  begin(label, id);
}
void kokkosp_end_parallel_scan(std::uint64_t id) {
  end(id);
}

void kokkosp_finalize_library() {
  const char* path = std::getenv("HIKILN_LAUNCH_COUNTS");
  if (path == nullptr || *path == '\0') {
    writeCounts(stderr);
    return;
  }
  // write-then-rename, so a reader never sees half a table
  const std::string partial = std::string(path) + ".partial";
  std::FILE* out = std::fopen(partial.c_str(), "w");
  if (out == nullptr) {
    std::fprintf(stderr, "hikiln_launch_counter: cannot write %s; counts follow\n",
                 partial.c_str());
    writeCounts(stderr);
    return;
  }
  writeCounts(out);
  const bool written = std::fclose(out) == 0;
  if (!written || std::rename(partial.c_str(), path) != 0) {
    std::fprintf(stderr, "hikiln_launch_counter: cannot write %s\n", path);
  }
}

} // extern "C"
