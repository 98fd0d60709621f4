// Cell binning and the full neighbour list (kernels/dem/CellGrid.hpp, NeighborList.hpp,
// Reorder.hpp) against a brute-force pair search on the host, with and without periodic x;
// history carried over by id through a random reordering; overflow detection.
#include "kernels/dem/CellGrid.hpp"
#include "kernels/dem/NeighborList.hpp"
#include "kernels/dem/ParticleArrays.hpp"
#include "kernels/dem/Reorder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
using mem = space::memory_space;

constexpr double skin = 0.004;
constexpr double rmax = 0.012;

// n random discs in [0, 0.6] x [0, 0.4]; ids are a shuffled, gappy set so id order != index order.
ParticleArrays<Kokkos::HostSpace> randomParticles(int n, unsigned seed) {
  ParticleArrays<Kokkos::HostSpace> h(n, n);
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<std::int64_t> ids(n);
  for (int i = 0; i < n; ++i) {
    ids[i] = 3 * i + 11;
  }
  std::shuffle(ids.begin(), ids.end(), gen);
  for (int i = 0; i < n; ++i) {
    h.position(i, 0) = 0.6 * u(gen);
    h.position(i, 1) = 0.4 * u(gen);
    h.radius(i) = 0.008 + 0.004 * u(gen);
    h.id(i) = ids[i];
  }
  return h;
}

double minimumImage(double dx, const PeriodicX& p) {
  return p.minimumImage(dx);
}

// pairs (i, j), i != j, within r_i + r_j + skin, by brute force
std::set<std::pair<int, int>> brutePairs(const ParticleArrays<Kokkos::HostSpace>& h,
                                         const PeriodicX& p) {
  std::set<std::pair<int, int>> pairs;
  const int n = static_cast<int>(h.count());
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (i == j) {
        continue;
      }
      const double dx = minimumImage(h.position(j, 0) - h.position(i, 0), p);
      const double dy = h.position(j, 1) - h.position(i, 1);
      const double cut = h.radius(i) + h.radius(j) + skin;
      if (dx * dx + dy * dy < cut * cut) {
        pairs.emplace(i, j);
      }
    }
  }
  return pairs;
}

struct Built {
  CellBins<mem> bins;
  NeighborList<mem> list;
  int maxCount = 0;
};

Built build(const ParticleArrays<mem>& d, const PeriodicX& p, int capacity,
            const NeighborList<mem>& previous) {
  const std::size_t n = d.count();
  Built b;
  const Bounds bounds = particleBounds(space(), d.position, n);
  const CellGrid grid = makeCellGrid(bounds.xmin, bounds.xmax, bounds.ymin, bounds.ymax,
                                     2.0 * rmax + skin, p, 4 * n + 64);
  binParticles(space(), grid, d.position, n, b.bins);
  b.list = NeighborList<mem>(n, capacity);
  b.maxCount =
      buildNeighborList(space(), b.bins, d.position, d.radius, d.id, n, skin, p, previous, b.list);
  return b;
}

