#pragma once
// Helpers shared by the tests of drivers/io: a private scratch directory per test and whole-file
// reads.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace hikiln::io::test {

/// \brief A fresh directory under the test's working directory, removed with its contents.
class ScratchDir {
public:
  /// \brief Creates "io-scratch-<tag>-<pid>", emptying it first if a previous run left it.
  explicit ScratchDir(const std::string& tag)
      : _path(std::filesystem::absolute("io-scratch-" + tag + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(_path);
    std::filesystem::create_directories(_path);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(_path, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  /// \brief Path of `name` inside the directory.
  std::string file(const std::string& name) const { return (_path / name).string(); }
  /// \brief The directory itself.
  const std::filesystem::path& path() const { return _path; }
  /// \brief Number of entries (hidden ones included) in the directory.
  std::size_t entryCount() const {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(_path))
      ++n;
    return n;
  }

private:
  std::filesystem::path _path;
};

/// \brief Whole content of a file as bytes ("" if it cannot be opened).
inline std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

} // namespace hikiln::io::test
