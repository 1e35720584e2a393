// Issue 44 item 5 at the command line: careless and hostile input on the commands added last
// round (init, the CSV readers, --uncertainty) exits 2 with one message naming the file, line
// and key or the option, changes no input and leaves no output behind.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/hammer_lines.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::slurp;

const std::string kSrc = MODALTYRE_SOURCE_DIR;

class CliCareless : public modaltyre_test::CliFixture {
 protected:
  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  CliRun run_limited(const std::vector<std::string>& args) { return run_with("timeout 120", args); }

  /// Exit 2 and every needle in the one error line; stdout empty.
  void expect_input_error(const CliRun& r, const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.out, "") << "stdout of a refused input";
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << n << "\n" << r.err;
  }
};

// A Latin-1 byte in a comment line of each CSV the commands read through core's one reader
// (hammer data, a bevameter test, a road profile) is refused at its line, as YAML refuses it.
TEST_F(CliCareless, NonUtf8CommentsInTheCsvFilesAreRefusedAtTheirLine) {
  std::string hammer =
      "# measured at 20 \xB0"
      "C\n";
  for (const auto& l : modaltyre_test::hammer_lines()) hammer += l + "\n";
  const std::string h = write("hammer.csv", hammer);
  expect_input_error(run_limited({"fit-modes", h}), {h + ":1: comment:", "\\xB0 is not UTF-8"});

  std::string plate = slurp(kSrc + "/tests/data/soil/plate_sinkage.csv");
  plate.insert(plate.find('\n') + 1, "# sol sabl\xE9\n");
  const std::string b = write("plate.csv", plate);
  const std::string before = slurp(b);
  expect_input_error(run_limited({"identify", "bevameter", b}),
                     {b + ":2: comment:", "\\xE9 is not UTF-8"});
  EXPECT_EQ(slurp(b), before);

  const std::string road = write("road.csv", "x_m,height_m\n-1,0\n# bosse \xE0 0 m\n0,0.01\n1,0\n");
  const std::string ground =
      write("road.yaml", "ground:\n  model: profile\n  profile_csv: road.csv\n");
  expect_input_error(run_limited({"footprint", kSrc + "/configs/sf350_2d_table3.yaml", "--load",
                                  "3000", "--ground", ground}),
                     {road + ":3: comment:", "\\xE0 is not UTF-8"});
}

}  // namespace
