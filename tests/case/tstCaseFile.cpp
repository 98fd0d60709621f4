#include "CaseTestSupport.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace {

using namespace hikiln::cases;
using hikiln::cases::test::loadErrors;
using hikiln::cases::test::requiredOnly;
using hikiln::cases::test::TempDir;
using hikiln::cases::test::testSchema;

/// Asserts every key of `a` and `b` holds the identical value (bit-exact reals).
void expectSameValues(const CaseFile& a, const CaseFile& b) {
  EXPECT_EQ(a.real("drum.diameter"), b.real("drum.diameter"));
  EXPECT_EQ(a.real("drum.fill"), b.real("drum.fill"));
  EXPECT_EQ(a.real("drum.rpm"), b.real("drum.rpm"));
  EXPECT_EQ(a.integer("drum.slices"), b.integer("drum.slices"));
  EXPECT_EQ(a.real("particles.diameter"), b.real("particles.diameter"));
  EXPECT_EQ(a.boolean("output.xdmf"), b.boolean("output.xdmf"));
  EXPECT_EQ(a.string("output.prefix"), b.string("output.prefix"));
  EXPECT_EQ(a.string("contact.model"), b.string("contact.model"));
  EXPECT_EQ(a.realList("gravity"), b.realList("gravity"));
}

/// True if `yaml` has the line `text`, padding spaces, "  # comment".
bool hasLine(const std::string& yaml, const std::string& text, const std::string& comment) {
  std::istringstream lines(yaml);
  for (std::string line; std::getline(lines, line);) {
    const std::string tail = "  # " + comment;
    if (line.size() < text.size() + tail.size() || line.compare(0, text.size(), text) != 0 ||
        line.compare(line.size() - tail.size(), tail.size(), tail) != 0)
      continue;
    const std::string padding = line.substr(text.size(), line.size() - tail.size() - text.size());
    if (padding.find_first_not_of(' ') == std::string::npos)
      return true;
  }
  return false;
}

TEST(case_file, validFileLoadsWithDefaultsFilled) {
  TempDir dir;
  const std::string file = dir.write("drum.yaml", "# a drum\n"
                                                  "drum:\n"
                                                  "  diameter: 3.5\n"
                                                  "  rpm: 2        # integers are fine for reals\n"
                                                  "  slices: 16\n"
                                                  "particles: {diameter: 2.5e-3}\n"
                                                  "output:\n"
                                                  "  xdmf: false\n"
                                                  "contact:\n"
                                                  "  model: linear\n"
                                                  "gravity:\n"
                                                  "  - 0\n"
                                                  "  - 0\n"
                                                  "  - -9.81\n");
  const CaseFile c = CaseFile::load(file, testSchema());
  EXPECT_EQ(c.source(), file);
  EXPECT_EQ(c.real("drum.diameter"), 3.5);
  EXPECT_EQ(c.real("drum.rpm"), 2.0);
  EXPECT_EQ(c.integer("drum.slices"), 16);
  EXPECT_EQ(c.real("particles.diameter"), 2.5e-3);
  EXPECT_FALSE(c.boolean("output.xdmf"));
  EXPECT_EQ(c.string("contact.model"), "linear");
  EXPECT_EQ(c.realList("gravity"), (std::vector<double>{0.0, 0.0, -9.81}));
  // Defaults.
  EXPECT_EQ(c.real("drum.fill"), 0.15);
  EXPECT_EQ(c.string("output.prefix"), "run");
  EXPECT_EQ(c.origin("drum.fill"), CaseFile::Origin::Default);
  EXPECT_EQ(c.origin("drum.rpm"), CaseFile::Origin::File);
}

TEST(case_file, emptyCaseUsesAllDefaults) {
  CaseSchema s("defaults");
  s.real("a.b").defaultsTo("1.25");
  s.integer("n").defaultsTo("-7");
  s.realList("v").defaultsTo("[]");
  for (const char* text : {"", "# only a comment\n", "---\n"}) {
    const CaseFile c = CaseFile::fromString(text, "mem.yaml", s);
    EXPECT_EQ(c.real("a.b"), 1.25);
    EXPECT_EQ(c.integer("n"), -7);
    EXPECT_TRUE(c.realList("v").empty());
  }
}

