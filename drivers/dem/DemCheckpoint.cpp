#include "drivers/dem/DemCheckpoint.hpp"

#include "kernels/dem/ParticleArrays.hpp"

#include <stdexcept>
#include <string>

namespace hikiln::dem {

namespace {
template <class T>
const std::vector<T>& entry(const std::map<std::string, std::vector<T>>& map, const char* name) {
  const auto it = map.find(name);
  if (it == map.end()) {
    throw std::runtime_error(std::string("checkpoint lacks the DEM array '") + name + "'");
  }
  return it->second;
}

double scalar(const io::Checkpoint& c, const char* name) {
  const auto it = c.scalars.find(name);
  if (it == c.scalars.end()) {
    throw std::runtime_error(std::string("checkpoint lacks the scalar '") + name + "'");
  }
  return it->second;
}
} // namespace

io::Checkpoint toCheckpoint(const DemState& s, const std::string& stage) {
  io::Checkpoint c;
  c.stage = stage;
  c.step = s.step;
  c.time = s.time;
  c.integers["id"] = s.id;
  c.reals["position"] = s.position;
  c.reals["velocity"] = s.velocity;
  c.reals["angular_velocity"] = s.angularVelocity;
  c.reals["force"] = s.force;
  c.reals["torque"] = s.torque;
  c.reals["radius"] = s.radius;
  c.reals["mass"] = s.mass;
  c.reals["inertia"] = s.inertia;
  c.reals["wall_shear"] = s.wallShear;
  c.integers["contact_id"] = s.contactId;
  c.integers["contact_neighbor_id"] = s.contactNeighborId;
  c.reals["contact_shear"] = s.contactShear;
  c.integers["kind"].assign(s.kind.begin(), s.kind.end());
  c.reals["shell_home"] = s.shellHome;
  c.scalars["shell_angle"] = s.shellAngle;
  if (!s.orientation.empty()) { // a blocky system; disc checkpoints stay as they were
    c.reals["orientation"] = s.orientation;
    c.reals["shape_a"] = s.shapeA;
    c.reals["shape_b"] = s.shapeB;
    c.reals["shape_n"] = s.shapeN;
    c.reals["contact_angle"] = s.contactAngle;
  }
  return c;
}

DemState fromCheckpoint(const io::Checkpoint& c) {
  DemState s;
  s.step = c.step;
  s.time = c.time;
  s.id = entry(c.integers, "id");
  s.position = entry(c.reals, "position");
  s.velocity = entry(c.reals, "velocity");
  s.angularVelocity = entry(c.reals, "angular_velocity");
  s.force = entry(c.reals, "force");
  s.torque = entry(c.reals, "torque");
  s.radius = entry(c.reals, "radius");
  s.mass = entry(c.reals, "mass");
  s.inertia = entry(c.reals, "inertia");
  s.wallShear = entry(c.reals, "wall_shear");
  s.contactId = entry(c.integers, "contact_id");
  s.contactNeighborId = entry(c.integers, "contact_neighbor_id");
  s.contactShear = entry(c.reals, "contact_shear");
  // particle kinds and the shell's rotation (absent in checkpoints written before them: all free)
  if (const auto it = c.integers.find("kind"); it != c.integers.end()) {
    for (const std::int64_t k : it->second) {
      if (k < 0 || k > static_cast<std::int64_t>(ParticleKind::Shell)) {
        throw std::runtime_error("checkpoint has an unknown particle kind " + std::to_string(k));
      }
      s.kind.push_back(static_cast<std::uint8_t>(k));
    }
  }
  if (const auto it = c.reals.find("shell_home"); it != c.reals.end()) {
    s.shellHome = it->second;
  }
  if (const auto it = c.scalars.find("shell_angle"); it != c.scalars.end()) {
    s.shellAngle = it->second;
  }
  // blocky particles: orientations, shapes and the pairs' stored search directions (all or none;
  // importState() checks their sizes)
  if (c.reals.count("orientation") != 0) {
    s.orientation = entry(c.reals, "orientation");
    s.shapeA = entry(c.reals, "shape_a");
    s.shapeB = entry(c.reals, "shape_b");
    s.shapeN = entry(c.reals, "shape_n");
    s.contactAngle = entry(c.reals, "contact_angle");
  }
  return s;
}

void addHeatState(io::Checkpoint& c, const DemHeatState& s) {
  c.scalars["heat_shells"] = s.shells;
  c.scalars["heat_time"] = s.time;
  c.scalars["heat_sub_steps"] = static_cast<double>(s.subSteps);
  c.scalars["heat_initial_energy"] = s.initialEnergy;
  c.scalars["heat_stable_time_step"] = s.stableTimeStep;
  c.integers["heat_id"] = s.id;
  c.reals["heat_temperature"] = s.temperature;
  c.reals["heat_environment_heat"] = s.environmentHeat;
  c.integers["heat_contact_id"] = s.contactId;
  c.integers["heat_contact_neighbor_id"] = s.contactNeighborId;
  c.reals["heat_contact_area"] = s.contactArea;
  c.reals["heat_contact_layer"] = s.contactLayer;
  c.reals["heat_contact_layer_other"] = s.contactLayerOther;
}

bool hasHeatState(const io::Checkpoint& c) {
  return c.integers.count("heat_id") != 0;
}

DemHeatState heatStateFromCheckpoint(const io::Checkpoint& c) {
  DemHeatState s;
  s.shells = static_cast<int>(scalar(c, "heat_shells"));
  s.time = scalar(c, "heat_time");
  s.subSteps = static_cast<std::int64_t>(scalar(c, "heat_sub_steps"));
  s.initialEnergy = scalar(c, "heat_initial_energy");
  s.stableTimeStep = scalar(c, "heat_stable_time_step");
  s.id = entry(c.integers, "heat_id");
  s.temperature = entry(c.reals, "heat_temperature");
  s.environmentHeat = entry(c.reals, "heat_environment_heat");
  s.contactId = entry(c.integers, "heat_contact_id");
  s.contactNeighborId = entry(c.integers, "heat_contact_neighbor_id");
  s.contactArea = entry(c.reals, "heat_contact_area");
  s.contactLayer = entry(c.reals, "heat_contact_layer");
  s.contactLayerOther = entry(c.reals, "heat_contact_layer_other");
  return s;
}

} // namespace hikiln::dem
