// Point functions of the DEM heat model: shell geometry and the stability limit, contact areas
// (overlap, stiffness-ratio and Hertz rescaling), the boundary-layer pair update (energy balance,
// flux continuity at the contact surface, steady series conductance, capacity exchange) and
// radiation. Evaluated on the host and, for the kernels' view of them, on TEST_EXECSPACE.
#include "kernels/dem/heat/ContactConduction.hpp"
#include "kernels/dem/heat/Radiation.hpp"
#include "kernels/dem/heat/ShellModel.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace hikiln::dem;
using space = TEST_EXECSPACE;
constexpr double pi = 3.14159265358979323846;

HeatCoefficients coefficients(MassConvention g, int shells) {
  HeatParameters p;
  p.geometry = g;
  p.shells = shells;
  p.radiation = false;
  return prepareHeat(p, 1.0e5, 0.004);
}

TEST(TEST_CATEGORY, heat_shell_geometry) {
  for (MassConvention g : {MassConvention::Sphere, MassConvention::Disc}) {
    for (int n : {1, 3, 8}) {
      double sum = 0.0;
      for (int m = 0; m < n; ++m) {
        sum += shellVolumeFraction(g, n, m);
      }
      EXPECT_NEAR(sum, 1.0, 1e-15);
    }
  }
  // face 3 of 8 at r = 3 R/8: k x area / dr
  const double k = 2.5, r = 0.01, t = 0.02, dr = r / 8, rf = 3 * dr;
  EXPECT_NEAR(shellFaceConductance(MassConvention::Sphere, 8, 3, k, r, t),
              k * 4 * pi * rf * rf / dr, 1e-15);
  EXPECT_NEAR(shellFaceConductance(MassConvention::Disc, 8, 3, k, r, t), k * 2 * pi * rf * t / dr,
              1e-15);
}

TEST(TEST_CATEGORY, heat_stable_step_is_the_explicit_limit) {
  // with no exchange at the surface: dr^2 / (2 alpha) in a disc, dr^2 / (3 alpha) at the centre
  // of a sphere (the centre shell: volume dr^3, one face of area 4 pi dr^2)
  const double r = 0.01, rho = 2700.0;
  for (MassConvention g : {MassConvention::Disc, MassConvention::Sphere}) {
    HeatCoefficients c = coefficients(g, 8);
    c.contactConduction = false;
    const double m = rho * particleVolume(g, r, c.thickness);
    const double alpha = c.conductivity / (rho * c.specificHeat);
    const double dr = r / 8;
    const double expected = dr * dr / ((g == MassConvention::Disc ? 2.0 : 3.0) * alpha);
    EXPECT_NEAR(stableHeatTimeStep(c, r, m, 12, 1000.0), expected, 1e-12 * expected);
    // contact layers at their cap on every slot lower it, but not by more than a few times
    c.contactConduction = true;
    const double withContacts = stableHeatTimeStep(c, r, m, 12, 1000.0);
    EXPECT_LT(withContacts, expected);
    EXPECT_GT(withContacts, 0.4 * expected);
  }
}

TEST(TEST_CATEGORY, heat_contact_area_models) {
  const double ra = 0.01, rb = 0.006, rEff = ra * rb / (ra + rb), delta = 2e-5;
  for (MassConvention g : {MassConvention::Sphere, MassConvention::Disc}) {
    HeatCoefficients c = coefficients(g, 8);
    const double t = c.thickness;
    c.contactArea = ContactAreaModel::Overlap;
    const double geometric = contactArea(c, ra, rb, delta);
    EXPECT_NEAR(geometric,
                g == MassConvention::Sphere ? pi * rEff * delta
                                            : 2 * std::sqrt(2 * rEff * delta) * t,
                1e-15);
    EXPECT_EQ(geometric, contactArea(c, rb, ra, delta)); // symmetric
    EXPECT_EQ(contactArea(c, ra, rb, 0.0), 0.0);
    EXPECT_EQ(contactArea(c, ra, rb, -1e-4), 0.0);
    // stiffness ratio: area ~ overlap (sphere) or ~ sqrt(overlap) (disc chord)
    c.contactArea = ContactAreaModel::StiffnessRatio;
    const double ratio = 1.0e5 / (c.effectiveModulus * 2 * rEff);
    EXPECT_NEAR(contactArea(c, ra, rb, delta) / geometric,
                g == MassConvention::Sphere ? ratio : std::sqrt(ratio), 1e-12);
    c.realStiffness = 4.0e5; // an explicit k_real
    EXPECT_NEAR(contactArea(c, ra, rb, delta) / geometric, g == MassConvention::Sphere ? 0.25 : 0.5,
                1e-12);
    // Hertz at the spring force
    c.contactArea = ContactAreaModel::Hertz;
    const double f = 1.0e5 * delta;
    const double estar = 70e9 / (2 * (1 - 0.25 * 0.25));
    const double a = std::cbrt(3 * f * rEff / (4 * estar));
    const double hertz = g == MassConvention::Sphere
                             ? pi * a * a
                             : 2 * t * std::sqrt(4 * f * rEff / (pi * estar * t));
    EXPECT_NEAR(contactArea(c, ra, rb, delta), hertz, 1e-12 * hertz);
    EXPECT_LT(hertz, geometric); // the soft spring inflates the area
    // the cap: a fraction of the smaller surface
    c.contactArea = ContactAreaModel::Overlap;
    EXPECT_NEAR(contactArea(c, ra, rb, 0.5 * rb),
                c.maxContactAreaFraction * particleSurfaceArea(g, rb, t), 1e-15);
  }
}

