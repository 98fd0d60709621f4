// Coarse-graining of DEM samples into averaged fields (physics.md 2), against known answers:
// (1) the integrated cell mass equals the particle mass on both grids (also for particles outside
// the grids); (2) particles on a lattice moving with a linear velocity field give that field at
// the cell centres (Cartesian) / area centroids (polar), its strain rate, and the streaming stress
// of the within-cell velocity spread computed by hand; rigid rotation gives no strain rate;
// (3) a synthetic simple-shear stress [[-p, tau], [tau, -p]] (tension positive) gives p, q = |tau|
// and m = |tau| / p = tau / sigma_n on the shear plane (the Drucker-Prager convention); (4) one
// particle resting on the shell gives mu_wall = 0 and normal stress m g / (arc x thickness).
#include "CoarseGrainTestUtils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace {

using namespace hikiln::dem;
using hikiln::constants::pi;
using space = TEST_EXECSPACE;
using cg::CellSum;

double massSum(const std::vector<double>& sums) {
  double m = 0.0;
  for (std::size_t c = 0; c < sums.size(); c += CellSum::Size)
    m += sums[c + CellSum::Mass];
  return m;
}

TEST(TEST_CATEGORY, coarse_grain_mass_is_conserved_on_both_grids) {
  DemConfig cfg;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = 0.3;
  auto h = test::drumParticles(300, 0.3, 0.01, 0.2, 0.5, 5, 0.0, true);
  ASSERT_EQ(h.count(), 300u);
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  double total = 0.0;
  for (std::size_t i = 0; i < h.count(); ++i)
    total += h.mass(i);
  // The second averager's grids cover only r < 0.12 and [-0.12, 0.12]^2: the particles outside go
  // to the edge cells and must still be counted once.
  for (double gridRadius : {0.3, 0.12}) {
    AveragingSettings s;
    s.drumRadius = gridRadius;
    s.thickness = 0.02;
    FieldAverager<space> averager(s);
    const int samples = 5;
    DemSystem<space> run(cfg);
    run.setParticles(h);
    for (int k = 0; k < samples; ++k) {
      run.advance(50);
      averager.sample(run, run.time());
    }
    const AveragingSums sums = averager.sums();
    EXPECT_EQ(sums.samples, samples);
    for (const auto* grid : {&sums.polar, &sums.cartesian}) {
      EXPECT_NEAR(massSum(*grid) / samples, total, 1e-12 * total) << "grid radius " << gridRadius;
      double count = 0.0;
      for (std::size_t c = 0; c < grid->size(); c += CellSum::Size)
        count += (*grid)[c + CellSum::Count];
      EXPECT_EQ(count, static_cast<double>(samples * static_cast<int>(h.count())));
    }
  }
}

// u = (a y, 0) on the Cartesian lattice: velocity exact at the centres, gamma_dot = |a| everywhere
// (one-sided differences at the edge are exact for a linear field too), streaming stress of the
// within-cell spread sum m (a (y_i - y_c))^2 / V.
TEST(TEST_CATEGORY, coarse_grain_simple_shear_on_cartesian_grid) {
  AveragingSettings s;
  s.drumRadius = 1.0;
  s.thickness = 0.01;
  s.minVolumeFraction = 0.0;
  s.minParticleSamples = 1;
  const cg::CartesianGrid g = s.cartesianGrid();
  const double a = -0.7, u0 = 0.3, radius = 0.005, mass = 0.01;
  auto placed = test::cartesianLattice(g, radius, mass);
  test::setVelocity(placed, [&](double, double y, double& vx, double& vy) {
    vx = u0 + a * y;
    vy = 0.0;
  });
  auto sys = test::placedSystem<space>(placed);
  FieldAverager<space> averager(s);
  averager.sample(sys, 0.0);
  averager.sample(sys, 0.1);
  const AveragedFields f = averager.result();
  const CellFields& c = f.cartesian;
  ASSERT_EQ(c.slow, 30u);
  ASSERT_EQ(c.fast, 30u);
  const double volume = g.dx * g.dy * s.thickness;
  // sum over a cell's 16 particles of (y_i - y_c)^2 = 8 ((dy/8)^2 + (3 dy/8)^2) = 1.25 dy^2
  const double streaming = mass * a * a * 1.25 * g.dy * g.dy / volume;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t k = static_cast<std::size_t>(iy * g.nx + ix);
      EXPECT_NEAR(c.velocityX[k], u0 + a * g.yCentre(iy), 1e-13);
      EXPECT_NEAR(c.velocityY[k], 0.0, 1e-15);
      EXPECT_NEAR(c.strainRate[k], std::fabs(a), 1e-10 * std::fabs(a)) << ix << " " << iy;
      EXPECT_NEAR(c.volumeFraction[k], 16 * pi * radius * radius / (g.dx * g.dy), 1e-13);
      EXPECT_NEAR(c.kineticXX[k], streaming, 1e-9 * streaming);
      EXPECT_NEAR(c.kineticYY[k], 0.0, 1e-12 * streaming);
      EXPECT_NEAR(c.kineticXY[k], 0.0, 1e-12 * streaming);
      EXPECT_NEAR(c.granularTemperature[k], 0.5 * a * a * 1.25 * g.dy * g.dy / 16, 1e-15);
      EXPECT_EQ(c.contactXX[k], 0.0); // no contacts
      // the only stress is the streaming one: p = q = streaming / 2, m = 1
      EXPECT_NEAR(c.pressure[k], 0.5 * streaming, 1e-9 * streaming);
      EXPECT_NEAR(c.shearStress[k], 0.5 * streaming, 1e-9 * streaming);
      EXPECT_NEAR(c.viscosity[k], 0.5 * streaming / std::fabs(a), 1e-8 * streaming);
      EXPECT_NEAR(c.frictionM[k], 1.0, 1e-9);
      EXPECT_EQ(c.valid[k], 1);
    }
}

