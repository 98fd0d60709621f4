#include "drivers/dem/DemCase.hpp"

#include <cmath>

namespace hikiln::dem {

namespace {
using cases::Bounds;

cases::CaseSchema buildSchema() {
  cases::CaseSchema s("dem");
  s.real("drum.diameter").unit("m").positive().defaultsTo("2.0").doc("Drum inner diameter");
  s.real("drum.rpm")
      .unit("rev/min")
      .nonNegative()
      .defaultsTo("3.0")
      .doc("Rotation speed, counter-clockwise (3 rpm = 10 % of critical at D = 2 m)");
  s.real("drum.fill")
      .unit("fraction")
      .range(0, 1, Bounds::Open)
      .defaultsTo("0.20")
      .doc("Bed area (including voids) over drum cross-section area");
  s.choice("walls.roughness", {"none", "glued"})
      .defaultsTo("none")
      .doc("Shell: smooth analytic cylinder, or a ring of discs glued to it (turning with it)");
  s.real("walls.bump_diameter")
      .unit("ratio")
      .range(0.25, 4)
      .defaultsTo("1.0")
      .doc("Glued disc diameter over particles.diameter (roughness: glued)");
  s.real("walls.bump_spacing")
      .unit("ratio")
      .range(1, 4)
      .defaultsTo("1.0")
      .doc("Centre distance of the glued discs over their diameter (1: touching)");
  s.real("particles.diameter")
      .unit("m")
      .positive()
      .defaultsTo("0.02")
      .doc("Mean diameter; superquadric: equal-area diameter d (area pi d^2/4, so the mass of a "
           "disc of d)");
  s.real("particles.size_range")
      .unit("fraction")
      .range(0, 1)
      .defaultsTo("0.05")
      .doc("Diameters uniform in mean*(1 +- range); floored at 5 % of the mean");
  s.real("particles.density").unit("kg/m^3").positive().defaultsTo("2700").doc("Solid density");
  s.choice("particles.mass_convention", {"sphere", "disc"})
      .defaultsTo("sphere")
      .doc("2D mass: sphere of the disc diameter (as LAMMPS) or disc of given thickness");
  s.real("particles.thickness")
      .unit("m")
      .positive()
      .defaultsTo("0.02")
      .doc("Disc thickness (mass_convention: disc)");
  s.integer("particles.seed")
      .nonNegative()
      .defaultsTo("12345")
      .doc("Seed of the size draw (and, after it, of the superquadric orientations)");
  s.choice("particles.shape", {"disc", "superquadric"})
      .defaultsTo("disc")
      .doc("Outline: disc, or superquadric |x/a|^N + |y/b|^N = 1 (docs/blocky-particles.md; needs "
           "mass_convention disc, no heat)");
  s.real("particles.blockiness")
      .range(minBlockiness, maxBlockiness)
      .defaultsTo("2")
      .doc("Superquadric exponent N (2: ellipse or disc, 4, 6, 8: increasingly square)");
  s.real("particles.aspect_ratio")
      .unit("ratio")
      .range(1, maxAspectRatio)
      .defaultsTo("1")
      .doc("Superquadric semi-axes b/a (1: as wide as long)");
  s.real("contact.normal_stiffness")
      .unit("N/m")
      .positive()
      .defaultsTo("1.0e5")
      .doc("Linear normal spring k_n");
  s.real("contact.tangential_stiffness")
      .unit("N/m")
      .nonNegative()
      .defaultsTo("5.0e4")
      .doc("Tangential spring k_t");
  s.real("contact.friction")
      .nonNegative()
      .defaultsTo("0.5")
      .doc("Particle-particle Coulomb friction");
  s.real("contact.wall_friction")
      .nonNegative()
      .defaultsTo("0.5")
      .doc("Particle-shell Coulomb friction");
  s.choice("contact.damping", {"restitution", "rate"})
      .defaultsTo("restitution")
      .doc("restitution: dashpot from e; rate: LAMMPS gamma_n, gamma_t (1/s) times m_eff");
  s.real("contact.restitution")
      .range(0, 1, Bounds::OpenMin)
      .defaultsTo("0.5")
      .doc("Normal coefficient of restitution (damping: restitution)");
  s.real("contact.tangential_damping_factor")
      .nonNegative()
      .defaultsTo("0.5")
      .doc("c_t / c_n (damping: restitution)");
  s.real("contact.normal_damping_rate")
      .unit("1/s")
      .nonNegative()
      .defaultsTo("1813")
      .doc("gamma_n (damping: rate)");
  s.real("contact.tangential_damping_rate")
      .unit("1/s")
      .nonNegative()
      .defaultsTo("906")
      .doc("gamma_t (damping: rate)");
  s.boolean("contact.limit_damping")
      .defaultsTo("true")
      .doc("No tensile normal force: clamp F_n >= 0 (LAMMPS default: false)");
  s.real("contact.rolling_friction")
      .nonNegative()
      .defaultsTo("0.0")
      .doc("Constant-torque rolling resistance mu_r between particles (0: off)");
  s.real("contact.wall_rolling_friction")
      .nonNegative()
      .defaultsTo("0.0")
      .doc("Rolling resistance mu_r against the shell (0: off)");
  s.real("time.step")
      .unit("s")
      .nonNegative()
      .defaultsTo("0")
      .doc("Time step; 0 = step_safety x shortest contact duration");
  s.real("time.step_safety")
      .range(0, 0.2, Bounds::OpenMin)
      .defaultsTo("0.05")
      .doc("Fraction of the contact duration used as time step (stable up to ~0.2)");
  s.real("time.settle")
      .unit("s")
      .positive()
      .defaultsTo("1.0")
      .doc("Settling time before trimming to the fill (and half of it after)");
  s.real("time.settle_damping")
      .unit("1/s")
      .nonNegative()
      .defaultsTo("0")
      .doc("While settling, free particles' velocities and spins are multiplied by "
           "exp(-rate x 0.05 s) every 0.05 s (0: off); large drums come to rest sooner");
  s.real("time.duration").unit("s").positive().defaultsTo("60").doc("Simulated rotation time");
  s.real("time.spin_up")
      .unit("s")
      .nonNegative()
      .defaultsTo("5")
      .doc("Rotation time before averages and bed measures start");
  s.real("output.sample_interval")
      .unit("s")
      .positive()
      .defaultsTo("0.05")
      .doc("Time between samples for averages, slip and surface angle");
  s.real("output.snapshot_interval")
      .unit("s")
      .positive()
      .defaultsTo("1.0")
      .doc("Time between particle snapshots (HDF5 + XDMF)");
  s.real("output.checkpoint_interval")
      .unit("s")
      .positive()
      .defaultsTo("10")
      .doc("Time between restart checkpoints");
  s.real("output.average_interval")
      .unit("s")
      .positive()
      .defaultsTo("10")
      .doc("Time between writes of the cumulative averages");
  s.real("neighbor.skin")
      .unit("fraction")
      .positive()
      .defaultsTo("0.2")
      .doc(
          "Neighbour skin as a fraction of the largest diameter (superquadric: bounding diameter)");
  s.integer("neighbor.capacity")
      .range(4, 64)
      .defaultsTo("12")
      .doc("Neighbour slots per particle (an overflow stops the run with an error)");
  s.boolean("neighbor.pair_once")
      .defaultsTo("false")
      .doc("Discs: evaluate each pair once, the partner's side summed exactly as integers (the "
           "same guarantees, a different rounding; CPU backends)");
  s.real("gravity").unit("m/s^2").nonNegative().defaultsTo("9.81").doc("Gravity, along -y");
  addHeatKeys(s);
  s.require("particles.blockiness = 2 and particles.aspect_ratio = 1 unless particles.shape: "
            "superquadric",
            [](const cases::CaseFile& c) {
              return c.string("particles.shape") == "superquadric" ||
                     (c.real("particles.blockiness") == 2 && c.real("particles.aspect_ratio") == 1);
            });
  s.require("particles.shape: superquadric needs particles.mass_convention: disc (a prism of "
            "particles.thickness; the sphere convention has no blocky counterpart)",
            [](const cases::CaseFile& c) {
              return c.string("particles.shape") != "superquadric" ||
                     c.string("particles.mass_convention") == "disc";
            });
  s.require("spin_up < duration", [](const cases::CaseFile& c) {
    return c.real("time.spin_up") < c.real("time.duration");
  });
  s.require("the particles fit the drum: diameter*(1+size_range) < drum.diameter/4",
            [](const cases::CaseFile& c) {
              return c.real("particles.diameter") * (1 + c.real("particles.size_range")) <
                     0.25 * c.real("drum.diameter");
            });
  s.require("below critical speed: Froude number omega^2 R / g < 1", [](const cases::CaseFile& c) {
    const double omega = c.real("drum.rpm") * 2 * constants::pi / 60;
    return c.real("gravity") == 0 ||
           omega * omega * 0.5 * c.real("drum.diameter") / c.real("gravity") < 1;
  });
  return s;
}

ContactParameters contactFromCase(const cases::CaseFile& c, bool wall) {
  ContactParameters p;
  p.normalStiffness = c.real("contact.normal_stiffness");
  p.tangentialStiffness = c.real("contact.tangential_stiffness");
  p.friction = c.real(wall ? "contact.wall_friction" : "contact.friction");
  p.dampingMode =
      c.string("contact.damping") == "rate" ? DampingMode::Rate : DampingMode::Restitution;
  p.restitution = c.real("contact.restitution");
  p.tangentialDampingFactor = c.real("contact.tangential_damping_factor");
  p.normalDampingRate = c.real("contact.normal_damping_rate");
  p.tangentialDampingRate = c.real("contact.tangential_damping_rate");
  p.limitDamping = c.boolean("contact.limit_damping");
  const double mur = c.real(wall ? "contact.wall_rolling_friction" : "contact.rolling_friction");
  p.rolling = mur > 0 ? RollingModel::ConstantTorque : RollingModel::None;
  p.rollingFriction = mur;
  return p;
}
} // namespace

const cases::CaseSchema& demSchema() {
  static const cases::CaseSchema schema = buildSchema();
  return schema;
}

DrumRunSettings drumSettingsFromCase(const cases::CaseFile& c) {
  DrumRunSettings s;
  s.fill.drumRadius = 0.5 * c.real("drum.diameter");
  s.fill.fill = c.real("drum.fill");
  s.fill.meanDiameter = c.real("particles.diameter");
  s.fill.sizeRange = c.real("particles.size_range");
  s.fill.density = c.real("particles.density");
  s.fill.convention = c.string("particles.mass_convention") == "disc" ? MassConvention::Disc
                                                                      : MassConvention::Sphere;
  s.fill.thickness = c.real("particles.thickness");
  s.fill.seed = static_cast<std::uint64_t>(c.integer("particles.seed"));
  s.fill.shape.superquadric = c.string("particles.shape") == "superquadric";
  s.fill.shape.blockiness = c.real("particles.blockiness");
  s.fill.shape.aspectRatio = c.real("particles.aspect_ratio");
  if (c.string("walls.roughness") == "glued") {
    s.fill.shellBumpDiameter = c.real("walls.bump_diameter") * s.fill.meanDiameter;
    s.fill.shellBumpSpacing = c.real("walls.bump_spacing");
  }
  s.config.particleContact = contactFromCase(c, false);
  s.config.wallContact = contactFromCase(c, true);
  s.config.timeStep = c.real("time.step");
  s.config.timeStepSafety = c.real("time.step_safety");
  s.config.gravityX = 0.0;
  s.config.gravityY = -c.real("gravity");
  s.config.skin = c.real("neighbor.skin") * s.fill.meanDiameter * (1 + s.fill.sizeRange) *
                  boundingRadiusRatio(s.fill.shape);
  s.config.neighborCapacity = static_cast<int>(c.integer("neighbor.capacity"));
  s.config.pairOnceForces = c.boolean("neighbor.pair_once");
  s.config.walls.drum.enabled = true;
  s.config.walls.drum.radius = s.fill.drumRadius;
  s.config.walls.drum.angularVelocity = 0.0; // still while filling and settling
  s.rpm = c.real("drum.rpm");
  s.settleTime = c.real("time.settle");
  s.settleDamping = c.real("time.settle_damping");
  s.duration = c.real("time.duration");
  s.spinUp = c.real("time.spin_up");
  s.sampleInterval = c.real("output.sample_interval");
  s.snapshotInterval = c.real("output.snapshot_interval");
  s.checkpointInterval = c.real("output.checkpoint_interval");
  s.averageInterval = c.real("output.average_interval");
  s.heat = heatSettingsFromCase(c, s.fill);
  return s;
}

} // namespace hikiln::dem
