// Issue 44 item 5 at the command line: careless and hostile input on the commands added last
// round (init, the CSV readers, --uncertainty) exits 2 with one message naming the file, line
// and key or the option, changes no input and leaves no output behind.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "../support/hammer_lines.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::slurp;

using modaltyre_test::kSrc;

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

// A run that fails leaves none of its outputs: the band of a 50 % belt width fails at a sample
// (exit 1, the computation's error), and neither the plot nor the map is written.
TEST_F(CliCareless, AFailedBandLeavesNoOutput) {
  const std::string plot = (dir_ / "p.svg").string(), map = (dir_ / "m.csv").string();
  const CliRun r =
      run_limited({"footprint", kSrc + "/configs/sf350_init.yaml", "--load", "4000",
                   "--uncertainty", "--uncertainty-method", "sampled", "--set",
                   "modal.belt_width_std_percent=50", "--map-csv", map, "--plot", plot});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("sample"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(plot));
  EXPECT_FALSE(fs::exists(map));
}

// The Monte Carlo sample count is bounded, the option named (100 000 samples: about 1 h on the
// default footprint); the bound itself is accepted.
TEST_F(CliCareless, UncertaintySamplesAreBounded) {
  for (const char* cmd : {"footprint", "validate"}) {
    std::vector<std::string> args = {cmd, kSrc + "/configs/sf350_2d_table3.yaml"};
    if (std::string(cmd) == "validate")
      args.push_back(kSrc + "/configs/data/sf350_footprint_table3.csv");
    for (const char* w : {"--uncertainty", "--samples", "100000"}) args.push_back(w);
    expect_input_error(run_limited(args), {"--samples: ", "100000 is outside [20, 2000] samples"});
  }
  const CliRun ok = run_limited({"footprint", kSrc + "/configs/sf350_2d_table3.yaml", "--load",
                                 "3000", "--uncertainty", "--samples", "2000", "--json"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

// init: a given number <= 0 is refused at its option, never read as "not given"; an empty list
// item, --orders with --hammer, frequencies that make a ring of tonnes per metre, a name that
// would break out of the header comment and a range the config reader refuses are named by the
// option. Nothing is written.
TEST_F(CliCareless, InitRefusesCarelessOptionsByName) {
  const std::string out = (dir_ / "out.yaml").string();
  const std::vector<std::string> base = {"init", "--size",   "205/55R16", "--test-pressure-kPa",
                                         "200",  "--output", out};
  const std::string freqs = "90,105,124,146,170,195";
  auto init = [&](std::vector<std::string> extra, bool with_list = true) {
    std::vector<std::string> args = base;
    if (with_list) args.insert(args.end(), {"--frequencies", freqs});
    args.insert(args.end(), extra.begin(), extra.end());
    return run_limited(args);
  };
  const std::vector<std::pair<std::string, std::string>> not_positive = {
      {"--pressure-kPa", "0"},   {"--pressure-kPa", "-1"}, {"--belt-mass-kg", "0"},
      {"--wheel-mass-kg", "-7"}, {"--belt-width-mm", "0"}, {"--tread-depth-mm", "-8"},
      {"--tread-width-mm", "0"}, {"--fnomin", "0"},        {"--fnomin", "-4000"}};
  for (const auto& [option, value] : not_positive) {
    expect_input_error(init({option, value}), {option + ": ", "> 0, got " + value});
  }
  expect_input_error(init({"--belt-width-mm", "300"}), {"--belt-width-mm: ", "section width 205"});
  expect_input_error(init({"--tread-depth-mm", "0.05"}),
                     {"--tread-depth-mm: ", "[0.1, 200]", "tread.thickness_mm"});
  expect_input_error(run_limited({"init", "--size", "205/55R16", "--test-pressure-kPa", "200",
                                  "--frequencies", "90,,124,146,170,195", "--output", out}),
                     {"--frequencies: ", "item 2 of 6 is empty"});
  expect_input_error(init({"--damping", "0.03,0.04,", "--orders", "1,2,3,4,5,6"}),
                     {"--damping: ", "item 3 of 3 is empty"});
  expect_input_error(
      init({"--hammer", kSrc + "/configs/data/sf350_hammer_12pt.csv", "--orders", "1,2,3"}, false),
      {"--orders: ", "belongs to --frequencies"});
  expect_input_error(
      run_limited({"init", "--size", "205/55R16", "--test-pressure-kPa", "200", "--frequencies",
                   "1,1.1,1.2,1.3,1.4,1.5", "--orders", "1,2,3,4,5,6", "--output", out}),
      {"--frequencies: ", "kg/m", "in Hz?"});
  expect_input_error(init({"--name", "x\nground:\n  model: bekker\n#"}),
                     {"--name: ", "control character \\x0A"});
  EXPECT_FALSE(fs::exists(out)) << "a refused init wrote its config";
  // Left out, the same options take their stated defaults.
  const CliRun ok = init({});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::exists(out));
}

}  // namespace