// u = (a y, 0) on the polar grid: velocity exact at each cell's area centroid, gamma_dot = |a|
// within 1 % (the theta differences of sin 2 theta are short by sin(2 dtheta) / (2 dtheta), 0.7 %
// at 60 sectors; the r differences are exact).
TEST(TEST_CATEGORY, coarse_grain_simple_shear_on_polar_grid) {
  AveragingSettings s;
  s.drumRadius = 1.0;
  s.minVolumeFraction = 0.0;
  s.minParticleSamples = 1;
  const cg::PolarGrid g = s.polarGrid();
  const double a = 1.3;
  auto placed = test::polarLattice(g, 5e-5, 2700.0);
  test::setVelocity(placed, [&](double, double y, double& vx, double& vy) {
    vx = a * y;
    vy = 0.0;
  });
  auto sys = test::placedSystem<space>(placed);
  FieldAverager<space> averager(s);
  averager.sample(sys, 0.0);
  const AveragedFields f = averager.result();
  const CellFields& c = f.polar;
  ASSERT_EQ(c.slow, 60u);
  ASSERT_EQ(c.fast, 15u);
  double worst = 0.0;
  for (int it = 0; it < g.ntheta; ++it)
    for (int ir = 0; ir < g.nr; ++ir) {
      const std::size_t k = static_cast<std::size_t>(it * g.nr + ir);
      const double theta = (it + 0.5) * g.sectorWidth();
      EXPECT_NEAR(c.velocityX[k], a * g.centroidRadius(ir) * std::sin(theta), 1e-12 * a);
      EXPECT_NEAR(c.velocityY[k], 0.0, 1e-15);
      EXPECT_NEAR(c.particlesPerSample[k], 16.0, 0.0);
      worst = std::max(worst, std::fabs(c.strainRate[k] - a) / a);
    }
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(worst, 1e-4); // the theta truncation error is there: the test sees the polar path
}

// Rigid rotation u = Omega (-y, x) has no strain rate on either grid (to round-off).
TEST(TEST_CATEGORY, coarse_grain_rigid_rotation_has_no_strain_rate) {
  AveragingSettings s;
  s.drumRadius = 1.0;
  s.minVolumeFraction = 0.0;
  s.minParticleSamples = 1;
  const double omega = 0.5;
  const auto rotate = [&](double x, double y, double& vx, double& vy) {
    vx = -omega * y;
    vy = omega * x;
  };
  auto polar = test::polarLattice(s.polarGrid(), 5e-5, 2700.0);
  auto cartesian = test::cartesianLattice(s.cartesianGrid(), 0.005, 0.01);
  test::setVelocity(polar, rotate);
  test::setVelocity(cartesian, rotate);
  FieldAverager<space> polarAverager(s), cartesianAverager(s);
  polarAverager.sample(test::placedSystem<space>(polar), 0.0);
  cartesianAverager.sample(test::placedSystem<space>(cartesian), 0.0);
  const AveragedFields p = polarAverager.result(), c = cartesianAverager.result();
  for (double rate : p.polar.strainRate)
    EXPECT_NEAR(rate, 0.0, 1e-12 * omega);
  for (double rate : c.cartesian.strainRate)
    EXPECT_NEAR(rate, 0.0, 1e-12 * omega);
}

