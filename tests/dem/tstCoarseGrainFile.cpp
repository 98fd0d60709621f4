// averages.h5 as `hikiln dem` writes it is what `hikiln calibrate` reads (docs/averaged-fields.md):
// fields finalised from known sums are written, read back through the calibration's reader, and
// compared value by value; units, grid axes, the wall group and the XDMF sidecar are checked.
#include "../io/IoTestSupport.hpp"
#include "drivers/calibrate/AveragesReader.hpp"
#include "drivers/dem/AveragesFile.hpp"
#include "drivers/io/Hdf5File.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

using namespace hikiln::dem;
using hikiln::io::test::ScratchDir;

// Cells with mass, a shear flow u = (2 y, 0) and a stress that grows with depth; every third cell
// too dilute to be valid.
void fillCells(std::vector<double>& sums, int cells, double samples) {
  sums.assign(static_cast<std::size_t>(cells) * cg::CellSum::Size, 0.0);
  for (int c = 0; c < cells; ++c) {
    double* a = &sums[static_cast<std::size_t>(c) * cg::CellSum::Size];
    a[cg::CellSum::Count] = 50.0 * samples;
    a[cg::CellSum::Area] = (c % 3 == 0 ? 1e-6 : 1e-3) * samples;
    a[cg::CellSum::Mass] = samples;
    a[cg::CellSum::MomentumX] = 0.1 * (c % 7) * samples;
    a[cg::CellSum::MvvXX] = 0.02 * (c % 7) * (c % 7) * samples;
    a[cg::CellSum::VirialXX] = -(1.0 + 0.01 * c) * samples;
    a[cg::CellSum::VirialYY] = -(1.5 + 0.01 * c) * samples;
    a[cg::CellSum::VirialXY] = 0.2 * samples;
    a[cg::CellSum::VirialYX] = 0.2 * samples;
  }
}

bool sameOrBothNan(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || a == b;
}

TEST(coarse_grain_file, calibration_reads_what_dem_writes) {
  ScratchDir dir("averages-file");
  AveragingSettings s;
  s.drumRadius = 0.5;
  s.thickness = 0.02;
  s.minVolumeFraction = 0.1;
  AveragingSums sums;
  sums.samples = 4;
  sums.firstTime = 5.0;
  sums.lastTime = 8.0;
  sums.slipSum = 0.4;
  sums.slipSamples = 4;
  fillCells(sums.polar, s.polarGrid().cellCount(), 4.0);
  fillCells(sums.cartesian, s.cartesianGrid().cellCount(), 4.0);
  sums.wall.assign(static_cast<std::size_t>(s.angularCells) * cg::WallSum::Size, 0.0);
  for (int b = 40; b < 50; ++b) { // a bed resting on bins 40..49
    sums.wall[static_cast<std::size_t>(b) * cg::WallSum::Size + cg::WallSum::NormalForce] = 8.0;
    sums.wall[static_cast<std::size_t>(b) * cg::WallSum::Size + cg::WallSum::ShearForce] = 2.0;
  }
  const AveragedFields fields = finalizeAverages(s, sums);
  const AveragesConditions conditions{0.314, 0.021, 2700.0, 0.19};
  const std::string path =
      writeAveragesFile(dir.path().string(), fields, conditions, {"dem", "Serial", "case: {}"});
  EXPECT_EQ(path, dir.file("averages.h5"));
  EXPECT_TRUE(std::filesystem::is_regular_file(dir.file("averages.xmf")));
  EXPECT_NE(hikiln::io::test::readWholeFile(dir.file("averages.xmf"))
                .find("averages.h5:/cartesian/pressure"),
            std::string::npos);

  const auto run = hikiln::calibrate::readRunHeader(path);
  EXPECT_EQ(run.conditions.omega, 0.314);
  EXPECT_EQ(run.conditions.drumRadius, 0.5);
  EXPECT_EQ(run.conditions.particleDiameter, 0.021);
  EXPECT_EQ(run.conditions.particleDensity, 2700.0);
  EXPECT_EQ(run.conditions.fill, 0.19);
  EXPECT_EQ(run.conditions.averageStart, 5.0);
  EXPECT_EQ(run.conditions.averageEnd, 8.0);
  EXPECT_EQ(run.conditions.samples, 4);
  EXPECT_DOUBLE_EQ(run.muWall, 0.25);
  EXPECT_DOUBLE_EQ(run.slipPercent, 10.0);

  using hikiln::calibrate::AveragesGrid;
  for (AveragesGrid grid : {AveragesGrid::Polar, AveragesGrid::Cartesian}) {
    const CellFields& f = grid == AveragesGrid::Polar ? fields.polar : fields.cartesian;
    const auto read = hikiln::calibrate::readGridFields(path, grid);
    ASSERT_EQ(read.cells.pressure.size(), f.size());
    std::size_t valid = 0;
    for (std::size_t c = 0; c < f.size(); ++c) {
      EXPECT_EQ(read.cells.pressure[c], f.pressure[c]);
      EXPECT_EQ(read.cells.shearStress[c], f.shearStress[c]);
      EXPECT_EQ(read.cells.volumeFraction[c], f.volumeFraction[c]);
      EXPECT_TRUE(sameOrBothNan(read.cells.strainRate[c], f.strainRate[c])) << c;
      EXPECT_TRUE(sameOrBothNan(read.cells.viscosity[c], f.viscosity[c])) << c;
      EXPECT_TRUE(sameOrBothNan(read.cells.frictionM[c], f.frictionM[c])) << c;
      EXPECT_EQ(read.valid[c], f.valid[c]);
      valid += f.valid[c];
    }
    EXPECT_EQ(valid, f.size() - (f.size() + 2) / 3); // every third cell too dilute
  }
  // cell (it = 0, ir = 1) of the polar grid sits at mid radius 1.5 R / 15, angle half a sector
  const auto polar = hikiln::calibrate::readGridFields(path, AveragesGrid::Polar);
  EXPECT_NEAR(polar.cells.r[1], 1.5 * 0.5 / 15, 1e-15);
  EXPECT_NEAR(polar.cells.theta[1], 3.141592653589793 / 60, 1e-15);

  const auto file = hikiln::io::H5File::openRead(path);
  EXPECT_EQ(file.units("/polar/contact_stress_yx"), "Pa");
  EXPECT_EQ(file.units("/cartesian/viscosity"), "Pa s");
  EXPECT_EQ(file.units("/wall/shear_stress"), "Pa");
  EXPECT_EQ(file.readStringAttribute("/", "stage"), "dem");
  EXPECT_EQ(file.readDoubleAttribute("/", "slice_thickness"), 0.02);
  EXPECT_EQ(file.readDoubleVectorAttribute("/cartesian", "spacing"),
            (std::vector<double>{1.0 / 30, 1.0 / 30}));
  EXPECT_EQ(file.datasetDims("/polar/theta_edges"), (std::vector<hsize_t>{61}));
  EXPECT_EQ(file.datasetDims("/cartesian/velocity"), (std::vector<hsize_t>{30, 30, 2}));
  const auto normal = file.readDataset<double>("/wall/normal_stress");
  const double binArea = 0.5 * 2 * 3.141592653589793 / 60 * 0.02;
  EXPECT_NEAR(normal[45], 8.0 / 4 / binArea, 1e-9);
  EXPECT_EQ(normal[0], 0.0);
}

} // namespace
