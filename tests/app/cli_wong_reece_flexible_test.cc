// `traction` on the default tyre with Wong and Reece's stress (docs/soil.md section 10): the
// switch is accepted on the flexible tyre's 3D patch and its 2D patch, the JSON states it, and the
// tyre sinks deeper and pulls less than under the front-only stress; a bad coefficient is refused
// naming its key (exit 2).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig3d;
using modaltyre_test::kLeteSandYaml;
using modaltyre_test::kSrc;

class WongReeceFlexibleCli : public modaltyre_test::CliFixture {
 protected:
  // The default tyre on LETE sand at 3 kN, s = 0.1 and 0.3, on a patch, with or without the
  // option; coarse: 2 mm sections, 10 mm columns.
  nlohmann::json rolled(const std::string& patch, bool wong_reece) {
    const auto r =
        run({"traction", kConfig3d, "--ground", kLeteSandYaml, "--load", "3000", "--slip", "0.1",
             "0.3", "--json", "--patch", patch, "--set", "contact.unit_length_mm=2", "--set",
             "footprint_3d.lateral_cell_mm=10", "--set",
             std::string("ground.bekker.wong_reece.enabled=") + (wong_reece ? "true" : "false")});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }
};

TEST_F(WongReeceFlexibleCli, TheDefaultTyreTakesWongReecesStressOnBothPatches) {
  for (const char* patch : {"3d", "2d"}) {
    SCOPED_TRACE(patch);
    const nlohmann::json front = rolled(patch, false), wr = rolled(patch, true);
    EXPECT_FALSE(front["ground"]["bekker"]["wong_reece"].get<bool>());
    EXPECT_TRUE(wr["ground"]["bekker"]["wong_reece"].get<bool>());
    ASSERT_EQ(wr["cases"].size(), 2u);
    for (int k = 0; k < 2; ++k) {
      const auto &a = front["cases"][k], &b = wr["cases"][k];
      ASSERT_TRUE(b["converged"].get<bool>()) << b;
      EXPECT_GT(b["soil_sinkage_mm"].get<double>(), a["soil_sinkage_mm"].get<double>());
      EXPECT_LT(b["drawbar_pull_N"].get<double>(), a["drawbar_pull_N"].get<double>());
    }
    EXPECT_GT(wr["cases"][1]["soil_sinkage_mm"].get<double>(),
              wr["cases"][0]["soil_sinkage_mm"].get<double>());
  }
}

TEST_F(WongReeceFlexibleCli, ABadCoefficientIsRefusedNamingItsKey) {
  const auto r = run({"traction", kConfig3d, "--ground", kLeteSandYaml, "--load", "3000", "--slip",
                      "0.1", "--set", "ground.bekker.wong_reece.enabled=true", "--set",
                      "ground.bekker.wong_reece.c2=1.5"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("wong_reece.c2"), std::string::npos) << r.err;
}

// A case rolled with a shorter reach of the rut's extrapolation (contact/traction.h,
// TractionOptions::wong_reece_exit_reach) is marked in the table with its reach and a note, and
// carries it in its JSON; the case beside it that settled with the rut at theta2 carries neither
// (the fold's point of WongReeceFlexible.ARunThatOrbits..., 0.5 mm units: only the last rear
// cell's depth settles there).
TEST_F(WongReeceFlexibleCli, ACaseRolledWithAShorterReachSaysSo) {
  const std::vector<std::string> args = {"traction",
                                         kSrc + "/configs/sf350_2d_table3.yaml",
                                         "--ground",
                                         kLeteSandYaml,
                                         "--load",
                                         "2500",
                                         "--slip",
                                         "0.05",
                                         "0.2",
                                         "--set",
                                         "contact.unit_length_mm=0.5",
                                         "--set",
                                         "ground.bekker.wong_reece.enabled=true",
                                         "--set",
                                         "ground.bekker.wong_reece.c1=0.457719",
                                         "--set",
                                         "ground.bekker.wong_reece.c2=0.266089",
                                         "--set",
                                         "modal.compliance_scale=0.599631",
                                         "--set",
                                         "tread.modulus_MPa=1.11304"};
  const auto text = run(args);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("  ~0.0\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("~R: Wong-Reece's rut behind theta2 extrapolated R"), std::string::npos)
      << text.out;
  std::vector<std::string> with_json = args;
  with_json.push_back("--json");
  const auto js = run(with_json);
  ASSERT_EQ(js.exit_code, 0) << js.err;
  const nlohmann::json j = nlohmann::json::parse(js.out);
  ASSERT_EQ(j["cases"].size(), 2u);
  EXPECT_FALSE(j["cases"][0].contains("wong_reece_rut_reach_units")) << j["cases"][0];
  ASSERT_TRUE(j["cases"][1].contains("wong_reece_rut_reach_units")) << j["cases"][1];
  EXPECT_EQ(j["cases"][1]["wong_reece_rut_reach_units"].get<double>(), 0.0);
}

}  // namespace
