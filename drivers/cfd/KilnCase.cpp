#include "drivers/cfd/KilnCase.hpp"

#include "drivers/cfd/TwoPhaseKeys.hpp"

#include <cmath>

namespace hikiln::cfd {

namespace {
using cases::Bounds;

cases::CaseSchema buildSchema() {
  cases::CaseSchema s("kiln");
  s.real("kiln.length").unit("m").positive().defaultsTo("15.0").doc("Kiln length");
  s.real("kiln.diameter").unit("m").positive().defaultsTo("5.0").doc("Kiln inner diameter");
  s.real("kiln.rpm")
      .unit("rev/min")
      .nonNegative()
      .defaultsTo("3.0")
      .doc("Rotation speed, counter-clockwise seen from the discharge end");
  s.real("kiln.slope")
      .unit("deg")
      .range(0, 45, Bounds::OpenMax)
      .defaultsTo("0.0")
      .doc("Inclination of the axis, the discharge end lower (gravity tilted along the axis)");
  s.real("kiln.fill")
      .unit("fraction")
      .range(0, 1, Bounds::OpenMax)
      .defaultsTo("0.24")
      .doc("Initial bed: a flat bed filling this fraction of the cross-section, uniform along "
           "the kiln, at rest");
  s.real("feed.area_fraction")
      .unit("fraction")
      .range(0, 1)
      .defaultsTo("0.046")
      .doc("Solids feed patch: the lowest part of the inlet face, as a fraction of its area");
  s.real("feed.velocity").unit("m/s").nonNegative().defaultsTo("0.05").doc("Feed speed");
  s.real("feed.packing")
      .unit("fraction")
      .range(0, 1, Bounds::OpenMin)
      .defaultsTo("1.0")
      .doc("Solids volume fraction of the feed over material.phi_max (1: a packed bed)");
  s.real("air.area_fraction")
      .unit("fraction")
      .range(0, 1)
      .defaultsTo("0.35")
      .doc("Air inlet patch: the highest part of the inlet face, as a fraction of its area");
  s.real("air.velocity").unit("m/s").nonNegative().defaultsTo("2.0").doc("Air inlet speed");
  s.real("dam.height")
      .unit("m")
      .nonNegative()
      .defaultsTo("0.0")
      .doc("Radial height of the dam ring at the discharge end; 0: no ring");
  s.real("dam.width").unit("m").nonNegative().defaultsTo("0.0").doc("Axial width of the ring");
  s.real("dam.on_at")
      .unit("s")
      .nonNegative()
      .defaultsTo("0.0")
      .doc("Time at which the ring is put in (the cut cells are measured again)");
  s.integer("grid.cells_across")
      .range(8, 1024)
      .defaultsTo("32")
      .doc("Cells across the square cross-section (kiln plus 2 cells each side)");
  s.integer("grid.cells_along").range(2, 4096).defaultsTo("48").doc("Cells along the kiln");
  addTwoPhaseKeys(s);
  addHeatKeys(s);
  s.real("heat.initial_temperature")
      .unit("K")
      .positive()
      .defaultsTo("300")
      .doc("Initial temperature of the bed and the gas");
  s.real("heat.feed_temperature").unit("K").positive().defaultsTo("300").doc("Feed temperature");
  s.real("heat.air_temperature")
      .unit("K")
      .positive()
      .defaultsTo("300")
      .doc("Air inlet temperature");
  s.real("heat.wall_temperature")
      .unit("K")
      .positive()
      .defaultsTo("300")
      .doc("Shell temperature (a hot shell: the cylinder's cut faces, not the end plates)");
  s.real("heat.wall_bed_transfer")
      .unit("W/(m^2 K)")
      .nonNegative()
      .defaultsTo("0")
      .doc("Shell-to-bed heat transfer coefficient (contact); 0 with wall_gas_transfer 0: "
           "an adiabatic shell");
  s.real("heat.wall_gas_transfer")
      .unit("W/(m^2 K)")
      .nonNegative()
      .defaultsTo("0")
      .doc("Shell-to-gas heat transfer coefficient (convection)");
  s.real("tracer.pulse_start")
      .unit("s")
      .nonNegative()
      .defaultsTo("0")
      .doc("Start of a passive tracer pulse in the feed (residence time)");
  s.real("tracer.pulse_duration")
      .unit("s")
      .nonNegative()
      .defaultsTo("0")
      .doc("Length of the tracer pulse; 0: no tracer");
  s.real("kramers.average_from")
      .unit("s")
      .nonNegative()
      .defaultsTo("0")
      .doc("Start of the steady-state window: from then on each output's bed depth and surface "
           "angle per cross-section are averaged, and the mean depth profile is compared with "
           "Kramers-Croockewit at the end (kramers_croockewit.csv, summary.json); 0: no "
           "comparison");
  s.real("time.duration").unit("s").positive().defaultsTo("49").doc("Simulated time");
  s.real("time.output_interval")
      .unit("s")
      .positive()
      .defaultsTo("1.0")
      .doc("Time between field outputs (HDF5 + XDMF)");
  s.realList("time.snapshots")
      .unit("s")
      .nonNegative()
      .items(0, 64)
      .defaultsTo("[0.1, 4, 21, 22, 30, 49]")
      .doc("Extra output times; the bed surface is rendered at each (plot_kiln.py)");
  s.real("gravity").unit("m/s^2").nonNegative().defaultsTo("9.81").doc("Gravity magnitude");
  s.require("feed and air patches not overlapping (area fractions sum to at most 1)",
            [](const cases::CaseFile& c) {
              return c.real("feed.area_fraction") + c.real("air.area_fraction") <= 1.0;
            });
  s.require("dam.height below the kiln radius", [](const cases::CaseFile& c) {
    return c.real("dam.height") < 0.5 * c.real("kiln.diameter");
  });
  s.require("dam.width in (0, kiln.length] when dam.height > 0", [](const cases::CaseFile& c) {
    return c.real("dam.height") == 0.0 ||
           (c.real("dam.width") > 0.0 && c.real("dam.width") <= c.real("kiln.length"));
  });
  s.require("output_interval at most the duration", [](const cases::CaseFile& c) {
    return c.real("time.output_interval") <= c.real("time.duration");
  });
  s.require("the tracer pulse inside the run (pulse_start + pulse_duration < duration)",
            [](const cases::CaseFile& c) {
              return c.real("tracer.pulse_duration") == 0.0 ||
                     c.real("tracer.pulse_start") + c.real("tracer.pulse_duration") <
                         c.real("time.duration");
            });
  s.require("kramers.average_from before the end of the run (average_from < duration)",
            [](const cases::CaseFile& c) {
              return c.real("kramers.average_from") < c.real("time.duration");
            });
  return s;
}

} // namespace

const cases::CaseSchema& kilnSchema() {
  static const cases::CaseSchema schema = buildSchema();
  return schema;
}

KilnSettings kilnSettingsFromCase(const cases::CaseFile& c) {
  KilnSettings s;
  s.length = c.real("kiln.length");
  s.diameter = c.real("kiln.diameter");
  s.rpm = c.real("kiln.rpm");
  s.slopeDegrees = c.real("kiln.slope");
  s.fill = c.real("kiln.fill");
  s.feedFraction = c.real("feed.area_fraction");
  s.feedVelocity = c.real("feed.velocity");
  s.feedPacking = c.real("feed.packing");
  s.airFraction = c.real("air.area_fraction");
  s.airVelocity = c.real("air.velocity");
  s.damHeight = c.real("dam.height");
  s.damWidth = c.real("dam.width");
  s.damOnAt = c.real("dam.on_at");
  s.cellsAcross = static_cast<int>(c.integer("grid.cells_across"));
  s.cellsAlong = static_cast<int>(c.integer("grid.cells_along"));
  s.duration = c.real("time.duration");
  s.outputInterval = c.real("time.output_interval");
  s.snapshots = c.realList("time.snapshots");
  TwoPhaseParameters& p = s.params;
  const double slope = s.slopeDegrees * constants::pi / 180.0;
  p.gravity[0] = 0.0;
  p.gravity[1] = -c.real("gravity") * std::cos(slope);
  p.gravity[2] = c.real("gravity") * std::sin(slope); // towards the discharge end (+z)
  s.rheologySource = readTwoPhaseKeys(c, p);
  readHeatKeys(c, p);
  s.initialTemperature = c.real("heat.initial_temperature");
  s.feedTemperature = c.real("heat.feed_temperature");
  s.airTemperature = c.real("heat.air_temperature");
  p.thermal.wallTemperature = c.real("heat.wall_temperature");
  p.thermal.wallBedTransfer = c.real("heat.wall_bed_transfer");
  p.thermal.wallGasTransfer = c.real("heat.wall_gas_transfer");
  s.tracerStart = c.real("tracer.pulse_start");
  s.tracerDuration = c.real("tracer.pulse_duration");
  s.kramersFrom = c.real("kramers.average_from");
  p.validate();
  return s;
}

Grid kilnGrid(KilnSettings const& s) {
  const Grid section = drumGrid(s.cellsAcross, s.diameter);
  return makeGrid(section.nx, section.ny, s.cellsAlong, section.nx * section.hx,
                  section.ny * section.hy, s.length, section.x0, section.y0, 0.0);
}

KilnDomain kilnDomain(KilnSettings const& s, bool withDam) {
  KilnDomain d;
  d.shell.radius = 0.5 * s.diameter;
  d.shell.omega = s.omega();
  d.shell.zInlet = 0.0;
  d.shell.zOutlet = s.length;
  if (withDam && s.damHeight > 0.0) {
    d.shell.damHeight = s.damHeight;
    d.shell.damWidth = s.damWidth;
  }
  d.shell.validate("kiln");
  d.inlet = makeKilnInlet(d.shell, s.feedFraction, s.airFraction, s.feedVelocity, s.airVelocity,
                          s.feedPacking * s.params.rheology.phiMax, "kiln");
  return d;
}

} // namespace hikiln::cfd
