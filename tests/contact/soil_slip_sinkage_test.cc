// The flexible tyre with the soil's slip sinkage (ground/soil_options.h, docs/soil.md section
// 5.3): sinkage rises with slip where without it it falls, and k1 = k2 = 0 is the law without it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/traction.h"

namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig2d;

// LETE sand from its soil file with the slip sinkage's keys set as `--set` would.
std::vector<TractionResult> lete_curve(const std::vector<std::string>& soil_sets) {
  TyreConfig c = load_tyre_config(kConfig2d, {"contact.unit_length_mm=2"});
  c.ground = modaltyre::ground::load_ground_file(
      std::string(MODALTYRE_SOURCE_DIR) + "/configs/soils/lete_sand.yaml", soil_sets);
  const TyreModel m = build_tyre_model(c);
  std::vector<TractionResult> rs =
      steady_traction(m, c.ground, {{3000, 0.0}, {3000, 0.25}, {3000, 0.5}});
  for (const auto& r : rs) EXPECT_TRUE(r.ok()) << r.message;
  return rs;
}

TEST(SoilSlipSinkage, TheFlexibleTyresSinkageRisesWithSlip) {
  const auto off = lete_curve({});
  const auto on = lete_curve({"ground.bekker.slip_sinkage.enabled=true"});
  // Without it the shear's vertical share lifts the tyre a little as slip rises.
  EXPECT_LT(off[2].soil_sinkage_m, off[0].soil_sinkage_m);
  // With it: the same at free rolling (f(0) = 1), then deeper with slip; the tyre spreads its
  // load over a longer contact, so less than Lyasko's f(0.5) = 2 of a fixed pressure.
  EXPECT_NEAR(on[0].soil_sinkage_m, off[0].soil_sinkage_m, 1e-3 * off[0].soil_sinkage_m);
  EXPECT_GT(on[1].soil_sinkage_m, 1.15 * on[0].soil_sinkage_m);
  EXPECT_GT(on[2].soil_sinkage_m, 1.3 * on[0].soil_sinkage_m);
  EXPECT_LT(on[2].soil_sinkage_m, 2.0 * on[0].soil_sinkage_m);
  EXPECT_GT(on[2].motion_resistance_N, off[2].motion_resistance_N);
  // k1 = k2 = 0 is f = 1: bit for bit the law without slip sinkage.
  const auto zero =
      lete_curve({"ground.bekker.slip_sinkage.enabled=true", "ground.bekker.slip_sinkage.k1=0",
                  "ground.bekker.slip_sinkage.k2=0"});
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(zero[k].soil_sinkage_m, off[k].soil_sinkage_m);
    EXPECT_EQ(zero[k].drawbar_pull_N, off[k].drawbar_pull_N);
  }
}

}  // namespace
