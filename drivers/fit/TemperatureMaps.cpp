#include "drivers/fit/TemperatureMaps.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hikiln::fit {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double pi = 3.14159265358979323846;

bool isBed(const TemperatureMap& map, std::size_t b, double threshold) {
  return map.bedFraction[b] >= threshold && std::isfinite(map.temperature[b]);
}
} // namespace

int BlockGrid::index(double x, double y) const {
  const double fx = std::floor((x - x0) / h), fy = std::floor((y - y0) / h);
  if (!(fx >= 0.0 && fx < n && fy >= 0.0 && fy < n))
    return -1;
  return static_cast<int>(fx) + n * static_cast<int>(fy);
}

TemperatureMap binParticles(const BlockGrid& blocks, const ParticleTemperatureSnapshot& s) {
  const std::size_t cells = static_cast<std::size_t>(blocks.n) * blocks.n;
  std::vector<double> area(cells, 0.0), heat(cells, 0.0);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const int b = blocks.index(s.x[i], s.y[i]);
    if (b < 0 || s.kind[i] != 0)
      continue;
    const double a = pi * s.radius[i] * s.radius[i];
    area[b] += a;
    heat[b] += a * s.temperature[i];
  }
  TemperatureMap map;
  for (std::size_t b = 0; b < cells; ++b) {
    map.temperature.push_back(area[b] > 0.0 ? heat[b] / area[b] : nan);
    map.bedFraction.push_back(area[b] / (blocks.h * blocks.h));
  }
  return map;
}

TemperatureMap coarsenCells(int nx, int ny, int factor, const std::vector<double>& temperature,
                            const std::vector<double>& capacity,
                            const std::vector<double>& relativePhi) {
  if (factor < 1 || nx % factor != 0 || ny % factor != 0)
    throw std::invalid_argument("hikiln::fit::coarsenCells: cell counts not multiples of factor");
  const int mx = nx / factor, my = ny / factor;
  TemperatureMap map;
  for (int J = 0; J < my; ++J) {
    for (int I = 0; I < mx; ++I) {
      double weight = 0.0, heat = 0.0;
      for (int j = J * factor; j < (J + 1) * factor; ++j) {
        for (int i = I * factor; i < (I + 1) * factor; ++i) {
          const std::size_t c = static_cast<std::size_t>(i) + static_cast<std::size_t>(nx) * j;
          const double w = capacity[c] * relativePhi[c];
          weight += w;
          heat += w * temperature[c];
        }
      }
      map.temperature.push_back(weight > 0.0 ? heat / weight : nan);
      map.bedFraction.push_back(weight / (factor * factor));
    }
  }
  return map;
}

double mixedFraction(const TemperatureMap& map, double cold, double hot, double bedThreshold) {
  double bed = 0.0, mixed = 0.0;
  for (std::size_t b = 0; b < map.temperature.size(); ++b) {
    if (!isBed(map, b, bedThreshold))
      continue;
    const double theta = (map.temperature[b] - cold) / (hot - cold);
    bed += 1.0;
    mixed += theta > 0.1 && theta < 0.9 ? 1.0 : 0.0;
  }
  return bed > 0.0 ? mixed / bed : nan;
}

double thetaRms(const TemperatureMap& a, double thresholdA, const TemperatureMap& b,
                double thresholdB, double cold, double hot) {
  double sum = 0.0, count = 0.0;
  for (std::size_t c = 0; c < a.temperature.size() && c < b.temperature.size(); ++c) {
    if (!isBed(a, c, thresholdA) || !isBed(b, c, thresholdB))
      continue;
    const double d = (a.temperature[c] - b.temperature[c]) / (hot - cold);
    sum += d * d;
    count += 1.0;
  }
  return count > 0.0 ? std::sqrt(sum / count) : nan;
}

} // namespace hikiln::fit
