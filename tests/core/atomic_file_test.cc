// Output files are written whole or not at all, and leave no temporary files behind.
#include "modaltyre/core/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("modaltyre_atomic_") + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {}));
  }
  fs::path dir_;
};

// New file and overwrite both give exactly the content (binary-safe), no temp file remains.
TEST_F(AtomicFile, WritesAndOverwrites) {
  const fs::path p = dir_ / "out.json";
  std::string content = "first\n";
  content.push_back('\0');
  content += "\xff tail";
  write_file_atomically(p.string(), content);
  EXPECT_EQ(slurp(p), content);
  write_file_atomically(p.string(), "second");
  EXPECT_EQ(slurp(p), "second");
  EXPECT_EQ(entries(), 1u);
}

// A missing folder is an InputError naming the path; nothing is created.
TEST_F(AtomicFile, MissingFolder) {
  const std::string p = (dir_ / "no_such_dir" / "out.txt").string();
  try {
    write_file_atomically(p, "x");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, p);
  }
  EXPECT_EQ(entries(), 0u);
}

// A directory as target is refused and left untouched.
TEST_F(AtomicFile, DirectoryTarget) {
  const fs::path d = dir_ / "sub";
  fs::create_directories(d);
  EXPECT_THROW(write_file_atomically(d.string(), "x"), InputError);
  EXPECT_TRUE(fs::is_directory(d));
  EXPECT_EQ(entries(), 1u);
}

// A symbolic link stays a link; the file it points to gets the content.
TEST_F(AtomicFile, SymlinkIsFollowedNotReplaced) {
  const fs::path real = dir_ / "real.csv", link = dir_ / "link.csv";
  std::ofstream(real) << "old";
  fs::create_symlink(real, link);
  write_file_atomically(link.string(), "new");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(slurp(real), "new");
  EXPECT_EQ(entries(), 2u);
}

// A dangling link stays a link too: the file it names is created (the file CommandFiles compared
// with the command's other files, command_files.h final_target), relative to the link's folder.
TEST_F(AtomicFile, DanglingSymlinkCreatesItsTarget) {
  const fs::path link = dir_ / "link.svg";
  fs::create_symlink("made.csv", link);
  write_file_atomically(link.string(), "new");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(slurp(dir_ / "made.csv"), "new");
  EXPECT_EQ(entries(), 2u);
}

// An overwrite keeps the file's permissions.
TEST_F(AtomicFile, OverwriteKeepsPermissions) {
  const fs::path p = dir_ / "out.csv";
  std::ofstream(p) << "old";
  fs::permissions(p, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  write_file_atomically(p.string(), "new");
  EXPECT_EQ(fs::status(p).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

// Devices are written in place, never replaced by a regular file (e.g. /dev/null run as
// root); a device that refuses the bytes (/dev/full: "no space left") is an error.
TEST_F(AtomicFile, DevicesAreWrittenInPlace) {
  write_file_atomically("/dev/null", "discarded");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  if (fs::exists("/dev/full")) {
    EXPECT_THROW(write_file_atomically("/dev/full", std::string(1 << 16, 'x')), InputError);
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
  }
}

// A named pipe is written through (a reader gets the bytes), not replaced.
TEST_F(AtomicFile, NamedPipeIsWrittenThrough) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string got;
  std::thread reader([&] { got = slurp(fifo); });
  write_file_atomically(fifo.string(), "through the pipe");
  reader.join();
  EXPECT_EQ(got, "through the pipe");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

}  // namespace
}  // namespace modaltyre
