// H5File: every element type and shape round-trips bit for bit, groups and attributes behave,
// and every failure is an exception that names the file and the object.
#include "drivers/io/Hdf5File.hpp"
#include "io/IoTestSupport.hpp"
#include "kernels/common/Compat.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <limits>
#include <random>
#include <regex>

namespace {
using hikiln::io::H5File;
using hikiln::io::test::ScratchDir;

template <class T> bool bitwiseEqual(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Message of the exception `f` throws ("" if it throws none).
template <class F> std::string errorOf(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

std::vector<double> awkwardDoubles(std::size_t n) {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> uniform(-1e3, 1e3);
  std::vector<double> values(n);
  for (double& v : values)
    v = uniform(random);
  values[0] = -0.0;
  values[1] = std::numeric_limits<double>::denorm_min();
  values[2] = std::numeric_limits<double>::max();
  values[3] = 0.1;
  return values;
}
} // namespace

TEST(io_hdf5, datasets_round_trip_bitwise) {
  ScratchDir dir("hdf5-roundtrip");
  const std::string path = dir.file("data.h5");
  const std::vector<double> field = awkwardDoubles(3 * 4);
  const std::vector<float> cube = {1.5f, -2.25f, 3e-38f, 3e38f, 0.f, -0.f, 7.f, 8.125f};
  const std::vector<std::int32_t> ints = {std::numeric_limits<std::int32_t>::min(), -1, 0, 1, 2,
                                          std::numeric_limits<std::int32_t>::max()};
  const std::vector<std::int64_t> ids = {std::numeric_limits<std::int64_t>::min(), -7, 0,
                                         std::numeric_limits<std::int64_t>::max()};
  std::vector<std::uint8_t> flags(256);
  for (std::size_t i = 0; i < flags.size(); ++i)
    flags[i] = static_cast<std::uint8_t>(255 - i);
  const double scalar = 2.5;
  {
    H5File file = H5File::create(path);
    file.writeDataset("/step_000010/fields/temperature", field, {3, 4}, "K");
    file.writeDataset("cube", cube.data(), {2, 2, 2});
    file.writeDataset("/ints", ints, {2, 1, 3});
    file.writeDataset("/step_000010/id", ids);
    file.writeDataset("/step_000010/flags", flags, {16, 16});
    file.writeDataset("/scalar", &scalar, {});
    file.writeDataset("/empty", std::vector<double>{}, {0, 3});
    file.commit();
  }
  const H5File file = H5File::openRead(path);
  std::vector<hsize_t> dims;
  EXPECT_TRUE(
      bitwiseEqual(file.readDataset<double>("/step_000010/fields/temperature", &dims), field));
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 4}));
  EXPECT_TRUE(bitwiseEqual(file.readDataset<float>("/cube", &dims), cube));
  EXPECT_EQ(dims, (std::vector<hsize_t>{2, 2, 2}));
  EXPECT_EQ(file.readDataset<std::int32_t>("/ints", &dims), ints);
  EXPECT_EQ(dims, (std::vector<hsize_t>{2, 1, 3}));
  EXPECT_EQ(file.readDataset<std::int64_t>("/step_000010/id", &dims), ids);
  EXPECT_EQ(dims, (std::vector<hsize_t>{4}));
  EXPECT_EQ(file.readDataset<std::uint8_t>("/step_000010/flags", &dims), flags);
  EXPECT_EQ(dims, (std::vector<hsize_t>{16, 16}));
  EXPECT_EQ(file.readDataset<double>("/scalar", &dims), std::vector<double>{2.5});
  EXPECT_TRUE(dims.empty());
  EXPECT_TRUE(file.readDataset<double>("/empty", &dims).empty());
  EXPECT_EQ(dims, (std::vector<hsize_t>{0, 3}));
  // Lossless widening is allowed: uint8 -> int32, float -> double, int32 -> int64.
  EXPECT_EQ(file.readDataset<std::int32_t>("/step_000010/flags")[0], 255);
  EXPECT_EQ(file.readDataset<double>("/cube")[7], 8.125);
  EXPECT_EQ(file.readDataset<std::int64_t>("/ints")[0], std::numeric_limits<std::int32_t>::min());

  EXPECT_TRUE(file.exists("/step_000010"));
  EXPECT_TRUE(file.exists("/step_000010/fields"));
  EXPECT_TRUE(file.exists("/"));
  EXPECT_FALSE(file.exists("/step_000011"));
  EXPECT_FALSE(file.exists("/step_000010/fields/temperature/deeper"));
  EXPECT_TRUE(file.isDataset("/step_000010/id"));
  EXPECT_FALSE(file.isDataset("/step_000010"));
  EXPECT_EQ(file.children("/"),
            (std::vector<std::string>{"cube", "empty", "ints", "scalar", "step_000010"}));
  EXPECT_EQ(file.children("/step_000010"), (std::vector<std::string>{"fields", "flags", "id"}));
  EXPECT_EQ(file.units("/step_000010/fields/temperature"), "K");
  EXPECT_EQ(file.units("/cube"), "");
}

