// Issue 38 item 1: no command writes over one of its own inputs (config, data, hammer CSV,
// sweep file and base, FRF file, .tir) or over another of its outputs. Each case runs the
// command as a user would, on copies in a temporary folder, and checks exit 2, a message
// naming both files' roles, and the input byte for byte unchanged. Identity, not spelling:
// symbolic links, hard links and ".." are seen through.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::slurp;

using modaltyre_test::kSrc;

class CliOutputsOverInputs : public modaltyre_test::CliFixture {
 protected:
  // The 2D and 3D configs with their hammer data, copied so that nothing in the tree is at
  // risk if a guard were missing.
  void SetUp() override {
    CliFixture::SetUp();
    fs::create_directories(dir_ / "data");
    fs::copy_file(kSrc + "/configs/data/sf350_hammer_12pt.csv", hammer());
    fs::copy_file(kSrc + "/configs/sf350_2d_table3.yaml", config2d());
    fs::copy_file(kSrc + "/configs/sf350.yaml", config3d());
    fs::copy_file(kSrc + "/configs/data/sf350_footprint_table3.csv", measured());
  }
  std::string hammer() const { return (dir_ / "data/sf350_hammer_12pt.csv").string(); }
  std::string config2d() const { return (dir_ / "tyre2d.yaml").string(); }
  std::string config3d() const { return (dir_ / "tyre3d.yaml").string(); }
  std::string measured() const { return (dir_ / "measured.csv").string(); }

  // Runs `args`; expects exit 2, every `words` in stderr and `input` unchanged.
  void expect_refused(const std::vector<std::string>& args, const std::string& input,
                      const std::vector<std::string>& words) {
    const std::string before = slurp(input);
    const CliRun r = run(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    for (const auto& w : words) EXPECT_NE(r.err.find(w), std::string::npos) << w << ": " << r.err;
    EXPECT_EQ(slurp(input), before) << input << " was changed";
  }
};

TEST_F(CliOutputsOverInputs, EmaOutputOverTheFrfFile) {
  const std::string frf = (dir_ / "frf.unv").string();
  fs::copy_file(kSrc + "/tests/data/ema/fixed_columns.unv", frf);
  expect_refused({"ema", frf, "--output", frf}, frf, {"--output", "FRF_FILE", "over an input"});
  expect_refused({"ema", frf, "--plot", frf}, frf, {"--plot", "FRF_FILE"});
}

TEST_F(CliOutputsOverInputs, SweepOutputOverItsSpecItsBaseOrTheHammerData) {
  const std::string spec = (dir_ / "sweep.yaml").string();
  auto write_spec = [&](const std::string& output) {
    std::ofstream(spec) << "base: tyre2d.yaml\ngrid:\n  load_N: [3000, 4000]\noutput: " << output
                        << "\n";
  };
  write_spec("sweep.yaml");
  expect_refused({"sweep", spec}, spec, {"output", "SWEEP"});
  write_spec("tyre2d.yaml");
  expect_refused({"sweep", spec}, config2d(), {"output", "base:"});
  write_spec("out.csv");
  expect_refused({"sweep", spec, "--output", hammer()}, hammer(), {"--output", "modal.hammer_csv"});
  expect_refused({"sweep", spec, "--output", ""}, spec, {"--output", "empty"});
  EXPECT_FALSE(fs::exists(dir_ / "out.csv"));
}

TEST_F(CliOutputsOverInputs, TirExportOverItsConfig) {
  expect_refused({"tir", "export", config2d(), "--output", config2d()}, config2d(),
                 {"--output", "CONFIG"});
  expect_refused({"tir", "export", config2d(), "--output", ""}, config2d(), {"--output", "empty"});
}

TEST_F(CliOutputsOverInputs, TransientCsvOverItsConfig) {
  expect_refused({"transient", config2d(), "--scenario", "load-hold", "--csv", config2d()},
                 config2d(), {"--csv", "CONFIG"});
}

TEST_F(CliOutputsOverInputs, TractionPlotOverItsSoilFileOrConfig) {
  const std::string soil = (dir_ / "soil.yaml").string();
  fs::copy_file(kSrc + "/configs/soils/lete_sand.yaml", soil);
  expect_refused(
      {"traction", config2d(), "--ground", soil, "--load", "3000", "--slip", "0.2", "--plot", soil},
      soil, {"--plot", "--ground"});
  expect_refused({"traction", config2d(), "--ground", soil, "--load", "3000", "--slip", "0.2",
                  "--plot", hammer()},
                 hammer(), {"--plot", "modal.hammer_csv"});
}

TEST_F(CliOutputsOverInputs, FootprintMapOverTheHammerDataAndPlotOverTheMap) {
  expect_refused({"footprint", config3d(), "--load", "4000", "--map-csv", hammer()}, hammer(),
                 {"--map-csv", "modal.hammer_csv"});
  const std::string x = (dir_ / "x.svg").string();
  const CliRun r = run({"footprint", config3d(), "--load", "4000", "--plot", x, "--map-csv", x});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--plot"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--map-csv"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(x));
}

