#pragma once
// Synthetic averaged-field files (docs/averaged-fields.md layout) whose cells follow a known
// friction law, for end-to-end tests of `hikiln calibrate`.
#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Summary.hpp"
#include "solvers/calibration/MuIFit.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace hikiln::calibration::test {

/// \brief What a synthetic run looks like.
struct SyntheticRun {
  double m0 = 0.35, m1 = 0.012; ///< m = m0 + m1 gamma_dot (used unless muI is set)
  bool useMuI = false;          ///< m from the mu(I) law below instead
  MuIParameters muI{0.383, 0.643, 0.279};
  double muWall = 0.33, slipPercent = 10.0;
  double omega = 0.314159, fill = 0.2, drumRadius = 0.5;
  double particleDiameter = 0.02, particleDensity = 2500.0;
  std::uint64_t seed = 1;
  int nr = 15, ntheta = 24, nxy = 20;
  double strainRateFloor = 1e-2; ///< cells made "not flowing" sit below this
  bool allInvalid = false;       ///< every valid flag 0
  std::set<std::string>
      omit; ///< datasets ("/polar/pressure") and attributes ("/wall@mu_wall") not to write
};

/// \brief Cells of one grid and how many of them a calibration should select.
struct SyntheticGrid {
  std::vector<double> volumeFraction, pressure, shear, strainRate, viscosity, m;
  std::vector<std::uint8_t> valid;
  std::size_t usable = 0;
};

inline double frictionOf(const SyntheticRun& run, double strainRate, double pressure) {
  if (!run.useMuI)
    return run.m0 + run.m1 * strainRate;
  return evaluateMuI(
      run.muI, inertialNumber(strainRate, run.particleDiameter, pressure, run.particleDensity));
}

// 70 % of cells valid; of those, one in ten is not flowing (and given an absurd m, so that it
// would spoil the fit if selected) and one in twenty has a NaN.
inline SyntheticGrid makeGrid(const SyntheticRun& run, std::size_t cells, std::uint64_t salt) {
  std::mt19937_64 random(run.seed * 1000 + salt);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  SyntheticGrid g;
  for (std::size_t i = 0; i < cells; ++i) {
    const bool valid = !run.allInvalid && unit(random) < 0.7;
    const double kind = unit(random);
    const double p = 50.0 + 2950.0 * unit(random);
    double rate = 0.1 * std::pow(200.0, unit(random)); // 0.1 .. 20 1/s, log-uniform
    double m = frictionOf(run, rate, p);
    if (kind < 0.1) {
      rate = 0.5 * run.strainRateFloor;
      m = 5.0;
    }
    const double q = m * p;
    g.volumeFraction.push_back(valid ? 0.6 + 0.2 * unit(random) : 0.05);
    g.pressure.push_back(p);
    g.shear.push_back(q);
    g.strainRate.push_back(rate);
    g.viscosity.push_back(valid ? q / rate : nan);
    g.m.push_back(valid && kind >= 0.1 && kind < 0.15 ? nan : (valid ? m : nan));
    g.valid.push_back(valid ? 1 : 0);
    if (valid && kind >= 0.15)
      ++g.usable;
  }
  return g;
}

inline void writeCellFields(io::H5File& file, const SyntheticRun& run, const std::string& group,
                            const SyntheticGrid& g, const std::vector<hsize_t>& shape) {
  auto put = [&](const std::string& name, const std::vector<double>& values,
                 const std::string& units) {
    if (run.omit.count(group + "/" + name) == 0)
      file.writeDataset(group + "/" + name, values, shape, units);
  };
  const std::size_t n = g.pressure.size();
  std::vector<double> zero(n, 0.0), sxx(n), syy(n), sxy(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    // A total stress with exactly this p and q: p I + diag(q, -q).
    sxx[i] = g.pressure[i] + g.shear[i];
    syy[i] = g.pressure[i] - g.shear[i];
  }
  put("volume_fraction", g.volumeFraction, "1");
  put("velocity_x", zero, "m/s");
  put("velocity_y", zero, "m/s");
  for (const char* c : {"xx", "xy", "yy"})
    put(std::string("kinetic_stress_") + c, zero, "Pa");
  put("contact_stress_xx", sxx, "Pa");
  put("contact_stress_xy", sxy, "Pa");
  put("contact_stress_yx", sxy, "Pa");
  put("contact_stress_yy", syy, "Pa");
  put("granular_temperature", zero, "m2/s2");
  put("strain_rate", g.strainRate, "1/s");
  put("pressure", g.pressure, "Pa");
  put("shear_stress", g.shear, "Pa");
  put("viscosity", g.viscosity, "Pa s");
  put("friction_m", g.m, "1");
  if (run.omit.count(group + "/valid") == 0)
    file.writeDataset(group + "/valid", g.valid, shape, "1");
}

