#include "drivers/io/AtomicFile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace hikiln::io {

namespace {
std::string temporaryName(const std::string& target) {
  const std::filesystem::path p(target);
  const std::string name = "." + p.filename().string() + ".tmp-" + std::to_string(::getpid());
  return (p.parent_path() / name).string();
}

void syncFile(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0)
    return; // nothing to sync; rename will report a missing file
  ::fsync(fd);
  ::close(fd);
}
} // namespace

AtomicFile::AtomicFile(std::string target)
    : _target(std::move(target)), _temporary(temporaryName(_target)) {}

AtomicFile::~AtomicFile() {
  if (!_committed)
    std::remove(_temporary.c_str());
}

void AtomicFile::commit() {
  syncFile(_temporary);
  if (std::rename(_temporary.c_str(), _target.c_str()) != 0) {
    throw std::runtime_error("cannot move " + _temporary + " to " + _target + ": " +
                             std::strerror(errno));
  }
  _committed = true;
}

void writeTextAtomically(const std::string& path, const std::string& content) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temporaryPath(), std::ios::binary | std::ios::trunc);
    if (!out)
      throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    out << content;
    out.close();
    if (!out)
      throw std::runtime_error("write to " + path + " failed: " + std::strerror(errno));
  }
  file.commit();
}

} // namespace hikiln::io
