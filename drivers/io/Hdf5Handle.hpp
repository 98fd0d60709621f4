#pragma once
/// \file Hdf5Handle.hpp
/// \brief Owning wrapper for HDF5 C API identifiers and the error helpers hikiln's HDF5 code
/// shares: every failure becomes a std::runtime_error naming the file and the object.

#include <hdf5.h>

#include <string>

namespace hikiln::io {

/// \brief Owns one HDF5 identifier (file, group, dataset, dataspace, datatype, attribute,
/// property list) and closes it with the matching H5?close function. Move-only.
class H5Handle {
public:
  /// \brief Function that releases an identifier (H5Fclose, H5Dclose, ...).
  using Closer = herr_t (*)(hid_t);

  /// \brief An empty handle that owns nothing.
  H5Handle() = default;
  /// \brief Takes ownership of `id`; a negative id is kept as "invalid" and never closed.
  H5Handle(hid_t id, Closer closer) : _id(id), _closer(closer) {}
  ~H5Handle() { reset(); }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  /// \brief Transfers ownership; the source becomes empty.
  H5Handle(H5Handle&& other) noexcept : _id(other._id), _closer(other._closer) {
    other._id = H5I_INVALID_HID;
  }
  /// \brief Closes the current identifier, then takes ownership of `other`'s.
  H5Handle& operator=(H5Handle&& other) noexcept;

  /// \brief The raw identifier for C API calls (H5I_INVALID_HID when empty).
  hid_t get() const { return _id; }
  /// \brief True when an identifier is owned.
  bool valid() const { return _id >= 0; }
  /// \brief Closes the identifier now; returns the closer's status (0 when nothing was owned).
  herr_t reset();

private:
  hid_t _id = H5I_INVALID_HID;
  Closer _closer = nullptr;
};

/// \brief Link-creation property list that creates missing parent groups of a new object.
H5Handle parentsCreatingLinkList();

/// \brief Turns off HDF5's automatic printing of error stacks to stderr (hikiln reports errors
/// through exceptions instead). Idempotent; called by every H5File factory.
void silenceHdf5Errors();

/// \brief The innermost message of the current HDF5 error stack, or "" when it is empty.
std::string hdf5ErrorDetail();

/// \brief Throws std::runtime_error "HDF5 error in <file> at <object>: <what> (<detail>)", where
/// detail comes from the HDF5 error stack.
[[noreturn]] void throwHdf5Error(const std::string& file, const std::string& object,
                                 const std::string& what);

/// \brief Returns `id` if it is valid, otherwise throws via throwHdf5Error.
hid_t checkHdf5Id(hid_t id, const std::string& file, const std::string& object,
                  const std::string& what);

/// \brief Throws via throwHdf5Error if `status` is negative.
void checkHdf5Status(herr_t status, const std::string& file, const std::string& object,
                     const std::string& what);

} // namespace hikiln::io
