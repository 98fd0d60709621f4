// The blocky force kernel evaluates each pair of non-circles once (a first pass in the lower id's
// row, a second pass summing the rows). Its definition is simpler: every row evaluates each of its
// pairs with BlockyContacts::pair() and sums in neighbour order. On a packed, sheared drum bed of
// blocks mixed with circles (pairs block-block, block-circle and circle-circle, with contact
// history and pair directions), both give bitwise the same forces, torques, histories and pair
// directions, over two evaluations in a row (nothing of the first pass's scratch leaks into the
// next). An all-circle system takes the disc engine's kernel instead (DemSystem::evaluateForces);
// the blocky kernel's circle branch, which mixed systems use, gives bitwise the same forces,
// torques and histories on such a bed, walls included.
#include "BlockyTestUtils.hpp"
#include "kernels/dem/BlockyForceKernel.hpp"

#include <gtest/gtest.h>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
using memory = space::memory_space;

// The definition: each row evaluates every pair itself (pairs only: no walls, no gravity).
struct EveryRowEvaluates {
  detail::BlockyContacts<memory> b;
  Kokkos::View<double* [2], memory> f;
  Kokkos::View<double*, memory> tq;

  KOKKOS_INLINE_FUNCTION void operator()(int i) const {
    double fx = 0.0, fy = 0.0, t = 0.0;
    for (int k = 0; k < b.count(i); ++k) {
      ContactFrame frame;
      ContactForce c;
      double px = 0.0, py = 0.0, pt = 0.0, lx = 0.0, ly = 0.0;
      double angle = b.normalAngle(i, k);
      const bool touching = b.pair(i, b.index(i, k), b.shear(i, k), b.s.updateHistory, frame, c, px,
                                   py, pt, angle, lx, ly);
      b.normalAngle(i, k) = angle;
      b.shear(i, k) = touching ? c.shear : 0.0;
      if (touching) {
        fx += px;
        fy += py;
        t += pt;
      }
    }
    f(i, 0) = fx;
    f(i, 1) = fy;
    tq(i) = t;
  }
};

// A host copy of a View.
template <class View> auto onHost(const View& view) {
  return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, view);
}

// Forces and torques of two evaluations, bitwise.
void expectSameForces(const ParticleArrays<memory>& first, const ParticleArrays<memory>& second,
                      int round) {
  const auto a = copyParticles<Kokkos::HostSpace>(first);
  const auto b = copyParticles<Kokkos::HostSpace>(second);
  for (std::size_t i = 0; i < a.count(); ++i) {
    EXPECT_EQ(a.force(i, 0), b.force(i, 0)) << "round " << round << " particle " << i;
    EXPECT_EQ(a.force(i, 1), b.force(i, 1)) << "round " << round << " particle " << i;
    EXPECT_EQ(a.torque(i), b.torque(i)) << "round " << round << " particle " << i;
  }
}

// A copy of the rows with their own history views (count and index shared).
NeighborList<memory> historyCopy(const NeighborList<memory>& rows) {
  NeighborList<memory> copy = rows;
  copy.shear = Kokkos::View<double**, memory>("shear", rows.rows(), rows.capacity());
  copy.normalAngle = Kokkos::View<double**, memory>("angle", rows.rows(), rows.capacity());
  Kokkos::deep_copy(copy.shear, rows.shear);
  Kokkos::deep_copy(copy.normalAngle, rows.normalAngle);
  return copy;
}

