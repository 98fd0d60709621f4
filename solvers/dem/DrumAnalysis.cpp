#include "solvers/dem/DrumAnalysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace hikiln::dem {

double shellInnerRadius(const ParticleArrays<Kokkos::HostSpace>& p, double R) {
  for (std::size_t i = 0; i < p.count(); ++i)
    if (p.kind(i) == static_cast<std::uint8_t>(ParticleKind::Shell))
      R = std::min(R, std::hypot(p.position(i, 0), p.position(i, 1)) - p.radius(i));
  return R;
}

double wallSlip(const ParticleArrays<Kokkos::HostSpace>& p, double R, double omega, double gap) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (omega == 0.0)
    return nan;
  R = shellInnerRadius(p, R);
  // summed in id order: the same value whatever the particle order (restarts, reorders)
  std::vector<std::pair<std::int64_t, double>> speeds;
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double x = p.position(i, 0), y = p.position(i, 1);
    const double rho = std::hypot(x, y);
    if (isFree(p.kind(i)) && rho > R - p.radius(i) - gap)
      speeds.emplace_back(p.id(i), (-y * p.velocity(i, 0) + x * p.velocity(i, 1)) / rho);
  }
  std::sort(speeds.begin(), speeds.end());
  double sum = 0;
  for (const auto& [id, speed] : speeds)
    sum += speed; // along e_theta
  const auto n = static_cast<double>(speeds.size());
  return n > 0 ? 1.0 - (sum / n) / (omega * R) : nan;
}

double surfaceAngleDegrees(const ParticleArrays<Kokkos::HostSpace>& p, double binWidth) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < p.count(); ++i) {
    if (!isFree(p.kind(i)))
      continue;
    lo = std::min(lo, p.position(i, 0));
    hi = std::max(hi, p.position(i, 0));
  }
  const double w = hi - lo;
  std::map<long, std::pair<double, double>> top; // bin -> (x, y) of the highest centre
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double x = p.position(i, 0), y = p.position(i, 1);
    if (!isFree(p.kind(i)) || x <= lo + 0.2 * w || x >= hi - 0.2 * w)
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
