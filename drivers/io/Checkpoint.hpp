#pragma once
/// \file Checkpoint.hpp
/// \brief Restart files: the complete state of a stage at one step, as named arrays, written
/// atomically to HDF5 and read back bit for bit.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace hikiln::io {

/// \brief Version of the checkpoint layout this build writes and reads.
inline constexpr std::int64_t checkpointFormatVersion = 1;

/// \brief State needed to resume a stage. Map keys become HDF5 names: non-empty, without '/'.
struct Checkpoint {
  std::string stage;
  std::int64_t step = 0;
  double time = 0.0;
  std::map<std::string, std::vector<double>> reals;
  std::map<std::string, std::vector<std::int64_t>> integers;
  std::map<std::string, double> scalars;
  std::string resolvedCaseYaml;
};

/// \brief Writes `checkpoint` to `path` atomically: a crash leaves the previous file intact.
void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint);

/// \brief Reads a checkpoint; throws std::runtime_error naming `path` if it is not a hikiln
/// checkpoint or was written in another format version.
Checkpoint readCheckpoint(const std::string& path);

} // namespace hikiln::io
