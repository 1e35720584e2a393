// `traction` on a Kelvin-Voigt soil with its rate term eta2 on the default tyre (the 3D patch,
// docs/soil.md section 9.1): the rate term acts at --speed-km-h, without the warning the
// flexible tyre gave before it was built, and moves the sinkage, drawbar pull and torque.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig3d;

class SoilRateCli : public modaltyre_test::CliFixture {
 protected:
  // Section 3.2's soil (no bundled soil is a Kelvin-Voigt one), eta2 0 in the file.
  std::string kv_soil() {
    const std::string path = (dir_ / "kv_soil.yaml").string();
    std::ofstream(path) << "ground:\n"
                           "  model: kelvin_voigt\n"
                           "  name: section 3.2's Kelvin-Voigt soil\n"
                           "  source: \"docs/soil.md section 3.2 (seed 000 eq. 23)\"\n"
                           "  kelvin_voigt:\n"
                           "    E2_MPa: 2\n"
                           "    layer_mm: 200\n"
                           "    elastic_share: 0.7\n"
                           "    eta2_kPa_s: 0\n"
                           "    cohesion_kPa: 1\n"
                           "    friction_angle_deg: 30\n"
                           "    shear_modulus_K_mm: 25\n";
    return path;
  }
  modaltyre_test::CliRun traction(const std::string& eta2) {
    return run({"traction", kConfig3d, "--ground", kv_soil(), "--load", "3000", "--slip", "0.1",
                "--speed-km-h", "5", "--set", "ground.kelvin_voigt.eta2_kPa_s=" + eta2, "--json",
                // coarse: 2 mm sections, 10 mm columns
                "--set", "contact.unit_length_mm=2", "--set", "footprint_3d.lateral_cell_mm=10"});
  }
};

TEST_F(SoilRateCli, TheRateTermActsOnTheDefaultTyresThreeDPatch) {
  const auto viscous = traction("50"), elastic = traction("0");
  ASSERT_EQ(viscous.exit_code, 0) << viscous.err;
  ASSERT_EQ(elastic.exit_code, 0) << elastic.err;
  EXPECT_EQ(viscous.err.find("viscous"), std::string::npos) << viscous.err;
  const auto v = nlohmann::json::parse(viscous.out), e = nlohmann::json::parse(elastic.out);
  EXPECT_EQ(v["model"], "flexible tyre, 3D patch");
  EXPECT_EQ(v["speed_km_h"], 5.0);
  const auto &a = v["cases"][0], &b = e["cases"][0];
  ASSERT_TRUE(a["converged"].get<bool>());
  ASSERT_TRUE(b["converged"].get<bool>());
  // Stiffer at speed: shallower, and the soil's rate term resists (section 9.1's table: 20.5 to
  // 19.5 mm, 60 to 273 N at 1 mm sections).
  EXPECT_LT(a["soil_sinkage_mm"].get<double>(), 0.97 * b["soil_sinkage_mm"].get<double>());
  EXPECT_GT(a["compaction_resistance_N"].get<double>(),
            2 * b["compaction_resistance_N"].get<double>());
  EXPECT_LT(a["drawbar_pull_N"].get<double>(), b["drawbar_pull_N"].get<double>() - 100);
  EXPECT_LT(a["torque_Nm"].get<double>(), b["torque_Nm"].get<double>());
}

}  // namespace
