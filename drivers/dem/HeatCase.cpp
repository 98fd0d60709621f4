#include "drivers/dem/HeatCase.hpp"

#include <fmt/format.h>

#include <limits>
#include <stdexcept>

namespace hikiln::dem {

namespace {
using cases::Bounds;
constexpr double infinity = std::numeric_limits<double>::infinity();

// The neighbour-list skin in metres, as drumSettingsFromCase() sets it.
double skinOf(const cases::CaseFile& c) {
  return c.real("neighbor.skin") * c.real("particles.diameter") *
         (1 + c.real("particles.size_range"));
}
} // namespace

TemperatureField DrumHeatSettings::initialField() const {
  switch (initial) {
  case InitialTemperatureKind::LeftRight:
    return leftRightTemperature(splitX, leftTemperature, rightTemperature);
  case InitialTemperatureKind::Region: {
    const std::array<double, 4> box = regionBox;
    return regionTemperature(
        [box](double x, double y) {
          return x >= box[0] && y >= box[1] && x <= box[2] && y <= box[3];
        },
        insideTemperature, baseTemperature);
  }
  case InitialTemperatureKind::Uniform:
    break;
  }
  return uniformTemperature(baseTemperature);
}

void addHeatKeys(cases::CaseSchema& s) {
  s.boolean("heat.enabled")
      .defaultsTo("false")
      .doc("Particle heat transfer (physics.md 6.1, docs/heat.md); temperatures start with the "
           "rotation");
  s.integer("heat.shells")
      .range(1, 1000)
      .defaultsTo("8")
      .doc("Radial shells per particle (8: centre error < 1.5e-3 of the Bi = 1 solution)");
  s.boolean("heat.internal_conduction")
      .defaultsTo("true")
      .doc("Radial conduction inside each particle; false: lumped particles (one shell)");
  s.boolean("heat.contact_conduction")
      .defaultsTo("false")
      .doc("Conduction through contacts (boundary layers, Hertz area); off in the physics.md 6.2 "
           "runs; a heat step then costs ~4x more");
  s.boolean("heat.radiation")
      .defaultsTo("true")
      .doc("Radiation between neighbouring surfaces, sigma eps (T1^4 - T2^4)");
  s.real("heat.radiation_range")
      .unit("m")
      .nonNegative()
      .defaultsTo("0")
      .doc("Surface gap up to which neighbours exchange radiation (0: touching pairs only; > 0 "
           "depends on the neighbour-list schedule: restarts then not bitwise)");
  s.boolean("heat.environment_exchange")
      .defaultsTo("false")
      .doc("Exchange with a fixed environment through the surface not facing neighbours (summed "
           "apart from the conserved heat)");
  s.real("heat.environment_temperature")
      .unit("K")
      .positive()
      .defaultsTo("293.15")
      .doc("Environment temperature (heat.environment_exchange)");
  s.real("heat.environment_heat_transfer")
      .unit("W/m^2/K")
      .nonNegative()
      .defaultsTo("0")
      .doc("Convective coefficient to the environment (heat.environment_exchange)");
  s.boolean("heat.environment_radiation")
      .defaultsTo("true")
      .doc("Grey radiation to the environment too (heat.environment_exchange)");
  s.real("heat.conductivity")
      .unit("W/m/K")
      .positive()
      .defaultsTo("2.5")
      .doc("Particle conductivity k (limestone/calcite, 400-800 C)");
  s.real("heat.specific_heat")
      .unit("J/kg/K")
      .positive()
      .defaultsTo("1000")
      .doc("Particle specific heat c (heat capacity = DEM mass x c)");
  s.real("heat.emissivity")
      .range(0, 1, Bounds::OpenMin)
      .defaultsTo("0.85")
      .doc("Total hemispherical emissivity of the particle surfaces");
  s.real("heat.youngs_modulus")
      .unit("Pa")
      .positive()
      .defaultsTo("70e9")
      .doc("Young's modulus E of the particle material (real contact area)");
  s.real("heat.poisson_ratio")
      .range(-1, 0.5, Bounds::Open)
      .defaultsTo("0.25")
      .doc("Poisson ratio of the particle material (real contact area)");
  s.choice("heat.contact_area", {"hertz", "stiffness_ratio", "overlap"})
      .defaultsTo("hertz")
      .doc("Real contact area: Hertz area under the DEM force, overlap rescaled by k_n/k_real, or "
           "the raw DEM overlap");
  s.integer("heat.step_every")
      .range(1, 100000)
      .defaultsTo("10")
      .doc("Heat step every this many mechanical steps (10: +5-20 % cost, ~+45 % with contact "
           "conduction)");
  s.choice("heat.initial", {"uniform", "left_right", "region"})
      .defaultsTo("uniform")
      .doc("Initial temperatures: uniform, left/right halves, or a box region");
  s.real("heat.initial_temperature")
      .unit("K")
      .positive()
      .defaultsTo("293.15")
      .doc("uniform: every particle; region: the particles outside heat.region");
  s.real("heat.left_temperature")
      .unit("K")
      .positive()
      .defaultsTo("673")
      .doc("left_right: particles with centre x < heat.split_x");
  s.real("heat.right_temperature")
      .unit("K")
      .positive()
      .defaultsTo("1073")
      .doc("left_right: the other particles");
  s.real("heat.split_x")
      .unit("m")
      .range(-infinity, infinity)
      .defaultsTo("0")
      .doc("left_right: the split line (0: through the drum axis)");
  s.real("heat.region_temperature")
      .unit("K")
      .positive()
      .defaultsTo("1073")
      .doc("region: particles with centres inside heat.region");
  s.realList("heat.region")
      .unit("m")
      .items(4)
      .defaultsTo("[0, 0, 0, 0]")
      .doc("region: box [x_min, y_min, x_max, y_max], drum axis at the origin");
  s.real("heat.equilibrium_threshold")
      .range(0, 1, Bounds::Open)
      .defaultsTo("0.05")
      .doc("Thermal equilibrium: std of particle mean temperatures / its initial value below this");

  s.addCheck("heat.region is a box x_min < x_max, y_min < y_max (heat.initial: region)",
             [](const cases::CaseFile& c) {
               const auto& b = c.realList("heat.region");
               if (c.string("heat.initial") == "region" && !(b[0] < b[2] && b[1] < b[3])) {
                 throw std::runtime_error(
                     fmt::format("got [{}, {}, {}, {}]", b[0], b[1], b[2], b[3]));
               }
             });
  s.addCheck("heat.radiation_range <= the neighbour skin (neighbor.skin x largest diameter)",
             [](const cases::CaseFile& c) {
               if (c.real("heat.radiation_range") > skinOf(c)) {
                 throw std::runtime_error(
                     fmt::format("{:.4g} m > {:.4g} m: the neighbour list holds no "
                                 "farther pairs (raise neighbor.skin)",
                                 c.real("heat.radiation_range"), skinOf(c)));
               }
             });
  s.require("heat.enabled needs particles.shape: disc (heat is disc-only: its shells, contact "
            "areas and radiating surfaces are disc geometry; docs/blocky-particles.md)",
            [](const cases::CaseFile& c) {
              return !c.boolean("heat.enabled") || c.string("particles.shape") == "disc";
            });
  s.addCheck("heat.internal_conduction: false lumps each particle into one shell",
             [](const cases::CaseFile& c) {
               if (!c.boolean("heat.internal_conduction") &&
                   c.origin("heat.shells") != cases::CaseFile::Origin::Default &&
                   c.integer("heat.shells") != 1) {
                 throw std::runtime_error(fmt::format(
                     "heat.shells = {} contradicts it (leave heat.shells out or set it to 1)",
                     c.integer("heat.shells")));
               }
             });
}

DrumHeatSettings heatSettingsFromCase(const cases::CaseFile& c, const FillSpec& fill) {
  DrumHeatSettings s;
  s.enabled = c.boolean("heat.enabled");
  HeatParameters& p = s.parameters;
  p.conductivity = c.real("heat.conductivity");
  p.specificHeat = c.real("heat.specific_heat");
  p.emissivity = c.real("heat.emissivity");
  p.youngsModulus = c.real("heat.youngs_modulus");
  p.poissonRatio = c.real("heat.poisson_ratio");
  p.geometry = fill.convention;
  p.thickness = fill.thickness;
  p.shells = c.boolean("heat.internal_conduction") ? static_cast<int>(c.integer("heat.shells")) : 1;
  p.contactConduction = c.boolean("heat.contact_conduction");
  const std::string& area = c.string("heat.contact_area");
  p.contactArea = area == "overlap"           ? ContactAreaModel::Overlap
                  : area == "stiffness_ratio" ? ContactAreaModel::StiffnessRatio
                                              : ContactAreaModel::Hertz;
  p.radiation = c.boolean("heat.radiation");
  p.radiationRange = c.real("heat.radiation_range");
  p.environmentExchange = c.boolean("heat.environment_exchange");
  p.environmentTemperature = c.real("heat.environment_temperature");
  p.environmentHeatTransfer = c.real("heat.environment_heat_transfer");
  p.environmentRadiation = c.boolean("heat.environment_radiation");
  s.stepEvery = c.integer("heat.step_every");
  s.equilibriumThreshold = c.real("heat.equilibrium_threshold");
  const std::string& initial = c.string("heat.initial");
  s.initial = initial == "left_right" ? InitialTemperatureKind::LeftRight
              : initial == "region"   ? InitialTemperatureKind::Region
                                      : InitialTemperatureKind::Uniform;
  s.baseTemperature = c.real("heat.initial_temperature");
  s.leftTemperature = c.real("heat.left_temperature");
  s.rightTemperature = c.real("heat.right_temperature");
  s.splitX = c.real("heat.split_x");
  s.insideTemperature = c.real("heat.region_temperature");
  const auto& box = c.realList("heat.region");
  for (std::size_t i = 0; i < 4; ++i)
    s.regionBox[i] = box[i];
  return s;
}

} // namespace hikiln::dem