TEST(TEST_CATEGORY, heat_layer_pair_balance) {
  LayerSide a, b;
  a.capacityPerArea = 2.0e3;
  a.conductancePerArea = 8.0e3;
  a.shell = 900.0;
  a.layer = 950.0;
  b.capacityPerArea = 1.2e3;
  b.conductancePerArea = 1.5e4;
  b.shell = 500.0;
  b.layer = 480.0;
  const double area = 3e-6, dt = 0.7;
  LayerChange ua, ub;
  advanceLayerPair(a, b, area, area, dt, ua, ub);
  // each layer's heat balance, and the contact heat is exactly antisymmetric, from hot to cold
  const double scale = ua.capacityNew * a.layer;
  EXPECT_NEAR(ua.capacityNew * (ua.layer - a.layer), ua.shellHeat + ua.contactHeat, 1e-14 * scale);
  EXPECT_NEAR(ub.capacityNew * (ub.layer - b.layer), ub.shellHeat + ub.contactHeat, 1e-14 * scale);
  EXPECT_EQ(ua.contactHeat, -ub.contactHeat);
  EXPECT_LT(ua.contactHeat, 0.0);
  // the contact surface at T_edge passes the same flux into both sides: k A (T_edge - L) / delta
  const double ha = a.conductancePerArea, hb = b.conductancePerArea;
  const double edge = contactEdgeTemperature(ha, ua.layer, hb, ub.layer);
  EXPECT_NEAR(dt * ha * area * (edge - ua.layer), ua.contactHeat,
              1e-12 * std::fabs(ua.contactHeat));
  EXPECT_NEAR(dt * hb * area * (edge - ub.layer), ub.contactHeat,
              1e-12 * std::fabs(ua.contactHeat));
  // the new layer temperatures do not depend on the area: the heat is proportional to it
  LayerChange va, vb;
  advanceLayerPair(a, b, 7 * area, 7 * area, dt, va, vb);
  EXPECT_NEAR(va.layer, ua.layer, 1e-12 * ua.layer);
  EXPECT_NEAR(va.contactHeat, 7 * ua.contactHeat, 1e-12 * std::fabs(7 * ua.contactHeat));
  // steady state with the shells held: the four resistances delta/(k A) in series
  for (int s = 0; s < 2000; ++s) {
    a.layer = ua.layer;
    b.layer = ub.layer;
    advanceLayerPair(a, b, area, area, dt, ua, ub);
  }
  const double series = 1.0 / (2.0 / (ha * area) + 2.0 / (hb * area));
  EXPECT_NEAR(ua.shellHeat / dt, series * (a.shell - b.shell), 1e-9 * series * 400.0);
  EXPECT_NEAR(-ub.shellHeat / dt, series * (a.shell - b.shell), 1e-9 * series * 400.0);
}

TEST(TEST_CATEGORY, heat_layer_capacity_exchange_conserves) {
  LayerSide a, b;
  a.capacityPerArea = b.capacityPerArea = 1.0e3;
  a.conductancePerArea = b.conductancePerArea = 1.0e4;
  a.shell = 700.0;
  a.layer = 650.0;
  b.shell = 300.0;
  b.layer = 320.0;
  LayerChange ua, ub;
  // growth: bulk material at the bulk temperature joins the layer (dt = 0: no conduction)
  advanceLayerPair(a, b, 1e-6, 3e-6, 0.0, ua, ub);
  EXPECT_NEAR(ua.capacityNew * ua.layer, ua.capacityOld * a.layer - ua.bulkExchange, 1e-12);
  EXPECT_NEAR(ua.layer, (1.0 * 650.0 + 2.0 * 700.0) / 3.0, 1e-12);
  EXPECT_NEAR(ub.layer, (1.0 * 320.0 + 2.0 * 300.0) / 3.0, 1e-12);
  // shrinkage: the layer keeps its temperature and returns material at it
  advanceLayerPair(a, b, 3e-6, 1e-6, 0.0, ua, ub);
  EXPECT_NEAR(ua.layer, a.layer, 1e-12 * a.layer); // (through the dt = 0 solve)
  EXPECT_NEAR(ua.bulkExchange, 2e-3 * a.layer, 1e-15);
  // separation: everything returns, the layer is back at the bulk temperature
  advanceLayerPair(a, b, 3e-6, 0.0, 0.7, ua, ub);
  EXPECT_NEAR(ua.bulkExchange, 3e-3 * a.layer, 1e-15);
  EXPECT_EQ(ua.capacityNew, 0.0);
  EXPECT_EQ(ua.layer, a.shell);
  EXPECT_EQ(ua.shellHeat, 0.0);
}

