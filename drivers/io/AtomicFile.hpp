#pragma once
/// \file AtomicFile.hpp
/// \brief Write-then-rename: a file either keeps its old content or gets the complete new one,
/// never a half-written one, even if the process is killed mid-way.

#include <string>

namespace hikiln::io {

/// \brief Owns a temporary sibling of the target path; commit() renames it over the target.
/// Destroying an uncommitted AtomicFile removes the temporary file.
class AtomicFile {
public:
  /// \brief Prepares to replace `target`; the parent directory must exist.
  explicit AtomicFile(std::string target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// \brief Path to write to (a hidden temporary next to the target, unique per process).
  const std::string& temporaryPath() const { return _temporary; }
  /// \brief Final path.
  const std::string& targetPath() const { return _target; }
  /// \brief Flushes the temporary file to disk and renames it over the target (atomic on POSIX).
  void commit();

private:
  std::string _target;
  std::string _temporary;
  bool _committed = false;
};

/// \brief Writes `content` to `path` atomically; throws std::runtime_error naming the path on
/// failure.
void writeTextAtomically(const std::string& path, const std::string& content);

} // namespace hikiln::io
