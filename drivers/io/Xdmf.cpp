#include "drivers/io/Xdmf.hpp"

#include "drivers/io/AtomicFile.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace hikiln::io {

namespace {
namespace fs = std::filesystem;

std::string escapeXml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

// Shortest text that reads back as the same double (0.1, not 0.10000000000000001).
std::string number(double value) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value)
      break;
  }
  return text;
}

std::string joinDims(const std::vector<std::uint64_t>& dims) {
  std::string out;
  for (std::size_t i = 0; i < dims.size(); ++i)
    out += (i ? " " : "") + std::to_string(dims[i]);
  return out;
}

std::string numberType(XdmfNumber type) {
  switch (type) {
  case XdmfNumber::Float64:
    return "NumberType=\"Float\" Precision=\"8\"";
  case XdmfNumber::Float32:
    return "NumberType=\"Float\" Precision=\"4\"";
  case XdmfNumber::Int32:
    return "NumberType=\"Int\" Precision=\"4\"";
  case XdmfNumber::Int64:
    return "NumberType=\"Int\" Precision=\"8\"";
  case XdmfNumber::UInt8:
    return "NumberType=\"UChar\" Precision=\"1\"";
  }
  return "";
}

// The HDF5 file as seen from the directory of the .xmf, so the pair can be moved together.
std::string relativeH5(const std::string& xmfPath, const std::string& h5File) {
  const fs::path xmfDir = fs::absolute(xmfPath).lexically_normal().parent_path();
  const fs::path h5 = fs::absolute(h5File).lexically_normal();
  const fs::path relative = h5.lexically_relative(xmfDir);
  return relative.empty() ? h5.string() : relative.generic_string();
}

std::string datasetPath(const std::string& group, const std::string& dataset) {
  if (!dataset.empty() && dataset.front() == '/')
    return dataset;
  std::string base = group.empty() || group.front() != '/' ? "/" + group : group;
  if (base.back() != '/')
    base += '/';
  return base + dataset;
}

void dataItem(std::ostringstream& out, const std::string& indent,
              const std::vector<std::uint64_t>& dims, XdmfNumber type, const std::string& h5,
              const std::string& path) {
  out << indent << "<DataItem Dimensions=\"" << joinDims(dims) << "\" " << numberType(type)
      << " Format=\"HDF\">" << escapeXml(h5) << ":" << escapeXml(path) << "</DataItem>\n";
}

std::string attributeType(int components) {
  if (components == 1)
    return "Scalar";
  return components == 3 ? "Vector" : "Matrix";
}

void attribute(std::ostringstream& out, const std::string& indent, const XdmfAttribute& a,
               const char* center, const std::vector<std::uint64_t>& dims, const std::string& h5,
               const std::string& group) {
  if (a.components < 1)
    throw std::invalid_argument("XDMF attribute '" + a.name + "' has no components");
  out << indent << "<Attribute Name=\"" << escapeXml(a.name) << "\" AttributeType=\""
      << attributeType(a.components) << "\" Center=\"" << center << "\">\n";
  dataItem(out, indent + "  ", dims, a.number, h5, datasetPath(group, a.dataset));
  out << indent << "</Attribute>\n";
}

void header(std::ostringstream& out, const std::string& name, bool collection) {
  out << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf xmlns:xi=\"http://www.w3.org/2001/XInclude\" Version=\"3.0\">\n  <Domain>\n";
  if (collection)
    out << "    <Grid Name=\"" << name
        << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
}

void footer(std::ostringstream& out, bool collection) {
  if (collection)
    out << "    </Grid>\n";
  out << "  </Domain>\n</Xdmf>\n";
}

std::string stepName(const std::string& group, std::size_t index) {
  const std::string trimmed =
      group.empty() || group == "/" ? "" : fs::path(group).filename().string();
  return escapeXml(trimmed.empty() ? "step_" + std::to_string(index) : trimmed);
}
} // namespace

