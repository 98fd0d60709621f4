#include "CaseTestSupport.hpp"

#include <algorithm>
#include <filesystem>

namespace {

using namespace hikiln::cases;
using hikiln::cases::test::loadErrors;
using hikiln::cases::test::requiredOnly;
using hikiln::cases::test::TempDir;
using hikiln::cases::test::testSchema;

/// Loads `body` (after the required key) as drum.yaml and expects exactly one message equal to
/// "<path>:<where>: <reason>".
void expectOneError(const std::string& body, const std::string& where, const std::string& reason) {
  TempDir dir;
  const auto errors = loadErrors(dir, "drum.yaml", std::string(requiredOnly()) + body);
  ASSERT_EQ(errors.size(), 1u) << body;
  EXPECT_EQ(errors[0], dir.path("drum.yaml") + where + ": " + reason) << body;
}

TEST(case_errors, unknownKeyWithSuggestion) {
  expectOneError("drum:\n  diamter: 2.0\n", ":4:3",
                 "unknown key 'drum.diamter' (did you mean 'drum.diameter'?)");
  expectOneError("drm:\n  diameter: 2.0\n", ":3:1", "unknown key 'drm' (did you mean 'drum'?)");
  expectOneError("temperature: 300\n", ":3:1", "unknown key 'temperature'");
}

TEST(case_errors, outOfRange) {
  expectOneError("drum:\n  fill: 1.3\n", ":4:9",
                 "'drum.fill' = 1.3 is out of range: must be in (0, 1] (fraction of drum area)");
  expectOneError("drum:\n  fill: 0\n", ":4:9",
                 "'drum.fill' = 0 is out of range: must be in (0, 1] (fraction of drum area)");
  expectOneError("drum: {diameter: -2}\n", ":3:18",
                 "'drum.diameter' = -2 is out of range: must be > 0 (Drum inner diameter [m])");
  expectOneError("drum: {slices: 65}\n", ":3:16",
                 "'drum.slices' = 65 is out of range: must be in [1, 64] (Number of DEM slices)");
  expectOneError("gravity: [0, 0, -9.81, 1]\n", ":3:10",
                 "'gravity' must have exactly 3 items, got 4");
  // The boundaries themselves: fill = 1 and rpm = 0 are allowed.
  EXPECT_NO_THROW(CaseFile::fromString(std::string(requiredOnly()) + "drum: {fill: 1, rpm: 0}", "m",
                                       testSchema()));
}

TEST(case_errors, wrongTypes) {
  expectOneError("drum:\n  rpm: fast\n", ":4:8", "'drum.rpm' must be a real number, got 'fast'");
  expectOneError("drum:\n  rpm: \"3\"\n", ":4:8",
                 "'drum.rpm' must be a real number, got the quoted string '3' (remove the quotes)");
  expectOneError("drum:\n  slices: 3.5\n", ":4:11", "'drum.slices' must be an integer, got '3.5'");
  expectOneError("drum:\n  slices: 1e3\n", ":4:11", "'drum.slices' must be an integer, got '1e3'");
  expectOneError("drum:\n  slices: 99999999999999999999\n", ":4:11",
                 "'drum.slices' = 99999999999999999999 does not fit in a 64-bit integer");
  expectOneError("output:\n  xdmf: yes\n", ":4:9",
                 "'output.xdmf' must be true or false, got 'yes'");
  expectOneError("output:\n  xdmf: 1\n", ":4:9", "'output.xdmf' must be true or false, got '1'");
  expectOneError("contact: {model: hooke}\n", ":3:18",
                 "'contact.model' must be one of 'hertz', 'linear', got 'hooke'");
  expectOneError("gravity: 9.81\n", ":3:10",
                 "'gravity' must be a list of real numbers such as [1.0, 2.0], got '9.81'");
  expectOneError("gravity: [0, x, 0]\n", ":3:14",
                 "'gravity' item 2 must be a real number, got 'x'");
  expectOneError("gravity: [0, .nan, 0]\n", ":3:14",
                 "'gravity' item 2 must be a finite real number, got '.nan'");
  expectOneError("output: {prefix: [a, b]}\n", ":3:18",
                 "'output.prefix' must be a string, got a list");
}

TEST(case_errors, nonFiniteRealsRejected) {
  for (const char* bad : {".nan", ".NaN", ".inf", "-.inf", "+.Inf", "nan", "inf"})
    expectOneError(std::string("drum: {rpm: ") + bad + "}\n", ":3:13",
                   std::string("'drum.rpm' must be a finite real number, got '") + bad + "'");
  expectOneError("drum: {rpm: 1e999}\n", ":3:13",
                 "'drum.rpm' = 1e999 cannot be represented as a double");
}

TEST(case_errors, mapWhereScalarExpectedAndViceVersa) {
  expectOneError("drum:\n  diameter:\n    inner: 2.0\n", ":5:5",
                 "'drum.diameter' must be a real number, got a map");
  expectOneError("drum: 3\n", ":3:7",
                 "'drum' must be a map of keys such as 'drum.diameter', got '3'");
  expectOneError("drum: [1, 2]\n", ":3:7",
                 "'drum' must be a map of keys such as 'drum.diameter', got a list");
  // A key with nothing after it points at the key, not at wherever yaml-cpp puts the null.
  expectOneError("drum:\n  rpm:\n", ":4:3", "'drum.rpm' has no value (expected a real number)");
}

TEST(case_errors, duplicateKeys) {
  expectOneError("drum:\n  rpm: 1\n  rpm: 2\n", ":5:3",
                 "duplicate key 'drum.rpm' (first given at line 4)");
  expectOneError("drum: {rpm: 1}\ndrum.rpm: 2\n", ":4:1",
                 "duplicate key 'drum.rpm' (first given at line 3)");
  expectOneError("drum: {rpm: 1}\ndrum: {fill: 0.2}\n", ":4:1",
                 "duplicate key 'drum' (first given at line 3)");
}

TEST(case_errors, missingRequiredKey) {
  TempDir dir;
  const auto errors = loadErrors(dir, "drum.yaml", "drum: {diameter: 2.0}\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0],
            dir.path("drum.yaml") +
                ": missing required key 'particles.diameter' (Mean particle diameter [m])");
  // Given but invalid is reported once, as invalid, not also as missing.
  const auto invalid = loadErrors(dir, "drum.yaml", "particles: {diameter: big}\n");
  ASSERT_EQ(invalid.size(), 1u);
  EXPECT_NE(invalid[0].find(":1:23: 'particles.diameter' must be a real number"), std::string::npos)
      << invalid[0];
}

TEST(case_errors, malformedYaml) {
  TempDir dir;
  const auto errors = loadErrors(dir, "drum.yaml", "drum: {diameter: 2.0}\ngravity: [1, 2\nx: 1\n");
  ASSERT_EQ(errors.size(), 1u); // no "missing key" noise after a parse failure
  const std::string prefix = dir.path("drum.yaml") + ":3:";
  EXPECT_EQ(errors[0].rfind(prefix, 0), 0u) << errors[0];
  EXPECT_NE(errors[0].find(": malformed YAML: "), std::string::npos) << errors[0];

  const auto topList = loadErrors(dir, "list.yaml", "- 1\n- 2\n");
  ASSERT_EQ(topList.size(), 1u);
  EXPECT_EQ(topList[0], dir.path("list.yaml") +
                            ":1:1: a case file must be a map of keys (such as 'drum: {diameter: "
                            "2.0}'), got a list");

  const auto twoDocs = loadErrors(dir, "two.yaml", std::string(requiredOnly()) + "---\na: 1\n");
  ASSERT_EQ(twoDocs.size(), 1u);
  EXPECT_NE(twoDocs[0].find("two.yaml:4:1: a case file holds one YAML document, found 2"),
            std::string::npos)
      << twoDocs[0];
}

TEST(case_errors, cannotOpenFile) {
  TempDir dir;
  const std::string missing = dir.path("nope.yaml");
  try {
    CaseFile::load(missing, testSchema());
    ADD_FAILURE() << "expected a CaseError";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open file: No such file or directory");
  }
  std::filesystem::create_directories(dir.path("adir"));
  try {
    CaseFile::load(dir.path("adir"), testSchema());
    ADD_FAILURE() << "expected a CaseError";
  } catch (const CaseError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(dir.path("adir") + ": cannot ", 0), 0u) << e.what();
  }
}

