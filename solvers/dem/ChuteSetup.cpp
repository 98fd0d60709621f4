#include "solvers/dem/ChuteSetup.hpp"

#include "solvers/dem/DrumFill.hpp"
#include "solvers/dem/SplitMix.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hikiln::dem {

namespace {
void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("chute: " + what);
}
} // namespace

Chute makeChute(const ChuteSpec& s) {
  require(s.meanDiameter > 0, "meanDiameter must be > 0");
  require(s.sizeRange >= 0 && s.sizeRange < 1 && s.baseSizeRange >= 0 && s.baseSizeRange < 1,
          "size ranges must be in [0, 1)");
  require(s.lengthDiameters >= 4 && s.heightDiameters > 0, "the chute needs length >= 4 and "
                                                           "height > 0 diameters");
  require(s.angleDegrees >= 0 && s.angleDegrees < 90, "angle must be in [0, 90) degrees");
  const double d = s.meanDiameter;
  SplitMix64 rng(s.seed);
  const auto uniform = [&](double a, double b) { return a + (b - a) * rng.uniform(); };

  Chute c;
  c.length = s.lengthDiameters * d;
  const auto baseCount = static_cast<std::size_t>(std::lround(s.lengthDiameters));
  const double maxD = d * (1 + s.sizeRange);
  const double pitch = 1.05 * maxD;
  const auto perRow = static_cast<std::size_t>(std::floor(c.length / pitch));
  const double meanArea = constants::pi / 4 * d * d * (1 + s.sizeRange * s.sizeRange / 3);
  const auto freeCount =
      static_cast<std::size_t>(std::lround(0.8 * s.heightDiameters * d * c.length / meanArea));
  c.baseCount = baseCount;
  const std::size_t n = baseCount + freeCount;
  c.particles = ParticleArrays<Kokkos::HostSpace>(n, n);
  auto& p = c.particles;
  double topSum = 0, baseHigh = 0;
  for (std::size_t k = 0; k < baseCount; ++k) {
    const double r = 0.5 * d * uniform(1 - s.baseSizeRange, 1 + s.baseSizeRange);
    const double y = d * uniform(-s.baseHeightJitter, s.baseHeightJitter);
    p.position(k, 0) = (static_cast<double>(k) + 0.5) * c.length / static_cast<double>(baseCount);
    p.position(k, 1) = y;
    p.radius(k) = r;
    p.kind(k) = static_cast<std::uint8_t>(ParticleKind::Fixed);
    topSum += y + r;
    baseHigh = std::max(baseHigh, y + r);
  }
  c.baseTop = topSum / static_cast<double>(baseCount);
  for (std::size_t m = 0; m < freeCount; ++m) {
    const std::size_t row = m / perRow, col = m % perRow;
    const std::size_t i = baseCount + m;
    const double shift = (row % 2) * 0.5; // staggered rows
    p.position(i, 0) =
        (static_cast<double>(col) + 0.25 + shift) * c.length / static_cast<double>(perRow);
    p.position(i, 1) = baseHigh + (static_cast<double>(row) + 0.5) * pitch;
    p.radius(i) = 0.5 * d * uniform(1 - s.sizeRange, 1 + s.sizeRange);
  }
  for (std::size_t i = 0; i < n; ++i) {
    p.id(i) = static_cast<std::int64_t>(i);
  }
  assignMassPropertiesHost(p, s.density, MassConvention::Sphere);

  const double theta = s.angleDegrees * constants::pi / 180;
  c.config.particleContact = s.contact;
  c.config.wallContact = s.contact;
  c.config.gravityX = s.gravity * std::sin(theta);
  c.config.gravityY = -s.gravity * std::cos(theta);
  c.config.periodic.enabled = true;
  c.config.periodic.xlo = 0.0;
  c.config.periodic.length = c.length;
  c.config.neighborCapacity = 16; // +-20 % sizes: a small disc may touch up to 7 others
  return c;
}

ChuteProfileSampler::ChuteProfileSampler(double length, double baseTop, double slab, double top)
    : _length(length), _baseTop(baseTop), _slab(slab) {
  require(length > 0 && slab > 0 && top > slab, "profile slabs need length, slab, top > 0");
  const auto count = static_cast<std::size_t>(std::ceil(top / slab));
  _area.assign(count, 0.0);
  _momentum.assign(count, 0.0);
}

