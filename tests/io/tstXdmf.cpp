// XDMF sidecars: well-formed XML, and every "file.h5:/path" they reference exists with the stated
// shape, for particles (2D and 3D) and uniform grids (2D and 3D).
#include "drivers/io/Hdf5File.hpp"
#include "drivers/io/Xdmf.hpp"
#include "io/IoTestSupport.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <regex>
#include <sstream>

namespace {
namespace fs = std::filesystem;
using hikiln::io::H5File;
using hikiln::io::XdmfAttribute;
using hikiln::io::XdmfNumber;
using hikiln::io::test::ScratchDir;

// Tiny well-formedness check: tags nest and close in order, quotes pair up, one root element.
std::string xmlProblem(const std::string& text) {
  std::vector<std::string> open;
  int roots = 0;
  std::size_t at = 0;
  while ((at = text.find('<', at)) != std::string::npos) {
    const std::size_t end = text.find('>', at);
    if (end == std::string::npos)
      return "unterminated tag at " + std::to_string(at);
    const std::string tag = text.substr(at + 1, end - at - 1);
    at = end + 1;
    if (tag.empty() || tag[0] == '?' || tag[0] == '!')
      continue;
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0)
      return "unbalanced quotes in <" + tag + ">";
    const bool closing = tag[0] == '/';
    const bool selfClosing = tag.back() == '/';
    const std::string name =
        tag.substr(closing ? 1 : 0, tag.find_first_of(" /", 1) - (closing ? 1 : 0));
    if (closing) {
      if (open.empty() || open.back() != name)
        return "</" + name + "> does not close <" + (open.empty() ? "" : open.back()) + ">";
      open.pop_back();
    } else {
      if (open.empty())
        ++roots;
      if (!selfClosing)
        open.push_back(name);
    }
  }
  if (!open.empty())
    return "<" + open.back() + "> never closed";
  return roots == 1 ? "" : std::to_string(roots) + " root elements";
}

struct Reference {
  std::vector<hsize_t> dims;
  std::string file;
  std::string dataset;
};

std::vector<Reference> hdfReferences(const std::string& text) {
  static const std::regex item(
      R"re(<DataItem Dimensions="([0-9 ]*)"[^>]*Format="HDF">([^<]*)</DataItem>)re");
  std::vector<Reference> refs;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), item); it != std::sregex_iterator();
       ++it) {
    Reference ref;
    std::istringstream dims((*it)[1].str());
    for (hsize_t d; dims >> d;)
      ref.dims.push_back(d);
    const std::string target = (*it)[2].str();
    const std::size_t colon = target.find(":/");
    ref.file = target.substr(0, colon);
    ref.dataset = colon == std::string::npos ? "" : target.substr(colon + 1);
    refs.push_back(ref);
  }
  return refs;
}

// Every reference resolved from the .xmf's directory; returns a description of each mismatch.
std::vector<std::string> referenceProblems(const std::string& xmfPath, const std::string& text) {
  std::vector<std::string> problems;
  for (const Reference& ref : hdfReferences(text)) {
    const fs::path h5 = fs::path(xmfPath).parent_path() / ref.file;
    try {
      const H5File file = H5File::openRead(h5.string());
      if (!file.isDataset(ref.dataset))
        problems.push_back("missing " + ref.dataset);
      else if (file.datasetDims(ref.dataset) != ref.dims)
        problems.push_back("wrong dims for " + ref.dataset);
    } catch (const std::exception& error) {
      problems.push_back(error.what());
    }
  }
  return problems;
}

void expectValidXdmf(const std::string& xmfPath, const std::string& text, std::size_t refs) {
  EXPECT_EQ(xmlProblem(text), "");
  EXPECT_EQ(hdfReferences(text).size(), refs);
  EXPECT_EQ(referenceProblems(xmfPath, text), std::vector<std::string>{});
  EXPECT_EQ(hikiln::io::test::readWholeFile(xmfPath), text);
  if (fs::exists("/usr/bin/xmllint"))
    EXPECT_EQ(std::system(("/usr/bin/xmllint --noout '" + xmfPath + "'").c_str()), 0);
  else
    std::cout << "[ info ] /usr/bin/xmllint not found: skipping its check\n";
}

std::vector<double> ramp(std::size_t n, double start) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i)
    v[i] = start + static_cast<double>(i);
  return v;
}

