#include "drivers/cfd/TwoPhaseKeys.hpp"

#include "solvers/calibration/RheologyFile.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace hikiln::cfd {

namespace fs = std::filesystem;
using cases::Bounds;

void addTwoPhaseKeys(cases::CaseSchema& s) {
  s.real("material.solid_density")
      .unit("kg/m^3")
      .positive()
      .defaultsTo("2700")
      .doc("Grain material density (bed density = phi_max x this)");
  s.real("material.phi_max")
      .unit("fraction")
      .range(0, 1, Bounds::OpenMin)
      .defaultsTo("0.6")
      .doc("Solids volume fraction of the settled bed");
  s.real("material.settling_velocity")
      .unit("m/s")
      .nonNegative()
      .defaultsTo("0.5")
      .doc("Grains falling through the gas (drift flux; keeps the bed surface sharp)");
  s.real("gas.density").unit("kg/m^3").positive().defaultsTo("1.2").doc("Gas density");
  s.real("gas.viscosity").unit("Pa s").positive().defaultsTo("1.8e-5").doc("Gas viscosity");
  s.string("rheology.file")
      .defaultsTo("\"\"")
      .doc("Rheology file of `hikiln calibrate` (relative to this file); empty: the keys below");
  s.real("rheology.m0")
      .unit("1")
      .nonNegative()
      .defaultsTo("0.55")
      .doc("Drucker-Prager friction m at zero strain rate (m = m0 + m1 gamma_dot)");
  s.real("rheology.m1")
      .unit("s")
      .defaultsTo("0.0")
      .doc("dm / d gamma_dot (m is floored at 0 when negative)");
  s.real("rheology.mu_wall")
      .unit("1")
      .nonNegative()
      .defaultsTo("0.35")
      .doc("Bed-shell Coulomb friction coefficient");
  s.real("rheology.strain_rate_floor")
      .unit("1/s")
      .positive()
      .defaultsTo("1e-3")
      .doc("Regularisation: eta = m p / max(gamma_dot, floor)");
  s.real("rheology.viscosity_max")
      .unit("Pa s")
      .positive()
      .defaultsTo("1e5")
      .doc("Cap of the bed viscosity");
  s.real("rheology.viscosity_min")
      .unit("Pa s")
      .nonNegative()
      .defaultsTo("0")
      .doc("Floor of the bed viscosity, for beds without confining pressure (10 keeps the "
           "incremental projection stable in the 30 % drum; docs/compare.md)");
  s.real("numerics.cfl")
      .unit("1")
      .range(0, 1, Bounds::OpenMin)
      .defaultsTo("0.5")
      .doc("Largest advective outflow per step over a cell's capacity (the solids transport "
           "sub-steps for the settling)");
  s.real("numerics.dt_max").unit("s").positive().defaultsTo("0.01").doc("Largest time step");
  s.choice("numerics.projection", {"plain", "incremental"})
      .defaultsTo("plain")
      .doc("plain: the momentum predictor's stresses act on a velocity without the pressure "
           "gradient, so a steady state depends on dt; incremental: it carries the last step's "
           "gravity and pressure acceleration and a steady state does not "
           "(test_cfd_inclined_layer), "
           "but it needs rheology.viscosity_min at the shell's cut faces and the Kramers kilns "
           "fail their validation with it (docs/compare.md)");
  s.choice("numerics.edge_viscosity", {"arithmetic", "harmonic"})
      .defaultsTo("arithmetic")
      .doc("The viscosity of the shear stress on a cell edge, from the four cells around it. "
           "harmonic: cells in series, so a flowing layer can shear against the plug below it; "
           "with arithmetic an incremental bed stands about 13 deg above its friction angle "
           "(docs/compare.md). The shipped cases were run with arithmetic");
  s.choice("numerics.shell_gas", {"no_slip", "slip"})
      .defaultsTo("no_slip")
      .doc("The gas at the shell. no_slip: the shell holds gas as a wall holds a fluid, and a "
           "cut face holds the Coulomb cap from a solids fraction of phi_max / 10 on (blended "
           "below); slip (before 2026-12-04): the Coulomb cap, zero without bed, let the gas "
           "slide freely, and with the incremental projection a gas jet ran up the inclined "
           "kiln's shell (docs/compare.md)");
  const char* const solves[][4] = {{"momentum", "1e-9", "momentum (viscous)", "u^n"},
                                   {"pressure", "1e-11", "pressure", "p = 0"}};
  for (auto const& solve : solves) {
    s.real(std::string("numerics.") + solve[0] + "_tolerance")
        .unit("1")
        .range(0, 0.1, Bounds::OpenMin)
        .defaultsTo(solve[1])
        .doc(std::string("The ") + solve[2] + " solve stops at this residual over that of its " +
             "cold start (from " + solve[3] + "), also when numerics.warm_start starts it closer");
  }
  s.boolean("numerics.warm_start")
      .defaultsTo("true")
      .doc("Start the momentum solve from u^n moved by the last step's predictor change, and the "
           "pressure solve from the last pressure; the tolerances keep referring to the cold "
           "starts, so only the iterations change (perf/README.md)");
  s.require("viscosity_max above the gas viscosity", [](const cases::CaseFile& c) {
    return c.real("rheology.viscosity_max") > c.real("gas.viscosity");
  });
}