TEST(case_file, flatDottedKeysAndEmptySections) {
  const CaseFile c = CaseFile::fromString("drum.diameter: 4.0\nparticles.diameter: 0.1\noutput:\n",
                                          "flat.yaml", testSchema());
  EXPECT_EQ(c.real("drum.diameter"), 4.0);
  EXPECT_EQ(c.real("particles.diameter"), 0.1);
  EXPECT_TRUE(c.boolean("output.xdmf"));
}

TEST(case_file, accessorMisuseIsALogicError) {
  const CaseFile c = CaseFile::fromString(requiredOnly(), "mem.yaml", testSchema());
  EXPECT_THROW(c.real("drum.nope"), std::logic_error);
  EXPECT_THROW(c.real("drum"), std::logic_error);
  EXPECT_THROW(c.integer("drum.diameter"), std::logic_error);
  EXPECT_THROW(c.real("drum.slices"), std::logic_error);
  EXPECT_THROW(c.boolean("output.prefix"), std::logic_error);
  EXPECT_THROW(c.string("gravity"), std::logic_error);
  EXPECT_THROW(c.realList("drum.diameter"), std::logic_error);
  EXPECT_THROW(c.origin("nope"), std::logic_error);
  // CaseError is for user input only.
  try {
    c.real("drum.nope");
  } catch (const CaseError&) {
    ADD_FAILURE() << "accessor misuse must not look like a user error";
  } catch (const std::logic_error&) {
  }
  EXPECT_EQ(c.string("contact.model"), "hertz"); // Choice through string()
}

TEST(case_file, setOverrideWinsAndIsValidated) {
  TempDir dir;
  const std::string file =
      dir.write("drum.yaml", "drum:\n  rpm: 3\n  slices: 8\nparticles:\n  diameter: 0.01\n");
  const CaseFile c = CaseFile::load(file, testSchema(),
                                    {"drum.rpm=5.5", "gravity=[0, 0, -9.81]", "drum.slices = 12",
                                     "drum.rpm=6", "output.prefix=a=b", "contact.model=linear"});
  EXPECT_EQ(c.real("drum.rpm"), 6.0); // the later --set of the same key wins
  EXPECT_EQ(c.origin("drum.rpm"), CaseFile::Origin::Override);
  EXPECT_EQ(c.integer("drum.slices"), 12);
  EXPECT_EQ(c.realList("gravity"), (std::vector<double>{0.0, 0.0, -9.81}));
  EXPECT_EQ(c.string("output.prefix"), "a=b"); // split at the first '='
  EXPECT_EQ(c.string("contact.model"), "linear");
  EXPECT_EQ(c.overrides().size(), 6u);

  // --set may supply a required key the file lacks.
  const CaseFile d =
      CaseFile::fromString("", "empty.yaml", testSchema(), {"particles.diameter=0.02"});
  EXPECT_EQ(d.real("particles.diameter"), 0.02);
}

TEST(case_file, badSetIsReportedAsSet) {
  TempDir dir;
  const auto check = [&](const std::string& set, const std::string& expected) {
    const auto errors = loadErrors(dir, "ok.yaml", requiredOnly(), {set});
    ASSERT_EQ(errors.size(), 1u) << set;
    EXPECT_EQ(errors[0], expected);
  };
  check("drum.rpm=fast", "--set drum.rpm=fast: 'drum.rpm' must be a real number, got 'fast'");
  check("drum.fill=1.3", "--set drum.fill=1.3: 'drum.fill' = 1.3 is out of range: must be in "
                         "(0, 1] (fraction of drum area)");
  check("drum.rmp=4", "--set drum.rmp=4: unknown key 'drum.rmp' (did you mean 'drum.rpm'?)");
  check("drum.rpm", "--set drum.rpm: expected dotted.key=value");
  check("drum.rpm=", "--set drum.rpm=: 'drum.rpm' has no value (expected a real number)");
  check("drum=3", "--set drum=3: 'drum' is a section; set one of its keys, such as "
                  "'drum.diameter'");
  check("drum.slices=2.5", "--set drum.slices=2.5: 'drum.slices' must be an integer, got '2.5'");
  const auto malformed = loadErrors(dir, "ok.yaml", requiredOnly(), {"gravity=[1, 2"});
  ASSERT_EQ(malformed.size(), 1u);
  EXPECT_EQ(malformed[0].rfind("--set gravity=[1, 2: malformed YAML value: ", 0), 0u)
      << malformed[0];
}

