// The heat model coupled to a moving bed: a small rotating drum (200 discs, left half at 673 K,
// right half at 1073 K, contact conduction and radiation on) keeps its heat content to round-off
// through contacts forming and breaking, list rebuilds and particle reorders, whether heat is
// stepped after every mechanical step or every 20; temperatures are bitwise identical for any
// thread count (vs Kokkos::Serial), for any reorder schedule, and after an export/import restart.
#include "HeatTestUtils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
// on a device the compiler may contract a*b+c into FMA: compare with the host to round-off only
constexpr bool bitwiseVsHost =
    Kokkos::SpaceAccessibility<Kokkos::HostSpace, space::memory_space>::accessible;

DemConfig drumConfig(int sortEveryRebuilds = 2) {
  DemConfig cfg;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = 0.12;
  cfg.walls.drum.angularVelocity = 3.0;
  cfg.particleContact.normalStiffness = 2.0e3; // soft: the bed settles within a few 1000 steps
  cfg.particleContact.tangentialStiffness = 1.0e3;
  cfg.wallContact = cfg.particleContact;
  cfg.sortEveryRebuilds = sortEveryRebuilds;
  return cfg;
}

// A bed settled for 3000 steps in the rotating drum (computed once per test executable).
const DemState& settledBed() {
  static const DemState state = [] {
    auto h = test::drumParticles(200, 0.12, 0.005, 0.05, 0.05, 31, 1.05, true);
    assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
    DemSystem<space> sys(drumConfig());
    sys.setParticles(h);
    sys.advance(3000);
    return sys.exportState();
  }();
  return state;
}

// All mechanisms between particles on; the Overlap area so that conduction is visible within a
// fraction of a second (the Hertz area of these soft springs is tiny).
HeatParameters drumHeat(double radiationRange = -1.0) {
  HeatParameters p;
  p.geometry = MassConvention::Sphere;
  p.contactArea = ContactAreaModel::Overlap;
  p.radiationRange = radiationRange;
  return p;
}

const TemperatureField halves = leftRightTemperature(0.0, 673.0, 1073.0);

template <class System, class Heat> void advance(System& sys, Heat& heat, int steps, int every) {
  for (int s = 0; s < steps; ++s) {
    sys.step();
    if ((s + 1) % every == 0) {
      heat.step(sys, every * sys.timeStep());
    }
  }
}

std::size_t touchingLayers(const DemHeatState& s) {
  return s.contactId.size();
}

TEST(TEST_CATEGORY, heat_drum_conserves_heat_content) {
  DemSystem<space> sys(drumConfig());
  sys.importState(settledBed());
  DemHeat<space> heat(drumHeat());
  heat.initialize(sys, halves);
  const auto before = test::meanById(heat);
  const std::int64_t sorts = sys.sortCount(), rebuilds = sys.rebuildCount();
  double worst = 0.0;
  std::size_t layersSeen = 0;
  for (int block = 0; block < 20; ++block) { // heat after every mechanical step
    advance(sys, heat, 100, 1);
    worst = std::max(worst, std::fabs(heat.energyDrift()));
    layersSeen = std::max(layersSeen, touchingLayers(heat.exportState()));
  }
  for (int block = 0; block < 20; ++block) { // heat after every 20 mechanical steps
    advance(sys, heat, 100, 20);
    worst = std::max(worst, std::fabs(heat.energyDrift()));
  }
  EXPECT_LT(worst, 1e-13) << "relative drift of the heat content";
  EXPECT_GT(layersSeen, 300u);                  // many contacts conducted
  EXPECT_GE(sys.sortCount(), sorts + 2);        // through reorders
  EXPECT_GE(sys.rebuildCount(), rebuilds + 10); // and rebuilds
  // heat flowed across the split and stayed within the initial bounds (maximum principle)
  const auto after = test::meanById(heat);
  double changed = 0.0;
  for (const auto& [id, t] : after) {
    EXPECT_GE(t, 673.0 - 1e-9);
    EXPECT_LE(t, 1073.0 + 1e-9);
    changed = std::max(changed, std::fabs(t - before.at(id)));
  }
  EXPECT_GT(changed, 1.0);
  EXPECT_NEAR(heat.time(), 4000 * sys.timeStep(), 1e-9);
}

TEST(TEST_CATEGORY, heat_drum_thread_count_independent_bitwise_vs_serial) {
#ifdef KOKKOS_ENABLE_SERIAL
  DemSystem<space> sys(drumConfig());
  DemSystem<Kokkos::Serial> ref(drumConfig());
  sys.importState(settledBed());
  ref.importState(settledBed());
  DemHeat<space> heat(drumHeat());
  DemHeat<Kokkos::Serial> refHeat(drumHeat());
  heat.initialize(sys, halves);
  refHeat.initialize(ref, halves);
  advance(sys, heat, 1500, 1);
  advance(ref, refHeat, 1500, 1);
  const auto a = test::shellsById(heat.exportState());
  const auto b = test::shellsById(refHeat.exportState());
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [id, shells] : a) {
    for (std::size_t m = 0; m < shells.size(); ++m) {
      if (bitwiseVsHost) {
        EXPECT_EQ(shells[m], b.at(id)[m]) << "id " << id << " shell " << m;
      } else {
        EXPECT_NEAR(shells[m], b.at(id)[m], 1e-9) << "id " << id << " shell " << m;
      }
    }
  }