TEST(TEST_CATEGORY, heat_radiation_point_functions) {
  const double s = 1e-3;
  const double p = radiativeExchange(0.7 * s, 900.0, 600.0);
  EXPECT_NEAR(p, 5.670374419e-8 * 0.7 * s * (std::pow(600.0, 4) - std::pow(900.0, 4)),
              1e-12 * std::fabs(p));
  EXPECT_EQ(radiativeExchange(0.7 * s, 600.0, 900.0), -p);
  EXPECT_EQ(radiativePairArea(2e-3, 1e-3, 4.0), 2.5e-4);
  EXPECT_EQ(environmentExposure(0, 6.0), 1.0);
  EXPECT_NEAR(environmentExposure(2, 6.0), 2.0 / 3.0, 1e-15);
  EXPECT_EQ(environmentExposure(8, 6.0), 0.0);
  HeatParameters hp;
  hp.emissivity = 0.8;
  EXPECT_NEAR(prepareHeat(hp, 1e5, 0.004).pairEmissivity, 1.0 / (2.0 / 0.8 - 1.0), 1e-15);
  EXPECT_EQ(prepareHeat(hp, 1e5, 0.004).radiationRange, 0.004); // default: the skin
  hp.radiationRange = 0.001;
  EXPECT_EQ(prepareHeat(hp, 1e5, 0.004).radiationRange, 0.001);
  hp.radiationRange = 0.01;
  EXPECT_EQ(prepareHeat(hp, 1e5, 0.004).radiationRange, 0.004); // at most the skin
  hp.emissivity = 1.5;
  EXPECT_THROW(prepareHeat(hp, 1e5, 0.004), std::invalid_argument);
}

// Kernels live in free functions: CUDA extended lambdas may not sit in a gtest TestBody (private).
// The same evaluation as the host part of heat_point_functions_in_a_kernel, in one kernel.
double heatPointFunctionsOnDevice(const HeatCoefficients& c) {
  double device = 0.0;
  Kokkos::parallel_reduce(
      "hikiln::test::heatPointFunctions", Kokkos::RangePolicy<space>(0, 1),
      KOKKOS_LAMBDA(int, double& sum) {
        LayerSide a, b;
        a.capacityPerArea = b.capacityPerArea = 1.0e3;
        a.conductancePerArea = b.conductancePerArea = 1.0e4;
        a.shell = a.layer = 700.0;
        b.shell = b.layer = 300.0;
        LayerChange ua, ub;
        const double area = contactArea(c, 0.01, 0.006, 2e-5);
        advanceLayerPair(a, b, area, area, 0.5, ua, ub);
        sum += ua.contactHeat / area + stableHeatTimeStep(c, 0.01, 0.0113, 12, 1000.0);
      },
      device);
  return device;
}

// The point functions as a kernel sees them (device compilation, same numbers as the host up to
// contraction into FMA).
TEST(TEST_CATEGORY, heat_point_functions_in_a_kernel) {
  const HeatCoefficients c = coefficients(MassConvention::Sphere, 8);
  const double device = heatPointFunctionsOnDevice(c);
  LayerSide a, b;
  a.capacityPerArea = b.capacityPerArea = 1.0e3;
  a.conductancePerArea = b.conductancePerArea = 1.0e4;
  a.shell = a.layer = 700.0;
  b.shell = b.layer = 300.0;
  LayerChange ua, ub;
  const double area = contactArea(c, 0.01, 0.006, 2e-5);
  advanceLayerPair(a, b, area, area, 0.5, ua, ub);
  const double host = ua.contactHeat / area + stableHeatTimeStep(c, 0.01, 0.0113, 12, 1000.0);
  EXPECT_NEAR(device, host, 1e-12 * std::fabs(host));
  EXPECT_LT(ua.contactHeat, 0.0);
}

} // namespace