/// \brief Writes `dir`/averages.h5 and `dir`/summary.json; returns the usable cell counts of
/// the polar and the cartesian grid.
inline std::pair<std::size_t, std::size_t> writeSyntheticRun(const std::filesystem::path& dir,
                                                             const SyntheticRun& run) {
  std::filesystem::create_directories(dir);
  io::H5File file = io::H5File::create((dir / "averages.h5").string());
  io::writeStandardAttributes(file, {"dem", "Serial", "synthetic: {}"});
  auto attribute = [&](const std::string& object, const std::string& name, double value) {
    if (run.omit.count(object + "@" + name) == 0)
      file.setAttribute(object, name, value);
  };
  attribute("/", "average_start", 10.0);
  attribute("/", "average_end", 40.0);
  file.setAttribute("/", "samples", std::int64_t(300));
  attribute("/", "drum_radius", run.drumRadius);
  attribute("/", "omega", run.omega);
  attribute("/", "particle_diameter", run.particleDiameter);
  attribute("/", "particle_density", run.particleDensity);
  attribute("/", "fill", run.fill);

  const double pi = 3.141592653589793;
  const std::size_t nr = static_cast<std::size_t>(run.nr),
                    nt = static_cast<std::size_t>(run.ntheta);
  std::vector<double> rEdges(nr + 1), thetaEdges(nt + 1);
  for (std::size_t i = 0; i <= nr; ++i)
    rEdges[i] = run.drumRadius * static_cast<double>(i) / static_cast<double>(nr);
  for (std::size_t i = 0; i <= nt; ++i)
    thetaEdges[i] = 2.0 * pi * static_cast<double>(i) / static_cast<double>(nt);
  file.writeDataset("/polar/r_edges", rEdges, {nr + 1}, "m");
  file.writeDataset("/polar/theta_edges", thetaEdges, {nt + 1}, "rad");
  const SyntheticGrid polar = makeGrid(run, nr * nt, 1);
  writeCellFields(file, run, "/polar", polar, {nt, nr});

  const std::size_t nxy = static_cast<std::size_t>(run.nxy);
  const double dx = 2.0 * run.drumRadius / static_cast<double>(nxy);
  std::vector<double> centres(nxy);
  for (std::size_t i = 0; i < nxy; ++i)
    centres[i] = -run.drumRadius + (static_cast<double>(i) + 0.5) * dx;
  file.createGroup("/cartesian");
  file.setAttribute("/cartesian", "origin", std::vector<double>{-run.drumRadius, -run.drumRadius});
  file.setAttribute("/cartesian", "spacing", std::vector<double>{dx, dx});
  file.writeDataset("/cartesian/x_centres", centres, {nxy}, "m");
  file.writeDataset("/cartesian/y_centres", centres, {nxy}, "m");
  const SyntheticGrid cartesian = makeGrid(run, nxy * nxy, 2);
  writeCellFields(file, run, "/cartesian", cartesian, {nxy, nxy});

  const std::size_t bins = 36;
  std::vector<double> theta(bins), normal(bins), shear(bins), speed(bins);
  for (std::size_t i = 0; i < bins; ++i) {
    theta[i] = 2.0 * pi * (static_cast<double>(i) + 0.5) / static_cast<double>(bins);
    normal[i] = 1000.0 + 10.0 * static_cast<double>(i);
    shear[i] = run.muWall * normal[i];
    speed[i] = (1.0 - run.slipPercent / 100.0) * run.omega * run.drumRadius;
  }
  const auto wallDataset = [&](const std::string& name, const std::vector<double>& values,
                               const std::string& units) {
    if (run.omit.count("/wall/" + name) == 0)
      file.writeDataset("/wall/" + name, values, {bins}, units);
  };
  wallDataset("theta_centres", theta, "rad");
  wallDataset("normal_stress", normal, "Pa");
  wallDataset("shear_stress", shear, "Pa");
  wallDataset("tangential_velocity", speed, "m/s");
  attribute("/wall", "mu_wall", run.muWall);
  attribute("/wall", "slip_percent", run.slipPercent);
  file.commit();
  io::writeSummaryJson((dir / "summary.json").string(), {{"stage", "dem"}, {"fill", run.fill}});
  return {polar.usable, cartesian.usable};
}

} // namespace hikiln::calibration::test