// Writes particle steps of the given sizes in `dim` dimensions; returns their descriptions.
std::vector<hikiln::io::XdmfParticleStep>
writeParticles(const std::string& h5, const std::vector<hsize_t>& counts, hsize_t dim) {
  H5File file = H5File::create(h5);
  std::vector<hikiln::io::XdmfParticleStep> steps;
  for (std::size_t s = 0; s < counts.size(); ++s) {
    const hsize_t n = counts[s];
    const std::string group = hikiln::io::stepGroupName(static_cast<std::int64_t>(10 * s));
    file.writeDataset(group + "/position", ramp(n * dim, 0.0), {n, dim}, "m");
    file.writeDataset(group + "/velocity", ramp(n * dim, 1.0), {n, dim}, "m/s");
    file.writeDataset(group + "/radius", ramp(n, 0.5), {n}, "m");
    file.writeDataset(group + "/id", std::vector<std::int64_t>(n, 3), {n});
    file.writeDataset(group + "/omega", std::vector<float>(n, 0.5f), {n});
    steps.push_back({0.5 * static_cast<double>(s),
                     h5,
                     group,
                     static_cast<std::int64_t>(n),
                     static_cast<int>(dim),
                     "position",
                     XdmfNumber::Float64,
                     {{"velocity", "velocity", static_cast<int>(dim)},
                      {"radius", "radius"},
                      {"id", "id", 1, XdmfNumber::Int64},
                      {"omega", "omega", 1, XdmfNumber::Float32}}});
  }
  file.commit();
  return steps;
}
} // namespace

