// Batched slices (solvers/dem/DemBatch.hpp): three different systems (two drums of different
// size, speed, friction, restitution and gravity, and a box of flat walls with a sliding floor)
// share one set of arrays and launches. They overlap in space, so a slice that met another one
// would leave its own trajectory at once. Each slice must follow its own DemSystem bitwise
// (positions, velocities, forces, contact history, clock), at any thread count.

#include "DemTestUtils.hpp"
#include "solvers/dem/DemBatch.hpp"

#include <gtest/gtest.h>

#include <map>
#include <utility>
#include <vector>

namespace {

using namespace hikiln::dem;
using test::history;
using test::History;
using space = TEST_EXECSPACE;

constexpr double commonTimeStep = 5.0e-5; // t_c / 50 for the softest springs below

DemConfig softDrum(double radius, double omega) {
  DemConfig cfg;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = radius;
  cfg.walls.drum.angularVelocity = omega;
  cfg.particleContact.normalStiffness = 2.0e3;
  cfg.particleContact.tangentialStiffness = 1.0e3;
  cfg.wallContact = cfg.particleContact;
  cfg.timeStep = commonTimeStep;
  cfg.sortEveryRebuilds = 2;
  return cfg;
}

// slice 0: the determinism tests' drum (rolling resistance on)
DemConfig sliceConfig0() {
  DemConfig cfg = softDrum(0.12, 3.0);
  cfg.particleContact.rolling = RollingModel::ConstantTorque;
  cfg.particleContact.rollingFriction = 0.05;
  return cfg;
}

// slice 1: a smaller drum turning the other way, other friction, restitution and gravity
DemConfig sliceConfig1() {
  DemConfig cfg = softDrum(0.10, -5.0);
  cfg.particleContact.friction = 0.3;
  cfg.particleContact.restitution = 0.3;
  cfg.wallContact.friction = 0.8;
  cfg.gravityX = 2.0;
  return cfg;
}

// slice 2: a box of flat walls (no drum) with a floor sliding at 0.2 m/s
DemConfig sliceConfig2() {
  DemConfig cfg = softDrum(1.0, 0.0);
  cfg.walls.drum.enabled = false;
  cfg.walls.numFlat = 3;
  cfg.walls.flat[0] = FlatWall{0.0, -0.1, 0.0, 1.0, 0.2};
  cfg.walls.flat[1] = FlatWall{-0.1, 0.0, 1.0, 0.0, 0.0};
  cfg.walls.flat[2] = FlatWall{0.1, 0.0, -1.0, 0.0, 0.0};
  return cfg;
}

DemConfig sliceConfig(int k) {
  return k == 0 ? sliceConfig0() : (k == 1 ? sliceConfig1() : sliceConfig2());
}

ParticleArrays<Kokkos::HostSpace> sliceParticles(int k) {
  const std::size_t counts[3] = {200, 150, 100};
  const double reach[3] = {0.12, 0.10, 0.11};
  auto h = test::drumParticles(counts[k], reach[k], 0.005, 0.05, 0.05, 21 + k, 1.05, true);
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  return h;
}

// Every particle's kinematics and forces by id, and the wall history, from a state.
std::map<std::int64_t, std::vector<double>> particlesById(const DemState& s) {
  std::map<std::int64_t, std::vector<double>> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::vector<double> v = {
        s.position[2 * i],    s.position[2 * i + 1], s.velocity[2 * i],  s.velocity[2 * i + 1],
        s.angularVelocity[i], s.force[2 * i],        s.force[2 * i + 1], s.torque[i]};
    for (int m = 0; m < wallSlotCount; ++m) {
      v.push_back(s.wallShear[wallSlotCount * i + m]);
    }
    out[s.id[i]] = std::move(v);
  }
  return out;
}

void expectSameState(const DemState& batched, const DemState& alone, int slice) {
  EXPECT_EQ(batched.step, alone.step) << "slice " << slice;
  EXPECT_EQ(batched.time, alone.time) << "slice " << slice;
  const auto a = particlesById(batched), b = particlesById(alone);
  ASSERT_EQ(a.size(), b.size()) << "slice " << slice;
  int differing = 0;
  for (const auto& [id, values] : a) {
    const auto it = b.find(id);
    ASSERT_NE(it, b.end()) << "slice " << slice << " id " << id;
    differing += values != it->second;
  }
  EXPECT_EQ(differing, 0) << "slice " << slice << ": particles not bitwise equal";
  const History ha = history(batched), hb = history(alone);
  EXPECT_EQ(ha, hb) << "slice " << slice << ": contact history differs";
}

struct Slices {
  std::vector<DemSystem<space>> alone;
  Slices() {
    for (int k = 0; k < 3; ++k) {
      alone.emplace_back(sliceConfig(k));
      alone.back().setParticles(sliceParticles(k));
      alone.back().advance(300); // beds in contact, history built up
    }
  }
  void advance(std::int64_t steps) {
    for (auto& s : alone) {
      s.advance(steps);
    }
  }
};

TEST(TEST_CATEGORY, dem_batch_slices_follow_their_own_systems_bitwise) {
  Slices slices;
  DemBatch<space> batch;
  for (const auto& s : slices.alone) {
    batch.add(s);
  }
  batch.start();
  EXPECT_EQ(batch.system().sliceCount(), 3);
  EXPECT_EQ(batch.size(), 450u);

  slices.advance(700);
  batch.advance(700);
  auto states = batch.exportSlices();
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(history(states[k]).size(), 40u) << "slice " << k << " should be in contact";
    expectSameState(states[k], slices.alone[k].exportState(), k);
  }
  slices.advance(1300);
  batch.advance(600);
  batch.advance(700);
  states = batch.exportSlices();
  for (int k = 0; k < 3; ++k) {
    expectSameState(states[k], slices.alone[k].exportState(), k);
  }
  EXPECT_GT(batch.system().rebuildCount(), 1);
  EXPECT_GT(batch.system().sortCount(), 0);
}

TEST(TEST_CATEGORY, dem_batch_exported_slice_continues_on_its_own) {
  Slices slices;
  DemBatch<space> batch;
  for (const auto& s : slices.alone) {
    batch.add(s);
  }
  batch.start();
  batch.advance(500);
  DemSystem<space> own(sliceConfig(1));
  own.importState(batch.exportSlices()[1]);
  own.advance(500);
  slices.advance(1000);
  expectSameState(own.exportState(), slices.alone[1].exportState(), 1);
}

TEST(TEST_CATEGORY, dem_batch_refuses_a_different_time_step) {
  DemSystem<space> a(sliceConfig(0));
  a.setParticles(sliceParticles(0));
  DemConfig other = sliceConfig(1);
  other.timeStep = 0.5 * commonTimeStep;
  DemSystem<space> b(other);
  b.setParticles(sliceParticles(1));
  DemBatch<space> batch;
  batch.add(a);
  EXPECT_THROW(batch.add(b), std::invalid_argument);
  EXPECT_THROW(batch.exportSlices(), std::logic_error); // not started
}

} // namespace
