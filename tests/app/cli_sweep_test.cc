// `modaltyre sweep` end to end: byte-identical CSV for 1 and 2 threads, the JSON summary, a
// failed case is a row (exit 0 while some case succeeds, exit 1 when all fail), bad sweep files
// exit 2 naming file:line: key, and the output is never half-written (a missing output folder
// fails before anything is computed; a failing sweep leaves an existing output untouched).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::slurp;

using modaltyre_test::kConfig2d;
using modaltyre_test::kSrc;

class SweepCli : public modaltyre_test::CliFixture {
 protected:
  /// Writes a sweep file whose base is the shipped SF-350 config.
  std::string sweep(const std::string& body, const std::string& name = "s.yaml") {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << "base: " << kConfig2d << "\n" << body;
    return p.string();
  }

  /// The sweep file must exit 2 with "file:line: key" on stderr.
  void expect_bad(const std::string& body, int line, const std::string& key) {
    const std::string path = sweep(body);
    const CliRun r = run({"sweep", path});
    EXPECT_EQ(r.exit_code, 2) << body << "\n" << r.err;
    const std::string needle = path + ":" + std::to_string(line) + ": " + key;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "expected '" << needle << "' in\n" << r.err;
    EXPECT_EQ(r.err.find("sweep: "), std::string::npos) << "computed before failing:\n" << r.err;
  }
};

TEST_F(SweepCli, OneAndTwoThreadsWriteByteIdenticalCsv) {
  const std::string grid = kSrc + "/configs/sweeps/modulus_load_grid.yaml";
  const std::string a = (dir_ / "a.csv").string(), b = (dir_ / "b.csv").string();
  const CliRun r1 = run({"sweep", grid, "--threads", "1", "--output", a});
  const CliRun r2 = run({"sweep", grid, "--threads", "2", "--output", b, "--json"});
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  ASSERT_EQ(r2.exit_code, 0) << r2.err;
  const std::string ca = slurp(a);
  EXPECT_EQ(ca, slurp(b));
  // horizontal_force_N is given in set: (a condition): a column of its own.
  EXPECT_EQ(ca.substr(0, ca.find('\n')),
            "horizontal_force_N,tread.modulus_MPa,load_N,sinking_mm,length_mm,width_mm,"
            "rolling_resistance_N,vertical_stiffness_N_mm,peak_pressure_kPa,iterations,status,"
            "message,valid");
  EXPECT_EQ(std::count(ca.begin(), ca.end(), '\n'), 13);
  EXPECT_NE(ca.find("\n0,4,2000,"), std::string::npos);
  EXPECT_NE(ca.find("\n0,8,8000,"), std::string::npos);
  // Summary: on stderr always, as JSON on stdout with --json; no progress bar off a terminal.
  EXPECT_NE(r1.err.find("sweep: 12 cases (3 models), 0 failed"), std::string::npos) << r1.err;
  EXPECT_NE(r1.err.find("1 thread "), std::string::npos) << r1.err;
  EXPECT_EQ(r1.err.find('\r'), std::string::npos) << r1.err;
  EXPECT_TRUE(r1.out.empty()) << r1.out;
  const auto j = nlohmann::json::parse(r2.out);
  EXPECT_EQ(j.at("cases"), 12);
  EXPECT_EQ(j.at("failed"), 0);
  EXPECT_EQ(j.at("models"), 3);
  EXPECT_EQ(j.at("threads"), 2);
  EXPECT_EQ(j.at("output"), b);
  EXPECT_GT(j.at("wall_s").get<double>(), 0.0);
  EXPECT_GT(j.at("cases_per_s").get<double>(), 0.0);
}

