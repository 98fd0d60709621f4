#pragma once
/// \file Hdf5File.hpp
/// \brief An HDF5 file as hikiln uses it: whole n-dimensional datasets of a few numeric types,
/// addressed by path ("/step_000010/position"), with string/number attributes. New files are
/// written to a temporary sibling and appear at their path only on commit().

#include "drivers/io/AtomicFile.hpp"
#include "drivers/io/Hdf5Handle.hpp"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace hikiln::io {

/// \brief Element types a dataset may hold.
enum class H5Element { Float64, Float32, Int32, Int64, UInt8 };

/// \brief Maps a C++ element type to its H5Element; only the five supported types compile.
template <class T> struct H5ElementOf;
template <> struct H5ElementOf<double> { static constexpr H5Element value = H5Element::Float64; };
template <> struct H5ElementOf<float> { static constexpr H5Element value = H5Element::Float32; };
template <> struct H5ElementOf<std::int32_t> {
  static constexpr H5Element value = H5Element::Int32;
};
template <> struct H5ElementOf<std::int64_t> {
  static constexpr H5Element value = H5Element::Int64;
};
template <> struct H5ElementOf<std::uint8_t> {
  static constexpr H5Element value = H5Element::UInt8;
};

/// \brief How a dataset is stored. The default is contiguous and uncompressed.
struct H5WriteOptions {
  /// \brief 1..9 enables chunked gzip (deflate) storage at that level; 0 stores uncompressed.
  int gzipLevel = 0;
};

/// \brief Number of elements described by `dims` (1 for a scalar, i.e. empty dims).
std::uint64_t elementCount(const std::vector<hsize_t>& dims);

/// \brief Conventional group name for output step `step`: "/step_000010".
std::string stepGroupName(std::int64_t step);

/// \brief One open HDF5 file; closes it in the destructor. Move-only.
class H5File {
public:
  /// \brief Starts a new file that will replace `path` on commit(); until then it lives in a
  /// hidden temporary next to `path`, which is removed if this object dies uncommitted.
  static H5File create(const std::string& path);
  /// \brief Opens an existing file read-only; throws naming `path` if it is missing or not HDF5.
  static H5File openRead(const std::string& path);

  H5File(H5File&&) noexcept;
  H5File& operator=(H5File&&) noexcept;
  H5File(const H5File&) = delete;
  H5File& operator=(const H5File&) = delete;
  ~H5File();

  /// \brief The file's final path (not the temporary).
  const std::string& path() const { return _path; }
  /// \brief True for files from create() that are not yet committed.
  bool writable() const { return _atomic != nullptr && _file.valid(); }
  /// \brief Closes the file (flushing everything) and renames it into place. The object is
  /// closed afterwards; any further use throws.
  void commit();

  /// \brief Writes a whole dataset of shape `dims` (row-major, last index fastest) from `data`,
  /// creating missing parent groups. A non-empty `units` is stored as a "units" attribute.
  template <class T>
  void writeDataset(const std::string& name, const T* data, const std::vector<hsize_t>& dims,
                    const std::string& units = "", const H5WriteOptions& options = {}) {
    writeRaw(name, data, dims, H5ElementOf<T>::value, units, options);
  }
  /// \brief As above from a vector, whose size must equal the product of `dims`.
  template <class T>
  void writeDataset(const std::string& name, const std::vector<T>& data,
                    const std::vector<hsize_t>& dims, const std::string& units = "",
                    const H5WriteOptions& options = {}) {
    if (data.size() != elementCount(dims))
      throw std::runtime_error("writing '" + name + "' to '" + _path + "': " +
                               std::to_string(data.size()) + " values do not fill the shape");
    writeRaw(name, data.data(), dims, H5ElementOf<T>::value, units, options);
  }
  /// \brief Writes a one-dimensional dataset holding all of `data`.
  template <class T> void writeDataset(const std::string& name, const std::vector<T>& data) {
    writeDataset(name, data, {static_cast<hsize_t>(data.size())});
  }

