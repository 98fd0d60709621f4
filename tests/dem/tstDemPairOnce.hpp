// The pair-once disc kernel (DemConfig::pairOnceForces, PairOnceForces.hpp): the forces of the
// full-row kernel to round-off, and the full-row kernel's guarantees bitwise: independent of the
// particle order and the rebuild schedule, of the thread count (against Kokkos::Serial), and a
// restart continues identically; the history copied into the partners' slots only when read
// changes nothing; a contribution too large for the integers gives NaN.
#include "BlockyTestUtils.hpp"
#include "DemTestUtils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

using namespace hikiln::dem;
using test::history;
using space = TEST_EXECSPACE;
constexpr bool onHost =
    Kokkos::SpaceAccessibility<Kokkos::HostSpace, space::memory_space>::accessible;

// The small rotating drum of the blocky tests with discs, rolling resistance on (its torque goes to
// the partner too): many sticking, slipping and breaking contacts.
DemConfig drumConfig(bool pairOnce) {
  DemConfig cfg = test::blockyDrumConfig();
  cfg.sortEveryRebuilds = 2;
  cfg.pairOnceForces = pairOnce;
  return cfg;
}

// A bed settled for 2000 steps with the full-row kernel (once per test executable).
const DemState& settledBed() {
  static const DemState state = [] {
    auto h = test::drumParticles(200, 0.12, 0.005, 0.05, 0.05, 31, 1.05, true);
    assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
    DemSystem<space> sys(drumConfig(false));
    sys.setParticles(h);
    sys.advance(2000);
    return sys.exportState();
  }();
  return state;
}

TEST(TEST_CATEGORY, dem_pair_once_forces_match_full_rows) {
  if (!onHost) {
    GTEST_SKIP() << "a device keeps the full-row kernel";
  }
  DemSystem<space> full(drumConfig(false)), once(drumConfig(true));
  full.importState(settledBed());
  once.importState(settledBed());
  full.advance(1); // the same imported forces move both to the same positions, where each
  once.advance(1); // kernel then evaluates the forces its own way
  const DemState a = full.exportState(), b = once.exportState();
  ASSERT_EQ(a.id, b.id);
  EXPECT_EQ(a.position, b.position);
  double largest = 0.0, torqueLargest = 0.0;
  for (std::size_t i = 0; i < a.force.size(); ++i) {
    largest = std::max(largest, std::fabs(a.force[i]));
  }
  for (std::size_t i = 0; i < a.torque.size(); ++i) {
    torqueLargest = std::max(torqueLargest, std::fabs(a.torque[i]));
  }
  ASSERT_GT(largest, 0.0);
  double worst = 0.0, torqueWorst = 0.0;
  int differing = 0;
  for (std::size_t i = 0; i < a.force.size(); ++i) {
    worst = std::max(worst, std::fabs(a.force[i] - b.force[i]));
    differing += a.force[i] != b.force[i];
  }
  for (std::size_t i = 0; i < a.torque.size(); ++i) {
    torqueWorst = std::max(torqueWorst, std::fabs(a.torque[i] - b.torque[i]));
  }
  // a particle's partners' side is off by less than one integer step per partner (<= 12), its
  // double sums by a few ulps of the largest force
  double rmax = 0.0;
  for (const double r : a.radius) {
    rmax = std::max(rmax, r);
  }
  const double kn = once.forceSettings().particle.kn; // the scales DemSystem chose
  const double forceStep = 1.0 / pairOnceScale(kn * 2.0 * rmax);
  const double torqueStep = 1.0 / pairOnceScale(kn * 2.0 * rmax * rmax);
  EXPECT_LT(worst, 12.0 * forceStep + 1e-14 * largest);
  EXPECT_LT(torqueWorst, 12.0 * torqueStep + 1e-14 * torqueLargest);
  EXPECT_LT(forceStep, 1e-11 * largest); // and that is far below the forces themselves
  EXPECT_GT(differing, 0); // the partners' side is summed differently: not the same kernel twice
  EXPECT_EQ(history(a), history(b)); // the history, mirrored into both rows, is the same
}

