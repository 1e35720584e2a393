// `identify bevameter|shear ... --write-ground SOIL.yaml [--into-ground BASE.yaml]` (docs/soil.md
// section 6): a soil file that `--ground` reads, both soil tests in one file, and its refusals.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kLeteSandYaml;
using modaltyre_test::kSrc;
const std::string kPlates = kSrc + "/tests/data/soil/plate_sinkage.csv";
const std::string kShear = kSrc + "/tests/data/soil/shear.csv";

class IdentifyGroundCli : public modaltyre_test::CliFixture {
 protected:
  nlohmann::json curve(std::vector<std::string> ground) {
    std::vector<std::string> a{"traction",
                               kConfig2d,
                               "--load",
                               "3000",
                               "--slip",
                               "-0.1",
                               "0",
                               "0.1",
                               "0.3",
                               "--set",
                               "contact.unit_length_mm=2",
                               "--json"};
    a.insert(a.end(), ground.begin(), ground.end());
    const auto r = run(a);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }
};

// Done-when: a soil written by --write-ground from planted plate and shear data (2 % noise; LETE
// sand with k_u = 2e4 kN/m^3 + 2e6 kN/m^4 z_max) gives the planted soil's traction curve within
// 2 % of the load.
TEST_F(IdentifyGroundCli, PlantedPlateAndShearDataGiveThePlantedSoilsTractionCurve) {
  const std::string plate_soil = (dir_ / "plates.yaml").string();
  const std::string soil = (dir_ / "soil.yaml").string();
  const auto a = run({"identify", "bevameter", kPlates, "--write-ground", plate_soil, "--json"});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(nlohmann::json::parse(a.out)["ground_file"]["path"], plate_soil);
  const auto b =
      run({"identify", "shear", kShear, "--into-ground", plate_soil, "--write-ground", soil});
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(b.out.find("soil file: " + soil), std::string::npos) << b.out;
  const nlohmann::json identified = curve({"--ground", soil});
  const nlohmann::json planted =
      curve({"--ground", kLeteSandYaml, "--set", "ground.bekker.unloading.k0=2e4", "--set",
             "ground.bekker.unloading.Au=2e6"});
  ASSERT_EQ(identified["cases"].size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const auto &i = identified["cases"][k], &p = planted["cases"][k];
    EXPECT_NEAR(i["drawbar_pull_N"].get<double>(), p["drawbar_pull_N"].get<double>(), 0.02 * 3000)
        << k;
    EXPECT_NEAR(i["soil_sinkage_mm"].get<double>(), p["soil_sinkage_mm"].get<double>(),
                0.02 * p["soil_sinkage_mm"].get<double>())
        << k;
  }
}

TEST_F(IdentifyGroundCli, WhatASoilFileCannotTakeIsRefused) {
  const std::string out = (dir_ / "out.yaml").string();
  // A shear test alone has no pressure-sinkage law.
  const auto shear = run({"identify", "shear", kShear, "--write-ground", out});
  EXPECT_EQ(shear.exit_code, 2);
  EXPECT_NE(shear.err.find("--into-ground"), std::string::npos) << shear.err;
  // Not a soil test.
  const auto ld = run({"identify", "b-factors", "--write-ground", out});
  EXPECT_EQ(ld.exit_code, 2);
  EXPECT_NE(ld.err.find("--write-ground"), std::string::npos) << ld.err;
  // --into-ground without a file to write, and over its own input.
  const auto half = run({"identify", "bevameter", kPlates, "--into-ground", kLeteSandYaml});
  EXPECT_EQ(half.exit_code, 2);
  EXPECT_NE(half.err.find("--write-ground"), std::string::npos) << half.err;
  const std::string base = (dir_ / "base.yaml").string();
  ASSERT_EQ(run({"identify", "bevameter", kPlates, "--write-ground", base}).exit_code, 0);
  const auto over =
      run({"identify", "shear", kShear, "--into-ground", base, "--write-ground", base});
  EXPECT_EQ(over.exit_code, 2);
  EXPECT_NE(over.err.find("same file"), std::string::npos) << over.err;
  EXPECT_FALSE(modaltyre_test::fs::exists(out));
}

}  // namespace
