#include "solvers/dem/DrumFill.hpp"

#include "solvers/dem/SplitMix.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace hikiln::dem {

namespace {
constexpr double pi = constants::pi;

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("drum fill: " + what);
}

// Equal-area radius: the disc radius, or sqrt(A / pi) of a superquadric.
double sizeRadius(const ParticleArrays<Kokkos::HostSpace>& p,
                  const BlockyArrays<Kokkos::HostSpace>& shapes, std::size_t i) {
  return shapes.capacity() > i ? std::sqrt(particleArea(p, shapes, i) / pi) : p.radius(i);
}

// Circle shapes of the shell discs, shapes of the free particles from their equal-area radii and
// orientations drawn after all sizes; then the mass properties (radius: the bounding radius).
BlockyArrays<Kokkos::HostSpace> assignShapes(const ParticleArrays<Kokkos::HostSpace>& p,
                                             const FillSpec& s, SplitMix64& random) {
  BlockyArrays<Kokkos::HostSpace> shapes(p.count());
  for (std::size_t i = 0; i < p.count(); ++i) {
    const double r = p.radius(i);
    const bool free = isFree(p.kind(i));
    shapes.shape(i) = free ? equalAreaShape(s.shape, 2 * r) : SuperquadricShape{r, r, 2.0};
    shapes.orientation(i) = free ? 2 * pi * random.uniform() : 0.0;
    shapes.axis(i, 0) = std::cos(shapes.orientation(i));
    shapes.axis(i, 1) = std::sin(shapes.orientation(i));
  }
  assignBlockyMassPropertiesHost(p, shapes, s.density, s.convention, s.thickness);
  return shapes;
}

ParticleArrays<Kokkos::HostSpace> subset(const ParticleArrays<Kokkos::HostSpace>& p,
                                         const std::vector<std::size_t>& keep) {
  ParticleArrays<Kokkos::HostSpace> out(keep.size(), keep.size());
  for (std::size_t k = 0; k < keep.size(); ++k) {
    const std::size_t i = keep[k];
    for (int d = 0; d < 2; ++d) {
      out.position(k, d) = p.position(i, d);
      out.velocity(k, d) = p.velocity(i, d);
    }
    out.angularVelocity(k) = p.angularVelocity(i);
    out.radius(k) = p.radius(i);
    out.mass(k) = p.mass(i);
    out.inertia(k) = p.inertia(i);
    out.inverseMass(k) = p.inverseMass(i);
    out.inverseInertia(k) = p.inverseInertia(i);
    out.id(k) = p.id(i);
    out.kind(k) = p.kind(i);
  }
  return out;
}
} // namespace

double circularSegmentArea(double radius, double height) {
  const double h = std::clamp(height, -radius, radius);
  return radius * radius * std::acos(-h / radius) + h * std::sqrt(radius * radius - h * h);
}