TEST(io_xdmf, particles_2d_temporal_collection) {
  ScratchDir dir("xdmf-particles");
  const auto steps = writeParticles(dir.file("dem.h5"), {5, 8, 0}, 2);
  const std::string xmf = dir.file("dem.xmf");
  hikiln::io::writeXdmfParticles(xmf, steps);
  const std::string text = hikiln::io::xdmfParticlesText(xmf, steps);
  expectValidXdmf(xmf, text, 3 * 5);
  EXPECT_NE(text.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_NE(text.find("GeometryType=\"XY\""), std::string::npos);
  EXPECT_EQ(text.find("GeometryType=\"XYZ\""), std::string::npos);
  EXPECT_NE(text.find("NumberOfElements=\"8\""), std::string::npos);
  EXPECT_NE(text.find("<Time Value=\"0.5\"/>"), std::string::npos);
  EXPECT_NE(text.find(">dem.h5:/step_000010/position<"), std::string::npos) << text;
  // 2-vectors go out as Matrix (ParaView's Vector means exactly 3 components).
  EXPECT_NE(text.find("Name=\"velocity\" AttributeType=\"Matrix\" Center=\"Node\""),
            std::string::npos);
  EXPECT_NE(text.find("NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">dem.h5:/step_000000/id<"),
            std::string::npos);

  // The checker itself notices a wrong count, so the assertions above can fail.
  auto wrong = steps;
  wrong[1].count = 9;
  EXPECT_EQ(referenceProblems(xmf, hikiln::io::xdmfParticlesText(xmf, wrong)).size(), 5u);
  wrong = steps;
  wrong[0].attributes[1].dataset = "diameter";
  EXPECT_EQ(referenceProblems(xmf, hikiln::io::xdmfParticlesText(xmf, wrong)),
            std::vector<std::string>{"missing /step_000000/diameter"});
}

TEST(io_xdmf, particles_3d_from_another_directory) {
  ScratchDir dir("xdmf-particles3d");
  const auto steps = writeParticles(dir.file("dem3.h5"), {6}, 3);
  fs::create_directories(dir.path() / "views");
  const std::string xmf = dir.file("views/dem3.xmf");
  hikiln::io::writeXdmfParticles(xmf, steps);
  const std::string text = hikiln::io::test::readWholeFile(xmf);
  expectValidXdmf(xmf, text, 5);
  EXPECT_NE(text.find(">../dem3.h5:/step_000000/position<"), std::string::npos) << text;
  EXPECT_NE(text.find("GeometryType=\"XYZ\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"velocity\" AttributeType=\"Vector\""), std::string::npos);
}

namespace {
std::vector<double> numbersIn(const std::string& text, const std::string& itemName) {
  const std::regex item("<DataItem Name=\"" + itemName + "\"[^>]*>([^<]*)</DataItem>");
  std::smatch match;
  std::vector<double> values;
  if (std::regex_search(text, match, item)) {
    std::istringstream in(match[1].str());
    for (double v; in >> v;)
      values.push_back(v);
  }
  return values;
}
} // namespace

TEST(io_xdmf, uniform_grids_2d_and_3d) {
  ScratchDir dir("xdmf-grid");
  const std::string h5 = dir.file("fields.h5");
  std::vector<hikiln::io::XdmfGridStep> flat;
  hikiln::io::XdmfGridStep cube;
  {
    H5File file = H5File::create(h5);
    for (int s = 0; s < 2; ++s) {
      const std::string group = hikiln::io::stepGroupName(s);
      file.writeDataset(group + "/temperature", ramp(3 * 4, 300.0), {3, 4}, "K");
      file.writeDataset(group + "/velocity", ramp(3 * 4 * 2, 0.0), {3, 4, 2}, "m/s");
      flat.push_back({0.25 * s,
                      h5,
                      group,
                      2,
                      {4, 3, 0},
                      {0.1, -0.2, 0.0},
                      {0.5, 0.25, 0.0},
                      {{"temperature", "temperature"}, {"velocity", "velocity", 2}}});
    }
    file.writeDataset("/cube/density", ramp(4 * 3 * 2, 1.0), {4, 3, 2}, "kg/m^3");
    file.writeDataset("/cube/velocity", ramp(4 * 3 * 2 * 3, 1.0), {4, 3, 2, 3}, "m/s");
    file.writeDataset("/cube/phase", std::vector<std::uint8_t>(24, 1), {4, 3, 2});
    cube = {1.0,
            h5,
            "/cube",
            3,
            {2, 3, 4},
            {1.0, 2.0, 3.0},
            {0.1, 0.2, 0.3},
            {{"density", "density"},
             {"velocity", "velocity", 3},
             {"phase", "/cube/phase", 1, XdmfNumber::UInt8}}};
    file.commit();
  }

  const std::string flatXmf = dir.file("flat.xmf");
  hikiln::io::writeXdmfGrids(flatXmf, flat);
  const std::string flatText = hikiln::io::test::readWholeFile(flatXmf);
  expectValidXdmf(flatXmf, flatText, 2 * 2);
  EXPECT_NE(flatText.find("CollectionType=\"Temporal\""), std::string::npos);
  // Node counts z y x: one node layer, 3 + 1 rows, 4 + 1 columns = 12 cells as the data holds.
  EXPECT_NE(flatText.find("TopologyType=\"3DCoRectMesh\" Dimensions=\"1 4 5\""), std::string::npos);
  EXPECT_EQ(numbersIn(flatText, "Origin"), (std::vector<double>{0.0, -0.2, 0.1}));
  EXPECT_EQ(numbersIn(flatText, "Spacing"), (std::vector<double>{1.0, 0.25, 0.5}));
  EXPECT_NE(flatText.find("Center=\"Cell\""), std::string::npos);
  EXPECT_EQ(hikiln::io::xdmfAttributeDims(flat[0], flat[0].attributes[1]),
            (std::vector<std::uint64_t>{3, 4, 2}));

  const std::string cubeXmf = dir.file("cube.xmf");
  hikiln::io::writeXdmfGrids(cubeXmf, {cube});
  const std::string cubeText = hikiln::io::test::readWholeFile(cubeXmf);
  expectValidXdmf(cubeXmf, cubeText, 3);
  EXPECT_EQ(cubeText.find("Collection"), std::string::npos); // one step: a plain grid
  EXPECT_NE(cubeText.find("Dimensions=\"5 4 3\""), std::string::npos);
  EXPECT_EQ(numbersIn(cubeText, "Origin"), (std::vector<double>{3.0, 2.0, 1.0}));
  EXPECT_EQ(numbersIn(cubeText, "Spacing"), (std::vector<double>{0.3, 0.2, 0.1}));
  EXPECT_NE(cubeText.find("NumberType=\"UChar\" Precision=\"1\""), std::string::npos);

  EXPECT_THROW(hikiln::io::xdmfGridsText(cubeXmf, {{0.0, h5, "/", 2, {0, 3, 0}, {}, {}, {}}}),
               std::invalid_argument);
}

TEST(io_xdmf, xml_checker_catches_malformed_text) {
  EXPECT_EQ(xmlProblem("<a><b/></a>"), "");
  EXPECT_NE(xmlProblem("<a><b></a></b>"), "");
  EXPECT_NE(xmlProblem("<a x=\"1></a>"), "");
  EXPECT_NE(xmlProblem("<a></a><a></a>"), "");
  EXPECT_NE(xmlProblem("<a>"), "");
}
