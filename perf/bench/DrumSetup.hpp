#pragma once
/// \file DrumSetup.hpp
/// \brief The benchmark drum shared by the DEM benchmarks (Dem.cpp, DemHeat.cpp): the physics.md
/// base case scaled up to n particles, started from a lattice bed and warmed up (see Dem.cpp).

#include "solvers/dem/DemSystem.hpp"
#include "solvers/dem/SplitMix.hpp"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <utility>
#include <vector>

namespace hikiln::perf::drum {

inline constexpr double meanDiameter = 0.02;
inline constexpr double sizeRange = 0.05;
inline constexpr double fill = 0.20;
inline constexpr double rpm = 3.0;

/// \brief Particle counts to run: 1e3 .. 1e6, capped by HIKILN_BENCH_MAX_PARTICLES.
inline std::vector<std::int64_t> particleCounts() {
  std::int64_t maxCount = 1000000;
  if (const char* text = std::getenv("HIKILN_BENCH_MAX_PARTICLES")) {
    char* end = nullptr;
    const long long value = std::strtoll(text, &end, 10);
    if (end != text && *end == '\0' && value >= 1000) {
      maxCount = value;
    } else {
      std::cerr << "hikiln_bench: ignoring HIKILN_BENCH_MAX_PARTICLES='" << text
                << "' (want an integer >= 1000)\n";
    }
  }
  std::vector<std::int64_t> counts;
  for (std::int64_t n = 1000; n <= maxCount; n *= 10) {
    counts.push_back(n);
  }
  return counts;
}

/// \brief Drum radius whose lower 20 % holds n lattice sites of the given pitch.
inline double drumRadiusFor(std::size_t n, double pitch) {
  const double siteArea = 0.5 * std::sqrt(3.0) * pitch * pitch;
  return std::sqrt(static_cast<double>(n) * siteArea / (fill * constants::pi)) + pitch;
}

/// \brief n discs on the lowest sites of a hexagonal lattice inside a drum of radius `radius`.
inline dem::ParticleArrays<Kokkos::HostSpace> latticeBed(std::size_t n, double radius) {
  const double pitch = meanDiameter;
  const double inner = radius - 0.6 * pitch * (1.0 + sizeRange);
  const double rowHeight = 0.5 * std::sqrt(3.0) * pitch;
  std::vector<std::pair<double, double>> sites;
  int row = 0;
  for (double y = -inner; sites.size() < n && y < inner; y += rowHeight, ++row) {
    const double half = std::sqrt(std::max(0.0, inner * inner - y * y));
    const double shift = (row % 2) * 0.5 * pitch; // rows share one x lattice
    for (double x = shift - std::floor((half + shift) / pitch) * pitch; x <= half; x += pitch) {
      sites.emplace_back(x, y);
    }
  }
  sites.resize(std::min(n, sites.size()));
  dem::ParticleArrays<Kokkos::HostSpace> p(sites.size(), sites.size());
  dem::SplitMix64 random(2024);
  for (std::size_t i = 0; i < sites.size(); ++i) {
    p.position(i, 0) = sites[i].first;
    p.position(i, 1) = sites[i].second;
    p.radius(i) = 0.5 * meanDiameter * (1.0 - sizeRange + 2.0 * sizeRange * random.uniform());
    p.id(i) = static_cast<std::int64_t>(i);
  }
  dem::assignMassPropertiesHost(p, 2700.0, dem::MassConvention::Sphere);
  return p;
}

/// \brief The base-case contact law with LAMMPS gran/hooke/history damping (as perf/lammps).
inline dem::DemConfig drumConfig(double radius) {
  dem::DemConfig cfg;
  cfg.particleContact.dampingMode = dem::DampingMode::Rate;
  cfg.particleContact.normalDampingRate = 1813.0;
  cfg.particleContact.tangentialDampingRate = 906.0;
  cfg.particleContact.limitDamping = false;
  cfg.wallContact = cfg.particleContact;
  cfg.timeStep = 2.5e-5;
  cfg.skin = 0.2 * meanDiameter * (1.0 + sizeRange);
  cfg.walls.drum.enabled = true;
  cfg.walls.drum.radius = radius;
  return cfg;
}

/// \brief A drum of n particles after warm-up, rotating at 3 rpm.
template <class ExecutionSpace> dem::DemSystem<ExecutionSpace> warmDrum(std::size_t n) {
  const double radius = drumRadiusFor(n, meanDiameter);
  dem::DemSystem<ExecutionSpace> system(drumConfig(radius));
  system.setParticles(latticeBed(n, radius));
  system.setDrumAngularVelocity(rpm * 2.0 * constants::pi / 60.0);
  system.advance(n >= 100000 ? 100 : 300);
  return system;
}

} // namespace hikiln::perf::drum
