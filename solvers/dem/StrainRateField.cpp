#include "solvers/dem/StrainRateField.hpp"

#include "kernels/dem/CoarseGrainInvariants.hpp"

#include <cmath>
#include <limits>

namespace hikiln::dem {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// One value and its position along a grid line; `ok` false where the cell has no velocity.
struct Sample {
  double value = 0.0, position = 0.0;
  bool ok = false;
};

// d f / d s at `mid` from its neighbours: central, one-sided, or NaN.
double derivative(const Sample& lo, const Sample& mid, const Sample& hi) {
  if (lo.ok && hi.ok)
    return (hi.value - lo.value) / (hi.position - lo.position);
  if (hi.ok)
    return (hi.value - mid.value) / (hi.position - mid.position);
  if (lo.ok)
    return (mid.value - lo.value) / (mid.position - lo.position);
  return nan;
}

} // namespace

std::vector<double> cartesianStrainRate(const cg::CartesianGrid& g, const std::vector<double>& ux,
                                        const std::vector<double>& uy,
                                        const std::vector<std::uint8_t>& available) {
  const auto at = [&](const std::vector<double>& f, int ix, int iy, double position) {
    if (ix < 0 || ix >= g.nx || iy < 0 || iy >= g.ny)
      return Sample{};
    const std::size_t c = static_cast<std::size_t>(iy * g.nx + ix);
    return Sample{f[c], position, available[c] != 0};
  };
  std::vector<double> rate(static_cast<std::size_t>(g.cellCount()), nan);
  for (int iy = 0; iy < g.ny; ++iy) {
    for (int ix = 0; ix < g.nx; ++ix) {
      const std::size_t c = static_cast<std::size_t>(iy * g.nx + ix);
      if (!available[c])
        continue;
      const double x = g.xCentre(ix), y = g.yCentre(iy);
      const auto ddx = [&](const std::vector<double>& f) {
        return derivative(at(f, ix - 1, iy, x - g.dx), at(f, ix, iy, x),
                          at(f, ix + 1, iy, x + g.dx));
      };
      const auto ddy = [&](const std::vector<double>& f) {
        return derivative(at(f, ix, iy - 1, y - g.dy), at(f, ix, iy, y),
                          at(f, ix, iy + 1, y + g.dy));
      };
      rate[c] = cg::strainRateInvariant(ddx(ux), 0.5 * (ddy(ux) + ddx(uy)), ddy(uy));
    }
  }
  return rate;
}

std::vector<double> polarStrainRate(const cg::PolarGrid& g, const std::vector<double>& ux,
                                    const std::vector<double>& uy,
                                    const std::vector<std::uint8_t>& available) {
  const std::size_t n = static_cast<std::size_t>(g.cellCount());
  std::vector<double> ur(n), ut(n);
  for (int it = 0; it < g.ntheta; ++it) {
    const double theta = (it + 0.5) * g.sectorWidth();
    const double c = std::cos(theta), s = std::sin(theta);
    for (int ir = 0; ir < g.nr; ++ir) {
      const std::size_t k = static_cast<std::size_t>(it * g.nr + ir);
      ur[k] = ux[k] * c + uy[k] * s;
      ut[k] = -ux[k] * s + uy[k] * c;
    }
  }
  // Neighbours along r (none beyond the axis ring or the shell) and along theta (periodic); theta
  // positions are offsets from the cell's own angle so that the wrap needs no special case.
  const auto alongR = [&](const std::vector<double>& f, int it, int ir) {
    if (ir < 0 || ir >= g.nr)
      return Sample{};
    const std::size_t k = static_cast<std::size_t>(it * g.nr + ir);
    return Sample{f[k], g.centroidRadius(ir), available[k] != 0};
  };
  const auto alongTheta = [&](const std::vector<double>& f, int it, int ir, int offset) {
    const int wrapped = ((it + offset) % g.ntheta + g.ntheta) % g.ntheta;
    const std::size_t k = static_cast<std::size_t>(wrapped * g.nr + ir);
    return Sample{f[k], offset * g.sectorWidth(), available[k] != 0};
  };
  std::vector<double> rate(n, nan);
  for (int it = 0; it < g.ntheta; ++it) {
    for (int ir = 0; ir < g.nr; ++ir) {
      const std::size_t k = static_cast<std::size_t>(it * g.nr + ir);
      if (!available[k])
        continue;
      const double r = g.centroidRadius(ir);
      const auto ddr = [&](const std::vector<double>& f) {
        return derivative(alongR(f, it, ir - 1), alongR(f, it, ir), alongR(f, it, ir + 1));
      };
      const auto ddt = [&](const std::vector<double>& f) {
        return derivative(alongTheta(f, it, ir, -1), alongTheta(f, it, ir, 0),
                          alongTheta(f, it, ir, 1));
      };
      const double drr = ddr(ur);
      const double dtt = (ddt(ut) + ur[k]) / r;
      const double drt = 0.5 * (ddr(ut) - ut[k] / r + ddt(ur) / r);
      rate[k] = cg::strainRateInvariant(drr, drt, dtt);
    }
  }
  return rate;
}

} // namespace hikiln::dem