TEST(io_hdf5, attributes_on_root_group_and_dataset) {
  ScratchDir dir("hdf5-attributes");
  const std::string path = dir.file("attrs.h5");
  const std::string longText(100000, 'y'); // above the 64 KiB compact attribute limit
  const std::vector<double> vector = awkwardDoubles(17);
  {
    H5File file = H5File::create(path);
    file.createGroup("/a/b");
    file.writeDataset("/a/b/velocity", std::vector<double>{1, 2, 3, 4}, {2, 2});
    file.setUnits("/a/b/velocity", "m/s");
    file.setAttribute("/", "title",
                      "rotary kiln \xc2\xb0"
                      "C"); // UTF-8 degree sign
    file.setAttribute("/", "empty", std::string());
    file.setAttribute("/", "long", longText);
    file.setAttribute("/", "pi", hikiln::constants::pi);
    file.setAttribute("/", "count", std::numeric_limits<std::int64_t>::min());
    file.setAttribute("/a", "origin", vector);
    file.setAttribute("/a", "nothing", std::vector<double>{});
    file.setAttribute("/a/b/velocity", "scale", 0.5);
    file.setAttribute("/a/b/velocity", "scale", 0.25); // replaces
    file.commit();
  }
  const H5File file = H5File::openRead(path);
  EXPECT_EQ(file.readStringAttribute("/", "title"), "rotary kiln \xc2\xb0"
                                                    "C");
  EXPECT_EQ(file.readStringAttribute("/", "empty"), "");
  EXPECT_EQ(file.readStringAttribute("/", "long"), longText);
  EXPECT_EQ(file.readDoubleAttribute("/", "pi"), hikiln::constants::pi);
  EXPECT_EQ(file.readInt64Attribute("/", "count"), std::numeric_limits<std::int64_t>::min());
  EXPECT_TRUE(bitwiseEqual(file.readDoubleVectorAttribute("/a", "origin"), vector));
  EXPECT_TRUE(file.readDoubleVectorAttribute("/a", "nothing").empty());
  EXPECT_EQ(file.readDoubleAttribute("/a/b/velocity", "scale"), 0.25);
  EXPECT_EQ(file.units("/a/b/velocity"), "m/s");
  EXPECT_EQ(file.attributeNames("/a/b/velocity"), (std::vector<std::string>{"scale", "units"}));
  EXPECT_TRUE(file.hasAttribute("/a", "origin"));
  EXPECT_FALSE(file.hasAttribute("/a", "missing"));
  EXPECT_FALSE(file.hasAttribute("/nowhere", "origin"));
  // Kind mismatches are errors, not silent conversions.
  EXPECT_NE(errorOf([&] { file.readDoubleAttribute("/", "title"); }).find("@title"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { file.readDoubleAttribute("/a", "origin"); }).find("single number"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { file.readStringAttribute("/", "pi"); }).find("not a single string"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { file.readInt64Attribute("/", "absent"); }).find("absent"),
            std::string::npos);
}

