#pragma once
/// \file Xdmf.hpp
/// \brief XDMF sidecar files (.xmf) so that ParaView/VisIt open hikiln's HDF5 output: particle
/// snapshots as Polyvertex grids and structured fields as uniform (CoRectMesh) grids, each as a
/// temporal collection. The .xmf holds only light metadata and "file.h5:/path" references.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace hikiln::io {

/// \brief Element type of a referenced dataset, as XDMF spells it (NumberType + Precision).
enum class XdmfNumber { Float64, Float32, Int32, Int64, UInt8 };

/// \brief One array shown on a grid: a scalar (components = 1), a 3-vector (components = 3) or
/// any other per-item tuple (written as XDMF "Matrix", which ParaView reads with that many
/// components; 2-vectors of 2D runs take this path).
struct XdmfAttribute {
  std::string name;    ///< name shown in ParaView
  std::string dataset; ///< dataset relative to the step's group, or an absolute "/..." path
  int components = 1;
  XdmfNumber number = XdmfNumber::Float64;
};

/// \brief One particle snapshot: `count` points whose coordinates are the dataset
/// `group + "/" + position`, of shape count x dim. Attribute datasets have shape count
/// (scalars) or count x components.
struct XdmfParticleStep {
  double time = 0.0;
  std::string h5File; ///< path of the HDF5 file (absolute, or relative to the working directory)
  std::string group;  ///< e.g. stepGroupName(step)
  std::int64_t count = 0;
  int dim = 2; ///< 2 (GeometryType XY) or 3 (XYZ)
  std::string position = "position";
  XdmfNumber positionNumber = XdmfNumber::Float64;
  std::vector<XdmfAttribute> attributes;
};

/// \brief One uniform-grid snapshot with cell-centred attributes. Attribute datasets are in C
/// order with x fastest: shape [ny][nx] in 2D or [nz][ny][nx] in 3D, plus a trailing
/// [components] axis when components > 1.
struct XdmfGridStep {
  double time = 0.0;
  std::string h5File; ///< as in XdmfParticleStep
  std::string group;
  int dim = 2;                            ///< 2 or 3
  std::array<std::int64_t, 3> cells{};    ///< cells along x, y, z (z unused in 2D)
  std::array<double, 3> origin{};         ///< lower corner x, y, z
  std::array<double, 3> spacing{1, 1, 1}; ///< cell size x, y, z
  std::vector<XdmfAttribute> attributes;
};

/// \brief Shape of the HDF5 dataset an attribute of `step` refers to (as the .xmf states it).
std::vector<std::uint64_t> xdmfAttributeDims(const XdmfGridStep& step, const XdmfAttribute& a);

/// \brief XDMF text for a time series of particle snapshots; HDF5 paths in it are written
/// relative to the directory of `xmfPath`.
std::string xdmfParticlesText(const std::string& xmfPath,
                              const std::vector<XdmfParticleStep>& steps);
/// \brief Writes xdmfParticlesText(...) to `xmfPath` atomically.
void writeXdmfParticles(const std::string& xmfPath, const std::vector<XdmfParticleStep>& steps);

/// \brief XDMF text for one or more structured-grid snapshots (several make a temporal
/// collection). 2D grids are written as a one-node-thick 3DCoRectMesh, which ParaView shows as a
/// flat image in the xy plane.
std::string xdmfGridsText(const std::string& xmfPath, const std::vector<XdmfGridStep>& steps);
/// \brief Writes xdmfGridsText(...) to `xmfPath` atomically.
void writeXdmfGrids(const std::string& xmfPath, const std::vector<XdmfGridStep>& steps);

} // namespace hikiln::io