// Sums of a synthetic sample in which every cell holds the tension-positive contact stress
// sigma = [[sxx, sxy], [syx, syy]], mass M at rest except for the velocity u(x, y), area fraction
// 0.8, 100 particles per sample.
AveragingSums syntheticSums(const AveragingSettings& s, double sxx, double sxy, double syx,
                            double syy, double shearRate, std::int64_t samples) {
  const cg::CartesianGrid g = s.cartesianGrid();
  AveragingSums sums;
  sums.samples = samples;
  sums.polar.assign(static_cast<std::size_t>(s.polarGrid().cellCount()) * CellSum::Size, 0.0);
  sums.wall.assign(static_cast<std::size_t>(s.angularCells) * cg::WallSum::Size, 0.0);
  sums.cartesian.assign(static_cast<std::size_t>(g.cellCount()) * CellSum::Size, 0.0);
  const double n = static_cast<double>(samples), mass = 2.0;
  const double sv = n * g.dx * g.dy * s.thickness;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      double* a = &sums.cartesian[static_cast<std::size_t>(iy * g.nx + ix) * CellSum::Size];
      const double ux = shearRate * g.yCentre(iy);
      a[CellSum::Count] = 100.0 * n;
      a[CellSum::Area] = 0.8 * g.dx * g.dy * n;
      a[CellSum::Mass] = mass * n;
      a[CellSum::MomentumX] = mass * n * ux;
      a[CellSum::MvvXX] = mass * n * ux * ux;
      a[CellSum::VirialXX] = sxx * sv; // the virial sum is sigma V, tension positive
      a[CellSum::VirialXY] = sxy * sv;
      a[CellSum::VirialYX] = syx * sv;
      a[CellSum::VirialYY] = syy * sv;
    }
  return sums;
}

TEST(TEST_CATEGORY, coarse_grain_drucker_prager_convention) {
  AveragingSettings s;
  s.drumRadius = 0.5;
  s.thickness = 0.02;
  const double p = 1500.0, rate = 2.5;
  for (double tau : {450.0, -450.0, 0.0}) {
    const AveragedFields f = finalizeAverages(s, syntheticSums(s, -p, tau, tau, -p, rate, 7));
    const CellFields& c = f.cartesian;
    for (std::size_t k = 0; k < c.size(); ++k) {
      ASSERT_EQ(c.valid[k], 1);
      // stored compressive positive
      EXPECT_NEAR(c.contactXX[k], p, 1e-12 * p);
      EXPECT_NEAR(c.contactYY[k], p, 1e-12 * p);
      EXPECT_NEAR(c.contactXY[k], -tau, 1e-12 * p);
      EXPECT_NEAR(c.kineticXX[k], 0.0, 1e-9 * p);
      EXPECT_NEAR(c.pressure[k], p, 1e-12 * p);
      EXPECT_NEAR(c.shearStress[k], std::fabs(tau), 1e-12 * p);
      EXPECT_NEAR(c.frictionM[k], std::fabs(tau) / p, 1e-12);
      // on the shear plane (normal e_y): tau / sigma_n = m, i.e. m = tan(phi)
      EXPECT_NEAR(std::fabs(c.contactXY[k]) / c.contactYY[k], c.frictionM[k], 1e-12);
      EXPECT_NEAR(c.strainRate[k], rate, 1e-9 * rate);
      EXPECT_NEAR(c.viscosity[k], std::fabs(tau) / rate, 1e-9 * p / rate);
    }
  }
  // uniaxial: q is half the normal stress difference; p the mean; not valid -> NaN m and viscosity
  s.minVolumeFraction = 0.9; // the synthetic cells hold 0.8
  const AveragedFields f = finalizeAverages(s, syntheticSums(s, -3000.0, 0.0, 0.0, -1000.0, 1, 3));
  EXPECT_NEAR(f.cartesian.pressure[0], 2000.0, 1e-9);
  EXPECT_NEAR(f.cartesian.shearStress[0], 1000.0, 1e-9);
  EXPECT_EQ(f.cartesian.valid[0], 0);
  EXPECT_TRUE(std::isnan(f.cartesian.frictionM[0]));
  EXPECT_TRUE(std::isnan(f.cartesian.viscosity[0]));
}

