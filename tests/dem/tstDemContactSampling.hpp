// The lean neighbour list and the sampled contact forces (kernels/dem/NeighborList.hpp,
// ForceKernel.hpp computeContactForces, DemSystem): sampled slot and wall forces rebuild the
// particles' total forces, are antisymmetric pair by pair, and rows widen on demand up to the
// configured limit without losing pairs.
#include "DemTestUtils.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;

DemConfig drumConfig(double radius = 0.12) {
  DemConfig cfg;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = radius;
  cfg.walls.drum.angularVelocity = 2.0;
  cfg.particleContact.rolling = RollingModel::ConstantTorque;
  cfg.particleContact.rollingFriction = 0.05;
  cfg.wallContact = cfg.particleContact;
  return cfg;
}

// A packed, jostling bed: discs on a lattice at 0.98 of their diameter (overlapping), moving.
ParticleArrays<Kokkos::HostSpace> packedBed(std::size_t n) {
  auto h = test::drumParticles(n, 0.12, 0.005, 0.05, 0.05, 31, 0.98, true);
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  return h;
}

// Right after setParticles the forces are those of the current state (history not advanced), so
// the sampled contact forces (the same evaluation, per slot) must add up to them.
TEST(TEST_CATEGORY, dem_sampled_contact_forces_add_up_to_particle_forces) {
  // a drum a little smaller than the lattice's: the outermost discs press on the shell
  DemSystem<space> sys(drumConfig(0.113));
  sys.setParticles(packedBed(150));
  const auto check = [](const DemSystem<space>& s, const char* when) {
    const auto& list = s.neighborList();
    const auto& walls = s.wallContacts();
    const auto h = s.hostParticles();
    auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, list.count);
    auto index = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, list.index);
    auto nid = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, list.neighborId);
    auto fn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, list.normalForce);
    auto ft = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, list.tangentialForce);
    auto wfn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, walls.normalForce);
    auto wft = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, walls.tangentialForce);
    const ForceSettings& fs = s.forceSettings();
    std::map<std::pair<std::int64_t, std::int64_t>, std::pair<double, double>> pairForce;
    int touching = 0, wallTouching = 0;
    double largest = 0.0;
    for (std::size_t i = 0; i < h.count(); ++i) {
      double fx = h.mass(i) * fs.gravityX, fy = h.mass(i) * fs.gravityY;
      for (int k = 0; k < count(i); ++k) {
        const int j = index(i, k);
        EXPECT_EQ(nid(i, k), h.id(j));
        if (fn(i, k) == 0.0 && ft(i, k) == 0.0) {
          continue;
        }
        ++touching;
        const double dx = h.position(j, 0) - h.position(i, 0);
        const double dy = h.position(j, 1) - h.position(i, 1);
        const double r = std::hypot(dx, dy);
        const double nx = dx / r, ny = dy / r;
        fx += -fn(i, k) * nx - ft(i, k) * ny;
        fy += -fn(i, k) * ny + ft(i, k) * nx;
        pairForce[{h.id(i), h.id(j)}] = {fn(i, k), ft(i, k)};
      }
      if (wfn(i, 0) != 0.0 || wft(i, 0) != 0.0) { // drum: n points outwards from the centre
        ++wallTouching;
        const double d = std::hypot(h.position(i, 0), h.position(i, 1));
        const double nx = h.position(i, 0) / d, ny = h.position(i, 1) / d;
        fx += -wfn(i, 0) * nx - wft(i, 0) * ny;
        fy += -wfn(i, 0) * ny + wft(i, 0) * nx;
      }
      largest = std::max(largest, std::hypot(h.force(i, 0), h.force(i, 1)));
      EXPECT_NEAR(fx, h.force(i, 0), 1e-9 * (1.0 + std::fabs(h.force(i, 0)))) << when << " " << i;
      EXPECT_NEAR(fy, h.force(i, 1), 1e-9 * (1.0 + std::fabs(h.force(i, 1)))) << when << " " << i;
    }
    EXPECT_GT(touching, 150) << when; // a packed bed: a few contacts per disc
    EXPECT_GT(wallTouching, 0) << when;
    EXPECT_GT(largest, 1.0) << when;         // forces well above round-off
    for (const auto& [key, f] : pairForce) { // both sides hold bitwise the same scalars
      const auto other = pairForce.find({key.second, key.first});
      ASSERT_NE(other, pairForce.end());
      EXPECT_EQ(f.first, other->second.first);
      EXPECT_EQ(f.second, other->second.second);
    }
  };
  check(sys, "set-up");
  sys.advance(50);
  // a moved, jostling state: a fresh set-up evaluation there (history cleared) and its samples
  DemSystem<space> again(drumConfig(0.113));
  again.setParticles(sys.hostParticles());
  check(again, "after 50 steps");
}

// Sampling changes nothing: a run that samples every step stays bitwise on the run that never
// samples (the deferred half kick and the sampler leave the trajectory alone).
TEST(TEST_CATEGORY, dem_sampling_does_not_change_the_trajectory) {
  DemSystem<space> quiet(drumConfig()), sampled(drumConfig());
  quiet.setParticles(packedBed(120));
  sampled.setParticles(packedBed(120));
  for (int s = 0; s < 200; ++s) {
    quiet.step();
    sampled.step();
    if (s % 3 == 0) {
      (void)sampled.neighborList();
      (void)sampled.wallContacts();
    } else if (s % 3 == 1) {
      (void)sampled.particles();
    }
  }
  test::expectBitwiseEqual(test::byId(quiet), test::byId(sampled));
}

// Rows start narrow and widen on demand: with a skin of two diameters a row needs ~20 slots.
TEST(TEST_CATEGORY, dem_neighbor_rows_widen_on_demand) {
  DemConfig cfg = drumConfig();
  cfg.skin = 0.02;
  cfg.neighborCapacity = 40;
  DemSystem<space> sys(cfg);
  const auto h = packedBed(150);
  sys.setParticles(h);
  const auto& rows = sys.neighborRows();
  auto count = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, rows.count);
  const auto p = sys.hostParticles();
  int longest = 0;
  std::size_t slots = 0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    longest = std::max(longest, count(i));
    slots += static_cast<std::size_t>(count(i));
  }
  std::size_t pairs = 0; // brute force: every pair within r_i + r_j + skin, both directions
  for (std::size_t i = 0; i < p.count(); ++i) {
    for (std::size_t j = 0; j < p.count(); ++j) {
      const double cut = p.radius(i) + p.radius(j) + cfg.skin;
      if (i != j && std::hypot(p.position(j, 0) - p.position(i, 0),
                               p.position(j, 1) - p.position(i, 1)) < cut) {
        ++pairs;
      }
    }
  }
  EXPECT_GT(longest, 8);               // wider than the initial rows
  EXPECT_LE(longest, rows.capacity()); // fits
  EXPECT_LE(rows.capacity(), cfg.neighborCapacity);
  EXPECT_EQ(slots, pairs); // nothing lost while widening
  EXPECT_LT(sys.memoryBytes(), 150u * (200u + 12u * static_cast<unsigned>(rows.capacity())));
}

} // namespace
