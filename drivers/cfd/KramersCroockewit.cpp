#include "drivers/cfd/KramersCroockewit.hpp"

#include "kernels/common/Compat.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hikiln::cfd {

namespace {
constexpr double pi = constants::pi;
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

void require(bool ok, char const* name, char const* rule) {
  if (!ok) {
    throw std::invalid_argument(std::string("Kramers-Croockewit: ") + name + " " + rule);
  }
}
} // namespace

void KramersCroockewit::validate() const {
  require(radius > 0.0, "radius", "must be > 0");
  require(revolutionsPerSecond > 0.0, "revolutionsPerSecond", "must be > 0");
  require(slope >= 0.0 && slope < 0.5 * pi, "slope", "must be in [0, pi/2)");
  require(reposeAngle > 0.0 && reposeAngle < 0.5 * pi, "reposeAngle", "must be in (0, pi/2)");
  require(feed >= 0.0, "feed", "must be >= 0");
}

double KramersCroockewit::depthGradient(double depth) const {
  const double s = depth / radius;
  const double chord = 2.0 * s - s * s; // (half chord / R)^2
  const double carried =
      0.75 * feed / (pi * revolutionsPerSecond * radius * radius * radius) / std::pow(chord, 1.5);
  return std::tan(reposeAngle) * (carried - std::tan(slope) / std::sin(reposeAngle));
}

double KramersCroockewit::uniformDepth() const {
  validate();
  if (slope == 0.0) {
    return infinity;
  }
  // the carried term falls as h grows to R; past R the chord narrows again
  if (depthGradient(radius) > 0.0) {
    return infinity;
  }
  double lo = 0.0, hi = radius;
  for (int n = 0; n < 200; ++n) {
    const double mid = 0.5 * (lo + hi);
    (depthGradient(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::vector<double> KramersCroockewit::profile(double start, double startDepth,
                                               std::vector<double> const& distances,
                                               double maxStep) const {
  validate();
  require(startDepth > 0.0 && startDepth < 2.0 * radius, "startDepth", "must be in (0, 2R)");
  require(maxStep > 0.0, "maxStep", "must be > 0");
  std::vector<double> depths;
  depths.reserve(distances.size());
  double z = start, h = startDepth;
  const auto inside = [&](double depth) { return depth > 0.0 && depth < 2.0 * radius; };
  for (double target : distances) {
    require(target >= z || !inside(h), "distances", "must increase from start");
    while (inside(h) && z < target) {
      const double dz = std::min(maxStep, target - z);
      const double k1 = depthGradient(h);
      const double k2 = depthGradient(h + 0.5 * dz * k1);
      const double k3 = depthGradient(h + 0.5 * dz * k2);
      const double k4 = depthGradient(h + dz * k3);
      h += dz / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
      z += dz;
    }
    depths.push_back(inside(h) ? h : nan);
  }
  return depths;
}

} // namespace hikiln::cfd
