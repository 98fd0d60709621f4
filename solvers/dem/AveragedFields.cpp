#include "solvers/dem/AveragedFields.hpp"

#include "kernels/dem/CoarseGrainInvariants.hpp"
#include "solvers/dem/StrainRateField.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hikiln::dem {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
using cg::CellSum;
using cg::WallSum;

std::vector<double> strainRateOn(const cg::PolarGrid& g, const std::vector<double>& ux,
                                 const std::vector<double>& uy,
                                 const std::vector<std::uint8_t>& available) {
  return polarStrainRate(g, ux, uy, available);
}

std::vector<double> strainRateOn(const cg::CartesianGrid& g, const std::vector<double>& ux,
                                 const std::vector<double>& uy,
                                 const std::vector<std::uint8_t>& available) {
  return cartesianStrainRate(g, ux, uy, available);
}

void resizeAll(CellFields& f) {
  const std::size_t n = f.size();
  for (auto* v : {&f.volumeFraction, &f.velocityX, &f.velocityY, &f.kineticXX, &f.kineticXY,
                  &f.kineticYY, &f.contactXX, &f.contactXY, &f.contactYX, &f.contactYY,
                  &f.granularTemperature, &f.strainRate, &f.pressure, &f.shearStress, &f.viscosity,
                  &f.frictionM, &f.particlesPerSample})
    v->assign(n, 0.0);
  f.valid.assign(n, 0);
}

// Fields of one grid from its sums (cells x CellSum::Size).
template <class Grid>
CellFields finalizeGrid(const Grid& grid, std::size_t slow, std::size_t fast,
                        const std::vector<double>& sums, const AveragingSettings& s,
                        std::int64_t samples) {
  CellFields f;
  f.slow = slow;
  f.fast = fast;
  resizeAll(f);
  std::vector<std::uint8_t> available(f.size(), 0);
  const double count = static_cast<double>(samples);
  for (std::size_t c = 0; c < f.size(); ++c) {
    const double* a = &sums[c * CellSum::Size];
    const double area = grid.cellArea(static_cast<int>(c));
    const double sv = count * area * s.thickness; // samples x cell volume
    const double mass = a[CellSum::Mass];
    f.particlesPerSample[c] = samples > 0 ? a[CellSum::Count] / count : 0.0;
    f.volumeFraction[c] = samples > 0 ? a[CellSum::Area] / (count * area) : 0.0;
    if (mass > 0.0) {
      const double ux = a[CellSum::MomentumX] / mass, uy = a[CellSum::MomentumY] / mass;
      // sum m (v - u)(v - u) = sum m v v - M u u; the diagonal cannot be negative (round-off).
      const double fxx = std::max(0.0, a[CellSum::MvvXX] - mass * ux * ux);
      const double fyy = std::max(0.0, a[CellSum::MvvYY] - mass * uy * uy);
      const double fxy = a[CellSum::MvvXY] - mass * ux * uy;
      f.velocityX[c] = ux;
      f.velocityY[c] = uy;
      f.kineticXX[c] = fxx / sv;
      f.kineticXY[c] = fxy / sv;
      f.kineticYY[c] = fyy / sv;
      f.granularTemperature[c] = 0.5 * (fxx + fyy) / mass;
      available[c] = a[CellSum::Count] >= static_cast<double>(s.minParticleSamples) ? 1 : 0;
    } else {
      f.velocityX[c] = f.velocityY[c] = f.granularTemperature[c] = nan;
    }
    if (samples > 0) { // the virial sum is tension positive; the fields are compressive positive
      f.contactXX[c] = -a[CellSum::VirialXX] / sv;
      f.contactXY[c] = -a[CellSum::VirialXY] / sv;
      f.contactYX[c] = -a[CellSum::VirialYX] / sv;
      f.contactYY[c] = -a[CellSum::VirialYY] / sv;
    }
    const cg::StressInvariants inv =
        cg::stressInvariants(f.kineticXX[c] + f.contactXX[c], f.kineticXY[c] + f.contactXY[c],
                             f.kineticXY[c] + f.contactYX[c], f.kineticYY[c] + f.contactYY[c]);
    f.pressure[c] = inv.pressure;
    f.shearStress[c] = inv.shear;
    f.valid[c] = samples > 0 && f.volumeFraction[c] >= s.minVolumeFraction &&
                         a[CellSum::Count] >= static_cast<double>(s.minParticleSamples)
                     ? 1
                     : 0;
  }
  f.strainRate = strainRateOn(grid, f.velocityX, f.velocityY, available);
  for (std::size_t c = 0; c < f.size(); ++c) {
    const double q = f.shearStress[c], rate = f.strainRate[c], p = f.pressure[c];
    f.viscosity[c] = f.valid[c] && rate > 0.0 && std::isfinite(rate) ? q / rate : nan;
    f.frictionM[c] = f.valid[c] && p > 0.0 ? q / p : nan;
  }
  return f;
}

