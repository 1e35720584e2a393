// Issue 9 at the command line: hostile input files make `modaltyre` exit 2 with one message on
// stderr naming the file (and line and column where there is one), print nothing that looks like
// a result on stdout, and never hang. A sweep's quoted CSV is valid measured data.
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "../support/hammer_lines.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;

using modaltyre_test::kConfig2d;
using modaltyre_test::kSrc;

class CliHostile : public modaltyre_test::CliFixture {
 protected:
  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  /// Runs the CLI with a 60 s limit (a hang shows as exit code 124, not a stuck test).
  CliRun run_limited(const std::vector<std::string>& args) { return run_with("timeout 60", args); }

  /// Exit 2, a single "error: " line on stderr holding every needle, nothing on stdout.
  void expect_input_error(const CliRun& r, const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.out, "") << "stdout of a refused input";
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one message: " << r.err;
    for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << n << "\n" << r.err;
  }
};

TEST_F(CliHostile, IdentifyLoadDeflectionOnADirectory) {
  const std::string d = (dir_ / "tests.csv").string();
  fs::create_directories(d);
  expect_input_error(run_limited({"identify", "load-deflection", d, "--r0-mm", "295"}),
                     {d + ": is a directory"});
}

TEST_F(CliHostile, ValidateNonUtf8File) {
  // Latin-1 "12,5" with a degree sign in a number cell (data row 2, file line 3).
  const std::string p = write("non_utf8.csv",
                              "load_N,sinking_mm,length_mm\n"
                              "2131,8,86\n"
                              "3261,12\xB0,112\n");
  expect_input_error(run_limited({"validate", kConfig2d, p}),
                     {p + ":3: sinking_mm: ", "'12\\xB0' is not a finite number", "not UTF-8"});
}

TEST_F(CliHostile, ValidateNamedPipeDoesNotHang) {
  const std::string fifo = (dir_ / "measured.csv").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_input_error(run_limited({"validate", kConfig2d, fifo}), {fifo, "not a regular file"});
}

TEST_F(CliHostile, FitModesHeaderOnly) {
  const std::string p = write("hammer.csv", modaltyre_test::hammer_lines()[0] + "\n");
  expect_input_error(run_limited({"fit-modes", p}), {p + ":1: header only, no data rows"});
}

TEST_F(CliHostile, FitModesUnterminatedQuote) {
  auto l = modaltyre_test::hammer_lines();
  modaltyre_test::set_field(l, 4, 5, "\"0.6");
  std::string s;
  for (const auto& x : l) s += x + "\n";
  const std::string p = write("hammer.csv", s);
  expect_input_error(run_limited({"fit-modes", p}), {p + ":4: radial: unterminated quoted field"});
}

// The measured data written as a sweep writes them (status and a quoted message with a comma)
// are validated like the plain table.
TEST_F(CliHostile, ValidateReadsASweepStyleQuotedCsv) {
  std::ifstream in(kSrc + "/configs/data/sf350_footprint_table3.csv");
  std::string s, line;
  for (bool header = true; std::getline(in, line); header = false) {
    s += line + (header ? ",status,message\n" : ",ok,\"converged, \"\"measured\"\"\"\n");
  }
  const std::string p = write("sweep_style.csv", s);
  const CliRun r = run_limited({"validate", kConfig2d, p});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("8321"), std::string::npos) << r.out;
}

// Issue 16 item 2: a key twice (here tread.modulus_MPa) used to keep the first value, exit 0.
TEST_F(CliHostile, FootprintConfigWithAKeyTwice) {
  std::string text = modaltyre_test::slurp(kConfig2d);
  const std::string line = "  modulus_MPa: 0.99096\n";
  const auto at = text.find(line);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + line.size(), "  modulus_MPa: 5.0\n");
  const int first = static_cast<int>(std::count(text.begin(), text.begin() + at, '\n')) + 1;
  const std::string p = write("twice.yaml", text);
  expect_input_error(run_limited({"footprint", p}),
                     {p + ":" + std::to_string(first + 1) + ": tread.modulus_MPa: ",
                      "first at line " + std::to_string(first)});
}

