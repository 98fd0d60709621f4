// Helpers shared by the DEM heat tests: small particle sets, parameters with single mechanisms,
// per-particle heat read back by id.
#pragma once

#include "DemTestUtils.hpp"
#include "solvers/dem/heat/DemHeat.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace hikiln::dem::test {

/// Parameters with every mechanism off (tests switch on what they check).
inline HeatParameters quietHeat(MassConvention geometry, int shells) {
  HeatParameters p;
  p.geometry = geometry;
  p.thickness = 0.02;
  p.shells = shells;
  p.contactConduction = false;
  p.radiation = false;
  p.environmentExchange = false;
  return p;
}

/// A DEM configuration without gravity or walls, for particles held still (the heat model is
/// stepped without mechanical steps).
inline DemConfig staticConfig() {
  DemConfig cfg;
  cfg.gravityY = 0.0;
  return cfg;
}

/// Host particles with the given centres and radii, ids 100 + 7 i, masses from 2700 kg/m^3 in the
/// geometry's mass convention (disc thickness 0.02 m).
inline ParticleArrays<Kokkos::HostSpace>
placedParticles(const std::vector<std::array<double, 3>>& xyr, MassConvention convention) {
  auto h = hostParticles(xyr.size());
  for (std::size_t i = 0; i < xyr.size(); ++i) {
    h.position(i, 0) = xyr[i][0];
    h.position(i, 1) = xyr[i][1];
    h.radius(i) = xyr[i][2];
  }
  assignMassPropertiesHost(h, 2700.0, convention, 0.02);
  return h;
}

/// Mean temperature of every particle keyed by id.
template <class Heat> std::map<std::int64_t, double> meanById(const Heat& heat) {
  const ParticleTemperatures t = heat.hostTemperatures();
  std::map<std::int64_t, double> out;
  for (std::size_t i = 0; i < t.id.size(); ++i) {
    out[t.id[i]] = t.mean[i];
  }
  return out;
}

/// Every shell temperature of every particle keyed by id (from an exported state).
inline std::map<std::int64_t, std::vector<double>> shellsById(const DemHeatState& s) {
  std::map<std::int64_t, std::vector<double>> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out[s.id[i]] = std::vector<double>(s.temperature.begin() + i * s.shells,
                                       s.temperature.begin() + (i + 1) * s.shells);
  }
  return out;
}

} // namespace hikiln::dem::test