TEST(case_errors, allErrorsReportedTogetherInFileOrder) {
  TempDir dir;
  const std::string file = dir.write("many.yaml", "drum:\n"
                                                  "  diamter: 2.0\n"
                                                  "  fill: 1.3\n"
                                                  "  rpm: fast\n"
                                                  "output: {xdmf: maybe}\n");
  try {
    CaseFile::load(file, testSchema(), {"drum.slices=0"});
    ADD_FAILURE() << "expected a CaseError";
  } catch (const CaseError& e) {
    const auto& m = e.messages();
    ASSERT_EQ(m.size(), 6u) << e.what();
    EXPECT_EQ(m[0].rfind(file + ":2:3: unknown key 'drum.diamter'", 0), 0u) << m[0];
    EXPECT_EQ(m[1].rfind(file + ":3:9: 'drum.fill' = 1.3", 0), 0u) << m[1];
    EXPECT_EQ(m[2].rfind(file + ":4:8: 'drum.rpm'", 0), 0u) << m[2];
    EXPECT_EQ(m[3].rfind(file + ":5:16: 'output.xdmf'", 0), 0u) << m[3];
    EXPECT_EQ(m[4].rfind("--set drum.slices=0: 'drum.slices' = 0 is out of range", 0), 0u) << m[4];
    EXPECT_EQ(m[5], file + ": missing required key 'particles.diameter' (Mean particle "
                           "diameter [m])");
    // what() is the same messages, one per line.
    const std::string what = e.what();
    EXPECT_EQ(static_cast<std::size_t>(std::count(what.begin(), what.end(), '\n')), 5u);
    EXPECT_EQ(what.substr(0, m[0].size() + 1), m[0] + "\n");
  }
}

} // namespace
