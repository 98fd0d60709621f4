/// \file LaunchCounterCheck.cpp
/// \brief Test of the launch counter (run by ctest with KOKKOS_PROFILE_LIBRARY set to it): makes
/// a known number of labelled launches, finalizes Kokkos (the tool writes its table) and checks
/// the counts the table gives for those labels. Exit code 0 when they match.

#include <Kokkos_Core.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

namespace hikiln::perf::launch_check {

constexpr int forLaunches = 7;
constexpr int reduceLaunches = 3;
constexpr int scanLaunches = 2;

void launchKnownKernels() {
  Kokkos::View<double*> values("hikiln::perf::launchCheck::values", 64);
  for (int n = 0; n < forLaunches; ++n) {
    Kokkos::parallel_for(
        "hikiln::perf::launchCheck::for", values.extent(0),
        KOKKOS_LAMBDA(const int i) { values(i) += 1.0; });
  }
  double sum = 0.0;
  for (int n = 0; n < reduceLaunches; ++n) {
    Kokkos::parallel_reduce(
        "hikiln::perf::launchCheck::reduce", values.extent(0),
        KOKKOS_LAMBDA(const int i, double& s) { s += values(i); }, sum);
  }
  for (int n = 0; n < scanLaunches; ++n) {
    Kokkos::parallel_scan(
        "hikiln::perf::launchCheck::scan", values.extent(0),
        KOKKOS_LAMBDA(const int i, double& partial, const bool last) {
          partial += values(i);
          if (last) {
            values(i) = partial;
          }
        });
  }
  Kokkos::fence();
}

/// Launch counts per label from the tool's table (lines "seconds s launches us-per-launch us
/// label").
std::map<std::string, long> readCounts(std::string const& path) {
  std::ifstream in(path);
  std::map<std::string, long> counts;
  std::string line;
  std::getline(in, line); // the totals
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    double seconds = 0.0, perLaunch = 0.0;
    long launches = 0;
    std::string unitS, unitUs, label;
    if (fields >> seconds >> unitS >> launches >> perLaunch >> unitUs >> label) {
      counts[label] = launches;
    }
  }
  return counts;
}

} // namespace hikiln::perf::launch_check

int main(int argc, char* argv[]) {
  using namespace hikiln::perf::launch_check;
  const char* path = std::getenv("HIKILN_LAUNCH_COUNTS");
  if (path == nullptr || std::getenv("KOKKOS_PROFILE_LIBRARY") == nullptr) {
    std::cerr << "launch counter check: set KOKKOS_PROFILE_LIBRARY and HIKILN_LAUNCH_COUNTS\n";
    return 2;
  }
  std::remove(path);
  Kokkos::initialize(argc, argv);
  launchKnownKernels();
  Kokkos::finalize();

  const auto counts = readCounts(path);
  const std::map<std::string, long> expected = {
      {"hikiln::perf::launchCheck::for", forLaunches},
      {"hikiln::perf::launchCheck::reduce", reduceLaunches},
      {"hikiln::perf::launchCheck::scan", scanLaunches}};
  int failures = 0;
  for (auto const& [label, launches] : expected) {
    const auto found = counts.find(label);
    const long got = found == counts.end() ? 0 : found->second;
    std::cout << label << ": " << got << " launches (expected " << launches << ")\n";
    failures += got == launches ? 0 : 1;
  }
  return failures == 0 ? 0 : 1;
}
