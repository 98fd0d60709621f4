#include "drivers/io/Checkpoint.hpp"

#include "drivers/io/Hdf5File.hpp"

#include <stdexcept>

namespace hikiln::io {

namespace {
// Layout: root attributes describe the run; /reals, /integers and /scalars hold one dataset per
// map entry (scalars as 0-d datasets), so h5py and h5dump show everything by name.
constexpr const char* formatName = "hikiln-checkpoint";

void checkKey(const std::string& path, const std::string& key) {
  if (key.empty() || key == "." || key.find('/') != std::string::npos)
    throw std::invalid_argument("checkpoint '" + path + "': invalid array name '" + key + "'");
}
} // namespace

void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint) {
  H5File file = H5File::create(path);
  file.setAttribute("/", "format", formatName);
  file.setAttribute("/", "format_version", checkpointFormatVersion);
  file.setAttribute("/", "stage", checkpoint.stage);
  file.setAttribute("/", "step", checkpoint.step);
  file.setAttribute("/", "time", checkpoint.time);
  file.setAttribute("/", "resolved_case", checkpoint.resolvedCaseYaml);
  for (const char* group : {"/reals", "/integers", "/scalars"})
    file.createGroup(group);
  for (const auto& [name, values] : checkpoint.reals) {
    checkKey(path, name);
    file.writeDataset("/reals/" + name, values);
  }
  for (const auto& [name, values] : checkpoint.integers) {
    checkKey(path, name);
    file.writeDataset("/integers/" + name, values);
  }
  for (const auto& [name, value] : checkpoint.scalars) {
    checkKey(path, name);
    file.writeDataset("/scalars/" + name, &value, {});
  }
  file.commit();
}

Checkpoint readCheckpoint(const std::string& path) {
  const H5File file = H5File::openRead(path);
  if (!file.hasAttribute("/", "format") || file.readStringAttribute("/", "format") != formatName)
    throw std::runtime_error("'" + path + "' is not a hikiln checkpoint (no format attribute '" +
                             formatName + "')");
  const std::int64_t version = file.hasAttribute("/", "format_version")
                                   ? file.readInt64Attribute("/", "format_version")
                                   : -1;
  if (version != checkpointFormatVersion)
    throw std::runtime_error("checkpoint '" + path + "' has format version " +
                             std::to_string(version) + "; this hikiln reads version " +
                             std::to_string(checkpointFormatVersion) +
                             " (re-run the stage that wrote it with this build)");
  Checkpoint checkpoint;
  checkpoint.stage = file.readStringAttribute("/", "stage");
  checkpoint.step = file.readInt64Attribute("/", "step");
  checkpoint.time = file.readDoubleAttribute("/", "time");
  checkpoint.resolvedCaseYaml = file.readStringAttribute("/", "resolved_case");
  for (const std::string& name : file.children("/reals"))
    checkpoint.reals[name] = file.readDataset<double>("/reals/" + name);
  for (const std::string& name : file.children("/integers"))
    checkpoint.integers[name] = file.readDataset<std::int64_t>("/integers/" + name);
  for (const std::string& name : file.children("/scalars")) {
    const std::vector<double> value = file.readDataset<double>("/scalars/" + name);
    if (value.size() != 1)
      throw std::runtime_error("checkpoint '" + path + "': scalar '" + name + "' has " +
                               std::to_string(value.size()) + " values");
    checkpoint.scalars[name] = value[0];
  }
  return checkpoint;
}

} // namespace hikiln::io