std::string readTwoPhaseKeys(const cases::CaseFile& c, TwoPhaseParameters& p) {
  p.solidDensity = c.real("material.solid_density");
  p.gasDensity = c.real("gas.density");
  p.settlingVelocity = c.real("material.settling_velocity");
  p.cfl = c.real("numerics.cfl");
  p.dtMax = c.real("numerics.dt_max");
  p.incrementalProjection = c.string("numerics.projection") == "incremental";
  p.harmonicEdgeViscosity = c.string("numerics.edge_viscosity") == "harmonic";
  p.shellHoldsGas = c.string("numerics.shell_gas") == "no_slip";
  p.viscousTolerance = c.real("numerics.momentum_tolerance");
  p.pressureTolerance = c.real("numerics.pressure_tolerance");
  p.warmStart = c.boolean("numerics.warm_start");
  GranularRheology& r = p.rheology;
  r.phiMax = c.real("material.phi_max");
  r.gasViscosity = c.real("gas.viscosity");
  r.m0 = c.real("rheology.m0");
  r.m1 = c.real("rheology.m1");
  r.muWall = c.real("rheology.mu_wall");
  r.strainRateFloor = c.real("rheology.strain_rate_floor");
  r.viscosityMax = c.real("rheology.viscosity_max");
  r.viscosityMin = c.real("rheology.viscosity_min");
  const std::string file = c.string("rheology.file");
  if (file.empty()) {
    return "case file";
  }
  fs::path path(file);
  if (path.is_relative()) {
    path = fs::path(c.source()).parent_path() / path;
  }
  const calibration::RheologyParameters fit = calibration::loadRheologyFile(path.string());
  if (fit.m0 < 0.0 || fit.muWall < 0.0) {
    throw std::runtime_error(path.string() + ": m0 and mu_wall must be >= 0 for the continuum");
  }
  r.m0 = fit.m0;
  r.m1 = fit.m1;
  r.muWall = fit.muWall;
  if (fit.strainRateFloor > 0.0) {
    r.strainRateFloor = fit.strainRateFloor;
  }
  return path.string();
}

void addHeatKeys(cases::CaseSchema& s) {
  s.boolean("heat.enabled").defaultsTo("false").doc("Solve the energy equation");
  s.real("heat.alpha_eff")
      .unit("m^2/s")
      .nonNegative()
      .defaultsTo("1e-6")
      .doc("Effective bed thermal diffusivity (physics.md 6.3)");
  s.real("heat.solid_heat_capacity")
      .unit("J/(kg K)")
      .positive()
      .defaultsTo("1000")
      .doc("Grain specific heat");
  s.real("heat.gas_heat_capacity")
      .unit("J/(kg K)")
      .nonNegative()
      .defaultsTo("1005")
      .doc("Gas specific heat");
  s.real("heat.gas_conductivity")
      .unit("W/(m K)")
      .nonNegative()
      .defaultsTo("0.026")
      .doc("Gas thermal conductivity");
}

void readHeatKeys(const cases::CaseFile& c, TwoPhaseParameters& p) {
  p.energy = c.boolean("heat.enabled");
  p.thermal.alphaEff = c.real("heat.alpha_eff");
  p.thermal.solidHeatCapacity = c.real("heat.solid_heat_capacity");
  p.thermal.gasHeatCapacity = c.real("heat.gas_heat_capacity");
  p.thermal.gasConductivity = c.real("heat.gas_conductivity");
}

} // namespace hikiln::cfd
