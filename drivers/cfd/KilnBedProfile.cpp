#include "drivers/cfd/KilnBedProfile.hpp"

#include "drivers/cfd/ContinuumCase.hpp"
#include "drivers/compare/BedSurface.hpp"
#include "kernels/common/Compat.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace hikiln::cfd {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double degrees = 180.0 / constants::pi;

nlohmann::json numberOrNull(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}
} // namespace

std::vector<BedSection> bedSections(Grid const& grid, std::vector<double> const& volumeFraction,
                                    std::vector<double> const& fluidVolume, double phiMax,
                                    double radius) {
  const auto perSection = static_cast<std::size_t>(grid.nx) * grid.ny;
  if (volumeFraction.size() != perSection * grid.nz ||
      fluidVolume.size() != volumeFraction.size()) {
    throw std::invalid_argument("bedSections: the arrays do not match the grid");
  }
  compare::CellGrid columns;
  columns.x0 = grid.x0;
  columns.y0 = grid.y0;
  columns.dx = grid.hx;
  columns.dy = grid.hy;
  columns.nx = grid.nx;
  columns.ny = grid.ny;
  const compare::DrumCircle shell{0.0, 0.0, radius};
  std::vector<BedSection> sections(static_cast<std::size_t>(grid.nz));
  std::vector<double> perCellArea(perSection); // the bed's share of each whole cell
  for (int k = 0; k < grid.nz; ++k) {
    double bedArea = 0.0;
    for (std::size_t n = 0; n < perSection; ++n) {
      const std::size_t c = k * perSection + n;
      perCellArea[n] = volumeFraction[c] * fluidVolume[c];
      bedArea += perCellArea[n] / phiMax * grid.hx * grid.hy;
    }
    BedSection& s = sections[static_cast<std::size_t>(k)];
    s.z = grid.z0 + (k + 0.5) * grid.hz;
    const double fill = std::min(bedArea / (constants::pi * radius * radius), 1.0);
    s.depth = radius + flatBedLevel(radius, fill);
    const auto heights =
        compare::surfaceHeights(columns, perCellArea, phiMax, shell, 0.25 * grid.hy);
    s.angleDeg = std::fabs(compare::surfaceAngleDeg(columns, heights, shell, 0.5));
  }
  return sections;
}

void KramersComparison::add(double time, std::vector<BedSection> const& sections, double solidsIn,
                            double solidsOut) {
  if (time < _setup.averageFrom * (1.0 - 1e-12)) {
    return;
  }
  if (_samples == 0) {
    _z.clear();
    for (BedSection const& s : sections) {
      _z.push_back(s.z);
    }
    _depth.assign(sections.size(), 0.0);
    _angleSum.assign(sections.size(), 0.0);
    _angleCount.assign(sections.size(), 0);
    _t0 = time;
    _in0 = solidsIn;
    _out0 = solidsOut;
  }
  for (std::size_t k = 0; k < sections.size(); ++k) {
    _depth[k] += sections[k].depth;
    if (std::isfinite(sections[k].angleDeg)) {
      _angleSum[k] += sections[k].angleDeg;
      ++_angleCount[k];
    }
  }
  ++_samples;
  _t1 = time;
  _in1 = solidsIn;
  _out1 = solidsOut;
}