double segmentHeightForFraction(double radius, double fraction) {
  const double target = fraction * pi * radius * radius;
  double lo = -radius, hi = radius;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (circularSegmentArea(radius, mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

ParticleArrays<Kokkos::HostSpace> generateDrumLattice(const FillSpec& s) {
  require(!s.shape.superquadric,
          "superquadric particles need their shapes: generateDrumParticles()");
  return generateDrumParticles(s).particles;
}

DrumParticles generateDrumParticles(const FillSpec& s) {
  require(s.drumRadius > 0, "drum radius must be > 0");
  require(s.fill > 0 && s.fill < 1, "fill must be in (0, 1), got " + std::to_string(s.fill));
  require(s.meanDiameter > 0, "mean diameter must be > 0");
  require(s.sizeRange >= 0 && s.sizeRange <= 1, "size range must be in [0, 1]");
  require(s.meanDiameter * (1 + s.sizeRange) < 0.5 * s.drumRadius,
          "particles must be much smaller than the drum");
  const double dMin = s.meanDiameter * std::max(1 - s.sizeRange, s.minDiameterFraction);
  const double dMax = s.meanDiameter * (1 + s.sizeRange);
  // Lattice spacing leaves a small gap between the largest bounding circles; rows are sqrt(3)/2
  // apart.
  const double spacing = 1.02 * dMax * boundingRadiusRatio(s.shape);
  const double rowHeight = 0.5 * std::sqrt(3.0) * spacing;
  // A settled bed packs to ~0.82 (2D discs); the loose lattice packs less, so it spans more area.
  const double latticePacking = 0.25 * pi * s.meanDiameter * s.meanDiameter / (spacing * rowHeight);
  const double latticeFraction = std::min(0.95, s.overfill * s.fill * 0.82 / latticePacking);
  const double top = segmentHeightForFraction(s.drumRadius, latticeFraction);
  require(s.shellBumpDiameter >= 0 && s.shellBumpDiameter < 0.25 * s.drumRadius,
          "shell bump diameter must be in [0, R/4)");
  require(s.shellBumpSpacing >= 1, "shell bump spacing must be >= 1 bump diameter");
  const double inner = s.drumRadius - s.shellBumpDiameter - 0.51 * spacing;
  std::vector<double> xs, ys;
  int row = 0;
  for (double y = -inner; y <= top; y += rowHeight, ++row) {
    const double half = std::sqrt(std::max(0.0, inner * inner - y * y));
    const double shift = (row % 2) * 0.5 * spacing;
    for (double x = -half + shift; x <= half; x += spacing) {
      if (x * x + y * y <= inner * inner) {
        xs.push_back(x);
        ys.push_back(y);
      }
    }
  }
  require(!xs.empty(), "no particle fits: drum too small for the particles");
  const std::size_t nFree = xs.size();
  // the ring of glued shell discs, touching (spacing 1) or evenly gapped, centres at R - d_b/2
  const double ringRadius = s.drumRadius - 0.5 * s.shellBumpDiameter;
  const std::size_t nRing =
      s.shellBumpDiameter > 0
          ? static_cast<std::size_t>(
                std::floor(2 * pi * ringRadius / (s.shellBumpSpacing * s.shellBumpDiameter)))
          : 0;
  ParticleArrays<Kokkos::HostSpace> p(nFree + nRing, nFree + nRing);
  SplitMix64 random(s.seed);
  for (std::size_t i = 0; i < nFree; ++i) {
    p.position(i, 0) = xs[i];
    p.position(i, 1) = ys[i];
    p.radius(i) = 0.5 * (dMin + (dMax - dMin) * random.uniform());
    p.id(i) = static_cast<std::int64_t>(i);
  }
  for (std::size_t k = 0; k < nRing; ++k) {
    const std::size_t i = nFree + k;
    const double angle = 2 * pi * static_cast<double>(k) / static_cast<double>(nRing);
    p.position(i, 0) = ringRadius * std::cos(angle);
    p.position(i, 1) = ringRadius * std::sin(angle);
    p.radius(i) = 0.5 * s.shellBumpDiameter;
    p.id(i) = static_cast<std::int64_t>(i);
    p.kind(i) = static_cast<std::uint8_t>(ParticleKind::Shell);
  }
  if (s.shape.superquadric) {
    BlockyArrays<Kokkos::HostSpace> shapes = assignShapes(p, s, random);
    return {p, shapes};
  }
  assignMassPropertiesHost(p, s.density, s.convention, s.thickness);
  return {p, {}};
}

BedMeasurement measureBed(const ParticleArrays<Kokkos::HostSpace>& p, double R,
                          const BlockyArrays<Kokkos::HostSpace>& shapes) {
  BedMeasurement m;
  double meanR = 0, reach = R; // reach: the wall, or the inner side of the shell discs
  for (std::size_t i = 0; i < p.count(); ++i) {
    if (!isFree(p.kind(i))) {
      reach = std::min(reach, std::hypot(p.position(i, 0), p.position(i, 1)) - p.radius(i));
      continue;
    }
    m.solidArea += particleArea(p, shapes, i);
    meanR += sizeRadius(p, shapes, i);
    ++m.count;
  }
  if (m.count == 0)
    return m;
  meanR /= static_cast<double>(m.count);
  // Surface: the top of the highest particle per bin (4 mean diameters wide) across the bed.
  const double bin = 8 * meanR;
  const int nb = static_cast<int>(std::ceil(2 * R / bin));
  std::vector<double> highest(nb, -1e300);
  for (std::size_t i = 0; i < p.count(); ++i) {
    if (!isFree(p.kind(i)))
      continue;
    const int b = std::clamp(static_cast<int>((p.position(i, 0) + R) / bin), 0, nb - 1);
    highest[b] = std::max(highest[b], p.position(i, 1) + sizeRadius(p, shapes, i));
  }
  double sum = 0;
  int used = 0;
  for (double h : highest)
    if (h > -1e299)
      sum += h, ++used;
  m.surfaceHeight = sum / used;
  // Bulk fraction: centres in the disc of radius reach - 4 r_mean below the surface - 4 r_mean.
  const double rIn = reach - 4 * meanR, hIn = m.surfaceHeight - 4 * meanR;
  double inside = 0;
  for (std::size_t i = 0; i < p.count(); ++i) {
    if (!isFree(p.kind(i)))
      continue;
    const double x = p.position(i, 0), y = p.position(i, 1);
    if (x * x + y * y < rIn * rIn && y < hIn)
      inside += particleArea(p, shapes, i);
  }
  const double region = circularSegmentArea(rIn, hIn);
  m.bulkFraction = region > 0 && inside > 0 ? inside / region : 0.0;
  m.fill = m.bulkFraction > 0 ? m.solidArea / (m.bulkFraction * pi * R * R) : 0.0;
  return m;
}

namespace {
// Indices (ascending) of the particles trimToFill() keeps.
std::vector<std::size_t> keptForFill(const ParticleArrays<Kokkos::HostSpace>& p,
                                     const BlockyArrays<Kokkos::HostSpace>& shapes, double R,
                                     double fill, double bulkFraction) {
  require(bulkFraction > 0 && bulkFraction <= 1, "bulk fraction must be in (0, 1]");
  std::vector<std::size_t> order(p.count());
  std::iota(order.begin(), order.end(), 0);
  // Lowest first; ties broken by id so the result does not depend on the particle order.
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double ya = p.position(a, 1), yb = p.position(b, 1);
    return ya != yb ? ya < yb : p.id(a) < p.id(b);
  });
  const double target = fill * bulkFraction * pi * R * R;
  std::vector<std::size_t> keep;
  double area = 0;
  for (std::size_t i = 0; i < p.count(); ++i)
    if (!isFree(p.kind(i)))
      keep.push_back(i); // the shell discs stay
  for (std::size_t i : order) {
    if (!isFree(p.kind(i)))
      continue;
    const double a = particleArea(p, shapes, i);
    if (area + 0.5 * a > target)
      break;
    keep.push_back(i);
    area += a;
  }
  std::sort(keep.begin(), keep.end());
  return keep;
}
} // namespace

ParticleArrays<Kokkos::HostSpace> trimToFill(const ParticleArrays<Kokkos::HostSpace>& p, double R,
                                             double fill, double bulkFraction) {
  return subset(p, keptForFill(p, {}, R, fill, bulkFraction));
}

DrumParticles trimToFill(const DrumParticles& d, double R, double fill, double bulkFraction) {
  const auto keep = keptForFill(d.particles, d.shapes, R, fill, bulkFraction);
  if (!d.blocky())
    return {subset(d.particles, keep), {}};
  return {subset(d.particles, keep), subsetShapes(d.shapes, keep)};
}

} // namespace hikiln::dem