TEST(io_hdf5, standard_attributes) {
  ScratchDir dir("hdf5-standard");
  const std::string path = dir.file("run.h5");
  const std::string yaml = "case:\n  name: kiln\n  drum: {radius: 0.5}\n";
  const std::time_t before = std::time(nullptr);
  {
    H5File file = H5File::create(path);
    hikiln::io::writeStandardAttributes(file, {"dem", "OpenMP", yaml});
    file.commit();
  }
  const H5File file = H5File::openRead(path);
  EXPECT_EQ(file.readStringAttribute("/", "hikiln_version"), HIKILN_VERSION);
  EXPECT_EQ(file.readStringAttribute("/", "kokkos_version"), hikiln::kokkosVersionString());
  EXPECT_EQ(file.readStringAttribute("/", "backend"), "OpenMP");
  EXPECT_EQ(file.readStringAttribute("/", "stage"), "dem");
  EXPECT_EQ(file.readStringAttribute("/", "resolved_case"), yaml);
  const std::string created = file.readStringAttribute("/", "created");
  ASSERT_TRUE(std::regex_match(created, std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")))
      << created;
  std::tm utc{};
  ASSERT_NE(strptime(created.c_str(), "%Y-%m-%dT%H:%M:%SZ", &utc), nullptr);
  const std::time_t stamp = timegm(&utc);
  EXPECT_GE(stamp, before);
  EXPECT_LE(stamp, std::time(nullptr));
}

TEST(io_hdf5, errors_name_file_and_object) {
  ScratchDir dir("hdf5-errors");
  const std::string path = dir.file("e.h5");
  {
    H5File file = H5File::create(path);
    file.writeDataset("/x", std::vector<std::int64_t>{1, 2, 3});
    file.writeDataset("/d", std::vector<double>{1.0});
    EXPECT_NE(errorOf([&] { file.writeDataset("/x", std::vector<double>{1.0}); }).find("'/x'"),
              std::string::npos); // no silent overwrite
    EXPECT_NE(errorOf([&] {
                file.writeDataset("/y", std::vector<double>(5), {2, 2});
              }).find("do not fill"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { file.writeDataset("/x/under", std::vector<double>{1.0}); }).find(path),
              std::string::npos); // a dataset cannot be a group
    file.commit();
    EXPECT_NE(errorOf([&] { file.exists("/x"); }).find("closed"), std::string::npos);
  }
  const H5File file = H5File::openRead(path);
  const std::string missing = errorOf([&] { file.readDataset<double>("/step_000003/velocity"); });
  EXPECT_NE(missing.find("/step_000003/velocity"), std::string::npos) << missing;
  EXPECT_NE(missing.find(path), std::string::npos) << missing;
  EXPECT_NE(errorOf([&] { file.readDataset<double>("/x"); }).find("without loss"),
            std::string::npos); // int64 -> double could round
  EXPECT_NE(errorOf([&] { file.readDataset<float>("/d"); }).find("'/d'"), std::string::npos);
  EXPECT_NE(errorOf([&] { file.readDataset<std::uint8_t>("/x"); }).find("'/x'"), std::string::npos);
  EXPECT_NE(errorOf([&] { file.children("/x"); }).find("not a group"), std::string::npos);

  H5File readOnly = H5File::openRead(path);
  EXPECT_NE(errorOf([&] { readOnly.writeDataset("/z", std::vector<double>{1}); }).find("read-only"),
            std::string::npos);

  const std::string text = dir.file("notes.txt");
  hikiln::io::writeTextAtomically(text, "this is not an HDF5 file\n");
  const std::string notHdf5 = errorOf([&] { H5File::openRead(text); });
  EXPECT_NE(notHdf5.find(text), std::string::npos) << notHdf5;
  EXPECT_NE(notHdf5.find("not an HDF5 file"), std::string::npos) << notHdf5;
  const std::string absent = dir.file("absent.h5");
  EXPECT_NE(errorOf([&] { H5File::openRead(absent); }).find(absent), std::string::npos);
  const std::string noDir = dir.file("no/such/dir/f.h5");
  EXPECT_NE(errorOf([&] { H5File::create(noDir); }).find(noDir), std::string::npos);
}

TEST(io_hdf5, uncommitted_file_never_appears) {
  ScratchDir dir("hdf5-uncommitted");
  const std::string path = dir.file("never.h5");
  {
    H5File file = H5File::create(path);
    file.writeDataset("/x", std::vector<double>(1000, 1.0));
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_EQ(dir.entryCount(), 1u); // the temporary
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_EQ(dir.entryCount(), 0u); // temporary removed too
}

TEST(io_hdf5, move_keeps_one_owner) {
  ScratchDir dir("hdf5-move");
  const std::string path = dir.file("moved.h5");
  H5File first = H5File::create(path);
  first.writeDataset("/a", std::vector<std::int32_t>{7});
  H5File second = std::move(first);
  EXPECT_TRUE(second.writable());
  EXPECT_FALSE(first.writable()); // NOLINT(bugprone-use-after-move): checking the moved-from state
  second.writeDataset("/b", std::vector<std::int32_t>{8});
  second.commit();
  EXPECT_FALSE(second.writable());
  const H5File file = H5File::openRead(path);
  EXPECT_EQ(file.readDataset<std::int32_t>("/a"), std::vector<std::int32_t>{7});
  EXPECT_EQ(file.readDataset<std::int32_t>("/b"), std::vector<std::int32_t>{8});
}

TEST(io_hdf5, gzip_compresses_and_round_trips) {
  ScratchDir dir("hdf5-gzip");
  const std::size_t n = 200000;
  std::vector<double> smooth(n);
  for (std::size_t i = 0; i < n; ++i)
    smooth[i] = static_cast<double>(i % 100); // highly compressible
  for (int level : {0, 6}) {
    const std::string path = dir.file("gzip" + std::to_string(level) + ".h5");
    H5File file = H5File::create(path);
    file.writeDataset("/v", smooth, {n / 400, 400}, "", {level});
    file.commit();
    const auto size = std::filesystem::file_size(path);
    if (level == 0)
      EXPECT_GE(size, n * sizeof(double));
    else
      EXPECT_LT(size, n * sizeof(double) / 4);
    EXPECT_TRUE(bitwiseEqual(H5File::openRead(path).readDataset<double>("/v"), smooth));
  }
}

TEST(io_hdf5, step_group_names) {
  EXPECT_EQ(hikiln::io::stepGroupName(10), "/step_000010");
  EXPECT_EQ(hikiln::io::stepGroupName(1234567), "/step_1234567");
  EXPECT_EQ(hikiln::io::elementCount({}), 1u);
  EXPECT_EQ(hikiln::io::elementCount({3, 0, 2}), 0u);
  EXPECT_EQ(hikiln::io::elementCount({3, 5, 2}), 30u);
}

TEST(io_hdf5, no_open_objects_left_behind) {
  ScratchDir dir("hdf5-leaks");
  const std::string path = dir.file("leaks.h5");
  {
    H5File file = H5File::create(path);
    file.writeDataset("/g/x", std::vector<double>{1, 2}, {2}, "m");
    file.setAttribute("/g", "s", "text");
    file.setAttribute("/g/x", "v", std::vector<double>{1.0});
    EXPECT_THROW(file.writeDataset("/g/x/y", std::vector<double>{1}), std::runtime_error);
    file.commit();
    const H5File read = H5File::openRead(path);
    read.readDataset<double>("/g/x");
    read.readStringAttribute("/g", "s");
    read.attributeNames("/g/x");
    read.children("/g");
    EXPECT_THROW(read.readDataset<float>("/g/x"), std::runtime_error);
    EXPECT_THROW(read.readInt64Attribute("/g", "s"), std::runtime_error);
    EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 1); // just `read` itself
  }
  // Files, groups, datasets, attributes and named types of every file: all closed.
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}
