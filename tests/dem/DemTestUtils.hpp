// Helpers shared by the DEM system tests: building particle sets and reading results by id.
#pragma once

#include "kernels/dem/ParticleArrays.hpp"
#include "solvers/dem/DemSystem.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <vector>

namespace hikiln::dem::test {

/// One particle's kinematic state, read back by id.
struct Kinematics {
  double x = 0.0, y = 0.0, vx = 0.0, vy = 0.0, w = 0.0, fx = 0.0, fy = 0.0, torque = 0.0;
};

/// Kinematics of every particle of a system, keyed by id (independent of the particle order).
template <class System> std::map<std::int64_t, Kinematics> byId(const System& sys) {
  const auto h = sys.hostParticles();
  std::map<std::int64_t, Kinematics> out;
  for (std::size_t i = 0; i < h.count(); ++i) {
    out[h.id(i)] =
        Kinematics{h.position(i, 0),     h.position(i, 1), h.velocity(i, 0), h.velocity(i, 1),
                   h.angularVelocity(i), h.force(i, 0),    h.force(i, 1),    h.torque(i)};
  }
  return out;
}

/// Bitwise comparison of two id maps (every field, exact equality).
inline void expectBitwiseEqual(const std::map<std::int64_t, Kinematics>& a,
                               const std::map<std::int64_t, Kinematics>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [id, ka] : a) {
    const auto it = b.find(id);
    ASSERT_NE(it, b.end()) << "id " << id;
    const Kinematics& kb = it->second;
    EXPECT_EQ(ka.x, kb.x) << "id " << id;
    EXPECT_EQ(ka.y, kb.y) << "id " << id;
    EXPECT_EQ(ka.vx, kb.vx) << "id " << id;
    EXPECT_EQ(ka.vy, kb.vy) << "id " << id;
    EXPECT_EQ(ka.w, kb.w) << "id " << id;
    EXPECT_EQ(ka.fx, kb.fx) << "id " << id;
    EXPECT_EQ(ka.fy, kb.fy) << "id " << id;
    EXPECT_EQ(ka.torque, kb.torque) << "id " << id;
  }
}

// One step of `plain` and of `shuffled`, the latter rebuilt and sorted by cell first (its list and
// particle order change every step); their particles must stay bitwise equal.
template <class System> void stepPlainAndReshuffled(System& plain, System& shuffled) {
  shuffled.forceRebuild();
  shuffled.sortByCell();
  plain.step();
  shuffled.step();
  expectBitwiseEqual(byId(plain), byId(shuffled));
}

/// Tangential history of an exported state by (particle id, neighbour id).
using History = std::map<std::pair<std::int64_t, std::int64_t>, double>;
inline History history(const DemState& s) {
  History h;
  for (std::size_t c = 0; c < s.contactId.size(); ++c) {
    h[{s.contactId[c], s.contactNeighborId[c]}] = s.contactShear[c];
  }
  return h;
}

/// Host container for n particles with ids 100 + 7 i (not equal to the indices).
inline ParticleArrays<Kokkos::HostSpace> hostParticles(std::size_t n) {
  ParticleArrays<Kokkos::HostSpace> h(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    h.id(i) = 100 + 7 * static_cast<std::int64_t>(i);
  }
  return h;
}

/// n discs of radius r (1 +- spread) on a jittered square lattice of pitch `pitchScale` x 2r
/// (default: 5 % gaps between the largest discs) inside a drum of radius R about the origin, at
/// most `n`: on random sites within 0.85 R, or (fromBottom) on the lowest sites, a bed resting
/// near the shell; random velocities of size ~speed. Ids shuffled.
inline ParticleArrays<Kokkos::HostSpace> drumParticles(std::size_t n, double drumRadius, double r,
                                                       double spread, double speed, unsigned seed,
                                                       double pitchScale = 0.0,
                                                       bool fromBottom = false) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double pitch = 2.0 * r * (pitchScale > 0.0 ? pitchScale : (1.0 + spread) * 1.05);
  std::vector<std::pair<double, double>> sites;
  const int m = static_cast<int>(drumRadius / pitch);
  const double reach = (fromBottom ? drumRadius : 0.85 * drumRadius) - pitch;
  for (int iy = -m; iy <= m; ++iy) {
    for (int ix = -m; ix <= m; ++ix) {
      const double x = ix * pitch, y = iy * pitch;
      if (std::hypot(x, y) < reach) {
        sites.emplace_back(x, y);
      }
    }
  }
  std::shuffle(sites.begin(), sites.end(), gen);
  if (fromBottom) {
    std::stable_sort(sites.begin(), sites.end(),
                     [](const auto& a, const auto& b) { return a.second < b.second; });
  }
  if (sites.size() < n) {
    n = sites.size();
  }
  auto h = hostParticles(n);
  std::vector<std::int64_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) {
    ids[i] = h.id(i);
  }
  std::shuffle(ids.begin(), ids.end(), gen);
  for (std::size_t i = 0; i < n; ++i) {
    h.id(i) = ids[i];
    h.radius(i) = r * (1.0 + spread * u(gen));
    h.position(i, 0) = sites[i].first + 0.02 * r * u(gen);
    h.position(i, 1) = sites[i].second + 0.02 * r * u(gen);
    h.velocity(i, 0) = speed * u(gen);
    h.velocity(i, 1) = speed * u(gen);
    h.angularVelocity(i) = speed / r * u(gen);
  }
  return h;
}

} // namespace hikiln::dem::test