  /// \brief Reads a whole dataset converted to T; its shape goes to `*dims` when given. Throws
  /// if the dataset is missing or its stored type cannot be read as T without loss.
  template <class T>
  std::vector<T> readDataset(const std::string& name, std::vector<hsize_t>* dims = nullptr) const {
    const std::vector<hsize_t> shape = datasetDims(name);
    std::vector<T> values(static_cast<std::size_t>(elementCount(shape)));
    readRaw(name, values.data(), values.size(), H5ElementOf<T>::value);
    if (dims != nullptr)
      *dims = shape;
    return values;
  }
  /// \brief Shape of dataset `name` (empty for a scalar dataset).
  std::vector<hsize_t> datasetDims(const std::string& name) const;

  /// \brief Creates group `path` and any missing parents; existing groups are left alone.
  void createGroup(const std::string& path);
  /// \brief True when every component of `path` exists ("/" always does).
  bool exists(const std::string& path) const;
  /// \brief True when `path` exists and is a dataset.
  bool isDataset(const std::string& path) const;
  /// \brief Names (not paths) of the members of group `group`, sorted by name.
  std::vector<std::string> children(const std::string& group = "/") const;

  /// \brief Sets a string attribute on the object at `object` ("/" is the file root),
  /// replacing any attribute of the same name.
  void setAttribute(const std::string& object, const std::string& name, const std::string& value);
  /// \brief Overload so string literals do not select the bool-like numeric overloads.
  void setAttribute(const std::string& object, const std::string& name, const char* value) {
    setAttribute(object, name, std::string(value));
  }
  /// \brief Sets a double attribute.
  void setAttribute(const std::string& object, const std::string& name, double value);
  /// \brief Sets a 64-bit integer attribute.
  void setAttribute(const std::string& object, const std::string& name, std::int64_t value);
  /// \brief Sets a one-dimensional double array attribute (may be empty).
  void setAttribute(const std::string& object, const std::string& name,
                    const std::vector<double>& value);
  /// \brief Sets the "units" attribute of a dataset (SI spelling, e.g. "m/s").
  void setUnits(const std::string& dataset, const std::string& units) {
    setAttribute(dataset, "units", units);
  }

  /// \brief True when the object at `object` exists and has attribute `name`.
  bool hasAttribute(const std::string& object, const std::string& name) const;
  /// \brief Names of the attributes of `object`, in creation/name order.
  std::vector<std::string> attributeNames(const std::string& object) const;
  /// \brief Reads a string attribute (fixed or variable length).
  std::string readStringAttribute(const std::string& object, const std::string& name) const;
  /// \brief Reads a scalar floating-point attribute.
  double readDoubleAttribute(const std::string& object, const std::string& name) const;
  /// \brief Reads a scalar integer attribute.
  std::int64_t readInt64Attribute(const std::string& object, const std::string& name) const;
  /// \brief Reads a floating-point array attribute (a scalar reads as one value).
  std::vector<double> readDoubleVectorAttribute(const std::string& object,
                                                const std::string& name) const;
  /// \brief The "units" attribute of a dataset, or "" when it has none.
  std::string units(const std::string& dataset) const;

private:
  H5File(std::string path, H5Handle file, std::unique_ptr<AtomicFile> atomic);
  hid_t id(const std::string& object) const;
  void requireWritable(const std::string& object) const;
  H5Handle openObject(const std::string& object) const;
  H5Handle openAttribute(const std::string& object, const std::string& name) const;
  void writeRaw(const std::string& name, const void* data, const std::vector<hsize_t>& dims,
                H5Element element, const std::string& units, const H5WriteOptions& options);
  void readRaw(const std::string& name, void* data, std::size_t count, H5Element element) const;

  std::string _path;
  std::unique_ptr<AtomicFile> _atomic; ///< set for files from create() until commit()
  H5Handle _file;                      ///< declared after _atomic: closed before its cleanup
};

/// \brief Provenance written on the root of every file a stage produces.
struct RunInfo {
  std::string stage;            ///< e.g. "dem", "coarse-grain", "cfd"
  std::string backend;          ///< Kokkos execution space name
  std::string resolvedCaseYaml; ///< the fully resolved case file
};

/// \brief Writes root attributes hikiln_version, kokkos_version, backend, stage, created (UTC,
/// ISO 8601) and resolved_case.
void writeStandardAttributes(H5File& file, const RunInfo& info);

/// \brief Current UTC time as "YYYY-MM-DDThh:mm:ssZ".
std::string utcTimestamp();

} // namespace hikiln::io
