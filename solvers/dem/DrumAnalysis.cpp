#include "solvers/dem/DrumAnalysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace hikiln::dem {

double wallSlip(const ParticleArrays<Kokkos::HostSpace>& p, double R, double omega, double gap) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (omega == 0.0)
    return nan;
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double x = p.position(i, 0), y = p.position(i, 1);
    const double rho = std::hypot(x, y);
    if (rho > R - p.radius(i) - gap) {
      sum += (-y * p.velocity(i, 0) + x * p.velocity(i, 1)) / rho; // along e_theta
      ++n;
    }
  }
  return n > 0 ? 1.0 - (sum / n) / (omega * R) : nan;
}

double surfaceAngleDegrees(const ParticleArrays<Kokkos::HostSpace>& p, double binWidth) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (p.count() == 0)
    return nan;
  double lo = p.position(0, 0), hi = lo;
  for (std::size_t i = 0; i < p.count(); ++i) {
    lo = std::min(lo, p.position(i, 0));
    hi = std::max(hi, p.position(i, 0));
  }
  const double w = hi - lo;
  std::map<long, std::pair<double, double>> top; // bin -> (x, y) of the highest centre
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double x = p.position(i, 0), y = p.position(i, 1);
    if (x <= lo + 0.2 * w || x >= hi - 0.2 * w)
      continue;
    const long b = static_cast<long>((x - lo) / binWidth);
    auto it = top.find(b);
    if (it == top.end() || y > it->second.second)
      top[b] = {x, y};
  }
  if (top.size() < 4)
    return nan;
  double mx = 0, my = 0;
  for (const auto& [b, xy] : top)
    mx += xy.first, my += xy.second;
  mx /= static_cast<double>(top.size());
  my /= static_cast<double>(top.size());
  double sxx = 0, sxy = 0;
  for (const auto& [b, xy] : top) {
    sxx += (xy.first - mx) * (xy.first - mx);
    sxy += (xy.first - mx) * (xy.second - my);
  }
  return std::atan(sxy / sxx) * 180.0 / constants::pi;
}

} // namespace hikiln::dem