TEST(case_file, resolvedYamlRoundTrips) {
  TempDir dir;
  const std::string file =
      dir.write("rt.yaml", "drum: {diameter: 0.1, fill: 0.3333333333333333, rpm: 1e-7}\n"
                           "particles: {diameter: 0.0001}\n"
                           "output: {prefix: \"it's: a \\\"#test\\\" \\\\ path/\\ttab\"}\n"
                           "gravity: [1.0000000000000002, -9.80665, 6.02214076e+23]\n");
  const CaseFile c = CaseFile::load(file, testSchema(), {"drum.slices=64", "output.xdmf=false"});
  EXPECT_EQ(c.string("output.prefix"), "it's: a \"#test\" \\ path/\ttab");
  const std::string yaml = c.resolvedYaml();

  // Header names the source and the overrides; every key appears once with its unit comment.
  EXPECT_NE(yaml.find("# source: " + file + "\n"), std::string::npos) << yaml;
  EXPECT_NE(yaml.find("# override: --set drum.slices=64\n"), std::string::npos) << yaml;
  EXPECT_TRUE(hasLine(yaml, "  diameter: 0.1", "[m] Drum inner diameter")) << yaml;
  EXPECT_TRUE(hasLine(yaml, "  slices: 64", "Number of DEM slices (--set)")) << yaml;
  EXPECT_TRUE(hasLine(yaml, "  model: \"hertz\"", "Normal contact law (default)")) << yaml;
  EXPECT_EQ(yaml.find("drum:"), yaml.rfind("drum:")); // each section once

  const CaseFile again = CaseFile::fromString(yaml, "resolved.yaml", testSchema());
  expectSameValues(c, again);
  EXPECT_EQ(again.origin("contact.model"), CaseFile::Origin::File);

  const std::string written = dir.path("resolved.yaml");
  c.writeResolved(written);
  std::ifstream in(written);
  std::stringstream content;
  content << in.rdbuf();
  EXPECT_EQ(content.str(), yaml);
  expectSameValues(c, CaseFile::load(written, testSchema()));
}

TEST(case_file, resolvedYamlKeepsSchemaOrderWithInterleavedSections) {
  CaseSchema s("order");
  s.real("b.x").defaultsTo("1");
  s.real("a").defaultsTo("2");
  s.real("b.y").defaultsTo("3");
  const std::string yaml = CaseFile::fromString("", "mem", s).resolvedYaml();
  const std::string body = yaml.substr(yaml.find("\nb:") + 1);
  EXPECT_EQ(body, "b:\n  x: 1.0  # (default)\n  y: 3.0  # (default)\na: 2.0    # (default)\n");
}

TEST(case_file, crossKeyCheckFailureNamesTheFile) {
  TempDir dir;
  const auto errors =
      loadErrors(dir, "big.yaml", "drum: {diameter: 2.0}\nparticles: {diameter: 0.5}\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0],
            dir.path("big.yaml") + ": check failed: particles.diameter < drum.diameter / 10");

  // A boundary case of the rule: 0.2 is not < 2.0 / 10, 0.19 is.
  EXPECT_THROW(CaseFile::fromString(requiredOnly(), "m", testSchema(), {"particles.diameter=0.2"}),
               CaseError);
  EXPECT_NO_THROW(
      CaseFile::fromString(requiredOnly(), "m", testSchema(), {"particles.diameter=0.19"}));

  // addCheck: the thrown reason follows the rule; several failing checks are all reported.
  CaseSchema s = testSchema();
  s.addCheck("fill leaves room for the bed", [](const CaseFile& c) {
    if (c.real("drum.fill") > 0.5)
      throw std::runtime_error("fill " + std::to_string(c.real("drum.fill")) + " > 0.5");
  });
  try {
    CaseFile::fromString("drum: {fill: 0.75}\nparticles: {diameter: 0.3}\n", "cases/x.yaml", s);
    ADD_FAILURE() << "expected a CaseError";
  } catch (const CaseError& e) {
    ASSERT_EQ(e.messages().size(), 2u) << e.what();
    EXPECT_EQ(e.messages()[1],
              "cases/x.yaml: check failed: fill leaves room for the bed: fill 0.750000 > 0.5");
  }

  // Misusing an accessor inside a check is a bug and is not disguised as a case error.
  CaseSchema buggy = testSchema();
  buggy.addCheck("buggy", [](const CaseFile& c) { (void)c.integer("drum.fill"); });
  EXPECT_THROW(CaseFile::fromString(requiredOnly(), "m", buggy), std::logic_error);
}

} // namespace
