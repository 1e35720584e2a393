// Issue 16 items 1, 4 and 9 at the command line: no output path reaches a shell, a plot is
// written whole or not at all (full disk, directory target), devices are written in place,
// and an unknown command is named.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::quote;

using modaltyre_test::kConfig2d;
using modaltyre_test::kHammer12pt;

class CliOutputSafety : public modaltyre_test::CliFixture {
 protected:
  std::size_t entries() const {
    return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {}));
  }
  // Runs the CLI under a shell-imposed file-size limit of `limit_kB` (a full disk as seen by
  // the program: writes fail with EFBIG); stdout goes to /dev/null, stderr is returned.
  CliRun run_with_file_limit(int limit_kB, const std::vector<std::string>& args) {
    const fs::path err = dir_ / "stderr.txt";
    std::string inner = "ulimit -f " + std::to_string(limit_kB) + "; exec " + quote(MODALTYRE_CLI);
    for (const auto& a : args) inner += " " + quote(a);
    inner += " >/dev/null 2>" + quote(err.string());
    const int status = std::system(("bash -c " + quote(inner)).c_str());
    CliRun r;
    if (status != -1 && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    r.err = modaltyre_test::slurp(err);
    fs::remove(err);
    return r;
  }
};

// `--plot 'a$(touch X).svg'` and backquotes: the plot gets exactly that name, nothing runs.
TEST_F(CliOutputSafety, PlotPathWithShellSyntaxRunsNothing) {
  // The name holds no '/', so a shell would create the marker in the working folder.
  const std::string marker = "modaltyre_pwned_" + std::to_string(::getpid());
  const std::string plot = (dir_ / ("a$(touch " + marker + ")`touch " + marker + "`.svg")).string();
  const CliRun r = run({"footprint", kConfig2d, "--plot", plot});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(marker));
  EXPECT_FALSE(fs::exists(dir_ / marker));
  EXPECT_TRUE(fs::is_regular_file(plot));
}

// A full disk: the plot fails with a named message and non-zero exit, and no truncated plot
// or temporary file is left (footprint and fit-modes; every command plots through one path).
TEST_F(CliOutputSafety, FullDiskLeavesNoHalfWrittenPlot) {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"footprint", kConfig2d, "--plot", (dir_ / "fp.svg").string()},
           {"fit-modes", kHammer12pt, "--plot", (dir_ / "modes.svg").string()}}) {
    const CliRun r = run_with_file_limit(8, args);
    EXPECT_NE(r.exit_code, 0) << args[0];
    EXPECT_NE(r.err.find(args.back()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("writing the output file failed"), std::string::npos) << r.err;
    EXPECT_EQ(entries(), 0u) << args[0] << ": something was left behind";
  }
}

// A directory as plot target is refused; nothing is written into it.
TEST_F(CliOutputSafety, PlotOntoADirectoryLeavesNothing) {
  const fs::path d = dir_ / "plots.svg";
  fs::create_directories(d);
  const CliRun r = run({"footprint", kConfig2d, "--plot", d.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(d));
}

// `--output /dev/stdout` (run as root in CI) writes through the pipe; the device link is
// never replaced by a regular file.
TEST_F(CliOutputSafety, OutputToDevStdoutIsWrittenThrough) {
  const fs::path spec = dir_ / "one.yaml", out = dir_ / "piped.csv";
  std::ofstream(spec) << "base: " << kConfig2d << "\ngrid:\n  load_N: [3000]\noutput: x.csv\n";
  const std::string cmd = quote(MODALTYRE_CLI) + " sweep " + quote(spec.string()) +
                          " --output /dev/stdout 2>/dev/null | cat > " + quote(out.string());
  ASSERT_EQ(std::system(("bash -o pipefail -c " + quote(cmd)).c_str()), 0);
  EXPECT_NE(modaltyre_test::slurp(out).find("load_N"), std::string::npos);
  EXPECT_TRUE(fs::is_symlink("/dev/stdout") || fs::is_character_file("/dev/stdout"));
  EXPECT_FALSE(fs::exists(dir_ / "x.csv"));
}

TEST_F(CliOutputSafety, UnknownCommandIsNamedWithTheList) {
  const CliRun r = run({"foo", kConfig2d});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown command 'foo'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("footprint"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("discover"), std::string::npos) << r.err;
}

}  // namespace