// Issue 16 item 3: an alias bomb in a config or a sweep is refused at once.
TEST_F(CliHostile, AliasBombsAreRefused) {
  std::string bomb = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < 12; ++i) {
    std::string items;
    for (int k = 0; k < 10; ++k) items += (k ? ", *a" : "*a") + std::to_string(i - 1);
    bomb += "a" + std::to_string(i) + ": &a" + std::to_string(i) + " [" + items + "]\n";
  }
  const std::string p = write("bomb.yaml", bomb);
  expect_input_error(run_limited({"footprint", p}), {p + ":2: a1: ", "aliases"});
  expect_input_error(run_limited({"sweep", p}), {p + ":2: a1: ", "aliases"});
  expect_input_error(run_limited({"footprint", kConfig2d, "--set", "modal.x=[&a [1], *a]"}),
                     {"--set: modal.x: ", "aliases"});
}

// Issue 16 item 3: the sweep reader now refuses devices like every other reader.
TEST_F(CliHostile, SweepSpecThatIsADevice) {
  expect_input_error(run_limited({"sweep", "/dev/zero"}), {"/dev/zero: ", "not a regular file"});
}

// Issue 16 item 2: "tread.modulus_MPa: 5" at the top of a config used to pass as the nested key
// that was read (its value ignored, exit 0); a key set twice in a sweep's set: through a
// dotted and a nested spelling kept one of them.
TEST_F(CliHostile, DottedKeyInAConfigAndTwiceInASweepSet) {
  const std::string text = modaltyre_test::slurp(kConfig2d);
  const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  std::string cfg = text;
  const std::string hammer = "hammer_csv: data/";
  cfg.replace(cfg.find(hammer), hammer.size(), "hammer_csv: " + kSrc + "/configs/data/");
  const std::string p = write("dotted.yaml", cfg + "tread.modulus_MPa: 5\n");
  expect_input_error(run_limited({"footprint", p}),
                     {p + ":" + std::to_string(lines + 1) + ": tread.modulus_MPa: ",
                      "a key with '.' is not read in a config file"});
  const std::string s = write("sweep.yaml", "base: " + kConfig2d +
                                                "\nset:\n  tread.modulus_MPa: 3\n"
                                                "  tread: {modulus_MPa: 4}\n"
                                                "grid:\n  load_N: [3000]\noutput: x.csv\n");
  expect_input_error(run_limited({"sweep", s}),
                     {s + ":4: set.tread.modulus_MPa: ", "twice in set (first at line 3)"});
}

// Issue 16 item 4: a result printed onto a full disk (here /dev/full) is a failure, not exit 0;
// so is the help text (the audit found --help and --version exiting 0 there).
TEST_F(CliHostile, StdoutOnAFullDiskIsAnError) {
  const std::vector<std::string> commands = {
      " footprint " + modaltyre_test::quote(kConfig2d) + " --load 3000", " --help",
      " footprint --help", " --version"};
  for (const std::string& args : commands) {
    const std::string cmd = modaltyre_test::quote(MODALTYRE_CLI) + args + " >/dev/full 2>" +
                            modaltyre_test::quote((dir_ / "err.txt").string());
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2) << args;
    EXPECT_NE(modaltyre_test::slurp(dir_ / "err.txt")
                  .find("writing the result to standard output failed"),
              std::string::npos)
        << args;
  }
}

