// Output files are written whole or not at all, and leave no temporary files behind.
#include "modaltyre/core/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

}  // namespace
}  // namespace modaltyre