TEST(TEST_CATEGORY, dem_pair_once_independent_of_order_and_rebuilds) {
  DemSystem<space> plain(drumConfig(true)), shuffled(drumConfig(true));
  plain.importState(settledBed());
  shuffled.importState(settledBed());
  for (int s = 0; s < 300; ++s) {
    test::stepPlainAndReshuffled(plain, shuffled);
    if (HasFailure()) {
      FAIL() << "diverged at step " << s;
    }
  }
  EXPECT_EQ(history(plain.exportState()), history(shuffled.exportState()));
  EXPECT_GE(shuffled.sortCount(), 300);
  EXPECT_GT(shuffled.rebuildCount(), plain.rebuildCount() + 200);
}

TEST(TEST_CATEGORY, dem_pair_once_thread_count_independent_and_restarts_bitwise) {
#ifdef KOKKOS_ENABLE_SERIAL
  DemSystem<space> sys(drumConfig(true));
  DemSystem<Kokkos::Serial> ref(drumConfig(true));
  sys.importState(settledBed());
  ref.importState(settledBed());
  sys.advance(400);
  ref.advance(400);
  EXPECT_GT(sys.rebuildCount(), 2);
  test::expectBitwiseEqual(test::byId(sys), test::byId(ref));
  EXPECT_EQ(history(sys.exportState()), history(ref.exportState()));
#endif
  DemSystem<space> first(drumConfig(true));
  first.importState(settledBed());
  first.advance(300);
  const DemState mid = first.exportState();
  first.advance(300);
  DemSystem<space> second(drumConfig(true));
  second.importState(mid);
  second.advance(300);
  test::expectBitwiseEqual(test::byId(first), test::byId(second));
  EXPECT_EQ(history(first.exportState()), history(second.exportState()));
}

// The step updates a pair's history in the owner's slot only and copies it into the partner's
// when something reads both rows: a run read every step (so every rebuild sees both rows
// current) and one never read in between (its rebuilds carry stale partner slots) end the same.
TEST(TEST_CATEGORY, dem_pair_once_history_copy_only_when_read) {
  DemSystem<space> read(drumConfig(true)), unread(drumConfig(true));
  read.importState(settledBed());
  unread.importState(settledBed());
  for (int s = 0; s < 400; ++s) {
    read.step();
    (void)read.neighborRows(); // copies the history into the partners' slots
  }
  unread.advance(400);
  EXPECT_GT(unread.rebuildCount(), 2);
  EXPECT_EQ(read.rebuildCount(), unread.rebuildCount());
  test::expectBitwiseEqual(test::byId(read), test::byId(unread));
  EXPECT_EQ(history(read.exportState()), history(unread.exportState()));
}

TEST(TEST_CATEGORY, dem_pair_once_out_of_range_gives_nan) {
  if (!onHost) {
    GTEST_SKIP() << "a device keeps the full-row kernel";
  }
  DemConfig cfg = drumConfig(true);
  cfg.walls.drum.enabled = false;
  cfg.gravityY = 0.0;
  cfg.timeStep = 1e-6;
  auto h = test::hostParticles(2);
  for (int i = 0; i < 2; ++i) {
    h.radius(i) = 0.005;
    h.position(i, 1) = 0.0;
  }
  h.position(0, 0) = -0.0049;
  h.position(1, 0) = 0.0049;
  h.velocity(0, 0) = 1e15; // a dashpot force far beyond 2^5 k_n d: it cannot be an integer
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  DemSystem<space> sys(cfg);
  sys.setParticles(h);
  const DemState s = sys.exportState();
  const std::size_t upper = s.id[0] < s.id[1] ? 1 : 0; // the partner's side went to the integers
  EXPECT_TRUE(std::isnan(s.force[2 * upper]));
  EXPECT_TRUE(std::isnan(s.torque[upper]));
  EXPECT_TRUE(std::isfinite(s.force[2 * (1 - upper)])); // the owner's side is a double sum
}

} // namespace
