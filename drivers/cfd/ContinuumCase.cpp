#include "drivers/cfd/ContinuumCase.hpp"

#include "drivers/cfd/TwoPhaseKeys.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hikiln::cfd {

namespace {
using cases::Bounds;

cases::CaseSchema buildSchema() {
  cases::CaseSchema s("continuum");
  s.real("drum.diameter").unit("m").positive().defaultsTo("2.0").doc("Drum inner diameter");
  s.real("drum.rpm")
      .unit("rev/min")
      .nonNegative()
      .defaultsTo("3.0")
      .doc("Rotation speed, counter-clockwise");
  s.real("drum.fill")
      .unit("fraction")
      .range(0, 1, Bounds::Open)
      .defaultsTo("0.20")
      .doc("Bed area over drum cross-section area (flat bed at rest at t = 0)");
  s.integer("grid.cells")
      .range(16, 4096)
      .defaultsTo("64")
      .doc("Cells across the square domain (drum plus 2 cells each side); powers of 2 suit "
           "the multigrid best");
  addTwoPhaseKeys(s);
  s.real("time.duration").unit("s").positive().defaultsTo("10").doc("Simulated time");
  s.real("time.output_interval")
      .unit("s")
      .positive()
      .defaultsTo("1.0")
      .doc("Time between field outputs (HDF5 + XDMF)");
  s.real("time.slip_after")
      .unit("s")
      .nonNegative()
      .defaultsTo("2.0")
      .doc("Wall slip is averaged over the outputs after this time (spin-up excluded)");
  s.real("gravity").unit("m/s^2").nonNegative().defaultsTo("9.81").doc("Gravity, along -y");
  addHeatKeys(s);
  s.real("heat.initial_left").unit("K").positive().defaultsTo("673").doc("Initial T, x < 0");
  s.real("heat.initial_right").unit("K").positive().defaultsTo("1073").doc("Initial T, x >= 0");
  s.require("output_interval at most the duration", [](const cases::CaseFile& c) {
    return c.real("time.output_interval") <= c.real("time.duration");
  });
  return s;
}

} // namespace

const cases::CaseSchema& continuumSchema() {
  static const cases::CaseSchema schema = buildSchema();
  return schema;
}

ContinuumSettings continuumSettingsFromCase(const cases::CaseFile& c) {
  ContinuumSettings s;
  s.diameter = c.real("drum.diameter");
  s.rpm = c.real("drum.rpm");
  s.fill = c.real("drum.fill");
  s.cells = static_cast<int>(c.integer("grid.cells"));
  s.duration = c.real("time.duration");
  s.outputInterval = c.real("time.output_interval");
  s.slipAfter = c.real("time.slip_after");
  s.initialLeft = c.real("heat.initial_left");
  s.initialRight = c.real("heat.initial_right");
  TwoPhaseParameters& p = s.params;
  p.gravity[0] = 0.0;
  p.gravity[1] = -c.real("gravity");
  p.gravity[2] = 0.0;
  s.rheologySource = readTwoPhaseKeys(c, p);
  readHeatKeys(c, p);
  p.validate();
  return s;
}

// The circular segment below height y has area R^2 (pi - acos(y / R)) + y sqrt(R^2 - y^2);
// solved for y by bisection.
double flatBedLevel(double R, double fill) {
  const auto segment = [R](double y) { // area below the chord at height y
    const double c = std::clamp(y / R, -1.0, 1.0);
    return R * R * (constants::pi - std::acos(c)) + y * std::sqrt(std::max(R * R - y * y, 0.0));
  };
  const double target = fill * constants::pi * R * R;
  double lo = -R, hi = R;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (segment(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

} // namespace hikiln::cfd
