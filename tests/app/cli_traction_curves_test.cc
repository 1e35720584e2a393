// `traction`'s curves as terramechanics reads them (docs/soil.md sections 5.1-5.2): the slip
// against the rolling radius, a failed slip kept as a row with its reason (exit 0 unless every
// case fails), the candidate window grown where the sinkage needs it, validity per row.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kSrc;
const std::string kSoils = kSrc + "/configs/soils/";

class TractionCurvesCli : public modaltyre_test::CliFixture {
 protected:
  modaltyre_test::CliRun traction(const std::string& soil, const std::string& load,
                                  std::vector<std::string> slips,
                                  std::vector<std::string> extra = {}) {
    std::vector<std::string> a{"traction", kConfig2d, "--ground", kSoils + soil + ".yaml",
                               "--load",   load,      "--set",    "contact.unit_length_mm=2",
                               "--slip"};
    a.insert(a.end(), slips.begin(), slips.end());
    a.insert(a.end(), extra.begin(), extra.end());
    return run(a);
  }
};

// Done-when: a curve with one impossible slip keeps every other row (exit 0). Heavy clay at
// 6 kN braked at s = -0.2 does not settle in 200 rolling steps (docs/soil.md section 9).
TEST_F(TractionCurvesCli, AFailedSlipIsARowWithItsReasonAndTheOthersAreKept) {
  const auto r = traction("heavy_clay", "6000", {"-0.2", "0", "0.1"}, {"--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["cases"].size(), 3u);
  const auto& failed = j["cases"][0];
  EXPECT_FALSE(failed["converged"].get<bool>());
  EXPECT_FALSE(failed["valid"].get<bool>());
  EXPECT_NE(failed["error"].get<std::string>().find("did not settle"), std::string::npos);
  EXPECT_FALSE(failed.contains("drawbar_pull_N"));  // no numbers for a failed slip
  for (int k : {1, 2}) {
    EXPECT_TRUE(j["cases"][k]["converged"].get<bool>());
    EXPECT_TRUE(j["cases"][k].contains("valid"));
  }
  const auto text = traction("heavy_clay", "6000", {"-0.2", "0"});
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("failed: steady rolling did not settle"), std::string::npos) << text.out;
  // Every case failing is a failed computation (exit 1) naming the first.
  const auto all = traction("heavy_clay", "6000", {"-0.2"});
  EXPECT_EQ(all.exit_code, 1);
  EXPECT_NE(all.err.find("no case converged"), std::string::npos) << all.err;
}

// Sandy loam at 6 kN leaves the 360 mm window (docs/soil.md section 9, "Limits seen"): the
// window grows to 540 mm by itself and the run says so.
TEST_F(TractionCurvesCli, TheWindowGrowsWhereTheSinkageNeedsIt) {
  const auto r = traction("sandy_loam", "6000", {"0", "0.2"}, {"--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("contact.window_mm grew from 360 to 540"), std::string::npos) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const auto& c : j["cases"]) {
    EXPECT_TRUE(c["converged"].get<bool>());
    EXPECT_EQ(c["window_mm"].get<double>(), 540.0);
  }
  // Where the window does not grow (the static footprint), the message asks for the key with a
  // value to try.
  const auto small = run({"footprint", kConfig2d, "--ground", kSoils + "sandy_loam.yaml", "--load",
                          "6000", "--set", "contact.window_mm=120"});
  EXPECT_EQ(small.exit_code, 1);
  EXPECT_NE(small.err.find("increase contact.window_mm (e.g. to 180)"), std::string::npos)
      << small.err;
}

TEST_F(TractionCurvesCli, RowsCarryTheirValidityAndTheCurvesTheirPoints) {
  // Sandy loam at 4 kN: 45-60 mm of soil sinkage and an entry beyond 30 deg (issue 48).
  const auto r = traction("sandy_loam", "4000", {"-0.1", "0", "0.1"}, {"--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["slip_reference"], "rolling");
  for (const auto& c : j["cases"]) {
    ASSERT_TRUE(c["converged"].get<bool>());
    const double re = c["rolling_radius_mm"], loaded = c["loaded_radius_mm"];
    EXPECT_GT(re, loaded);
    EXPECT_LT(re, j["outer_radius_mm"].get<double>());
    if (!c["valid"].get<bool>()) {
      EXPECT_NE(c["validity"].get<std::string>().find("deg from the bottom"), std::string::npos);
    }
  }
  ASSERT_EQ(j["curves"].size(), 1u);
  EXPECT_TRUE(j.contains("towed_point"));
  EXPECT_TRUE(j["towed_point"].is_object());
  EXPECT_LT(j["towed_point"]["slip"].get<double>(), 0.0);
  const auto text = traction("sandy_loam", "4000", {"0"});
  EXPECT_NE(text.out.find("outside the validity range"), std::string::npos) << text.out;
}

// Done-when: motion resistance = the sum of its reported parts; the flexing part is the tyre's
// own rolling resistance on the road at the same load and speed, as `transient --scenario
// rolling` measures it.
TEST_F(TractionCurvesCli, MotionResistanceIsTheSumOfItsReportedParts) {
  const auto r = traction("lete_sand", "3000", {"0", "0.2"},
                          {"--set", "ground.bekker.bulldozing.enabled=true", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const double speed = j["speed_km_h"];
  EXPECT_GT(speed, 0.0);
  for (const auto& c : j["cases"]) {
    const double parts = c["compaction_resistance_N"].get<double>() +
                         c["flexing_resistance_N"].get<double>() +
                         c["bulldozing_resistance_N"].get<double>();
    EXPECT_NEAR(c["motion_resistance_N"].get<double>(), parts, 1e-6 * parts);
    EXPECT_NEAR(c["drawbar_pull_N"].get<double>(),
                c["thrust_N"].get<double>() - c["motion_resistance_N"].get<double>(), 1e-6 * parts);
    EXPECT_GT(c["flexing_resistance_N"].get<double>(), 0.0);
    EXPECT_GT(c["bulldozing_resistance_N"].get<double>(), 0.0);
  }
  const auto t = run({"transient", kConfig2d, "--scenario", "rolling", "--set",
                      "contact.unit_length_mm=2", "--set", "transient.rolling.load_N=3000", "--set",
                      "transient.rolling.speed_km_h=" + std::to_string(speed), "--json"});
  ASSERT_EQ(t.exit_code, 0) << t.err;
  const double road = nlohmann::json::parse(t.out)["final"]["rolling_resistance_N"];
  EXPECT_NEAR(j["cases"][0]["flexing_resistance_N"].get<double>(), road, 1e-6 * road);
  // At zero speed the tyre has no hysteresis loss and bulldozing is off by default: the motion
  // resistance is the compaction alone, as before these parts.
  const auto still = traction("lete_sand", "3000", {"0.2"}, {"--speed-km-h", "0", "--json"});
  ASSERT_EQ(still.exit_code, 0) << still.err;
  const nlohmann::json still_json = nlohmann::json::parse(still.out);
  const auto& c = still_json["cases"][0];
  EXPECT_EQ(c["flexing_resistance_N"].get<double>(), 0.0);
  EXPECT_EQ(c["bulldozing_resistance_N"].get<double>(), 0.0);
  EXPECT_EQ(c["motion_resistance_N"], c["compaction_resistance_N"]);
  const auto fast = traction("lete_sand", "3000", {"0.2"}, {"--speed-km-h", "120"});
  EXPECT_EQ(fast.exit_code, 2);
  EXPECT_NE(fast.err.find("--speed-km-h"), std::string::npos) << fast.err;
}

}  // namespace
