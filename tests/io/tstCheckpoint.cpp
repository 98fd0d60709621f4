// Checkpoints read back bit for bit, replace older ones atomically and refuse other formats.
#include "drivers/io/Checkpoint.hpp"
#include "drivers/io/Hdf5File.hpp"
#include "io/IoTestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <random>

namespace {
using hikiln::io::Checkpoint;
using hikiln::io::test::ScratchDir;

// Random bit patterns, NaNs rejected: covers denormals, infinities and both zeros.
std::vector<double> randomDoubles(std::size_t n, std::mt19937_64& random) {
  std::vector<double> values;
  while (values.size() < n) {
    const std::uint64_t bits = random();
    double v;
    std::memcpy(&v, &bits, sizeof(v));
    if (!std::isnan(v))
      values.push_back(v);
  }
  return values;
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

void expectSame(const Checkpoint& a, const Checkpoint& b) {
  EXPECT_EQ(a.stage, b.stage);
  EXPECT_EQ(a.step, b.step);
  EXPECT_TRUE(sameBits(a.time, b.time));
  EXPECT_EQ(a.resolvedCaseYaml, b.resolvedCaseYaml);
  ASSERT_EQ(a.reals.size(), b.reals.size());
  for (const auto& [name, values] : a.reals) {
    ASSERT_EQ(b.reals.count(name), 1u) << name;
    const std::vector<double>& other = b.reals.at(name);
    ASSERT_EQ(values.size(), other.size()) << name;
    EXPECT_TRUE(values.empty() ||
                std::memcmp(values.data(), other.data(), values.size() * sizeof(double)) == 0)
        << name;
  }
  EXPECT_EQ(a.integers, b.integers);
  ASSERT_EQ(a.scalars.size(), b.scalars.size());
  for (const auto& [name, value] : a.scalars) {
    ASSERT_EQ(b.scalars.count(name), 1u) << name;
    EXPECT_TRUE(sameBits(value, b.scalars.at(name))) << name;
  }
}

Checkpoint sampleCheckpoint(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  Checkpoint c;
  c.stage = "dem";
  c.step = 123456789012LL;
  c.time = randomDoubles(1, random)[0];
  c.reals["position"] = randomDoubles(2 * 1001, random);
  c.reals["wall temperature"] = randomDoubles(7, random); // spaces are fine in HDF5 names
  c.reals["empty"] = {};
  for (int i = 0; i < 500; ++i)
    c.integers["contact_ids"].push_back(static_cast<std::int64_t>(random()));
  c.integers["none"] = {};
  c.scalars["dt"] = 1e-6;
  c.scalars["negative zero"] = -0.0;
  c.scalars["denormal"] = 4.9e-324;
  c.resolvedCaseYaml = "drum:\n  radius: 0.25\n  rpm: 3\n";
  return c;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& error) {
    return error.what();
  }
  return "";
}
} // namespace

TEST(io_checkpoint, round_trip_is_bitwise) {
  ScratchDir dir("checkpoint-roundtrip");
  const std::string path = dir.file("restart.h5");
  const Checkpoint written = sampleCheckpoint(7);
  hikiln::io::writeCheckpoint(path, written);
  const Checkpoint read = hikiln::io::readCheckpoint(path);
  expectSame(written, read);
  EXPECT_EQ(read.reals.at("position").size(), 2002u);
  EXPECT_TRUE(read.reals.at("empty").empty());
  EXPECT_TRUE(std::signbit(read.scalars.at("negative zero")));
  EXPECT_EQ(dir.entryCount(), 1u); // no temporary left behind
}

TEST(io_checkpoint, rewrite_replaces_previous) {
  ScratchDir dir("checkpoint-rewrite");
  const std::string path = dir.file("restart.h5");
  hikiln::io::writeCheckpoint(path, sampleCheckpoint(1));
  Checkpoint second = sampleCheckpoint(2);
  second.step = 2;
  second.reals.erase("wall temperature"); // a name that vanished must not survive
  hikiln::io::writeCheckpoint(path, second);
  const Checkpoint read = hikiln::io::readCheckpoint(path);
  expectSame(second, read);
  EXPECT_EQ(read.reals.count("wall temperature"), 0u);
}

TEST(io_checkpoint, invalid_name_writes_nothing) {
  ScratchDir dir("checkpoint-badname");
  const std::string path = dir.file("restart.h5");
  Checkpoint c = sampleCheckpoint(3);
  c.reals["a/b"] = {1.0};
  EXPECT_NE(errorOf([&] { hikiln::io::writeCheckpoint(path, c); }).find("a/b"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(dir.entryCount(), 0u);
}

TEST(io_checkpoint, wrong_format_version_is_a_clear_error) {
  ScratchDir dir("checkpoint-version");
  const std::string future = dir.file("future.h5");
  {
    auto file = hikiln::io::H5File::create(future);
    file.setAttribute("/", "format", "hikiln-checkpoint");
    file.setAttribute("/", "format_version", std::int64_t(99));
    file.commit();
  }
  const std::string message = errorOf([&] { hikiln::io::readCheckpoint(future); });
  EXPECT_NE(message.find(future), std::string::npos) << message;
  EXPECT_NE(message.find("format version 99"), std::string::npos) << message;
  EXPECT_NE(message.find("reads version 1"), std::string::npos) << message;

  const std::string other = dir.file("other.h5");
  {
    auto file = hikiln::io::H5File::create(other);
    file.writeDataset("/x", std::vector<double>{1.0});
    file.commit();
  }
  const std::string notCheckpoint = errorOf([&] { hikiln::io::readCheckpoint(other); });
  EXPECT_NE(notCheckpoint.find("not a hikiln checkpoint"), std::string::npos) << notCheckpoint;
  EXPECT_NE(notCheckpoint.find(other), std::string::npos) << notCheckpoint;
}