// Issue 16 item 3: step counts and sizes from options are bounded with a message naming the
// option and the bound (each ran for minutes or until out of memory).
TEST_F(CliHostile, TransientOutputStepAndSampleCountAreBounded) {
  expect_input_error(run_limited({"transient", kConfig2d, "--scenario", "load-hold", "--set",
                                  "transient.output_step_ms=1e-308"}),
                     {"--set: transient.output_step_ms: ", "out of range [0.001, "});
  // 1 us over the 121 s hold: 1.21e8 samples.
  expect_input_error(
      run_limited({"transient", kConfig2d, "--scenario", "load-hold", "--set",
                   "transient.output_step_ms=0.001"}),
      {"transient.output_step_ms: ", "1.21e+08 samples; at most 1e+06", "at least 0.121 ms"});
  expect_input_error(
      run_limited({"transient", kConfig2d, "--scenario", "load-hold", "--set",
                   "transient.load_hold.hold_s=1e6", "--set", "transient.output_step_ms=2"}),
      {"transient.output_step_ms: ", "5e+08 samples; at most 1e+06"});
  // The chosen grid (output_step_ms: auto) coarsens to at most 1e6 samples and says so.
  const auto r = run_limited({"transient", kConfig2d, "--scenario", "load-hold", "--set",
                              "transient.load_hold.hold_s=1e6", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_LE(j["samples"].get<double>(), 1e6 + 2);
  EXPECT_NE(j["output_grid"].get<std::string>().find("at most 1e+06 samples"), std::string::npos)
      << j["output_grid"];
}

TEST_F(CliHostile, BFactorSamplesAreBounded) {
  expect_input_error(run_limited({"identify", "b-factors", "--samples", "2147483647"}),
                     {"--samples: ", "need 3 to 100000 samples, got 2147483647"});
}

// Issue 16 item 3: one mode at 4000 points (a dense QR of 4000 columns took 45 s) and one at
// 10^6 points (the reader's row limit) are fitted; orders above the fitted range are named.
TEST_F(CliHostile, HammerFilesWithManyPointsAreFitted) {
  for (int N : {4000, 1000000}) {
    std::string s = modaltyre_test::hammer_lines(1, 1).front() + "\n";
    s.reserve(static_cast<std::size_t>(N) * 48);
    for (int i = 0; i < N; ++i) {
      const double th = 2 * M_PI * i / N;
      char line[160];
      std::snprintf(line, sizeof line, "1,120,0.03,%d,%.9f,%.6f,%.6f\n", i + 1, 360.0 * i / N,
                    0.6 * std::cos(3 * th), 0.3 * std::sin(3 * th));
      s += line;
    }
    const std::string p = write("hammer.csv", s);
    const CliRun r = run_limited({"fit-modes", p});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("1 modes at " + std::to_string(N) + " equally spaced points"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("orders above 50 are not fitted"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("radial          3  no       1.0000"), std::string::npos) << r.out;
  }
}

// Issue 16 item 5: extreme numbers are input errors naming the option, file or column and the
// range, in every command (README, "Input ranges"), not failed computations or results.
TEST_F(CliHostile, ExtremeNumbersAreInputErrorsWithTheirRange) {
  const std::string rh = kSrc + "/tests/data/rheology/";
  expect_input_error(run_limited({"footprint", kConfig2d, "--load", "1e308"}),
                     {"--load", "1e308 is outside [1e-6, 1e7] N"});
  expect_input_error(run_limited({"footprint", kConfig2d, "--load", "nan"}),
                     {"--load", "is not a finite number"});
  expect_input_error(run_limited({"footprint", kConfig2d, "--load", "5000", "--fx", "-1e308"}),
                     {"--fx", "-1e308 is outside [-1e7, 1e7] N"});
  expect_input_error(
      run_limited({"footprint", kConfig2d, "--set", "tyre.inflation_pressure_kPa=1e308"}),
      {"tyre.inflation_pressure_kPa", "out of range"});
  expect_input_error(run_limited({"identify", "load-deflection", rh + "load_deflection.csv",
                                  "--r0-mm", "294.8", "--pressure-kPa", "1e308"}),
                     {"--pressure-kPa", "outside [0, 10000] kPa", "gauge pressure"});
  expect_input_error(
      run_limited({"identify", "load-deflection", rh + "load_deflection.csv", "--r0-mm", "1e308"}),
      {"--r0-mm", "outside (0, 5000] mm"});
  expect_input_error(run_limited({"identify", "free-vibration", rh + "free_vibration.csv",
                                  "--mass-kg", "1e308", "--contact-length-mm", "120"}),
                     {"--mass-kg", "outside (0, 100000] kg", "test rig"});
  expect_input_error(run_limited({"identify", "free-vibration", rh + "free_vibration.csv",
                                  "--mass-kg", "30", "--contact-length-mm", "1e308"}),
                     {"--contact-length-mm", "outside (0, 10000] mm"});
  expect_input_error(run_limited({"identify", "contact-stress", rh + "contact_stress.csv",
                                  "--r0-mm", "294.8", "--tread-width-mm", "1e308"}),
                     {"--tread-width-mm", "outside (0, 5000] mm"});
  expect_input_error(run_limited({"identify", "b-factors", "--r0-mm", "1e308"}),
                     {"--r0-mm", "outside (0, 5000] mm"});
  expect_input_error(
      run_limited({"discover", kConfig2d, kSrc + "/configs/data/sf350_footprint_table3.csv",
                   "--unit-length-mm", "1e308"}),
      {"--unit-length-mm"});

  // A hammer frequency of 1e308 Hz (fit-modes, and footprint through the config's hammer file).
  std::vector<std::string> lines = modaltyre_test::hammer_lines();
  modaltyre_test::set_field(lines, 2, 1, "1e308");
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  const std::string hammer = write("hammer.csv", text);
  expect_input_error(run_limited({"fit-modes", hammer}), {hammer, ":2", "freq_hz", "(0, 1e5] Hz"});
  expect_input_error(run_limited({"footprint", kConfig2d, "--set", "modal.hammer_csv=" + hammer}),
                     {hammer, ":2", "freq_hz", "(0, 1e5] Hz"});

  // Measured rows: a hold time of 1e308 s.
  const std::string held = write("held.csv", "load_N,hold_s,sinking_mm\n2000,0,8\n3000,1e308,12\n");
  expect_input_error(run_limited({"validate", kConfig2d, held}),
                     {held, ":3", "hold_s", "[0, 1e7] s"});
}

// Issue 16 audit ("Done when", checked at check time): the other end of the ranges and the
// inputs that only the config names. A load of 1e-300 N printed a mean pressure of inf on the 3D
// patch (exit 0); --max-h-r0 1e-308 failed as a computation (exit 1); --band 80:1e308 was taken;
// a config's hammer file that is a device or missing, and a sweep's base: that is a device, were
// named without the config's line and key (or as "not found").
TEST_F(CliHostile, TinyAndOutOfRangeNumbersAreInputErrors) {
  const std::string sweep = write("tiny.yaml", "base: " + kConfig2d +
                                                   "\ngrid:\n  load_N: [2000, 1e-300]\n"
                                                   "output: o.csv\n");
  expect_input_error(run_limited({"footprint", kSrc + "/configs/sf350.yaml", "--load", "1e-300"}),
                     {"--load", "1e-300 is outside [1e-6, 1e7] N", "no contact"});
  expect_input_error(run_limited({"sweep", sweep}),
                     {sweep + ":3", "grid.load_N", "[1e-6, 1e7] N, got 1e-300"});
  expect_input_error(run_limited({"identify", "b-factors", "--max-h-r0", "1e-308"}),
                     {"--max-h-r0", "[1e-4, 1)"});
  // The bundled hammer data as FRFs: three lines are enough to reach the band check.
  const std::string frf = write("frf.csv",
                                "response_point,response_dir,reference_point,reference_dir,"
                                "freq_hz,re,im\n1,radial,1,radial,100,1,0\n"
                                "1,radial,1,radial,101,1,0\n1,radial,1,radial,102,1,0\n");
  expect_input_error(run_limited({"ema", frf, "--band", "80:1e308"}), {"--band", "1e5"});
}

TEST_F(CliHostile, ANonFileThatTheConfigNamesIsRefusedAtItsKey) {
  std::ifstream in(kConfig2d);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find("hammer_csv: ");
  ASSERT_NE(at, std::string::npos);
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
  const auto eol = text.find('\n', at);
  const std::vector<std::string> targets = {"/dev/zero", (dir_ / "missing.csv").string()};
  for (const std::string& target : targets) {
    const std::string cfg =
        write("device.yaml", text.substr(0, at) + "hammer_csv: " + target + text.substr(eol));
    expect_input_error(run_limited({"footprint", cfg}),
                       {cfg + ":" + std::to_string(line), "modal.hammer_csv", target});
  }
  const std::string sweep =
      write("base_device.yaml", "base: /dev/zero\ngrid:\n  load_N: [2000]\noutput: o.csv\n");
  expect_input_error(run_limited({"sweep", sweep}),
                     {sweep + ":1", "base", "/dev/zero' is not a regular file"});
}

// Issue 44 item 5: speeds inside the keys' ranges but beyond the carcass's critical speed ran to
// garbage with exit 0 (350 km/h: the hub held at the 4 kN sinking carried no load; 500 and
// 1000 km/h: 13 m and 605 m above the road). Refused, naming the key and the reason.
TEST_F(CliHostile, SpeedsBeyondTheCriticalSpeedAreRefusedWithTheReason) {
  const std::string sf350 = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";
  expect_input_error(
      run_limited({"transient", sf350, "--scenario", "rolling", "--set",
                   "transient.rolling.speed_km_h=350", "--set", "transient.rolling.duration_s=1.5",
                   "--set", "transient.rolling.ramp_s=0.5"}),
      {"transient.rolling.speed_km_h: ", "beyond the carcass's critical speed 262.9 km/h"});
  expect_input_error(run_limited({"transient", kConfig2d, "--scenario", "rolling", "--set",
                                  "transient.rolling.speed_km_h=500"}),
                     {"transient.rolling.speed_km_h: ", "critical speed"});
  expect_input_error(run_limited({"transient", kConfig2d, "--scenario", "cleat", "--set",
                                  "transient.cleat.speed_km_h=1000"}),
                     {"transient.cleat.speed_km_h: ", "critical speed"});
}

}  // namespace
