#include "drivers/dem/DemCheckpoint.hpp"

#include <stdexcept>

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
  return s;
}

} // namespace hikiln::dem
