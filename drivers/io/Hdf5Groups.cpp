// Navigation half of H5File: groups, existence tests and listings.
#include "drivers/io/Hdf5File.hpp"

#include <algorithm>

namespace hikiln::io {

void H5File::createGroup(const std::string& path) {
  requireWritable(path);
  if (exists(path)) {
    H5Handle object = openObject(path);
    if (H5Iget_type(object.get()) != H5I_GROUP)
      throw std::runtime_error("HDF5 file '" + _path + "': '" + path + "' is not a group");
    return;
  }
  H5Handle links = parentsCreatingLinkList();
  H5Handle group(H5Gcreate2(_file.get(), path.c_str(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
                 H5Gclose);
  checkHdf5Id(group.get(), _path, path, "cannot create group");
}

bool H5File::exists(const std::string& path) const {
  const hid_t file = id(path);
  // H5Lexists fails on a missing parent, so test each prefix in turn.
  std::string prefix;
  std::size_t start = 0;
  while (start <= path.size()) {
    const std::size_t slash = std::min(path.find('/', start), path.size());
    const std::string part = path.substr(start, slash - start);
    if (!part.empty() && part != ".") {
      prefix += "/" + part;
      if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0) {
        H5Eclear2(H5E_DEFAULT);
        return false;
      }
    }
    start = slash + 1;
  }
  return !path.empty();
}

bool H5File::isDataset(const std::string& path) const {
  if (!exists(path))
    return false;
  H5Handle object(H5Oopen(id(path), path.c_str(), H5P_DEFAULT), H5Oclose);
  return object.valid() && H5Iget_type(object.get()) == H5I_DATASET;
}

std::vector<std::string> H5File::children(const std::string& group) const {
  H5Handle object = openObject(group);
  if (H5Iget_type(object.get()) != H5I_GROUP)
    throw std::runtime_error("HDF5 file '" + _path + "': '" + group + "' is not a group");
  H5G_info_t info;
  checkHdf5Status(H5Gget_info(object.get(), &info), _path, group, "cannot list group");
  std::vector<std::string> names;
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const ssize_t length = H5Lget_name_by_idx(object.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i,
                                              nullptr, 0, H5P_DEFAULT);
    if (length < 0)
      throwHdf5Error(_path, group, "cannot read member name");
    std::string name(static_cast<std::size_t>(length) + 1, '\0');
    H5Lget_name_by_idx(object.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(length));
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

} // namespace hikiln::io