TEST_F(CliOutputsOverInputs, IdentifyRecordOverItsData) {
  const std::string data = (dir_ / "ld.csv").string();
  fs::copy_file(kSrc + "/tests/data/rheology/load_deflection.csv", data);
  expect_refused({"identify", "load-deflection", data, "--write-config", data}, data,
                 {"--write-config", "FILE"});
  expect_refused({"identify", "load-deflection", data, "--plot", data}, data, {"--plot", "FILE"});
  // With a tyre config, the augmented config must not replace the hammer data either.
  expect_refused(
      {"identify", "load-deflection", data, "--config", config2d(), "--write-config", hammer()},
      hammer(), {"--write-config", "modal.hammer_csv"});
}

TEST_F(CliOutputsOverInputs, DiscoverOutConfigOverItsConfigOrData) {
  expect_refused({"discover", config2d(), measured(), "--out-config", config2d()}, config2d(),
                 {"--out-config", "CONFIG"});
  expect_refused({"discover", config2d(), measured(), "--plot", measured()}, measured(),
                 {"--plot", "MEASURED"});
}

TEST_F(CliOutputsOverInputs, ValidateAndFitModesPlotOverTheirData) {
  expect_refused({"validate", config2d(), measured(), "--plot", measured()}, measured(),
                 {"--plot", "MEASURED"});
  expect_refused({"fit-modes", hammer(), "--plot", hammer()}, hammer(), {"--plot", "HAMMER"});
}

TEST_F(CliOutputsOverInputs, TirComparePlotOverTheTirFile) {
  const std::string tir = (dir_ / "t.tir").string();
  const CliRun ex = run({"tir", "export", config2d(), "--output", tir});
  ASSERT_EQ(ex.exit_code, 0) << ex.err;
  expect_refused({"tir", "compare", config2d(), tir, "--plot", tir}, tir, {"--plot", "TIR"});
}

// Identity, not spelling: a symbolic link to the config, a hard link to it and a path through
// "..": all the same file.
TEST_F(CliOutputsOverInputs, LinksAndDotDotAreSeenThrough) {
  const fs::path sym = dir_ / "link.yaml";
  fs::create_symlink(config2d(), sym);
  expect_refused({"tir", "export", config2d(), "--output", sym.string()}, config2d(), {"CONFIG"});
  EXPECT_TRUE(fs::is_symlink(sym));
  const fs::path hard = dir_ / "hard.yaml";
  fs::create_hard_link(config2d(), hard);
  expect_refused({"transient", config2d(), "--scenario", "load-hold", "--csv", hard.string()},
                 config2d(), {"CONFIG"});
  const std::string dotdot = (dir_ / "data" / ".." / "tyre2d.yaml").string();
  expect_refused({"transient", config2d(), "--scenario", "load-hold", "--csv", dotdot}, config2d(),
                 {"CONFIG"});
  // Two outputs that are one file not yet written: "./x.csv"-style spellings.
  const std::string a = (dir_ / "o.svg").string(), b = (dir_ / "data" / ".." / "o.svg").string();
  const CliRun r =
      run({"transient", config2d(), "--scenario", "load-hold", "--plot", a, "--csv", b});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(fs::exists(a));
}

