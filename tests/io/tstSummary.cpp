// Summary JSON: exact round trip, pretty-printed, atomic, clear errors.
#include "drivers/io/AtomicFile.hpp"
#include "drivers/io/Summary.hpp"
#include "io/IoTestSupport.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>

namespace {
using hikiln::io::test::ScratchDir;

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}
} // namespace

TEST(io_summary, json_round_trip) {
  ScratchDir dir("summary");
  const std::string path = dir.file("summary.json");
  nlohmann::json summary;
  summary["stage"] = "dem";
  summary["steps"] = std::int64_t(9007199254740993); // not representable as a double
  summary["dt"] = 0.1;
  summary["tiny"] = 4.9e-324;
  summary["fill_fraction"] = {{"target", 0.15}, {"measured", 0.1499999999999999}};
  summary["passed"] = true;
  summary["note"] = nullptr;
  summary["label"] = "\xc2\xb0"
                     "C \"quoted\"\n";
  summary["residuals"] = {1e-3, 1e-6, 1e-9};
  hikiln::io::writeSummaryJson(path, summary);

  const nlohmann::json read = hikiln::io::readSummaryJson(path);
  EXPECT_EQ(read, summary);
  EXPECT_EQ(read["steps"].get<std::int64_t>(), 9007199254740993);
  EXPECT_EQ(read["fill_fraction"]["measured"].get<double>(), 0.1499999999999999);
  const std::string text = hikiln::io::test::readWholeFile(path);
  EXPECT_EQ(text, summary.dump(2) + "\n");
  EXPECT_NE(text.find("\n  \"dt\": 0.1,\n"), std::string::npos) << text;
  EXPECT_EQ(dir.entryCount(), 1u);
}

TEST(io_summary, errors_name_the_file) {
  ScratchDir dir("summary-errors");
  const std::string broken = dir.file("broken.json");
  hikiln::io::writeTextAtomically(broken, "{\"a\": [1, 2,\n");
  const std::string message = errorOf([&] { hikiln::io::readSummaryJson(broken); });
  EXPECT_NE(message.find(broken), std::string::npos) << message;
  EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
  const std::string missing = dir.file("missing.json");
  EXPECT_NE(errorOf([&] { hikiln::io::readSummaryJson(missing); }).find(missing),
            std::string::npos);
}
