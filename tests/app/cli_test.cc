// The built CLI end to end: bad hammer files and bad configs exit with code 2 and a message that
// names the file, line and key on stderr (never a crash); fit-modes --json has its documented
// structure.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.h"
#include "../support/hammer_lines.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::slurp;
using modaltyre_test::hammer_lines;
using modaltyre_test::set_field;
constexpr double kPi = 3.14159265358979323846;

class Cli : public modaltyre_test::CliFixture {
 protected:
  std::string write(const std::string& content, const std::string& name = "h.csv") {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  /// fit-modes on `path` must exit 2 and print `needles` (file, file:line, column) on stderr.
  void expect_fit_modes_input_error(const std::string& path,
                                    const std::vector<std::string>& needles) {
    const CliRun r = run({"fit-modes", path});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << n << "\n" << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }

};


std::string join(const std::vector<std::string>& l) {
  std::string s;
  for (const auto& x : l) s += x + "\n";
  return s;
}


std::string loc(const std::string& path, int line) { return path + ":" + std::to_string(line); }

// Sanity: the valid generated file is accepted (so the failures below are the defects).
TEST_F(Cli, FitModesAcceptsValidFile) {
  const CliRun r = run({"fit-modes", write(join(hammer_lines()))});
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST_F(Cli, FitModesMissingColumn) {
  auto l = hammer_lines();
  for (auto& s : l) s = s.substr(0, s.rfind(','));
  const auto p = write(join(l));
  expect_fit_modes_input_error(p, {loc(p, 1), "tangential"});
}

TEST_F(Cli, FitModesNaNCell) {
  auto l = hammer_lines();
  set_field(l, 5, 5, "NaN");
  const auto p = write(join(l));
  expect_fit_modes_input_error(p, {loc(p, 5), "radial"});
}

TEST_F(Cli, FitModesInfCell) {
  auto l = hammer_lines();
  set_field(l, 9, 6, "inf");
  const auto p = write(join(l));
  expect_fit_modes_input_error(p, {loc(p, 9), "tangential"});
}

TEST_F(Cli, FitModesTextInNumberColumn) {
  auto l = hammer_lines();
  set_field(l, 16, 1, "abc");
  const auto p = write(join(l));
  expect_fit_modes_input_error(p, {loc(p, 16), "freq_hz"});
}

TEST_F(Cli, FitModesUnequalSpacing) {
  auto l = hammer_lines();
  set_field(l, 4, 4, "70");
  const auto p = write(join(l));
  expect_fit_modes_input_error(p, {loc(p, 2), "angle_deg", "equally spaced"});
}

TEST_F(Cli, FitModesDuplicatePoint) {
  auto l = hammer_lines();
  set_field(l, 6, 3, "3");
  const auto p = write(join(l));
  expect_fit_modes_input_error(p, {loc(p, 6), "point", "duplicate"});
}

TEST_F(Cli, FitModesTooFewPoints) {
  const auto p = write(join(hammer_lines(4, 2)));
  expect_fit_modes_input_error(p, {loc(p, 2), "point", "at least 6"});
}

TEST_F(Cli, FitModesFewerPointsThanOthers) {
  auto l = hammer_lines(12, 3);
  l.erase(l.begin() + 19);  // a point of mode 2 (lines 14-25)
  const auto p = write(join(l));
  expect_fit_modes_input_error(p, {loc(p, 14), "point", "mode 2 has 11 points"});
}

TEST_F(Cli, FitModesEmptyFile) {
  const auto p = write("");
  expect_fit_modes_input_error(p, {"empty"});
}

TEST_F(Cli, FitModesHeaderOnly) {
  const auto p = write(hammer_lines()[0] + "\n");
  expect_fit_modes_input_error(p, {"no data"});
}

TEST_F(Cli, FitModesDirectory) {
  const auto d = (dir_ / "folder.csv").string();
  fs::create_directories(d);
  expect_fit_modes_input_error(d, {"directory"});
}

TEST_F(Cli, FitModesBinaryAndNonUtf8) {
  std::mt19937 rng(7);
  std::string bin = "PK\x03\x04";
  for (int i = 0; i < 512; ++i) bin.push_back(static_cast<char>(rng() & 0xFF));
  const auto p1 = write(bin, "binary.csv");
  expect_fit_modes_input_error(p1, {loc(p1, 1)});

  auto l = hammer_lines();
  set_field(l, 3, 4, "30\xB0");  // Latin-1 degree sign
  const auto p2 = write(join(l), "latin1.csv");
  expect_fit_modes_input_error(p2, {loc(p2, 3), "angle_deg"});
}

// The bundled SF-350 data: exit 0 and JSON with the documented keys per mode.
TEST_F(Cli, FitModesJsonOnSf350) {
  const std::string data =
      std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_hammer_12pt.csv";
  const CliRun r = run({"fit-modes", data, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("points").get<int>(), 12);
  const auto& modes = j.at("modes");
  ASSERT_TRUE(modes.is_array());
  ASSERT_EQ(modes.size(), 16u);
  for (const auto& m : modes) {
    for (const char* key :
         {"mode", "freq_hz", "damping_ratio", "kind", "order", "aliased", "r2", "A", "B"}) {
      EXPECT_TRUE(m.contains(key)) << key;
    }
    EXPECT_TRUE(m.at("A").is_array());
    EXPECT_EQ(m.at("A").size(), 6u);  // A_0..A_5 for 12 points
    EXPECT_EQ(m.at("B").size(), 6u);
    EXPECT_GT(m.at("r2").get<double>(), 0.75);
  }
  EXPECT_EQ(modes[0].at("freq_hz").get<double>(), 112.839);
  EXPECT_EQ(modes[2].at("order").get<int>(), 0);
  EXPECT_EQ(modes[13].at("kind").get<std::string>(), "rotation");
  EXPECT_TRUE(modes[15].at("aliased").get<bool>());
  EXPECT_EQ(modes[15].at("likely_order").get<int>(), 8);
}

// A misspelt --set key is refused, naming the key and --set.
TEST_F(Cli, FootprintMisspeltSetKey) {
  const std::string cfg = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
  const CliRun r = run({"footprint", cfg, "--set", "tread.modolus_MPa=3"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("tread.modolus_MPa"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--set"), std::string::npos) << r.err;
}

// A misspelt key in a YAML file is refused with file:line and the dotted key.
TEST_F(Cli, FootprintMisspeltYamlKey) {
  std::string yaml = slurp(std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml");
  // Point the hammer data at the bundled copy (the config is written elsewhere).
  yaml = std::regex_replace(
      yaml, std::regex("hammer_csv: .*"),
      "hammer_csv: " + std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_hammer_12pt.csv");
  const auto pos = yaml.find("modulus_MPa:");
  ASSERT_NE(pos, std::string::npos);
  yaml.replace(pos, std::string("modulus_MPa").size(), "modolus_MPa");
  const int line = 1 + static_cast<int>(std::count(yaml.begin(), yaml.begin() + pos, '\n'));
  const auto p = write(yaml, "typo.yaml");
  const CliRun r = run({"footprint", p});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(loc(p, line)), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tread.modolus_MPa"), std::string::npos) << r.err;
}

// A negative tread modulus is physically impossible: exit 2, naming the key.
TEST_F(Cli, FootprintNegativeModulus) {
  const std::string cfg = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
  const CliRun r = run({"footprint", cfg, "--set", "tread.modulus_MPa=-3"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("tread.modulus_MPa"), std::string::npos) << r.err;
}

}  // namespace
