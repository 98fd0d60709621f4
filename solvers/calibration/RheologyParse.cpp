// Reading a rheology file back (the continuum stage's side of the contract).
#include "solvers/calibration/RheologyFile.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hikiln::calibration {

namespace {

YAML::Node require(const YAML::Node& parent, const std::string& section, const std::string& key,
                   const std::string& source) {
  const YAML::Node node = parent[key];
  if (!node)
    throw std::runtime_error("rheology file '" + source + "': missing key '" + section + key + "'");
  return node;
}

template <class T>
T read(const YAML::Node& parent, const std::string& section, const std::string& key,
       const std::string& source) {
  const YAML::Node node = require(parent, section, key, source);
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    throw std::runtime_error("rheology file '" + source + "': key '" + section + key +
                             "' is malformed");
  }
}

} // namespace

RheologyParameters parseRheologyYaml(const std::string& text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw std::runtime_error("rheology file '" + source + "' is not valid YAML: " + error.what());
  }
  RheologyParameters p;
  const YAML::Node rheology = require(root, "", "rheology", source);
  p.model = read<std::string>(rheology, "rheology.", "model", source);
  if (p.model != "drucker-prager-rate")
    throw std::runtime_error("rheology file '" + source + "': unknown model '" + p.model + "'");
  p.m0 = read<double>(rheology, "rheology.", "m0", source);
  p.m1 = read<double>(rheology, "rheology.", "m1", source);
  p.strainRateFloor = read<double>(rheology, "rheology.", "strain_rate_floor", source);
  const auto range = read<std::vector<double>>(rheology, "rheology.", "strain_rate_range", source);
  if (range.size() != 2)
    throw std::runtime_error("rheology file '" + source +
                             "': rheology.strain_rate_range needs 2 values");
  p.strainRateMin = range[0];
  p.strainRateMax = range[1];

  const YAML::Node muI = require(root, "", "mu_i", source);
  if (read<bool>(muI, "mu_i.", "fitted", source)) {
    p.muI = MuIParameters{read<double>(muI, "mu_i.", "m_s", source),
                          read<double>(muI, "mu_i.", "m_2", source),
                          read<double>(muI, "mu_i.", "I0", source)};
  }
  p.particleDiameter = read<double>(muI, "mu_i.", "particle_diameter", source);
  p.particleDensity = read<double>(muI, "mu_i.", "particle_density", source);

  const YAML::Node coulomb = require(root, "", "coulomb", source);
  p.frictionCoefficient = read<double>(coulomb, "coulomb.", "mu_fr", source);
  p.cohesion = read<double>(coulomb, "coulomb.", "cohesion", source);
  p.frictionAngleDeg = read<double>(coulomb, "coulomb.", "phi_deg", source);

  const YAML::Node wall = require(root, "", "wall", source);
  p.muWall = read<double>(wall, "wall.", "mu_wall", source);
  p.muWallStd = read<double>(wall, "wall.", "mu_wall_std", source);
  p.slipPercent = read<std::vector<double>>(wall, "wall.", "slip_percent", source);
  return p;
}

RheologyParameters loadRheologyFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw std::runtime_error("cannot open rheology file '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return parseRheologyYaml(text.str(), path);
}

} // namespace hikiln::calibration