nlohmann::json KramersComparison::report(std::filesystem::path const& out) const {
  nlohmann::json j;
  j["average_from_s"] = _setup.averageFrom;
  j["samples"] = _samples;
  if (_samples < 2 || !(_t1 > _t0)) {
    j["note"] = "fewer than two outputs in the averaging window: no comparison";
    return j;
  }
  const double window = _t1 - _t0;
  const double feed = (_in1 - _in0) / window;
  const std::size_t n = _z.size();
  std::vector<double> depth(n), angle(n, nan);
  const auto inDam = [&](std::size_t k) { return _z[k] > _setup.length - _setup.damWidth; };
  double angleSum = 0.0, angleLo = 90.0, angleHi = 0.0;
  int angleSections = 0;
  for (std::size_t k = 0; k < n; ++k) {
    depth[k] = _depth[k] / _samples;
    if (_angleCount[k] > 0) {
      angle[k] = _angleSum[k] / _angleCount[k];
    }
    // the repose angle away from the feed and the discharge
    const bool middle = _z[k] >= 0.1 * _setup.length && _z[k] <= 0.9 * _setup.length;
    if (middle && !inDam(k) && std::isfinite(angle[k])) {
      angleSum += angle[k];
      angleLo = std::min(angleLo, angle[k]);
      angleHi = std::max(angleHi, angle[k]);
      ++angleSections;
    }
  }
  j["window_s"] = {_t0, _t1};
  j["feed_bulk_m3_per_s"] = feed / _setup.phiMax;
  j["outflow_over_feed"] = feed > 0.0 ? (_out1 - _out0) / (_in1 - _in0) : nan;
  if (angleSections == 0 || !(feed > 0.0)) {
    j["note"] = "no bed surface or no feed in the averaging window: no comparison";
    return j;
  }
  KramersCroockewit kc;
  kc.radius = _setup.radius;
  kc.revolutionsPerSecond = _setup.revolutionsPerSecond;
  kc.slope = _setup.slope;
  kc.reposeAngle = angleSum / angleSections / degrees;
  kc.feed = feed / _setup.phiMax;
  // start at the section nearest the discharge end outside the dam; go upstream
  std::size_t start = n;
  for (std::size_t k = n; k-- > 0;) {
    if (!inDam(k)) {
      start = k;
      break;
    }
  }
  if (start == n || start == 0) {
    j["note"] = "no section upstream of the dam: no comparison";
    return j;
  }
  std::vector<double> distances;
  for (std::size_t k = start + 1; k-- > 0;) {
    distances.push_back(_setup.length - _z[k]);
  }
  const std::vector<double> theory = kc.profile(distances.front(), depth[start], distances);
  // the inlet section (the feed patch) and the start itself are not compared
  double worst = 0.0, squares = 0.0;
  int compared = 0;
  std::ofstream csv(out / "kramers_croockewit.csv");
  csv << "z_m,distance_from_discharge_m,depth_m,depth_kramers_m,angle_deg,compared\n";
  for (std::size_t m = 0; m < distances.size(); ++m) {
    const std::size_t k = start - m;
    const bool counted = m > 0 && k > 0;
    const double rel = (depth[k] - theory[m]) / theory[m];
    if (counted) {
      worst = std::max(worst, std::isfinite(rel) ? std::fabs(rel) : HUGE_VAL);
      squares += rel * rel;
      ++compared;
    }
    csv << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{}\n", _z[k], distances[m], depth[k],
                       theory[m], angle[k], counted ? 1 : 0);
  }
  if (!csv) {
    throw std::runtime_error("cannot write " + (out / "kramers_croockewit.csv").string());
  }
  j["repose_angle_deg"] = kc.reposeAngle * degrees;
  j["repose_angle_range_deg"] = {angleLo, angleHi};
  j["start_distance_m"] = distances.front();
  j["start_depth_m"] = depth[start];
  j["uniform_depth_m"] = numberOrNull(kc.uniformDepth());
  j["sections_compared"] = compared;
  j["max_rel_deviation"] = compared > 0 ? numberOrNull(worst) : nlohmann::json(nullptr);
  j["rms_rel_deviation"] =
      compared > 0 ? numberOrNull(std::sqrt(squares / compared)) : nlohmann::json(nullptr);
  // the rise from the start to the last compared section (next to the inlet's): the part of
  // the profile the theory predicts from the start depth
  if (compared > 0) {
    const std::size_t last = distances.size() - 2;
    const double rise = depth[start - last] - depth[start];
    const double riseTheory = theory[last] - depth[start];
    j["rise_m"] = rise;
    j["rise_kramers_m"] = numberOrNull(riseTheory);
    j["rise_rel_deviation"] = numberOrNull((rise - riseTheory) / riseTheory);
  }
  j["csv"] = "kramers_croockewit.csv";
  return j;
}

} // namespace hikiln::cfd
