#include "drivers/io/Hdf5Handle.hpp"

#include <stdexcept>

namespace hikiln::io {

H5Handle& H5Handle::operator=(H5Handle&& other) noexcept {
  if (this != &other) {
    reset();
    _id = other._id;
    _closer = other._closer;
    other._id = H5I_INVALID_HID;
  }
  return *this;
}

herr_t H5Handle::reset() {
  herr_t status = 0;
  if (_id >= 0 && _closer != nullptr)
    status = _closer(_id);
  _id = H5I_INVALID_HID;
  return status;
}

H5Handle parentsCreatingLinkList() {
  H5Handle list(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  if (list.valid())
    H5Pset_create_intermediate_group(list.get(), 1);
  return list;
}

void silenceHdf5Errors() {
  // Per-thread state in thread-safe HDF5 builds, so set it on every entry rather than once.
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

namespace {
herr_t keepInnermost(unsigned depth, const H5E_error2_t* error, void* data) {
  // Walking downward, depth 0 is the API call and the last entry is where the error arose.
  auto* out = static_cast<std::string*>(data);
  if (error->desc != nullptr && error->desc[0] != '\0') {
    const std::string where = error->func_name != nullptr ? error->func_name : "";
    *out = where.empty() ? error->desc : where + ": " + error->desc;
  }
  (void)depth;
  return 0;
}
} // namespace

std::string hdf5ErrorDetail() {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, keepInnermost, &detail);
  H5Eclear2(H5E_DEFAULT);
  return detail;
}

void throwHdf5Error(const std::string& file, const std::string& object, const std::string& what) {
  const std::string detail = hdf5ErrorDetail();
  std::string message = "HDF5 error in '" + file + "'";
  if (!object.empty())
    message += " at '" + object + "'";
  message += ": " + what;
  if (!detail.empty())
    message += " (" + detail + ")";
  throw std::runtime_error(message);
}

hid_t checkHdf5Id(hid_t id, const std::string& file, const std::string& object,
                  const std::string& what) {
  if (id < 0)
    throwHdf5Error(file, object, what);
  return id;
}

void checkHdf5Status(herr_t status, const std::string& file, const std::string& object,
                     const std::string& what) {
  if (status < 0)
    throwHdf5Error(file, object, what);
}

} // namespace hikiln::io