TEST_F(SweepCli, OutputIsRelativeToTheSweepFileAndSetOverridesApply) {
  fs::create_directories(dir_ / "sub");
  const std::string path =
      sweep("grid:\n  load_N: [4000, 6000]\noutput: out/r.csv\n", "sub/s.yaml");
  fs::create_directories(dir_ / "sub" / "out");
  const CliRun r =
      run({"sweep", path, "--set", "tread.modulus_MPa=9", "--set", "horizontal_force_N=200"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = slurp(dir_ / "sub" / "out" / "r.csv");
  // A condition from --set is a column (before the grid's), a config key is not.
  EXPECT_EQ(csv.substr(0, csv.find(',', csv.find(',') + 1)), "horizontal_force_N,load_N") << csv;
  EXPECT_NE(csv.find("\n200,4000,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n200,6000,"), std::string::npos) << csv;
  // No temporary file is left next to the output.
  for (const auto& e : fs::directory_iterator(dir_ / "sub" / "out")) {
    EXPECT_EQ(e.path().filename().string(), "r.csv");
  }
}

TEST_F(SweepCli, AFailedCaseIsARowAndTheSweepStillSucceeds) {
  const std::string out = (dir_ / "r.csv").string();
  const std::string path =
      sweep("grid:\n  solver.max_iterations: [1, 200]\n  load_N: [5000]\noutput: " + out + "\n");
  const CliRun r = run({"sweep", path, "--threads", "2"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("1 failed"), std::string::npos) << r.err;
  const std::string csv = slurp(out);
  EXPECT_NE(csv.find("\n1,5000,,,,,,,,failed,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n200,5000,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",ok,"), std::string::npos) << csv;
}

TEST_F(SweepCli, AllCasesFailedExitsOneButKeepsTheRows) {
  const std::string out = (dir_ / "r.csv").string();
  const std::string path = sweep(
      "set:\n  solver.max_iterations: 1\ngrid:\n  load_N: [4000, 7000]\noutput: " + out + "\n");
  const CliRun r = run({"sweep", path});
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("all 2 cases failed"), std::string::npos) << r.err;
  const std::string csv = slurp(out);
  EXPECT_NE(csv.find("\n4000,,,,,,,,failed,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\n7000,,,,,,,,failed,"), std::string::npos) << csv;
}

TEST_F(SweepCli, BadSweepFilesExitTwoNamingFileLineAndKey) {
  expect_bad("grid:\n  load_N: [1000]\noutput: x.csv\nthreads: 2\n", 5, "threads");
  expect_bad("grid:\n  load_N: [1000]\n  tread.modulus_MPa: []\noutput: x.csv\n", 4,
             "grid.tread.modulus_MPa");
  expect_bad("grid:\n  load_N: [1000]\n  tread.modulus_mpa: [5, 6]\noutput: x.csv\n", 4,
             "grid.tread.modulus_mpa");
  expect_bad("grid:\n  load_N: [1000, 0]\noutput: x.csv\n", 3, "grid.load_N");
  expect_bad("set:\n  contact.unit_length_mm: 0.001\ngrid:\n  load_N: [1000]\noutput: x.csv\n", 3,
             "set.contact.unit_length_mm");
  expect_bad("grid:\n  tread.modulus_MPa: [5]\noutput: x.csv\n", 3, "load_N");
  expect_bad("grid:\n  load_N: [1000]\n", 1, "output");
  // Missing base.
  const fs::path p = dir_ / "nobase.yaml";
  std::ofstream(p) << "grid:\n  load_N: [1000]\noutput: x.csv\n";
  const CliRun r = run({"sweep", p.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(p.string() + ":1: base"), std::string::npos) << r.err;
}

TEST_F(SweepCli, BadConditionValuesExitTwoNamingFileLineAndKey) {
  // Text conditions are checked against their lists, on the line of the offending item.
  expect_bad("grid:\n  load_N: [4000]\n  branch: [load, sideways]\noutput: x.csv\n", 4,
             "grid.branch");
  expect_bad("grid:\n  load_N: [4000]\n  branch:\n    - unload\n    - up\noutput: x.csv\n", 6,
             "grid.branch");
  expect_bad("set:\n  surface: sand\ngrid:\n  load_N: [4000]\noutput: x.csv\n", 3, "set.surface");
  expect_bad("grid:\n  load_N: [4000]\n  pressure_kPa: [230, 0]\noutput: x.csv\n", 4,
             "grid.pressure_kPa");
  expect_bad("grid:\n  load_N: [4000]\n  speed_kmh: [500]\noutput: x.csv\n", 4, "grid.speed_kmh");
  expect_bad("grid:\n  load_N: [4000]\n  hold_s: [-1]\noutput: x.csv\n", 4, "grid.hold_s");
  // The reason is stated too.
  const CliRun r =
      run({"sweep", sweep("grid:\n  load_N: [4000]\n  branch: [up]\noutput: x.csv\n")});
  EXPECT_NE(r.err.find("'up' is not one of: load, unload"), std::string::npos) << r.err;
}

TEST_F(SweepCli, AnEffectAndConditionColumnsReachTheCsv) {
  const std::string out = (dir_ / "r.csv").string();
  const std::string path = sweep(
      "set:\n  effects.tread_relaxation.enabled: true\n  branch: load\n"
      "grid:\n  hold_s: [0, 600]\n  load_N: [4000]\noutput: " +
      out + "\n");
  const CliRun r = run({"sweep", path, "--threads", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = slurp(out);
  EXPECT_EQ(csv.substr(0, csv.find(',', csv.find(',', csv.find(',') + 1) + 1)),
            "branch,hold_s,load_N")
      << csv;
  // The held load creeps: the 600 s row sinks further than the 0 s one.
  const auto sinking = [&](const std::string& prefix) {
    const auto at = csv.find("\n" + prefix);
    EXPECT_NE(at, std::string::npos) << csv;
    return std::stod(csv.substr(at + 1 + prefix.size()));
  };
  EXPECT_GT(sinking("load,600,4000,"), 1.01 * sinking("load,0,4000,"));
}

TEST_F(SweepCli, OutputIntoAMissingFolderFailsBeforeComputing) {
  // 2000 cases would take seconds; the check must come first.
  std::string loads;
  for (int i = 1; i <= 2000; ++i) loads += (i > 1 ? ", " : "") + std::to_string(1000 + i);
  const std::string path = sweep("grid:\n  load_N: [" + loads +
                                 "]\noutput: " + (dir_ / "missing" / "r.csv").string() + "\n");
  const auto t0 = std::chrono::steady_clock::now();
  const CliRun r = run({"sweep", path});
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(path + ":4: output"), std::string::npos) << r.err;
  EXPECT_LT(s, 2.0);  // generous: a computed sweep of this size takes far longer
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

TEST_F(SweepCli, AFailingSweepLeavesAnExistingOutputUntouched) {
  const fs::path out = dir_ / "r.csv";
  std::ofstream(out) << "previous results\n";
  const std::string path =
      sweep("grid:\n  load_N: [1000]\n  tread.bogus: [1]\noutput: " + out.string() + "\n");
  const CliRun r = run({"sweep", path});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(slurp(out), "previous results\n");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_)) files += e.path().extension() == ".csv";
  EXPECT_EQ(files, 1);
}

}  // namespace
