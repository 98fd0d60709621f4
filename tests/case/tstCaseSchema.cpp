#include "CaseTestSupport.hpp"

#include <algorithm>
#include <stdexcept>

namespace {

using namespace hikiln::cases;
using hikiln::cases::test::testSchema;

TEST(case_schema, keysInOrderAndFind) {
  const CaseSchema s = testSchema();
  const std::vector<std::string> expected = {"drum.diameter", "drum.fill",          "drum.rpm",
                                             "drum.slices",   "particles.diameter", "output.xdmf",
                                             "output.prefix", "contact.model",      "gravity"};
  EXPECT_EQ(s.keys(), expected);
  const KeySpec* fill = s.find("drum.fill");
  ASSERT_NE(fill, nullptr);
  EXPECT_EQ(fill->type, ValueType::Real);
  ASSERT_TRUE(fill->min && fill->max);
  EXPECT_EQ(*fill->min, 0.0);
  EXPECT_EQ(*fill->max, 1.0);
  EXPECT_TRUE(fill->minExclusive);
  EXPECT_FALSE(fill->maxExclusive);
  // An infinite end of range() means "no bound", not a bound at infinity.
  EXPECT_FALSE(s.find("drum.diameter")->max.has_value());
  EXPECT_TRUE(s.find("particles.diameter")->required());
  EXPECT_FALSE(s.find("drum.rpm")->required());
  EXPECT_EQ(s.find("drum"), nullptr);
  EXPECT_TRUE(s.isSection("drum"));
  EXPECT_FALSE(s.isSection("drum.rpm"));
  EXPECT_EQ(s.indexOf("gravity"), std::optional<std::size_t>(8));
  EXPECT_NO_THROW(s.validate());
}

TEST(case_schema, rejectsBadDeclarations) {
  CaseSchema s("bad");
  s.real("drum.rpm");
  EXPECT_THROW(s.real("drum.rpm"), std::logic_error);     // twice
  EXPECT_THROW(s.real("drum"), std::logic_error);         // a section already
  EXPECT_THROW(s.real("drum.rpm.max"), std::logic_error); // inside a key
  EXPECT_THROW(s.real("drum..rpm"), std::logic_error);    // empty component
  EXPECT_THROW(s.real("drum.r p m"), std::logic_error);   // space
  EXPECT_THROW(s.real(""), std::logic_error);
}

TEST(case_schema, validateCatchesInconsistentSpecs) {
  {
    CaseSchema s("bad-default");
    s.real("x").positive().defaultsTo("-1");
    EXPECT_THROW(s.validate(), std::logic_error);
  }
  {
    CaseSchema s("bad-default-type");
    s.integer("n").defaultsTo("2.5");
    EXPECT_THROW(s.validate(), std::logic_error);
  }
  {
    CaseSchema s("no-choices");
    s.choice("model", {});
    EXPECT_THROW(s.validate(), std::logic_error);
  }
  {
    CaseSchema s("empty-range");
    s.real("x").range(1, 1, Bounds::OpenMax);
    EXPECT_THROW(s.validate(), std::logic_error);
  }
  {
    CaseSchema s("range-on-string");
    s.string("name").atLeast(0);
    EXPECT_THROW(s.validate(), std::logic_error);
  }
  {
    // validate() runs before every load, so a broken schema never reads a file.
    CaseSchema s("bad");
    s.real("x").defaultsTo("abc");
    EXPECT_THROW(CaseFile::fromString("", "mem", s), std::logic_error);
  }
}

TEST(case_schema, nearestKeySuggestsPlausibleTypos) {
  const CaseSchema s = testSchema();
  EXPECT_EQ(s.nearestKey("drum.diamter"), "drum.diameter");
  EXPECT_EQ(s.nearestKey("drum.rmp"), "drum.rpm");
  EXPECT_EQ(s.nearestKey("particle.diameter"), "particles.diameter");
  EXPECT_EQ(s.nearestKey("output.prefx"), "output.prefix");
  // Right name, wrong section: found by the last component, closest full path wins the tie.
  EXPECT_EQ(s.nearestKey("diameter"), "drum.diameter");
  EXPECT_EQ(s.nearestKey("kiln.slices"), "drum.slices");
  // A misspelt section.
  EXPECT_EQ(s.nearestKey("drm"), "drum");
  // Nothing close: no suggestion rather than a random one.
  EXPECT_EQ(s.nearestKey("temperature"), "");
  EXPECT_EQ(s.nearestKey("x"), "");
}

TEST(case_schema, markdownReferenceListsEveryKey) {
  const CaseSchema s = testSchema();
  const std::string md = s.markdownReference();
  EXPECT_EQ(md.rfind("| key | type | default | unit | range | meaning |\n", 0), 0u) << md;
  for (const auto& key : s.keys())
    EXPECT_NE(md.find("| `" + key + "` |"), std::string::npos) << key << "\n" << md;
  EXPECT_NE(md.find("| `drum.diameter` | real | `2.0` | m | > 0 | Drum inner diameter |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| `drum.fill` | real | `0.15` |  | (0, 1] | fraction of drum area |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| `drum.slices` | integer | `4` |  | [1, 64] |"), std::string::npos) << md;
  EXPECT_NE(md.find("| `particles.diameter` | real | **required** | m | > 0 |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("one of `hertz`, `linear`"), std::string::npos) << md;
  EXPECT_NE(md.find("| list of reals | `[0, -9.81, 0]` | m/s^2 | 3 items |"), std::string::npos)
      << md;
  EXPECT_NE(md.find("- particles.diameter < drum.diameter / 10\n"), std::string::npos) << md;
  // One header, one separator, one row per key, then the rules.
  const auto rows = static_cast<std::size_t>(std::count(md.begin(), md.end(), '|')) / 7;
  EXPECT_EQ(rows, s.keys().size() + 2);
}

TEST(case_schema, markdownEscapesPipes) {
  CaseSchema s("pipes");
  s.string("a").doc("either x | y").defaultsTo("x");
  EXPECT_NE(s.markdownReference().find("either x \\| y"), std::string::npos);
}

} // namespace