// Outputs that are distinct files still work, and /dev/null may take two outputs.
TEST_F(CliOutputsOverInputs, DistinctOutputsAndStreamsAreAccepted) {
  const std::string tir = (dir_ / "t.tir").string();
  const CliRun r = run({"tir", "export", config2d(), "--output", tir});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(tir));
  const CliRun twice = run({"footprint", config3d(), "--load", "4000", "--map-csv", "/dev/null"});
  EXPECT_EQ(twice.exit_code, 0) << twice.err;
}

// Issue 44 item 5: the one identity check (core/command_files.h) in every command, through
// links: an output that is a link to one of the command's inputs, and an output that is a
// dangling link to another output of the same run (writing the one creates the file the other
// then writes over: transient's SVG over its CSV). Refused before anything is computed.
TEST_F(CliOutputsOverInputs, EveryCommandSeesThroughLinksToInputsAndOtherOutputs) {
  auto link = [&](const std::string& name, const std::string& to) {
    fs::create_symlink(to, dir_ / name);
    return (dir_ / name).string();
  };
  const std::string frf = (dir_ / "frf.unv").string();
  fs::copy_file(kSrc + "/tests/data/ema/fixed_columns.unv", frf);
  const std::string ld = (dir_ / "ld.csv").string();
  fs::copy_file(kSrc + "/tests/data/rheology/load_deflection.csv", ld);
  expect_refused({"validate", config2d(), measured(), "--plot", link("v.svg", measured())},
                 measured(), {"--plot", "MEASURED"});
  expect_refused({"fit-modes", hammer(), "--plot", link("f.svg", hammer())}, hammer(),
                 {"--plot", "HAMMER"});
  expect_refused({"init", "--size", "195/60R14", "--test-pressure-kPa", "230", "--hammer", hammer(),
                  "--output", link("i.yaml", hammer())},
                 hammer(), {"--output", "--hammer"});
  expect_refused({"fmu", config2d(), "--output", link("t.fmu", config2d())}, config2d(),
                 {"--output", "CONFIG"});
  expect_refused({"ema", frf, "--output", link("h.csv", frf)}, frf, {"--output", "FRF_FILE"});
  const std::string spec = (dir_ / "sweep.yaml").string();
  std::ofstream(spec) << "base: tyre2d.yaml\ngrid:\n  load_N: [3000, 4000]\noutput: s.csv\n";
  expect_refused({"sweep", spec, "--output", link("s.csv", config2d())}, config2d(),
                 {"--output", "base:"});

  // Two outputs, one of them a dangling link to the other: both named, neither written.
  auto expect_pair_refused = [&](const std::vector<std::string>& args, const std::string& first,
                                 const std::string& second, const std::string& target) {
    const CliRun r = run(args);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(first), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(second), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / target)) << target << " was written";
  };
  expect_pair_refused({"footprint", config3d(), "--load", "4000", "--map-csv",
                       (dir_ / "m.csv").string(), "--plot", link("p.svg", "m.csv")},
                      "--map-csv", "--plot", "m.csv");
  expect_pair_refused({"discover", config2d(), measured(), "--out-config",
                       (dir_ / "o.yaml").string(), "--plot", link("d.svg", "o.yaml")},
                      "--out-config", "--plot", "o.yaml");
  expect_pair_refused(
      {"ema", frf, "--output", (dir_ / "e.csv").string(), "--plot", link("e.svg", "e.csv")},
      "--output", "--plot", "e.csv");
  expect_pair_refused({"identify", "load-deflection", ld, "--write-config",
                       (dir_ / "w.yaml").string(), "--plot", link("w.svg", "w.yaml")},
                      "--write-config", "--plot", "w.yaml");
}

}  // namespace