#else
  GTEST_SKIP() << "Kokkos::Serial not enabled";
#endif
}

void expectSameTemperatures(const DemHeatState& a, const DemHeatState& b) {
  const auto ta = test::shellsById(a), tb = test::shellsById(b);
  ASSERT_EQ(ta.size(), tb.size());
  for (const auto& [id, shells] : ta) {
    EXPECT_EQ(shells, tb.at(id)) << "id " << id;
  }
  std::map<std::pair<std::int64_t, std::int64_t>, std::array<double, 3>> la, lb;
  for (std::size_t c = 0; c < a.contactId.size(); ++c) {
    la[{a.contactId[c], a.contactNeighborId[c]}] = {a.contactArea[c], a.contactLayer[c],
                                                    a.contactLayerOther[c]};
  }
  for (std::size_t c = 0; c < b.contactId.size(); ++c) {
    lb[{b.contactId[c], b.contactNeighborId[c]}] = {b.contactArea[c], b.contactLayer[c],
                                                    b.contactLayerOther[c]};
  }
  EXPECT_EQ(la, lb);
}

TEST(TEST_CATEGORY, heat_drum_independent_of_reordering) {
  // (1) reorders at every rebuild vs never: the same rebuild schedule, so every mechanism
  DemSystem<space> plain(drumConfig(0)), sorted(drumConfig(1));
  plain.importState(settledBed());
  sorted.importState(settledBed());
  DemHeat<space> plainHeat(drumHeat()), sortedHeat(drumHeat());
  plainHeat.initialize(plain, halves);
  sortedHeat.initialize(sorted, halves);
  const std::int64_t sorts = sorted.sortCount();
  advance(plain, plainHeat, 1000, 1);
  advance(sorted, sortedHeat, 1000, 1);
  EXPECT_GE(sorted.sortCount(), sorts + 5);
  expectSameTemperatures(plainHeat.exportState(), sortedHeat.exportState());

  // (2) a forced rebuild and reorder before every step: radiation between touching pairs only
  // (pairs with a gap in the list depend on the rebuild schedule)
  DemSystem<space> calm(drumConfig()), shuffled(drumConfig());
  calm.importState(settledBed());
  shuffled.importState(settledBed());
  DemHeat<space> calmHeat(drumHeat(0.0)), shuffledHeat(drumHeat(0.0));
  calmHeat.initialize(calm, halves);
  shuffledHeat.initialize(shuffled, halves);
  for (int s = 0; s < 300; ++s) {
    shuffled.forceRebuild();
    shuffled.sortByCell();
    calm.step();
    shuffled.step();
    calmHeat.step(calm, calm.timeStep());
    shuffledHeat.step(shuffled, shuffled.timeStep());
  }
  expectSameTemperatures(calmHeat.exportState(), shuffledHeat.exportState());
  EXPECT_GT(touchingLayers(calmHeat.exportState()), 300u);
}

TEST(TEST_CATEGORY, heat_drum_restart_continues_bitwise) {
  const int k = 400;
  DemSystem<space> first(drumConfig());
  first.importState(settledBed());
  DemHeat<space> firstHeat(drumHeat(0.0));
  firstHeat.initialize(first, halves);
  advance(first, firstHeat, k, 1);
  const DemState mechanics = first.exportState();
  const DemHeatState thermal = firstHeat.exportState();
  ASSERT_GT(thermal.contactId.size(), 300u);
  advance(first, firstHeat, k, 1);

  DemSystem<space> second(drumConfig());
  second.importState(mechanics);
  DemHeat<space> secondHeat(drumHeat(0.0));
  secondHeat.importState(second, thermal);
  {
    SCOPED_TRACE("read back");
    expectSameTemperatures(secondHeat.exportState(), thermal); // reads back identically
  }
  EXPECT_EQ(secondHeat.time(), thermal.time);
  // the sub-step limit travels with the state: a restart splits heat steps as the first run did,
  // even where the temperatures now would give another limit
  EXPECT_EQ(thermal.stableTimeStep, firstHeat.stableTimeStep());
  EXPECT_EQ(secondHeat.stableTimeStep(), firstHeat.stableTimeStep());
  DemHeatState cooler = thermal;
  for (double& t : cooler.temperature) {
    t = std::min(t, 700.0);
  }
  DemHeat<space> coolerHeat(drumHeat(0.0));
  coolerHeat.importState(second, cooler);
  EXPECT_EQ(coolerHeat.stableTimeStep(), firstHeat.stableTimeStep());
  advance(second, secondHeat, k, 1);
  test::expectBitwiseEqual(test::byId(first), test::byId(second));
  SCOPED_TRACE("continued");
  expectSameTemperatures(firstHeat.exportState(), secondHeat.exportState());
  // (a parallel sum: its order follows the particle order, which the restart changed)
  EXPECT_NEAR(firstHeat.energy(), secondHeat.energy(), 1e-14 * firstHeat.energy());
  EXPECT_EQ(firstHeat.initialEnergy(), secondHeat.initialEnergy());
  EXPECT_EQ(firstHeat.subStepCount(), secondHeat.subStepCount());
}

} // namespace