void ChuteProfileSampler::add(const ParticleArrays<Kokkos::HostSpace>& p) {
  const auto slabs = static_cast<long>(_area.size());
  for (std::size_t i = 0; i < p.count(); ++i) {
    if (!isFree(p.kind(i)))
      continue;
    const double z = p.position(i, 1) - _baseTop, r = p.radius(i);
    const long lo = std::max(0L, static_cast<long>(std::floor((z - r) / _slab)));
    const long hi = std::min(slabs - 1, static_cast<long>(std::floor((z + r) / _slab)));
    for (long k = lo; k <= hi; ++k) {
      const double a = circularSegmentArea(r, static_cast<double>(k + 1) * _slab - z) -
                       circularSegmentArea(r, static_cast<double>(k) * _slab - z);
      _area[static_cast<std::size_t>(k)] += a;
      _momentum[static_cast<std::size_t>(k)] += a * p.velocity(i, 0);
    }
  }
  ++_samples;
}

ChuteProfile ChuteProfileSampler::profile() const {
  ChuteProfile out;
  out.slab = _slab;
  const double slabArea = _length * _slab * std::max(1, _samples);
  double solid = 0; // solid area per unit length: the height the bed would have at fraction 1
  for (std::size_t k = 0; k < _area.size(); ++k) {
    out.z.push_back((static_cast<double>(k) + 0.5) * _slab);
    out.solidFraction.push_back(_area[k] / slabArea);
    out.velocity.push_back(_area[k] > 0 ? _momentum[k] / _area[k]
                                        : std::numeric_limits<double>::quiet_NaN());
    solid += out.solidFraction.back() * _slab;
  }
  // bulk fraction over the middle half of the bed; the bed height follows from it (twice)
  double bulk = *std::max_element(out.solidFraction.begin(), out.solidFraction.end());
  for (int it = 0; it < 3 && bulk > 0; ++it) {
    const double h = solid / bulk;
    double sum = 0;
    int n = 0;
    for (std::size_t k = 0; k < out.z.size(); ++k)
      if (out.z[k] >= 0.25 * h && out.z[k] <= 0.75 * h)
        sum += out.solidFraction[k], ++n;
    bulk = n > 0 ? sum / n : 0.0;
  }
  out.bulkSolidFraction = bulk;
  // the surface: the highest slab at or above half the bulk fraction, interpolated upwards
  for (std::size_t k = out.z.size(); k-- > 0;) {
    if (out.solidFraction[k] >= 0.5 * bulk) {
      const double above = k + 1 < out.z.size() ? out.solidFraction[k + 1] : 0.0;
      const double t = (out.solidFraction[k] - 0.5 * bulk) / (out.solidFraction[k] - above);
      out.height = out.z[k] + t * _slab;
      break;
    }
  }
  return out;
}

ProfileFit fitPowerProfile(const ChuteProfile& p, double exponent, double zMin, double zMax) {
  const double h = p.height;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  int n = 0;
  for (std::size_t k = 0; k < p.z.size(); ++k) {
    const double z = p.z[k];
    if (z < zMin || z > zMax || z >= h || !std::isfinite(p.velocity[k]))
      continue;
    const double x = std::pow(h, exponent) - std::pow(h - z, exponent), y = p.velocity[k];
    sx += x, sy += y, sxx += x * x, sxy += x * y, syy += y * y;
    ++n;
  }
  ProfileFit f;
  f.exponent = exponent;
  f.points = n;
  if (n < 3)
    return f;
  const double vx = sxx - sx * sx / n, vxy = sxy - sx * sy / n, vy = syy - sy * sy / n;
  f.amplitude = vx > 0 ? vxy / vx : 0.0;
  f.u0 = (sy - f.amplitude * sx) / n;
  // SS_res = vy - A vxy for the least-squares line
  f.rSquared = vy > 0 ? 1 - (vy - f.amplitude * vxy) / vy : 0.0;
  return f;
}

ProfileFit fitBestExponent(const ChuteProfile& p, double zMin, double zMax) {
  ProfileFit best;
  best.rSquared = -std::numeric_limits<double>::infinity();
  for (int k = 50; k <= 300; ++k) {
    const ProfileFit f = fitPowerProfile(p, 0.01 * k, zMin, zMax);
    if (f.points >= 3 && f.rSquared > best.rSquared)
      best = f;
  }
  return best;
}

} // namespace hikiln::dem
