// Contact-law point functions (kernels/dem/ContactLaw.hpp, Walls.hpp, TimeStep.hpp): closed-form
// values, Coulomb slip, the tensile clamp, rolling torque, and the exact antisymmetry of a pair
// evaluated from both sides inside a kernel on TEST_EXECSPACE.
#include "kernels/dem/ContactLaw.hpp"
#include "kernels/dem/TimeStep.hpp"
#include "kernels/dem/Walls.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace hikiln::dem;
constexpr double pi = hikiln::constants::pi;

TEST(TEST_CATEGORY, dem_restitution_damping_ratio_round_trip) {
  EXPECT_EQ(dampingRatioFromRestitution(1.0), 0.0);
  for (double e : {0.1, 0.5, 0.9, 0.99}) {
    const double z = dampingRatioFromRestitution(e);
    EXPECT_GT(z, 0.0);
    EXPECT_LT(z, 1.0);
    EXPECT_NEAR(restitutionFromDampingRatio(z), e, 1e-14);
  }
  // contact duration of an undamped spring: half a period
  EXPECT_NEAR(contactDuration(1.0e5, 2.0e-3, 0.0), pi * std::sqrt(2.0e-3 / 1.0e5), 1e-18);
}

TEST(TEST_CATEGORY, dem_damping_coefficients_both_modes) {
  ContactParameters p;
  p.restitution = 0.5;
  const ContactCoefficients c = prepareContact(p);
  const double meff = 3.0e-3;
  const double zeta = -std::log(0.5) / std::sqrt(pi * pi + std::log(0.5) * std::log(0.5));
  EXPECT_NEAR(normalDampingCoefficient(c, meff), 2.0 * zeta * std::sqrt(1.0e5 * meff), 1e-12);
  EXPECT_NEAR(tangentialDampingCoefficient(c, meff), zeta * std::sqrt(1.0e5 * meff), 1e-12);
  ContactParameters lmp; // LAMMPS gran/hooke/history 1e5 5e4 1813 906 0.5 1
  lmp.dampingMode = DampingMode::Rate;
  lmp.normalDampingRate = 1813.0;
  lmp.tangentialDampingRate = 906.0;
  const ContactCoefficients r = prepareContact(lmp);
  EXPECT_DOUBLE_EQ(normalDampingCoefficient(r, meff), 1813.0 * meff);
  EXPECT_DOUBLE_EQ(tangentialDampingCoefficient(r, meff), 906.0 * meff);
  lmp.tangentialDamping = false; // dampflag 0
  EXPECT_EQ(tangentialDampingCoefficient(prepareContact(lmp), meff), 0.0);
  p.restitution = 1.5;
  EXPECT_THROW(prepareContact(p), std::invalid_argument);
}

TEST(TEST_CATEGORY, dem_coulomb_slip_rescales_history) {
  ContactParameters p;
  p.friction = 0.3;
  const ContactCoefficients c = prepareContact(p);
  ContactFrame f;
  f.nx = 1.0;
  f.overlap = 1.0e-4;
  f.normalSpeed = -0.01;
  f.tangentialSpeed = 0.2;
  const double meff = 2.0e-3, dt = 1.0e-5;
  // small history: stick, history advanced by v_t dt
  ContactForce s = evaluateContact(c, f, meff, 0.005, 0.0, 1.0e-6, dt, true);
  const double fn = 1.0e5 * 1.0e-4 + normalDampingCoefficient(c, meff) * 0.01;
  EXPECT_DOUBLE_EQ(s.normal, fn);
  EXPECT_DOUBLE_EQ(s.shear, 1.0e-6 + 0.2 * dt);
  EXPECT_NEAR(s.tangential, 5.0e4 * s.shear + tangentialDampingCoefficient(c, meff) * 0.2, 1e-12);
  // large history: slip at mu F_n, history such that k_t s + c_t v_t is the capped force
  s = evaluateContact(c, f, meff, 0.005, 0.0, 1.0e-3, dt, true);
  EXPECT_NEAR(s.tangential, 0.3 * fn, 1e-12);
  EXPECT_NEAR(5.0e4 * s.shear + tangentialDampingCoefficient(c, meff) * 0.2, 0.3 * fn, 1e-12);
  s = evaluateContact(c, f, meff, 0.005, 0.0, -1.0e-3, dt, true);
  EXPECT_NEAR(s.tangential, -0.3 * fn, 1e-12);
  // no history update during set-up
  s = evaluateContact(c, f, meff, 0.005, 0.0, 1.0e-6, dt, false);
  EXPECT_DOUBLE_EQ(s.shear, 1.0e-6);
}