void checkAgainstBruteForce(const PeriodicX& p, unsigned seed) {
  const int n = 301;
  auto h = randomParticles(n, seed);
  if (p.enabled) { // keep x inside the period
    for (int i = 0; i < n; ++i) {
      h.position(i, 0) = p.wrap(h.position(i, 0));
    }
  }
  const auto d = copyParticles<mem>(h);
  const int capacity = 24;
  const Built b = build(d, p, capacity, NeighborList<mem>(n, 1));
  ASSERT_LE(b.maxCount, capacity);
  const auto expected = brutePairs(h, p);
  auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.list.count);
  auto index = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.list.index);
  auto nid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.list.neighborId);
  std::set<std::pair<int, int>> found;
  int maxRow = 0;
  for (int i = 0; i < n; ++i) {
    maxRow = std::max(maxRow, count(i));
    for (int k = 0; k < count(i); ++k) {
      const int j = index(i, k);
      EXPECT_EQ(nid(i, k), h.id(j));
      if (k > 0) {
        EXPECT_LT(nid(i, k - 1), nid(i, k)) << "row " << i << " not sorted by id";
      }
      found.emplace(i, j);
    }
  }
  EXPECT_EQ(found, expected);
  EXPECT_EQ(maxRow, b.maxCount);
  EXPECT_GT(expected.size(), static_cast<std::size_t>(n)); // a non-trivial test
  // binning: every particle once, cells in increasing index order
  auto offset = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.bins.cellOffset);
  auto members = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.bins.cellParticles);
  auto cellOf = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.bins.cellOfParticle);
  std::vector<int> seen(n, 0);
  for (int c = 0; c < b.bins.grid.numCells(); ++c) {
    for (int m = offset(c); m < offset(c + 1); ++m) {
      ++seen[members(m)];
      EXPECT_EQ(cellOf(members(m)), c);
      if (m > offset(c)) {
        EXPECT_LT(members(m - 1), members(m));
      }
    }
  }
  EXPECT_EQ(offset(b.bins.grid.numCells()), n);
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), n);
}

TEST(TEST_CATEGORY, dem_neighbor_list_matches_brute_force) {
  checkAgainstBruteForce(PeriodicX{}, 1);
}

TEST(TEST_CATEGORY, dem_neighbor_list_periodic_matches_brute_force) {
  PeriodicX p;
  p.enabled = true;
  p.xlo = 0.0;
  p.length = 0.6;
  checkAgainstBruteForce(p, 2);
  // also with particles hugging both ends of the period
  p.xlo = 0.05;
  p.length = 0.5;
  checkAgainstBruteForce(p, 3);
}

TEST(TEST_CATEGORY, dem_neighbor_list_empty_and_overflow) {
  const ParticleArrays<mem> empty(4, 0);
  const Built e = build(empty, PeriodicX{}, 4, NeighborList<mem>(4, 1));
  EXPECT_EQ(e.maxCount, 0);
  const auto d = copyParticles<mem>(randomParticles(301, 4));
  const Built b = build(d, PeriodicX{}, 2, NeighborList<mem>(301, 1));
  EXPECT_GT(b.maxCount, 2); // reported, so the caller can raise an error
  EXPECT_NE(neighborOverflowMessage(b.maxCount, 2).find("overflow"), std::string::npos);
}

// Shear tagged with the pair's ids survives a random reordering and a move of every particle;
// pairs that are new after the move start from zero.
TEST(TEST_CATEGORY, dem_neighbor_history_follows_ids_through_reordering) {
  const int n = 301;
  auto h = randomParticles(n, 5);
  auto d = copyParticles<mem>(h);
  const int capacity = 24;
  Built b = build(d, PeriodicX{}, capacity, NeighborList<mem>(n, 1));
  const auto tag = [](std::int64_t a, std::int64_t c) { return 1000.0 * a + c; };
  auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.list.count);
  auto nid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.list.neighborId);
  auto shear = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b.list.shear);
  std::set<std::pair<std::int64_t, std::int64_t>> oldPairs;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < count(i); ++k) {
      shear(i, k) = tag(h.id(i), nid(i, k));
      oldPairs.emplace(h.id(i), nid(i, k));
    }
  }
  Kokkos::deep_copy(b.list.shear, shear);

  std::vector<int> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(6));
  Kokkos::View<int*, Kokkos::HostSpace> permHost("hikiln::test::perm", n);
  for (int k = 0; k < n; ++k) {
    permHost(k) = perm[k];
  }
  auto permDev = Kokkos::create_mirror_view_and_copy(mem{}, permHost);
  ParticleArrays<mem> moved(n, n);
  permuteParticles(space(), permDev, d, moved);
  NeighborList<mem> rows(n, capacity);
  WallContactState<mem> w0(n), w1(n);
  permuteContactRows(space(), permDev, n, b.list, rows, w0, w1);
  auto hm = copyParticles<Kokkos::HostSpace>(moved);
  std::mt19937_64 gen(8);
  std::uniform_real_distribution<double> u(-0.003, 0.003);
  for (int i = 0; i < n; ++i) {
    EXPECT_EQ(hm.id(i), h.id(perm[i]));
    hm.position(i, 0) += u(gen);
    hm.position(i, 1) += u(gen);
  }
  Kokkos::deep_copy(moved.position, hm.position);
  const Built b2 = build(moved, PeriodicX{}, capacity, rows);
  auto count2 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b2.list.count);
  auto nid2 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b2.list.neighborId);
  auto shear2 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, b2.list.shear);
  int kept = 0, fresh = 0;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < count2(i); ++k) {
      if (oldPairs.count({hm.id(i), nid2(i, k)})) {
        EXPECT_EQ(shear2(i, k), tag(hm.id(i), nid2(i, k)));
        ++kept;
      } else {
        EXPECT_EQ(shear2(i, k), 0.0);
        ++fresh;
      }
    }
  }
  EXPECT_GT(kept, n);
  EXPECT_GT(fresh, 0);
}

