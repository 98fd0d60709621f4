// Attribute half of H5File, plus the provenance attributes every hikiln output file carries.
#include "drivers/io/Hdf5File.hpp"

#include "kernels/common/Compat.hpp"

#include <ctime>

namespace hikiln::io {

namespace {
// Variable-length UTF-8: no size limit in the object header, and h5py reads it as str.
H5Handle stringType() {
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (type.valid()) {
    H5Tset_size(type.get(), H5T_VARIABLE);
    H5Tset_cset(type.get(), H5T_CSET_UTF8);
  }
  return type;
}

hssize_t attributePoints(hid_t attribute) {
  H5Handle space(H5Aget_space(attribute), H5Sclose);
  if (!space.valid())
    return -1;
  if (H5Sget_simple_extent_type(space.get()) == H5S_NULL)
    return 0;
  return H5Sget_simple_extent_npoints(space.get());
}

herr_t collectName(hid_t, const char* name, const H5A_info_t*, void* data) {
  static_cast<std::vector<std::string>*>(data)->emplace_back(name);
  return 0;
}
} // namespace

H5Handle H5File::openAttribute(const std::string& object, const std::string& name) const {
  if (!hasAttribute(object, name))
    throw std::runtime_error("HDF5 file '" + _path + "': '" + object + "' has no attribute '" +
                             name + "'");
  H5Handle attribute(
      H5Aopen_by_name(id(object), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  checkHdf5Id(attribute.get(), _path, object + "@" + name, "cannot open attribute");
  return attribute;
}

namespace {
// Creates (replacing) attribute `name` on `owner` and writes `data` unless the space is empty.
void putAttribute(hid_t owner, const std::string& file, const std::string& object,
                  const std::string& name, hid_t fileTypeId, hid_t memoryTypeId, hid_t space,
                  const void* data) {
  const std::string where = object + "@" + name;
  if (H5Aexists(owner, name.c_str()) > 0)
    checkHdf5Status(H5Adelete(owner, name.c_str()), file, where, "cannot replace attribute");
  H5Handle attribute(H5Acreate2(owner, name.c_str(), fileTypeId, space, H5P_DEFAULT, H5P_DEFAULT),
                     H5Aclose);
  checkHdf5Id(attribute.get(), file, where, "cannot create attribute");
  if (H5Sget_simple_extent_type(space) != H5S_NULL)
    checkHdf5Status(H5Awrite(attribute.get(), memoryTypeId, data), file, where,
                    "cannot write attribute");
}
} // namespace

void H5File::setAttribute(const std::string& object, const std::string& name,
                          const std::string& value) {
  requireWritable(object);
  H5Handle owner = openObject(object);
  H5Handle type = stringType();
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const char* text = value.c_str();
  putAttribute(owner.get(), _path, object, name, type.get(), type.get(), space.get(), &text);
}

void H5File::setAttribute(const std::string& object, const std::string& name, double value) {
  requireWritable(object);
  H5Handle owner = openObject(object);
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  putAttribute(owner.get(), _path, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(),
               &value);
}

void H5File::setAttribute(const std::string& object, const std::string& name, std::int64_t value) {
  requireWritable(object);
  H5Handle owner = openObject(object);
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  putAttribute(owner.get(), _path, object, name, H5T_STD_I64LE, H5T_NATIVE_INT64, space.get(),
               &value);
}

void H5File::setAttribute(const std::string& object, const std::string& name,
                          const std::vector<double>& value) {
  requireWritable(object);
  H5Handle owner = openObject(object);
  const hsize_t size = value.size();
  // A zero-length simple dataspace is not allowed for attributes; the null dataspace is.
  H5Handle space(size == 0 ? H5Screate(H5S_NULL) : H5Screate_simple(1, &size, nullptr), H5Sclose);
  putAttribute(owner.get(), _path, object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(),
               value.data());
}

bool H5File::hasAttribute(const std::string& object, const std::string& name) const {
  if (!exists(object))
    return false;
  const htri_t found = H5Aexists_by_name(id(object), object.c_str(), name.c_str(), H5P_DEFAULT);
  if (found < 0)
    throwHdf5Error(_path, object + "@" + name, "cannot look up attribute");
  return found > 0;
}

std::vector<std::string> H5File::attributeNames(const std::string& object) const {
  H5Handle owner = openObject(object);
  std::vector<std::string> names;
  hsize_t index = 0;
  checkHdf5Status(H5Aiterate2(owner.get(), H5_INDEX_NAME, H5_ITER_INC, &index, collectName, &names),
                  _path, object, "cannot list attributes");
  return names;
}

std::string H5File::readStringAttribute(const std::string& object, const std::string& name) const {
  H5Handle attribute = openAttribute(object, name);
  const std::string where = object + "@" + name;
  H5Handle type(H5Aget_type(attribute.get()), H5Tclose);
  checkHdf5Id(type.get(), _path, where, "cannot read attribute type");
  if (H5Tget_class(type.get()) != H5T_STRING || attributePoints(attribute.get()) != 1)
    throw std::runtime_error("HDF5 file '" + _path + "': attribute '" + where +
                             "' is not a single string");
  if (H5Tis_variable_str(type.get()) > 0) {
    H5Handle memory = stringType();
    char* text = nullptr;
    checkHdf5Status(H5Aread(attribute.get(), memory.get(), &text), _path, where,
                    "cannot read attribute");
    std::string value = text != nullptr ? text : "";
    H5free_memory(text);
    return value;
  }
  std::string value(H5Tget_size(type.get()), '\0');
  checkHdf5Status(H5Aread(attribute.get(), type.get(), value.data()), _path, where,
                  "cannot read attribute");
  value.resize(std::min(value.size(), value.find('\0'))); // fixed-length strings may be padded
  return value;
}

std::vector<double> H5File::readDoubleVectorAttribute(const std::string& object,
                                                      const std::string& name) const {
  H5Handle attribute = openAttribute(object, name);
  const std::string where = object + "@" + name;
  H5Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_FLOAT)
    throw std::runtime_error("HDF5 file '" + _path + "': attribute '" + where +
                             "' is not floating point");
  const hssize_t points = attributePoints(attribute.get());
  if (points < 0)
    throwHdf5Error(_path, where, "cannot read attribute shape");
  std::vector<double> values(static_cast<std::size_t>(points));
  if (points > 0)
    checkHdf5Status(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, values.data()), _path, where,
                    "cannot read attribute");
  return values;
}

double H5File::readDoubleAttribute(const std::string& object, const std::string& name) const {
  const std::vector<double> values = readDoubleVectorAttribute(object, name);
  if (values.size() != 1)
    throw std::runtime_error("HDF5 file '" + _path + "': attribute '" + object + "@" + name +
                             "' is not a single number");
  return values[0];
}

std::int64_t H5File::readInt64Attribute(const std::string& object, const std::string& name) const {
  H5Handle attribute = openAttribute(object, name);
  const std::string where = object + "@" + name;
  H5Handle type(H5Aget_type(attribute.get()), H5Tclose);
  const bool integer = H5Tget_class(type.get()) == H5T_INTEGER;
  const bool fits = H5Tget_size(type.get()) < 8 || H5Tget_sign(type.get()) == H5T_SGN_2;
  if (!integer || !fits || attributePoints(attribute.get()) != 1)
    throw std::runtime_error("HDF5 file '" + _path + "': attribute '" + where +
                             "' is not a single int64");
  std::int64_t value = 0;
  checkHdf5Status(H5Aread(attribute.get(), H5T_NATIVE_INT64, &value), _path, where,
                  "cannot read attribute");
  return value;
}

std::string H5File::units(const std::string& dataset) const {
  return hasAttribute(dataset, "units") ? readStringAttribute(dataset, "units") : std::string();
}

std::string utcTimestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

void writeStandardAttributes(H5File& file, const RunInfo& info) {
  file.setAttribute("/", "hikiln_version", HIKILN_VERSION);
  file.setAttribute("/", "kokkos_version", kokkosVersionString());
  file.setAttribute("/", "backend", info.backend);
  file.setAttribute("/", "stage", info.stage);
  file.setAttribute("/", "created", utcTimestamp());
  file.setAttribute("/", "resolved_case", info.resolvedCaseYaml);
}

} // namespace hikiln::io