TEST(TEST_CATEGORY, dem_tensile_clamp_and_rolling_torque) {
  ContactParameters p;
  p.rolling = RollingModel::ConstantTorque;
  p.rollingFriction = 0.1;
  ContactFrame f;
  f.nx = 1.0;
  f.overlap = 1.0e-6;
  f.normalSpeed = 1.0; // separating fast: the dashpot pulls
  ContactForce s = evaluateContact(prepareContact(p), f, 1.0e-3, 0.01, 2.0, 0.0, 1e-5, true);
  EXPECT_EQ(s.normal, 0.0);
  EXPECT_EQ(s.tangential, 0.0);
  EXPECT_EQ(s.rollingTorque, 0.0);
  p.limitDamping = false;
  s = evaluateContact(prepareContact(p), f, 1.0e-3, 0.01, 2.0, 0.0, 1e-5, true);
  EXPECT_LT(s.normal, 0.0);
  f.normalSpeed = -0.1;
  f.overlap = 1.0e-4;
  s = evaluateContact(prepareContact(p), f, 1.0e-3, 0.01, 2.0, 0.0, 1e-5, true);
  EXPECT_NEAR(s.rollingTorque, -0.1 * 0.01 * s.normal, 1e-15);
  s = evaluateContact(prepareContact(p), f, 1.0e-3, 0.01, -2.0, 0.0, 1e-5, true);
  EXPECT_NEAR(s.rollingTorque, 0.1 * 0.01 * s.normal, 1e-15);
}

TEST(TEST_CATEGORY, dem_wall_frames) {
  DrumWall drum;
  drum.enabled = true;
  drum.radius = 1.0;
  drum.angularVelocity = 0.5;
  ContactFrame f;
  const double r = 0.01, delta = 1.0e-4;
  // at rest at the bottom of a counter-clockwise drum: the shell moves +x = +t there
  ASSERT_TRUE(drumFrame(drum, 0.0, -(1.0 - r + delta), 0.0, 0.0, 0.0, r, f));
  EXPECT_NEAR(f.overlap, delta, 1e-15);
  EXPECT_DOUBLE_EQ(f.nx, 0.0);
  EXPECT_DOUBLE_EQ(f.ny, -1.0);
  EXPECT_NEAR(f.normalSpeed, 0.0, 1e-15);
  EXPECT_NEAR(f.tangentialSpeed, 0.5, 1e-15);
  // spinning with the shell and moving with it: no relative motion
  ASSERT_TRUE(drumFrame(drum, 0.0, -(1.0 - r + delta), 0.5, 0.0, 0.0, r, f));
  EXPECT_NEAR(f.tangentialSpeed, 0.0, 1e-15);
  EXPECT_FALSE(drumFrame(drum, 0.3, -0.5, 0.0, 0.0, 0.0, r, f));
  // a disc rolling to +x on a floor has omega = -v/r: zero slip
  FlatWall floor;
  ASSERT_TRUE(flatFrame(floor, 2.0, r - delta, 0.3, -0.2, -0.3 / r, r, f));
  EXPECT_NEAR(f.overlap, delta, 1e-15);
  EXPECT_DOUBLE_EQ(f.ny, -1.0);
  EXPECT_NEAR(f.normalSpeed, -0.2, 1e-15);
  EXPECT_NEAR(f.tangentialSpeed, 0.0, 1e-14);
  floor.tangentialVelocity = 0.7; // a conveyor floor moving +x drags a disc at rest to +x
  ASSERT_TRUE(flatFrame(floor, 2.0, r - delta, 0.0, 0.0, 0.0, r, f));
  EXPECT_DOUBLE_EQ(f.nx, 0.0); // t = perp(n) = +x
  EXPECT_NEAR(f.tangentialSpeed, 0.7, 1e-15);
  EXPECT_FALSE(flatFrame(floor, 2.0, r + delta, 0.0, 0.0, 0.0, r, f));
}

TEST(TEST_CATEGORY, dem_time_step_helper) {
  ContactParameters p; // base case with the LAMMPS reference damping
  p.dampingMode = DampingMode::Rate;
  p.normalDampingRate = 1813.0;
  p.tangentialDampingRate = 906.0;
  const ContactCoefficients c = prepareContact(p);
  const double m = 4.0 / 3.0 * pi * std::pow(0.0095, 3) * 2700.0; // 19 mm sphere
  const double meff = 0.5 * m;
  const double tn = pi / std::sqrt(1.0e5 / meff - 0.25 * 1813.0 * 1813.0);
  const double tt = pi / std::sqrt(5.0e4 * 3.5 / meff);
  EXPECT_NEAR(shortestContactDuration(c, meff, 0.4), std::min(tn, tt), 1e-12 * tn);
  EXPECT_LT(tt, tn);
  const double dt = recommendedTimeStep(c, c, m, 0.4);
  EXPECT_NEAR(dt, 0.05 * tt, 1e-15);
  EXPECT_GT(dt, 2.0e-5); // next to the 2.5e-5 s of the LAMMPS reference
  EXPECT_LT(dt, 3.0e-5);
}