// The optional second history (normalAngle, blocky pairs) follows the pair like shear through an
// in-place rebuild after a move and through widening (copyNeighborRows), as DemSystem uses it for
// blocky particles.
TEST(TEST_CATEGORY, dem_neighbor_normal_angle_carried_like_shear) {
  const int n = 301;
  auto h = randomParticles(n, 12);
  auto d = copyParticles<mem>(h);
  const Bounds bounds = particleBounds(space(), d.position, n);
  const CellGrid grid = makeCellGrid(bounds.xmin, bounds.xmax, bounds.ymin, bounds.ymax,
                                     2.0 * rmax + skin, PeriodicX{}, 4 * n + 64);
  CellBins<mem> bins;
  binParticles(space(), grid, d.position, n, bins);
  auto list = NeighborList<mem>::lean(n, 24);
  list.allocateNormalAngle();
  ASSERT_LE(
      rebuildNeighborList(space(), bins, d.position, d.radius, d.id, n, skin, PeriodicX{}, list),
      24);
  const auto tag = [](std::int64_t a, std::int64_t c) { return 1000.0 * a + c; };
  auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, list.count);
  auto index = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, list.index);
  auto angle = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, list.normalAngle);
  std::set<std::pair<std::int64_t, std::int64_t>> oldPairs;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < count(i); ++k) {
      angle(i, k) = -tag(h.id(i), h.id(index(i, k)));
      oldPairs.emplace(h.id(i), h.id(index(i, k)));
    }
  }
  Kokkos::deep_copy(list.normalAngle, angle);
  auto wider = NeighborList<mem>::lean(n, 32);
  wider.allocateNormalAngle();
  copyNeighborRows(space(), n, list, wider);
  std::mt19937_64 gen(13);
  std::uniform_real_distribution<double> u(-0.003, 0.003);
  for (int i = 0; i < n; ++i) {
    h.position(i, 0) += u(gen);
    h.position(i, 1) += u(gen);
  }
  Kokkos::deep_copy(d.position, Kokkos::create_mirror_view_and_copy(mem{}, h.position));
  binParticles(space(), grid, d.position, n, bins);
  ASSERT_LE(
      rebuildNeighborList(space(), bins, d.position, d.radius, d.id, n, skin, PeriodicX{}, wider),
      32);
  count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, wider.count);
  index = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, wider.index);
  angle = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, wider.normalAngle);
  int kept = 0, fresh = 0;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < count(i); ++k) {
      const std::int64_t j = h.id(index(i, k));
      if (oldPairs.count({h.id(i), j})) {
        EXPECT_EQ(angle(i, k), -tag(h.id(i), j));
        ++kept;
      } else {
        EXPECT_EQ(angle(i, k), 0.0);
        ++fresh;
      }
    }
  }
  EXPECT_GT(kept, n);
  EXPECT_GT(fresh, 0);
}

} // namespace
