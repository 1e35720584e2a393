// The pre-read checks shared by the CSV, YAML, .tir and UFF readers (core/input_file.h): each
// refusal names the file before a byte is read; a pipe is refused, not waited on.
#include "modaltyre/core/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "modaltyre/core/errors.h"

namespace {

namespace fs = std::filesystem;
using modaltyre::InputError;

class InputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("modaltyre_input_file_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string refusal(const std::string& path, std::uintmax_t max_bytes = 1u << 20) {
    try {
      modaltyre::read_input_file(path, "a test file", "test files", max_bytes);
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().file, path);
      EXPECT_EQ(e.where().line, 0);
      return e.what();
    }
    ADD_FAILURE() << path << " accepted";
    return "";
  }

  fs::path dir_;
};

TEST_F(InputFile, ReadsARegularFileWhole) {
  const std::string p = (dir_ / "a.txt").string();
  { std::ofstream(p, std::ios::binary) << "x\r\ny"; }
  EXPECT_EQ(modaltyre::read_input_file(p, "a test file", "test files", 100), "x\r\ny");
}

TEST_F(InputFile, RefusesMissingDirectoryPipeAndOversize) {
  EXPECT_NE(refusal((dir_ / "none").string()).find("file not found"), std::string::npos);
  EXPECT_NE(refusal(dir_.string()).find("is a directory, not a test file"), std::string::npos);
  const std::string fifo = (dir_ / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(refusal(fifo).find("not a regular file"), std::string::npos);
  const std::string big = (dir_ / "big").string();
  { std::ofstream(big) << "x"; }
  fs::resize_file(big, (3u << 20) + 1);  // sparse
  EXPECT_NE(refusal(big, 2u << 20).find("is 4 MB; refusing test files over 2 MB"),
            std::string::npos)
      << refusal(big, 2u << 20);
}

TEST(FileSizeText, BytesBelowAMegabyteElseWholeMegabytesRoundedUp) {
  EXPECT_EQ(modaltyre::file_size_text(512), "512 bytes");
  EXPECT_EQ(modaltyre::file_size_text(1u << 20), "1 MB");
  EXPECT_EQ(modaltyre::file_size_text((1u << 20) + 1), "2 MB");
}

}  // namespace