// Kernels live in free functions: CUDA extended lambdas may not sit in a gtest TestBody (private).
// Evaluates each pair of `in` (columns as filled below) from both sides on TEST_EXECSPACE;
// out(c, side, :) = touching, force x, force y, shear, rolling torque, F_n, F_t.
Kokkos::View<double* [2][7], TEST_EXECSPACE::memory_space>
evaluatePairsFromBothSides(Kokkos::View<double* [16], Kokkos::HostSpace> in,
                           const ContactCoefficients& coeff) {
  using space = TEST_EXECSPACE;
  const int numCases = static_cast<int>(in.extent(0));
  auto inDev = Kokkos::create_mirror_view_and_copy(space::memory_space{}, in);
  Kokkos::View<double* [2][7], space::memory_space> out("hikiln::test::pairOut", numCases);
  Kokkos::parallel_for(
      "hikiln::test::pairAntisymmetry", Kokkos::RangePolicy<space>(space(), 0, numCases),
      KOKKOS_LAMBDA(int c) {
        for (int side = 0; side < 2; ++side) {
          const int a = side == 0 ? 0 : 2, b = side == 0 ? 2 : 0; // position columns
          const int va = side == 0 ? 4 : 6, vb = side == 0 ? 6 : 4;
          const double ra = inDev(c, side == 0 ? 10 : 11), rb = inDev(c, side == 0 ? 11 : 10);
          const double wa = inDev(c, side == 0 ? 8 : 9), wb = inDev(c, side == 0 ? 9 : 8);
          const double ma = 1.0e-3 * (1.0 + ra), mb = 1.0e-3 * (1.0 + rb);
          ContactFrame f;
          const bool touching = pairFrame(
              inDev(c, b) - inDev(c, a), inDev(c, b + 1) - inDev(c, a + 1),
              inDev(c, vb) - inDev(c, va), inDev(c, vb + 1) - inDev(c, va + 1), ra, rb, wa, wb, f);
          const ContactForce r =
              evaluateContact(coeff, f, effectiveMass(ma, mb), rollingRadius(ra, rb), wa - wb,
                              inDev(c, 12), 1.0e-5, true);
          out(c, side, 0) = touching ? 1.0 : 0.0;
          out(c, side, 1) = -r.normal * f.nx + r.tangential * (-f.ny);
          out(c, side, 2) = -r.normal * f.ny + r.tangential * f.nx;
          out(c, side, 3) = r.shear;
          out(c, side, 4) = r.rollingTorque;
          out(c, side, 5) = r.normal;
          out(c, side, 6) = r.tangential;
        }
      });
  return out;
}

// One pair evaluated from both sides in a kernel: vectors negate exactly, scalars are identical.
TEST(TEST_CATEGORY, dem_pair_force_exactly_antisymmetric) {
  constexpr int numCases = 200;
  Kokkos::View<double* [16], Kokkos::HostSpace> in("hikiln::test::pairIn", numCases);
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int c = 0; c < numCases; ++c) {
    const double ri = 0.01 + 0.002 * u(gen), rj = 0.01 + 0.002 * u(gen);
    const double ang = pi * u(gen);
    const double d = (ri + rj) * (1.0 - 0.01 * std::fabs(u(gen)));
    in(c, 0) = 0.3 * u(gen); // x_i
    in(c, 1) = 0.3 * u(gen);
    in(c, 2) = in(c, 0) + d * std::cos(ang); // x_j
    in(c, 3) = in(c, 1) + d * std::sin(ang);
    for (int k = 4; k < 8; ++k)
      in(c, k) = u(gen);      // v_i, v_j
    in(c, 8) = 50.0 * u(gen); // omega_i, omega_j
    in(c, 9) = 50.0 * u(gen);
    in(c, 10) = ri;
    in(c, 11) = rj;
    in(c, 12) = 1.0e-4 * u(gen); // shared shear history
  }
  ContactParameters p;
  p.rolling = RollingModel::ConstantTorque;
  p.rollingFriction = 0.05;
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{},
                                               evaluatePairsFromBothSides(in, prepareContact(p)));
  int slipping = 0;
  for (int c = 0; c < numCases; ++c) {
    ASSERT_EQ(h(c, 0, 0), 1.0);
    ASSERT_EQ(h(c, 1, 0), 1.0);
    EXPECT_EQ(h(c, 0, 1), -h(c, 1, 1)) << c;
    EXPECT_EQ(h(c, 0, 2), -h(c, 1, 2)) << c;
    EXPECT_EQ(h(c, 0, 3), h(c, 1, 3)) << c; // both copies of the history stay equal
    EXPECT_EQ(h(c, 0, 4), -h(c, 1, 4)) << c;
    EXPECT_EQ(h(c, 0, 5), h(c, 1, 5)) << c;
    EXPECT_EQ(h(c, 0, 6), h(c, 1, 6)) << c;
    if (std::fabs(h(c, 0, 6)) == 0.5 * h(c, 0, 5)) {
      ++slipping;
    }
  }
  EXPECT_GT(slipping, 0); // the cases exercise both the Coulomb branch and sticking
  EXPECT_LT(slipping, numCases);
}

} // namespace
