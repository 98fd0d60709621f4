// Running a 2D periodic chute to steady state and averaging its depth profiles (shared by the
// default and the long chute test).
#pragma once

#include "solvers/dem/ChuteSetup.hpp"
#include "solvers/dem/DemSystem.hpp"

#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace hikiln::dem::test {

/// What a chute run measured: profiles averaged over two consecutive windows (steadiness) and
/// over both, the flow height, the free discs' mean downslope speed at the end.
struct ChuteResult {
  ChuteProfile profile, firstHalf, secondHalf;
  double meanSpeedFirst = 0.0, meanSpeedSecond = 0.0; ///< area-weighted bed mean of u (m/s)
  double finalKineticPerMass = 0.0;                   ///< J/kg of the free discs at the end
  double timeStep = 0.0;
  std::int64_t steps = 0;
};

/// Area-weighted mean velocity over the bed (slabs below the flow height).
inline double bedMeanSpeed(const ChuteProfile& p) {
  double sum = 0.0, weight = 0.0;
  for (std::size_t k = 0; k < p.z.size(); ++k) {
    if (p.z[k] < p.height && std::isfinite(p.velocity[k])) {
      sum += p.solidFraction[k] * p.velocity[k];
      weight += p.solidFraction[k];
    }
  }
  return weight > 0.0 ? sum / weight : 0.0;
}

/// Relative standard deviation of the solid fraction over the slabs with zMin <= z <= zMax.
inline double relativeSpread(const ChuteProfile& p, double zMin, double zMax) {
  std::vector<double> v;
  for (std::size_t k = 0; k < p.z.size(); ++k) {
    if (p.z[k] >= zMin && p.z[k] <= zMax) {
      v.push_back(p.solidFraction[k]);
    }
  }
  const double mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  double var = 0.0;
  for (double x : v) {
    var += (x - mean) * (x - mean);
  }
  return std::sqrt(var / static_cast<double>(v.size())) / mean;
}

/// Runs `spec` for `spinUp` + 2 `window` units of sqrt(d/g), sampling every 0.5 sqrt(d/g) in the
/// two windows; slabs of `slab` mean diameters. time.step_safety 0.1 (stable up to ~0.2).
template <class Space>
ChuteResult runChute(const ChuteSpec& spec, double spinUp, double window, double slab = 0.5) {
  Chute chute = makeChute(spec);
  chute.config.timeStepSafety = 0.1;
  DemSystem<Space> sys(chute.config);
  sys.setParticles(chute.particles);
  const double d = spec.meanDiameter;
  const double tau = std::sqrt(d / spec.gravity);
  const auto stepsFor = [&](double t) {
    return static_cast<std::int64_t>(std::llround(t * tau / sys.timeStep()));
  };
  sys.advance(stepsFor(spinUp));
  const double top = (spec.heightDiameters * 1.5 + 4.0) * d;
  ChuteProfileSampler all(chute.length, chute.baseTop, slab * d, top);
  ChuteProfileSampler first = all, second = all;
  const std::int64_t sampleSteps = stepsFor(0.5);
  const std::int64_t samplesPerWindow = stepsFor(window) / sampleSteps;
  for (int w = 0; w < 2; ++w) {
    for (std::int64_t s = 0; s < samplesPerWindow; ++s) {
      sys.advance(sampleSteps);
      const auto host = sys.hostParticles();
      all.add(host);
      (w == 0 ? first : second).add(host);
    }
  }
  ChuteResult r;
  r.profile = all.profile();
  r.firstHalf = first.profile();
  r.secondHalf = second.profile();
  r.meanSpeedFirst = bedMeanSpeed(r.firstHalf);
  r.meanSpeedSecond = bedMeanSpeed(r.secondHalf);
  double freeMass = 0.0;
  const auto host = sys.hostParticles();
  for (std::size_t i = 0; i < host.count(); ++i) {
    if (isFree(host.kind(i))) {
      freeMass += host.mass(i);
    }
  }
  r.finalKineticPerMass = sys.energy().kinetic() / freeMass;
  r.timeStep = sys.timeStep();
  r.steps = sys.stepCount();
  return r;
}

} // namespace hikiln::dem::test
