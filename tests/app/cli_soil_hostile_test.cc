// Issue 44 item 5 on the soil input ("soil settings dropped silently", "false precision"): every
// case exits 2 with one message naming the file, line and key (or the option), nothing on stdout.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;

using modaltyre_test::kConfig2d;
using modaltyre_test::kLeteSandYaml;
const std::string kBekkerKeys = "    n: 0.79\n    k_c: 102\n    k_phi: 5301\n";

class SoilHostile : public modaltyre_test::CliFixture {
 protected:
  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << content;
    return p.string();
  }
  void expect_input_error(const CliRun& r, const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << n << "\n" << r.err;
  }
};

TEST_F(SoilHostile, ASoilFileWithoutModelIsNotTheRoad) {
  const std::string f = write("nomodel.yaml", "ground:\n  bekker:\n" + kBekkerKeys);
  expect_input_error(run({"footprint", kConfig2d, "--ground", f, "--load", "3000"}),
                     {"nomodel.yaml:3", "ground.bekker.n", "without ground.model"});
}

TEST_F(SoilHostile, ARigidModelWithABekkerBlockIsRefused) {
  const std::string f = write("rigid.yaml", "ground:\n  model: rigid\n  bekker:\n" + kBekkerKeys);
  expect_input_error(run({"footprint", kConfig2d, "--ground", f, "--load", "3000"}),
                     {"rigid.yaml:4", "ground.bekker.n", "ground.model is rigid"});
}

TEST_F(SoilHostile, SwitchingABekkerFileToKelvinVoigtIsRefused) {
  expect_input_error(run({"footprint", kConfig2d, "--ground", kLeteSandYaml, "--load", "3000",
                          "--set", "ground.model=kelvin_voigt"}),
                     {"lete_sand.yaml", "ground.bekker", "ground.model is kelvin_voigt"});
}

TEST_F(SoilHostile, ABekkerKeyOnAConfigWithoutAGroundIsNotDropped) {
  expect_input_error(
      run({"footprint", kConfig2d, "--load", "3000", "--set", "ground.bekker.n=0.8"}),
      {"--set", "ground.bekker", "without ground.model"});
}

TEST_F(SoilHostile, AHorizontalForceOnASoilIsAnInputError) {
  expect_input_error(
      run({"footprint", kConfig2d, "--ground", kLeteSandYaml, "--load", "3000", "--fx", "500"}),
      {"--fx", "ground.model: bekker", "traction"});
}

TEST_F(SoilHostile, TractionNeedsTheSoilsShearStated) {
  const std::string f =
      write("noshear.yaml", "ground:\n  model: bekker\n  bekker:\n" + kBekkerKeys);
  expect_input_error(run({"traction", kConfig2d, "--ground", f, "--load", "3000", "--slip", "0.1"}),
                     {"noshear.yaml", "ground.bekker.cohesion_kPa", "identify shear"});
}

TEST_F(SoilHostile, PlateDataThatCannotDetermineBekkersLawAreRefused) {
  const std::string one = write("one.csv",
                                "plate_width_mm,sinkage_mm,pressure_kPa\n50,10,120\n50,10,121\n"
                                "200,20,240\n200,20,238\n");
  expect_input_error(run({"identify", "bevameter", one}),
                     {"one.csv", "sinkage_mm", "at one sinkage"});
  const std::string point = write("point.csv",
                                  "plate_width_mm,sinkage_mm,pressure_kPa\n50,10,120\n50,10,120\n"
                                  "200,10,120\n200,10,120\n");
  expect_input_error(run({"identify", "bevameter", point}), {"point.csv", "at one sinkage"});
  const std::string diameter =
      write("diam.csv", "plate_diameter_mm,sinkage_mm,pressure_kPa\n100,10,120\n");
  expect_input_error(run({"identify", "bevameter", diameter}),
                     {"diam.csv", "plate_diameter_mm", "radius"});
}

}  // namespace
