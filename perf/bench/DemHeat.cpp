/// \file DemHeat.cpp
/// \brief The cost of DEM heat transfer (physics.md 6.1) on top of the mechanical step: the drum of
/// Dem.cpp advanced as `hikiln dem` does with heat on, a heat step every 10 mechanical steps
/// (heat.step_every default), 8 shells, particles at 673 K left / 1073 K right of the axis.
///
/// - `dem_heat_step`: radiation between touching neighbours + intra-particle conduction, contact
///   conduction off (the physics.md 6.2 thermal runs, the case-file defaults);
/// - `dem_heat_contact_step`: contact conduction (boundary layers, Hertz area) on as well.
///
/// Counters: particle_steps/s of the whole (mechanics + heat) and heat_overhead, the time spent in
/// heat steps over the time spent in mechanical steps, both fenced and timed inside the same
/// iterations (so it does not depend on a separate run of dem_step under different machine load).
/// The goal: heat_overhead <= 0.5.

#include "solvers/dem/heat/DemHeat.hpp"
#include "perf/bench/DrumSetup.hpp"
#include "perf/harness/Backends.hpp"
#include "perf/harness/Timing.hpp"

#include <Kokkos_Core.hpp>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace hikiln::perf {
namespace {

constexpr std::int64_t heatEvery = 10;

/// \brief The case-file heat defaults (drivers/dem/HeatCase.cpp): radiation between touching
/// pairs only, 8 shells, sphere geometry (the drum's mass convention).
dem::HeatParameters heatParameters(bool contactConduction) {
  dem::HeatParameters p;
  p.contactConduction = contactConduction;
  p.radiation = true;
  p.radiationRange = 0.0;
  return p;
}

template <class ExecutionSpace>
void benchmarkHeatStep(Backend<ExecutionSpace>, benchmark::State& state, bool contactConduction) {
  auto system = drum::warmDrum<ExecutionSpace>(static_cast<std::size_t>(state.range(0)));
  dem::DemHeat<ExecutionSpace> heat(heatParameters(contactConduction));
  heat.initialize(system, dem::leftRightTemperature(0.0, 673.0, 1073.0));
  const auto n = static_cast<std::int64_t>(system.size());
  const std::int64_t rounds = std::max<std::int64_t>(1, 1000000 / (n * heatEvery));
  const double heatDt = static_cast<double>(heatEvery) * system.timeStep();
  const auto space = system.executionSpace();
  double heatSeconds = 0.0;
  const double seconds = timeIterations(state, space, [&] {
    for (std::int64_t r = 0; r < rounds; ++r) {
      system.advance(heatEvery);
      space.fence();
      Kokkos::Timer timer;
      heat.step(system, heatDt);
      space.fence();
      heatSeconds += timer.seconds();
    }
  });
  const auto particleSteps =
      static_cast<double>(n * rounds * heatEvery) * static_cast<double>(state.iterations());
  state.SetItemsProcessed(static_cast<std::int64_t>(particleSteps));
  state.SetLabel(std::to_string(n) + " particles");
  state.counters["particle_steps/s"] =
      benchmark::Counter(seconds > 0.0 ? particleSteps / seconds : 0.0);
  state.counters["heat_overhead"] =
      benchmark::Counter(seconds > heatSeconds ? heatSeconds / (seconds - heatSeconds) : 0.0);
  if (!(std::fabs(heat.energyDrift()) < 1e-9)) {
    state.SkipWithError("heat energy not conserved (drift above 1e-9)");
  }
}

void registerDemHeat() {
  const auto counts = drum::particleCounts();
  registerPerBackend("dem_heat_step", counts, [](auto backend, benchmark::State& state) {
    benchmarkHeatStep(backend, state, false);
  });
  registerPerBackend("dem_heat_contact_step", counts, [](auto backend, benchmark::State& state) {
    benchmarkHeatStep(backend, state, true);
  });
}

HIKILN_PERF_REGISTER(registerDemHeat);

} // namespace
} // namespace hikiln::perf