// One disc resting at the bottom of a still drum: all the shell carries is its weight, normal.
TEST(TEST_CATEGORY, coarse_grain_wall_stress_of_a_resting_particle) {
  const double R = 0.5, r = 0.01, g = 9.81;
  DemConfig cfg;
  cfg.gravityY = -g;
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = R;
  auto h = test::hostParticles(1);
  h.radius(0) = r;
  assignMassPropertiesHost(h, 2700.0, MassConvention::Sphere);
  const double m = h.mass(0);
  h.position(0, 1) = -(R - r + m * g / cfg.wallContact.normalStiffness);
  DemSystem<space> sys(cfg);
  sys.setParticles(h);
  AveragingSettings s;
  s.drumRadius = R;
  s.thickness = 2 * r;
  FieldAverager<space> averager(s);
  for (int k = 0; k < 6; ++k) {
    averager.sample(sys, sys.time());
    sys.advance(200);
  }
  const WallFields w = averager.result().wall;
  const double arc = R * 2 * pi / s.angularCells;
  const double expected = m * g / (arc * s.thickness);
  int loaded = 0;
  for (std::size_t b = 0; b < w.normalStress.size(); ++b) {
    EXPECT_EQ(w.shearStress[b], 0.0);
    if (w.normalStress[b] != 0.0) {
      ++loaded;
      EXPECT_NEAR(w.normalStress[b], expected, 1e-6 * expected);
      EXPECT_NEAR(w.contactsPerSample[b], 1.0, 0.0);
      EXPECT_NEAR(w.tangentialVelocity[b], 0.0, 1e-12);
      EXPECT_NEAR(w.thetaCentres[b], 1.5 * pi, 2 * pi / s.angularCells);
    }
  }
  EXPECT_EQ(loaded, 1);
  EXPECT_EQ(w.muWall, 0.0);
  EXPECT_TRUE(std::isnan(w.slipPercent)); // a still drum has no slip
}

// The shear sign follows the shell motion: a hand-made contact with F_t > 0 (counter-clockwise
// drag on the particle) is positive shear for omega > 0 and negative for omega < 0; F_n, counts
// and the tangential speed of a particle touching the shell land in its angular bin.
TEST(TEST_CATEGORY, coarse_grain_shell_bins_follow_the_shell_motion) {
  using memory = space::memory_space;
  auto h = test::hostParticles(2);
  h.radius(0) = h.radius(1) = 0.01;
  h.position(0, 0) = 0.0; // at the bottom, touching (theta = 3 pi / 2)
  h.position(0, 1) = -0.99;
  h.velocity(0, 0) = 0.2; // counter-clockwise at the bottom is +x
  h.position(1, 0) = 0.5; // well inside
  const auto p = copyParticles<memory>(h);
  WallContactState<memory> walls(2);
  auto fnHost = Kokkos::create_mirror_view(walls.normalForce);
  auto ftHost = Kokkos::create_mirror_view(walls.tangentialForce);
  Kokkos::deep_copy(fnHost, 0.0);
  Kokkos::deep_copy(ftHost, 0.0);
  fnHost(0, 0) = 3.0;
  ftHost(0, 0) = 0.75;
  Kokkos::deep_copy(walls.normalForce, fnHost);
  Kokkos::deep_copy(walls.tangentialForce, ftHost);
  for (double omega : {0.3, -0.3}) {
    cg::ShellBins bins;
    bins.radius = 1.0;
    bins.ntheta = 37;
    bins.shearSign = cg::shellMotionSign(omega);
    Kokkos::View<double**, memory> sums("hikiln::test::shellSums", bins.ntheta, cg::WallSum::Size);
    cg::depositShell(space(), bins, p, walls, sums);
    const auto out = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace{}, sums);
    const int b = 27; // 3 pi / 2 is 27.75 bins of 37
    EXPECT_EQ(out(b, cg::WallSum::NormalForce), 3.0);
    EXPECT_EQ(out(b, cg::WallSum::ShearForce), omega > 0 ? 0.75 : -0.75);
    EXPECT_EQ(out(b, cg::WallSum::Contacts), 1.0);
    EXPECT_EQ(out(b, cg::WallSum::Touching), 1.0);
    EXPECT_NEAR(out(b, cg::WallSum::SpeedSum), 0.2, 1e-15);
    double all = 0.0;
    for (int k = 0; k < bins.ntheta; ++k)
      for (int c = 0; c < cg::WallSum::Size; ++c)
        all += std::fabs(out(k, c));
    EXPECT_NEAR(all, 3.0 + 0.75 + 1 + 1 + 0.2, 1e-15); // nothing else anywhere
  }
}

} // namespace