std::string xdmfParticlesText(const std::string& xmfPath,
                              const std::vector<XdmfParticleStep>& steps) {
  std::ostringstream out;
  header(out, "particles", true);
  const std::string in = "      ";
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const XdmfParticleStep& step = steps[s];
    if (step.dim != 2 && step.dim != 3)
      throw std::invalid_argument("XDMF particles: dim must be 2 or 3");
    if (step.count < 0)
      throw std::invalid_argument("XDMF particles: negative particle count");
    const std::string h5 = relativeH5(xmfPath, step.h5File);
    const auto n = static_cast<std::uint64_t>(step.count);
    out << "      <Grid Name=\"" << stepName(step.group, s) << "\" GridType=\"Uniform\">\n"
        << in << "  <Time Value=\"" << number(step.time) << "\"/>\n"
        << in << "  <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
        << "\" NodesPerElement=\"1\"/>\n"
        << in << "  <Geometry GeometryType=\"" << (step.dim == 2 ? "XY" : "XYZ") << "\">\n";
    dataItem(out, in + "    ", {n, static_cast<std::uint64_t>(step.dim)}, step.positionNumber, h5,
             datasetPath(step.group, step.position));
    out << in << "  </Geometry>\n";
    for (const XdmfAttribute& a : step.attributes) {
      std::vector<std::uint64_t> dims{n};
      if (a.components > 1)
        dims.push_back(static_cast<std::uint64_t>(a.components));
      attribute(out, in + "  ", a, "Node", dims, h5, step.group);
    }
    out << "      </Grid>\n";
  }
  footer(out, true);
  return out.str();
}

std::vector<std::uint64_t> xdmfAttributeDims(const XdmfGridStep& step, const XdmfAttribute& a) {
  std::vector<std::uint64_t> dims;
  if (step.dim == 3)
    dims.push_back(static_cast<std::uint64_t>(step.cells[2]));
  dims.push_back(static_cast<std::uint64_t>(step.cells[1]));
  dims.push_back(static_cast<std::uint64_t>(step.cells[0]));
  if (a.components > 1)
    dims.push_back(static_cast<std::uint64_t>(a.components));
  return dims;
}

std::string xdmfGridsText(const std::string& xmfPath, const std::vector<XdmfGridStep>& steps) {
  const bool collection = steps.size() != 1;
  std::ostringstream out;
  header(out, "fields", collection);
  const std::string in = collection ? "      " : "    ";
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const XdmfGridStep& step = steps[s];
    if (step.dim != 2 && step.dim != 3)
      throw std::invalid_argument("XDMF grid: dim must be 2 or 3");
    for (int d = 0; d < step.dim; ++d)
      if (step.cells[d] < 1)
        throw std::invalid_argument("XDMF grid: every direction needs at least one cell");
    const std::string h5 = relativeH5(xmfPath, step.h5File);
    // XDMF lists node counts, origin and spacing slowest axis first: z y x.
    const bool flat = step.dim == 2;
    const std::string nodes = std::to_string(flat ? 1 : step.cells[2] + 1) + " " +
                              std::to_string(step.cells[1] + 1) + " " +
                              std::to_string(step.cells[0] + 1);
    const double dz = flat ? 1.0 : step.spacing[2];
    out << in << "<Grid Name=\"" << stepName(step.group, s) << "\" GridType=\"Uniform\">\n"
        << in << "  <Time Value=\"" << number(step.time) << "\"/>\n"
        << in << "  <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << nodes << "\"/>\n"
        << in << "  <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
        << in << "    <DataItem Name=\"Origin\" Dimensions=\"3\" NumberType=\"Float\" "
        << "Precision=\"8\" Format=\"XML\">" << number(step.origin[2]) << " "
        << number(step.origin[1]) << " " << number(step.origin[0]) << "</DataItem>\n"
        << in << "    <DataItem Name=\"Spacing\" Dimensions=\"3\" NumberType=\"Float\" "
        << "Precision=\"8\" Format=\"XML\">" << number(dz) << " " << number(step.spacing[1]) << " "
        << number(step.spacing[0]) << "</DataItem>\n"
        << in << "  </Geometry>\n";
    for (const XdmfAttribute& a : step.attributes)
      attribute(out, in + "  ", a, "Cell", xdmfAttributeDims(step, a), h5, step.group);
    out << in << "</Grid>\n";
  }
  footer(out, collection);
  return out.str();
}

void writeXdmfParticles(const std::string& xmfPath, const std::vector<XdmfParticleStep>& steps) {
  writeTextAtomically(xmfPath, xdmfParticlesText(xmfPath, steps));
}

void writeXdmfGrids(const std::string& xmfPath, const std::vector<XdmfGridStep>& steps) {
  writeTextAtomically(xmfPath, xdmfGridsText(xmfPath, steps));
}

} // namespace hikiln::io
