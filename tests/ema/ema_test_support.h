#pragma once
// A scratch folder per test and a check that an InputError names file, line and field.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "modaltyre/core/errors.h"

namespace modaltyre_test {

namespace fs = std::filesystem;

class ScratchDir : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "_" + info->name();
    for (char& c : name) {
      if (c == '/') c = '_';
    }
    dir_ = fs::temp_directory_path() / ("modaltyre_ema_" + std::to_string(::getpid()) + "_" + name);
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& content, const std::string& name) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  fs::path dir_;
};

/// Runs `read`, expects an InputError whose location is (path, line) and whose key contains
/// `field`; returns the message for further checks.
inline std::string expect_input_error(const std::function<void()>& read, const std::string& path,
                                      int line, const std::string& field) {
  try {
    read();
  } catch (const modaltyre::InputError& e) {
    EXPECT_EQ(e.where().file, path) << e.what();
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_NE(e.where().key.find(field), std::string::npos)
        << "key '" << e.where().key << "' lacks '" << field << "': " << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no InputError for " << path;
  return "";
}

}  // namespace modaltyre_test