TEST(TEST_CATEGORY, blocky_pair_pass_equals_every_row_evaluating) {
  auto h = test::blockyDrumBed(200, 5);
  auto shapes = test::blockify(h, 4.0, 1.4, 6);
  for (std::size_t i = 0; i < h.count(); i += 3) { // every third particle a circle
    shapes.shape(i) = SuperquadricShape{h.radius(i), h.radius(i), 2.0};
  }
  const DemConfig cfg = test::blockyDrumConfig(); // with rolling resistance
  DemSystem<space> sys(cfg);
  sys.setParticles(h, shapes);
  sys.advance(3000); // settled and sheared: contacts with history and stored pair directions

  const auto particles = copyParticles<memory>(sys.particles());
  const auto blocky = copyBlocky<memory>(sys.hostShapes());
  auto settings = sys.forceSettings();
  settings.walls.drum.enabled = false; // pairs only: the definition above has no walls
  settings.walls.numFlat = 0;
  settings.gravityX = settings.gravityY = 0.0;
  const NeighborList<memory> passes = historyCopy(sys.neighborRows());
  const NeighborList<memory> rows = historyCopy(sys.neighborRows());
  const WallContactState<memory> walls(particles.capacity());
  const auto reference = copyParticles<memory>(particles);
  BlockyPairOutcomes<memory> scratch;

  int touchingShapes = 0, touchingMixed = 0;
  for (int round = 0; round < 2; ++round) {
    computeBlockyForces(space{}, particles, blocky, passes, walls, settings, scratch);
    Kokkos::parallel_for(
        "everyRowEvaluates", Kokkos::RangePolicy<space>(0, particles.count()),
        EveryRowEvaluates{detail::blockyContacts(reference, blocky, rows, walls, settings),
                          reference.force, reference.torque});
    Kokkos::fence();
    expectSameForces(particles, reference, round);
    const auto count = onHost(rows.count);
    const auto index = onHost(rows.index);
    const auto shearA = onHost(passes.shear);
    const auto shearB = onHost(rows.shear);
    const auto angleA = onHost(passes.normalAngle);
    const auto angleB = onHost(rows.normalAngle);
    const auto hostShapes = copyBlocky<Kokkos::HostSpace>(blocky);
    touchingShapes = touchingMixed = 0;
    for (std::size_t i = 0; i < particles.count(); ++i) {
      for (int k = 0; k < count(i); ++k) {
        EXPECT_EQ(shearA(i, k), shearB(i, k)) << "particle " << i << " slot " << k;
        EXPECT_EQ(angleA(i, k), angleB(i, k)) << "particle " << i << " slot " << k;
        const int j = index(i, k);
        const int circles = isCircle(hostShapes.shape(i)) + isCircle(hostShapes.shape(j));
        if (angleB(i, k) > 0.0) { // a contact normal is stored: touching non-circles
          ++(circles == 0 ? touchingShapes : touchingMixed);
        }
      }
    }
  }
  // the comparison covers many touching block-block and block-circle pairs (both rows each)
  EXPECT_GT(touchingShapes, 100);
  EXPECT_GT(touchingMixed, 50);
}

// A copy of the wall contact state (its own history).
WallContactState<memory> wallCopy(const WallContactState<memory>& walls, std::size_t capacity) {
  WallContactState<memory> copy(capacity);
  Kokkos::deep_copy(copy.shear, walls.shear);
  return copy;
}

TEST(TEST_CATEGORY, blocky_circle_branch_equals_disc_kernel) {
  auto h = test::blockyDrumBed(200, 7);
  const auto shapes = test::blockify(h, 2.0, 1.0, 0); // circles
  DemSystem<space> sys(test::blockyDrumConfig());     // with rolling resistance
  sys.setParticles(h, shapes);
  sys.advance(3000); // settled and sheared: pair and wall contacts with history

  const auto blocky = copyBlocky<memory>(sys.hostShapes());
  const auto settings = sys.forceSettings();
  const auto viaBlocky = copyParticles<memory>(sys.particles());
  const auto viaDisc = copyParticles<memory>(sys.particles());
  const NeighborList<memory> blockyRows = historyCopy(sys.neighborRows());
  const NeighborList<memory> discRows = historyCopy(sys.neighborRows());
  const auto blockyWalls = wallCopy(sys.wallContacts(), viaBlocky.capacity());
  const auto discWalls = wallCopy(sys.wallContacts(), viaDisc.capacity());
  BlockyPairOutcomes<memory> scratch;
  for (int round = 0; round < 2; ++round) {
    computeBlockyForces(space{}, viaBlocky, blocky, blockyRows, blockyWalls, settings, scratch);
    computeForces(space{}, viaDisc, discRows, discWalls, settings);
    Kokkos::fence();
    expectSameForces(viaBlocky, viaDisc, round);
    const auto count = onHost(discRows.count);
    const auto shearA = onHost(blockyRows.shear);
    const auto shearB = onHost(discRows.shear);
    const auto wallA = onHost(blockyWalls.shear);
    const auto wallB = onHost(discWalls.shear);
    int sliding = 0, wallTouching = 0;
    for (std::size_t i = 0; i < viaDisc.count(); ++i) {
      for (int k = 0; k < count(i); ++k) {
        EXPECT_EQ(shearA(i, k), shearB(i, k)) << "particle " << i << " slot " << k;
        sliding += shearB(i, k) != 0.0;
      }
      EXPECT_EQ(wallA(i, 0), wallB(i, 0)) << "particle " << i;
      wallTouching += wallB(i, 0) != 0.0;
    }
    EXPECT_GT(sliding, 200); // many pair contacts with history, and wall contacts
    EXPECT_GT(wallTouching, 10);
  }
}

} // namespace
