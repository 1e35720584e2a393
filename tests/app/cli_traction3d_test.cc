// `traction` on a 3D config (docs/soil.md section 9): the 3D patch by default, its 2D patch at the
// tread width with --patch 2d (the fast variant), --patch 3d refused on a 2D config (exit 2
// naming footprint_3d).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;
using modaltyre_test::kLeteSandYaml;

class Traction3dCli : public modaltyre_test::CliFixture {
 protected:
  nlohmann::json traction(std::vector<std::string> extra) {
    std::vector<std::string> a{"traction", kConfig3d, "--ground", kLeteSandYaml, "--load", "3000",
                               "--slip", "0.1", "0.3", "--json",
                               // coarse: 2 mm sections, 10 mm columns (15 columns, 8 classes)
                               "--set", "contact.unit_length_mm=2", "--set",
                               "footprint_3d.lateral_cell_mm=10"};
    a.insert(a.end(), extra.begin(), extra.end());
    const auto r = run(a);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }
};

TEST_F(Traction3dCli, A3DConfigRollsOnTheThreeDPatchUnlessAskedForItsTwoDPatch) {
  const nlohmann::json three = traction({}), two = traction({"--patch", "2d"});
  EXPECT_EQ(three["model"], "flexible tyre, 3D patch");
  EXPECT_EQ(two["model"], "flexible tyre, 2D patch");
  EXPECT_EQ(three["width_mm"], 150.0);
  EXPECT_EQ(two["width_mm"], 150.0);
  ASSERT_EQ(three["cases"].size(), 2u);
  ASSERT_EQ(two["cases"].size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const auto &a = three["cases"][k], &b = two["cases"][k];
    EXPECT_TRUE(a["converged"].get<bool>());
    // The crowned tread concentrates the load at its centre: the 3D patch sinks deeper there
    // than the flat 2D patch of the same width and load.
    EXPECT_GT(a["soil_sinkage_mm"].get<double>(), b["soil_sinkage_mm"].get<double>());
    EXPECT_LE(a["rut_depth_mm"].get<double>(), a["soil_sinkage_mm"].get<double>());
  }
  EXPECT_GT(three["cases"][1]["drawbar_pull_N"].get<double>(),
            three["cases"][0]["drawbar_pull_N"].get<double>());
}

TEST_F(Traction3dCli, ThePatchOption3dNeedsA3DConfig) {
  const auto r = run({"traction", kConfig2d, "--ground", kLeteSandYaml, "--load", "3000", "--slip",
                      "0.1", "--patch", "3d"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("footprint_3d"), std::string::npos) << r.err;
  const auto bad = run({"traction", kConfig3d, "--ground", kLeteSandYaml, "--load", "3000",
                        "--slip", "0.1", "--patch", "4d"});
  EXPECT_EQ(bad.exit_code, 2);
}

}  // namespace
