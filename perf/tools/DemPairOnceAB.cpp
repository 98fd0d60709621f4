/// \file DemPairOnceAB.cpp
/// \brief The disc force kernel with and without `neighbor.pair_once`, timed in turns inside one
/// process: two copies of one warmed-up benchmark drum (perf/bench/DrumSetup.hpp) advance slices
/// of S steps alternately (the order swapped every round), R rounds. Whole runs taken one after
/// the other drift by 20 % and more on a shared VM; slices a fraction of a second apart see the
/// same machine, so their ratio is steadier, and it works on two threads, where runs side by side
/// on the two cores (perf/scripts/side_by_side.sh) cannot go.
///
///     hikiln_dem_pair_once_ab PARTICLES ROUNDS SLICE_STEPS [Kokkos options]
///     OMP_NUM_THREADS=2 hikiln_dem_pair_once_ab 1800 60 2000      # the base drum's size
///     OMP_NUM_THREADS=2 hikiln_dem_pair_once_ab 100000 16 100
///
/// Prints both rates (particle-steps/s over all slices), the ratio of the total times and the
/// median and quartiles of the per-round ratios (above 1: pair-once is faster), and each system's
/// DemSystem::memoryBytes() per particle.

#include "perf/bench/DrumSetup.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using ExecutionSpace = Kokkos::DefaultExecutionSpace;
using System = hikiln::dem::DemSystem<ExecutionSpace>;

long positiveArgument(const char* text, const char* name) {
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || value < 1) {
    throw std::invalid_argument(std::string(name) + " must be a positive integer, got '" + text +
                                "'");
  }
  return value;
}

double secondsToAdvance(System& system, long steps) {
  Kokkos::fence();
  const auto start = std::chrono::steady_clock::now();
  system.advance(steps);
  Kokkos::fence();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int run(long particles, long rounds, long slice) {
  auto warm = hikiln::perf::drum::warmDrum<ExecutionSpace>(static_cast<std::size_t>(particles));
  warm.advance(particles >= 100000 ? 2000 : 20000); // from the lattice towards a flowing bed
  const hikiln::dem::DemState start = warm.exportState();
  hikiln::dem::DemConfig fullRows = warm.config(), pairOnce = fullRows;
  pairOnce.pairOnceForces = true;
  System a(fullRows), b(pairOnce);
  a.importState(start);
  b.importState(start);
  double timeA = 0.0, timeB = 0.0;
  std::vector<double> ratios;
  for (long r = 0; r < rounds; ++r) {
    const bool aFirst = r % 2 == 0;
    const double first = secondsToAdvance(aFirst ? a : b, slice);
    const double second = secondsToAdvance(aFirst ? b : a, slice);
    const double ta = aFirst ? first : second, tb = aFirst ? second : first;
    timeA += ta;
    timeB += tb;
    ratios.push_back(ta / tb);
  }
  if (!(std::isfinite(a.energy().kinetic()) && std::isfinite(b.energy().kinetic()))) {
    std::fprintf(stderr, "hikiln_dem_pair_once_ab: a drum blew up (non-finite kinetic energy)\n");
    return 1;
  }
  std::sort(ratios.begin(), ratios.end());
  const double particleSteps = static_cast<double>(start.size() * slice * rounds);
  const double n = static_cast<double>(start.size());
  std::printf("%zu particles, %d threads, %ld rounds of %ld steps: full rows %.3e, pair-once %.3e "
              "particle-steps/s; pair-once faster by %.3f in total, median round %.3f "
              "(quartiles %.3f-%.3f); bytes/particle %.0f and %.0f\n",
              start.size(), ExecutionSpace().concurrency(), rounds, slice, particleSteps / timeA,
              particleSteps / timeB, timeA / timeB, ratios[ratios.size() / 2],
              ratios[ratios.size() / 4], ratios[(3 * ratios.size()) / 4],
              static_cast<double>(a.memoryBytes()) / n, static_cast<double>(b.memoryBytes()) / n);
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  Kokkos::ScopeGuard guard(argc, argv); // takes the Kokkos options out of argv
  try {
    if (argc != 4) {
      std::fprintf(stderr, "usage: %s PARTICLES ROUNDS SLICE_STEPS [Kokkos options]\n", argv[0]);
      return 2;
    }
    return run(positiveArgument(argv[1], "PARTICLES"), positiveArgument(argv[2], "ROUNDS"),
               positiveArgument(argv[3], "SLICE_STEPS"));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hikiln_dem_pair_once_ab: %s\n", e.what());
    return 2;
  }
}
