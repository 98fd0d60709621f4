#pragma once
/// \file CaseTestSupport.hpp
/// \brief A schema with one key of every type, and a temporary directory for case files.

#include "drivers/case/CaseFile.hpp"
#include "drivers/case/CaseSchema.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>

namespace hikiln::cases::test {

/// \brief Every ValueType, bounds of each kind, one required key and one cross-key rule.
inline CaseSchema testSchema() {
  const double inf = std::numeric_limits<double>::infinity();
  CaseSchema s("test");
  s.real("drum.diameter")
      .unit("m")
      .range(0, inf, Bounds::OpenMin)
      .defaultsTo("2.0")
      .doc("Drum inner diameter");
  s.real("drum.fill").range(0, 1, Bounds::OpenMin).defaultsTo("0.15").doc("fraction of drum area");
  s.real("drum.rpm").unit("1/min").nonNegative().defaultsTo("3").doc("Rotation speed");
  s.integer("drum.slices").range(1, 64).defaultsTo("4").doc("Number of DEM slices");
  s.real("particles.diameter").unit("m").positive().doc("Mean particle diameter");
  s.boolean("output.xdmf").defaultsTo("true").doc("Write an XDMF index");
  s.string("output.prefix").defaultsTo("run").doc("Prefix of output files");
  s.choice("contact.model", {"hertz", "linear"}).defaultsTo("hertz").doc("Normal contact law");
  s.realList("gravity").unit("m/s^2").items(3).defaultsTo("[0, -9.81, 0]").doc("Gravity vector");
  s.require("particles.diameter < drum.diameter / 10", [](const CaseFile& c) {
    return c.real("particles.diameter") < c.real("drum.diameter") / 10;
  });
  return s;
}

/// \brief A fresh directory under the system temp dir, removed with everything in it.
class TempDir {
public:
  TempDir() {
    static std::atomic<int> counter{0};
    _path = std::filesystem::temp_directory_path() /
            ("hikiln-case-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(_path);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(_path, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// \brief Writes `content` to `name` inside the directory and returns its full path.
  std::string write(const std::string& name, const std::string& content) const {
    const std::string file = (_path / name).string();
    std::ofstream(file) << content;
    return file;
  }
  /// \brief Full path of `name` inside the directory.
  std::string path(const std::string& name) const { return (_path / name).string(); }

private:
  std::filesystem::path _path;
};

/// \brief The CaseError message list for loading `text` as file `name`; fails the test when the
/// load succeeds.
inline std::vector<std::string> loadErrors(const TempDir& dir, const std::string& name,
                                           const std::string& text,
                                           const std::vector<std::string>& overrides = {}) {
  const std::string file = dir.write(name, text);
  try {
    CaseFile::load(file, testSchema(), overrides);
  } catch (const CaseError& e) {
    return e.messages();
  }
  ADD_FAILURE() << "expected a CaseError for:\n" << text;
  return {};
}

/// \brief Minimal valid content: the one required key.
inline const char* requiredOnly() {
  return "particles:\n  diameter: 0.01\n";
}

} // namespace hikiln::cases::test
