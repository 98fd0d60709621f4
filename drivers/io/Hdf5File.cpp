#include "drivers/io/Hdf5File.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace hikiln::io {

namespace {
hid_t memoryType(H5Element element) {
  switch (element) {
  case H5Element::Float64:
    return H5T_NATIVE_DOUBLE;
  case H5Element::Float32:
    return H5T_NATIVE_FLOAT;
  case H5Element::Int32:
    return H5T_NATIVE_INT32;
  case H5Element::Int64:
    return H5T_NATIVE_INT64;
  case H5Element::UInt8:
    return H5T_NATIVE_UINT8;
  }
  return H5I_INVALID_HID;
}

// Files are always little-endian IEEE / two's complement, whatever the writing machine is.
hid_t fileType(H5Element element) {
  switch (element) {
  case H5Element::Float64:
    return H5T_IEEE_F64LE;
  case H5Element::Float32:
    return H5T_IEEE_F32LE;
  case H5Element::Int32:
    return H5T_STD_I32LE;
  case H5Element::Int64:
    return H5T_STD_I64LE;
  case H5Element::UInt8:
    return H5T_STD_U8LE;
  }
  return H5I_INVALID_HID;
}

const char* elementName(H5Element element) {
  switch (element) {
  case H5Element::Float64:
    return "float64";
  case H5Element::Float32:
    return "float32";
  case H5Element::Int32:
    return "int32";
  case H5Element::Int64:
    return "int64";
  case H5Element::UInt8:
    return "uint8";
  }
  return "?";
}

// True when every value of the stored type fits the requested one (no silent narrowing).
bool readableWithoutLoss(hid_t stored, H5Element wanted) {
  const H5T_class_t storedClass = H5Tget_class(stored);
  const std::size_t storedSize = H5Tget_size(stored);
  const std::size_t wantedSize = H5Tget_size(memoryType(wanted));
  const bool wantFloat = wanted == H5Element::Float64 || wanted == H5Element::Float32;
  if (wantFloat)
    return storedClass == H5T_FLOAT && storedSize <= wantedSize;
  if (storedClass != H5T_INTEGER || storedSize > wantedSize)
    return false;
  const bool storedSigned = H5Tget_sign(stored) == H5T_SGN_2;
  const bool wantSigned = wanted != H5Element::UInt8;
  if (storedSigned)
    return wantSigned;
  return !wantSigned || storedSize < wantedSize;
}

H5Handle makeDataspace(const std::vector<hsize_t>& dims) {
  if (dims.empty())
    return H5Handle(H5Screate(H5S_SCALAR), H5Sclose);
  return H5Handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
}

// Chunks of about 256 Ki elements, cut across the slowest dimensions.
std::vector<hsize_t> chunkShape(const std::vector<hsize_t>& dims) {
  std::vector<hsize_t> chunk(dims.size(), 1);
  hsize_t room = hsize_t(1) << 18;
  for (std::size_t i = dims.size(); i-- > 0;) {
    chunk[i] = std::max<hsize_t>(1, std::min(dims[i], room));
    room = std::max<hsize_t>(1, room / chunk[i]);
  }
  return chunk;
}
} // namespace

std::uint64_t elementCount(const std::vector<hsize_t>& dims) {
  std::uint64_t count = 1;
  for (hsize_t d : dims)
    count *= d;
  return count;
}

std::string stepGroupName(std::int64_t step) {
  char name[40];
  std::snprintf(name, sizeof(name), "/step_%06lld", static_cast<long long>(step));
  return name;
}

H5File::H5File(std::string path, H5Handle file, std::unique_ptr<AtomicFile> atomic)
    : _path(std::move(path)), _atomic(std::move(atomic)), _file(std::move(file)) {}

H5File::H5File(H5File&& other) noexcept = default;

H5File& H5File::operator=(H5File&& other) noexcept {
  if (this != &other) {
    _file.reset(); // close before the temporary it may live in is removed
    _atomic = std::move(other._atomic);
    _file = std::move(other._file);
    _path = std::move(other._path);
  }
  return *this;
}

H5File::~H5File() {
  _file.reset();
  _atomic.reset();
}

H5File H5File::create(const std::string& path) {
  silenceHdf5Errors();
  auto atomic = std::make_unique<AtomicFile>(path);
  // Strong close: closing the file also closes anything left open in it.
  H5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  checkHdf5Id(access.get(), path, "", "cannot create file access properties");
  H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG);
  H5Handle file(
      H5Fcreate(atomic->temporaryPath().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()),
      H5Fclose);
  checkHdf5Id(file.get(), path, "",
              "cannot create file (temporary " + atomic->temporaryPath() + ")");
  return H5File(path, std::move(file), std::move(atomic));
}

H5File H5File::openRead(const std::string& path) {
  silenceHdf5Errors();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw std::runtime_error("cannot open HDF5 file '" + path + "': no such file");
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    H5Eclear2(H5E_DEFAULT);
    throw std::runtime_error("cannot open '" + path + "': not an HDF5 file");
  }
  H5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  checkHdf5Id(access.get(), path, "", "cannot create file access properties");
  H5Pset_fclose_degree(access.get(), H5F_CLOSE_STRONG);
  H5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()), H5Fclose);
  checkHdf5Id(file.get(), path, "", "cannot open file for reading");
  return H5File(path, std::move(file), nullptr);
}

