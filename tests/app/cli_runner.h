#pragma once
// Runs the built `modaltyre` binary (MODALTYRE_CLI) in a fresh temporary folder per test and
// captures its exit code, stdout and stderr. Shared by the CLI end-to-end tests.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace modaltyre_test {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;  ///< -1 when killed by a signal
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Single-quotes a word for /bin/sh.
inline std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'') {
      q.append("'\\''");
    } else {
      q.push_back(c);
    }
  }
  q.push_back('\'');
  return q;
}

class CliFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("modaltyre_cli_") + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CliRun run(const std::vector<std::string>& args) { return run_with("", args); }

  /// The CLI behind a shell prefix (e.g. "timeout 60", "env OMP_NUM_THREADS=2"); the prefix is
  /// the test's own text, the arguments are quoted.
  CliRun run_with(const std::string& prefix, const std::vector<std::string>& args) {
    std::string cmd = (prefix.empty() ? "" : prefix + " ") + quote(MODALTYRE_CLI);
    for (const auto& a : args) cmd.append(" ").append(quote(a));
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    cmd.append(" >").append(quote(out.string())).append(" 2>").append(quote(err.string()));
    const int status = std::system(cmd.c_str());
    CliRun r;
    if (status != -1 && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  fs::path dir_;
};

}  // namespace modaltyre_test
