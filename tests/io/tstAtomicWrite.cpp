// A process killed while replacing a file must leave the previous file intact: HDF5 files through
// H5File::create/commit and text files through AtomicFile/writeTextAtomically.
#include "drivers/io/AtomicFile.hpp"
#include "drivers/io/Hdf5File.hpp"
#include "io/IoTestSupport.hpp"

#include <gtest/gtest.h>

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>

namespace {
using hikiln::io::H5File;
using hikiln::io::test::ScratchDir;

// Runs `body` in a child process that tells the parent (through a pipe) when it has started
// writing. With killOnSignal the parent SIGKILLs the child as soon as it hears that; otherwise the
// child must kill itself. Returns the child's pid after it has been reaped; fails the test unless
// it died of SIGKILL.
pid_t runAndKill(const std::function<void(int notifyFd)>& body, bool killOnSignal) {
  int fds[2];
  if (::pipe(fds) != 0) {
    ADD_FAILURE() << "pipe: " << std::strerror(errno);
    return -1;
  }
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(fds[0]);
    try {
      body(fds[1]);
    } catch (...) {
      ::_exit(3);
    }
    ::_exit(4); // the body must not finish: it is killed first
  }
  ::close(fds[1]);
  char byte = 0;
  const bool started = ::read(fds[0], &byte, 1) == 1;
  ::close(fds[0]);
  if (killOnSignal && started)
    ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(started) << "the child never started writing";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
      << "child did not die of SIGKILL (status " << status << ")";
  return child;
}

void notify(int fd) {
  const char byte = 'w';
  if (::write(fd, &byte, 1) != 1)
    ::_exit(5);
}

// Temporary file AtomicFile uses for `target` in process `pid`; the killed child leaves it behind.
std::string orphanTemporary(const std::string& target, pid_t pid) {
  const std::filesystem::path p(target);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp-" + std::to_string(pid))).string();
}

const std::vector<double> oldValues = {1.0, -2.5, 3.25, 1e-300, 6.02214076e23};

void writeOldHdf5(const std::string& path) {
  H5File file = H5File::create(path);
  file.writeDataset("/data", oldValues, {5}, "m");
  file.setAttribute("/", "generation", std::int64_t(1));
  file.commit();
}

void expectOldHdf5(const std::string& path) {
  const H5File file = H5File::openRead(path);
  const std::vector<double> values = file.readDataset<double>("/data");
  ASSERT_EQ(values.size(), oldValues.size());
  EXPECT_EQ(std::memcmp(values.data(), oldValues.data(), values.size() * sizeof(double)), 0);
  EXPECT_EQ(file.units("/data"), "m");
  EXPECT_EQ(file.readInt64Attribute("/", "generation"), 1);
  EXPECT_EQ(file.children("/"), std::vector<std::string>{"data"});
}

constexpr std::size_t bigCount = std::size_t(1) << 20; // 8 MiB of doubles per dataset
} // namespace

TEST(io_atomic, hdf5_killed_by_parent_mid_write_keeps_old_file) {
  ScratchDir dir("atomic-h5-parent");
  const std::string path = dir.file("state.h5");
  writeOldHdf5(path);
  const pid_t child = runAndKill(
      [&](int fd) {
        H5File file = H5File::create(path);
        const std::vector<double> big(bigCount, 2.0);
        for (int i = 0; i < 32; ++i) {
          file.writeDataset("/big_" + std::to_string(i), big);
          if (i == 0)
            notify(fd);
        }
        std::raise(SIGKILL); // never reach commit, even if the parent was slow
      },
      true);
  // The child really was writing a replacement of the same path.
  const std::string orphan = orphanTemporary(path, child);
  ASSERT_TRUE(std::filesystem::exists(orphan));
  EXPECT_GE(std::filesystem::file_size(orphan), bigCount * sizeof(double));
  std::filesystem::remove(orphan);
  expectOldHdf5(path);
}

TEST(io_atomic, hdf5_child_killed_before_commit_keeps_old_file) {
  ScratchDir dir("atomic-h5-self");
  const std::string path = dir.file("state.h5");
  writeOldHdf5(path);
  const pid_t child = runAndKill(
      [&](int fd) {
        H5File file = H5File::create(path);
        file.writeDataset("/data", std::vector<double>(bigCount, 9.0));
        file.setAttribute("/", "generation", std::int64_t(2));
        notify(fd);
        std::raise(SIGKILL);
      },
      false);
  std::filesystem::remove(orphanTemporary(path, child));
  expectOldHdf5(path);
}

TEST(io_atomic, text_child_killed_before_commit_keeps_old_file) {
  ScratchDir dir("atomic-text-self");
  const std::string path = dir.file("summary.json");
  const std::string oldText = "{\"generation\": 1}\n";
  hikiln::io::writeTextAtomically(path, oldText);
  const pid_t child = runAndKill(
      [&](int fd) {
        hikiln::io::AtomicFile file(path);
        std::ofstream out(file.temporaryPath(), std::ios::binary);
        out << std::string(1 << 20, 'n');
        out.flush();
        notify(fd);
        std::raise(SIGKILL);
      },
      false);
  const std::string orphan = orphanTemporary(path, child);
  EXPECT_EQ(std::filesystem::file_size(orphan), std::size_t(1) << 20);
  std::filesystem::remove(orphan);
  EXPECT_EQ(hikiln::io::test::readWholeFile(path), oldText);
}

TEST(io_atomic, text_killed_during_write_is_old_or_new_never_partial) {
  ScratchDir dir("atomic-text-parent");
  const std::string path = dir.file("big.txt");
  const std::string oldText(1000, 'o');
  std::string newText(std::size_t(64) << 20, 'N'); // 64 MiB: takes long enough to be interrupted
  newText.back() = '\n';
  hikiln::io::writeTextAtomically(path, oldText);
  const pid_t child = runAndKill(
      [&](int fd) {
        notify(fd);
        hikiln::io::writeTextAtomically(path, newText);
        std::raise(SIGKILL); // finished before the parent's kill arrived: still die by SIGKILL
      },
      true);
  std::error_code ec;
  std::filesystem::remove(orphanTemporary(path, child), ec);
  const std::string content = hikiln::io::test::readWholeFile(path);
  EXPECT_TRUE(content == oldText || content == newText)
      << "partial file of " << content.size() << " bytes";
}