void H5File::commit() {
  requireWritable("");
  checkHdf5Status(H5Fflush(_file.get(), H5F_SCOPE_LOCAL), _path, "", "cannot flush file");
  checkHdf5Status(_file.reset(), _path, "", "cannot close file");
  _atomic->commit();
  _atomic.reset();
}

hid_t H5File::id(const std::string& object) const {
  if (!_file.valid())
    throw std::runtime_error("HDF5 file '" + _path + "' is closed (accessing '" + object + "')");
  return _file.get();
}

void H5File::requireWritable(const std::string& object) const {
  id(object);
  if (_atomic == nullptr)
    throw std::runtime_error("HDF5 file '" + _path + "' is open read-only (writing '" + object +
                             "')");
}

H5Handle H5File::openObject(const std::string& object) const {
  const hid_t file = id(object);
  if (!exists(object))
    throw std::runtime_error("HDF5 file '" + _path + "' has no object '" + object + "'");
  H5Handle handle(H5Oopen(file, object.c_str(), H5P_DEFAULT), H5Oclose);
  checkHdf5Id(handle.get(), _path, object, "cannot open object");
  return handle;
}

void H5File::writeRaw(const std::string& name, const void* data, const std::vector<hsize_t>& dims,
                      H5Element element, const std::string& units, const H5WriteOptions& options) {
  requireWritable(name);
  if (name.empty() || name.back() == '/')
    throw std::runtime_error("HDF5 file '" + _path + "': invalid dataset name '" + name + "'");
  if (exists(name))
    throw std::runtime_error("HDF5 file '" + _path + "' already has '" + name + "'");
  const std::uint64_t count = elementCount(dims);
  if (data == nullptr && count > 0)
    throw std::runtime_error("writing '" + name + "' to '" + _path + "': no data");

  H5Handle space = makeDataspace(dims);
  checkHdf5Id(space.get(), _path, name, "cannot create dataspace");
  H5Handle links = parentsCreatingLinkList();
  checkHdf5Id(links.get(), _path, name, "cannot create link properties");
  H5Handle creation(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  checkHdf5Id(creation.get(), _path, name, "cannot create dataset properties");
  if (options.gzipLevel > 0 && count > 0 && !dims.empty()) {
    if (H5Zfilter_avail(H5Z_FILTER_DEFLATE) <= 0)
      throw std::runtime_error("writing '" + name + "' to '" + _path + "': no gzip in HDF5");
    const std::vector<hsize_t> chunk = chunkShape(dims);
    checkHdf5Status(H5Pset_chunk(creation.get(), static_cast<int>(chunk.size()), chunk.data()),
                    _path, name, "cannot set chunking");
    checkHdf5Status(H5Pset_deflate(creation.get(), static_cast<unsigned>(options.gzipLevel)), _path,
                    name, "cannot set gzip level");
  }
  H5Handle dataset(H5Dcreate2(_file.get(), name.c_str(), fileType(element), space.get(),
                              links.get(), creation.get(), H5P_DEFAULT),
                   H5Dclose);
  checkHdf5Id(dataset.get(), _path, name, "cannot create dataset");
  if (count > 0) {
    checkHdf5Status(
        H5Dwrite(dataset.get(), memoryType(element), H5S_ALL, H5S_ALL, H5P_DEFAULT, data), _path,
        name, "cannot write dataset");
  }
  dataset.reset();
  if (!units.empty())
    setUnits(name, units);
}

std::vector<hsize_t> H5File::datasetDims(const std::string& name) const {
  const hid_t file = id(name);
  if (!isDataset(name))
    throw std::runtime_error("HDF5 file '" + _path + "' has no dataset '" + name + "'");
  H5Handle dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
  checkHdf5Id(dataset.get(), _path, name, "cannot open dataset");
  H5Handle space(H5Dget_space(dataset.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(checkHdf5Id(space.get(), _path, name, "no space"));
  if (rank < 0)
    throwHdf5Error(_path, name, "cannot read dataset shape");
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    throwHdf5Error(_path, name, "cannot read dataset shape");
  return dims;
}

void H5File::readRaw(const std::string& name, void* data, std::size_t count,
                     H5Element element) const {
  const hid_t file = id(name);
  H5Handle dataset(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose);
  checkHdf5Id(dataset.get(), _path, name, "cannot open dataset");
  H5Handle stored(H5Dget_type(dataset.get()), H5Tclose);
  checkHdf5Id(stored.get(), _path, name, "cannot read dataset type");
  if (!readableWithoutLoss(stored.get(), element))
    throw std::runtime_error("HDF5 file '" + _path + "': dataset '" + name +
                             "' cannot be read as " + elementName(element) + " without loss");
  H5Handle space(H5Dget_space(dataset.get()), H5Sclose);
  const hssize_t points = H5Sget_simple_extent_npoints(space.get());
  if (points < 0 || static_cast<std::size_t>(points) != count)
    throw std::runtime_error("HDF5 file '" + _path + "': dataset '" + name + "' changed size");
  if (count > 0) {
    checkHdf5Status(
        H5Dread(dataset.get(), memoryType(element), H5S_ALL, H5S_ALL, H5P_DEFAULT, data), _path,
        name, "cannot read dataset");
  }
}

} // namespace hikiln::io