WallFields finalizeWall(const AveragingSettings& s, const AveragingSums& sums) {
  WallFields w;
  const int bins = s.angularCells;
  const double width = 2.0 * constants::pi / bins;
  const double count = static_cast<double>(sums.samples);
  const double sa = count * s.drumRadius * width * s.thickness; // samples x bin wall area
  double shearSum = 0.0, normalSum = 0.0;
  for (int b = 0; b < bins; ++b) {
    const double* a = &sums.wall[static_cast<std::size_t>(b) * WallSum::Size];
    const double normal = sums.samples > 0 ? a[WallSum::NormalForce] / sa : 0.0;
    const double shear = sums.samples > 0 ? a[WallSum::ShearForce] / sa : 0.0;
    w.thetaCentres.push_back((b + 0.5) * width);
    w.normalStress.push_back(normal);
    w.shearStress.push_back(shear);
    w.tangentialVelocity.push_back(
        a[WallSum::Touching] > 0.0 ? a[WallSum::SpeedSum] / a[WallSum::Touching] : nan);
    w.contactsPerSample.push_back(sums.samples > 0 ? a[WallSum::Contacts] / count : 0.0);
    if (normal > 0.0) { // bins in contact with the bed; all bins have the same width
      shearSum += shear;
      normalSum += normal;
    }
  }
  w.muWall = normalSum > 0.0 ? shearSum / normalSum : nan;
  w.slipPercent =
      sums.slipSamples > 0 ? 100.0 * sums.slipSum / static_cast<double>(sums.slipSamples) : nan;
  return w;
}

} // namespace

cg::PolarGrid AveragingSettings::polarGrid() const {
  cg::PolarGrid g;
  g.radius = drumRadius;
  g.nr = radialCells;
  g.ntheta = angularCells;
  return g;
}

cg::CartesianGrid AveragingSettings::cartesianGrid() const {
  return cg::drumCartesianGrid(drumRadius, cartesianCellsX, cartesianCellsY);
}

void AveragingSettings::validate() const {
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument("hikiln::dem::AveragingSettings: " + what);
  };
  if (!(drumRadius > 0.0))
    fail("drum radius must be > 0");
  if (!(thickness > 0.0))
    fail("slice thickness must be > 0");
  if (radialCells < 1 || angularCells < 3 || cartesianCellsX < 1 || cartesianCellsY < 1)
    fail("grids need >= 1 radial, >= 3 angular and >= 1 x 1 Cartesian cells");
  if (!(minVolumeFraction >= 0.0 && minVolumeFraction <= 1.0))
    fail("minVolumeFraction must be in [0, 1]");
  if (minParticleSamples < 0)
    fail("minParticleSamples must be >= 0");
  if (!(touchGap >= 0.0))
    fail("touchGap must be >= 0");
}

AveragedFields finalizeAverages(const AveragingSettings& s, const AveragingSums& sums) {
  s.validate();
  AveragedFields out;
  out.polarGrid = s.polarGrid();
  out.cartesianGrid = s.cartesianGrid();
  const auto need = [](const std::vector<double>& v, int rows, int columns, const char* what) {
    if (v.size() != static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns))
      throw std::invalid_argument(std::string("hikiln::dem::finalizeAverages: ") + what +
                                  " sums do not match the grid settings");
  };
  need(sums.polar, out.polarGrid.cellCount(), CellSum::Size, "polar");
  need(sums.cartesian, out.cartesianGrid.cellCount(), CellSum::Size, "Cartesian");
  need(sums.wall, s.angularCells, WallSum::Size, "shell");
  out.samples = sums.samples;
  out.averageStart = sums.firstTime;
  out.averageEnd = sums.lastTime;
  out.thickness = s.thickness;
  out.minVolumeFraction = s.minVolumeFraction;
  out.minParticleSamples = s.minParticleSamples;
  out.polar = finalizeGrid(out.polarGrid, static_cast<std::size_t>(s.angularCells),
                           static_cast<std::size_t>(s.radialCells), sums.polar, s, sums.samples);
  out.cartesian =
      finalizeGrid(out.cartesianGrid, static_cast<std::size_t>(s.cartesianCellsY),
                   static_cast<std::size_t>(s.cartesianCellsX), sums.cartesian, s, sums.samples);
  out.wall = finalizeWall(s, sums);
  return out;
}

BedAverage bedAverage(const CellFields& f) {
  BedAverage b;
  double p = 0.0, q = 0.0;
  for (std::size_t c = 0; c < f.size(); ++c) {
    if (f.valid[c]) {
      p += f.pressure[c];
      q += f.shearStress[c];
      ++b.validCells;
    }
  }
  if (b.validCells > 0) {
    b.pressure = p / static_cast<double>(b.validCells);
    b.shearStress = q / static_cast<double>(b.validCells);
    b.frictionM = b.pressure > 0.0 ? b.shearStress / b.pressure : nan;
  }
  return b;
}

} // namespace hikiln::dem
