// `modaltyre footprint` and `validate` end to end: the documented JSON shapes, equilibrium of the
// printed unit forces, exit 1 naming the load case when a solve does not converge, exit 2 for
// impossible loads.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kTable3;

class FootprintCli : public modaltyre_test::CliFixture {};

TEST_F(FootprintCli, JsonHasTheDocumentedShapeAndUnitForcesBalanceTheLoad) {
  const auto r = run({"footprint", kConfig2d, "--load", "2131", "--load", "8321", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["cases"].size(), 2u);
  for (const auto& c : j["cases"]) {
    EXPECT_TRUE(c["converged"].get<bool>());
    EXPECT_GT(c["sinking_mm"].get<double>(), 0);
    EXPECT_GT(c["contact_length_mm"].get<double>(), 0);
    EXPECT_GE(c["iterations"].get<int>(), 1);
    double sum = 0;
    for (const auto& u : c["units"]) {
      for (const char* key : {"x_mm", "dx_mm", "fz_N", "fx_N", "pressure_kPa"}) {
        ASSERT_TRUE(u.contains(key)) << key;
      }
      sum += u["fz_N"].get<double>();
    }
    // Unit forces are printed with 10 significant digits.
    EXPECT_NEAR(sum, c["load_N"].get<double>(), 1e-6 * c["load_N"].get<double>());
  }
}

TEST_F(FootprintCli, NonConvergenceExitsOneNamingTheLoadCase) {
  const auto r =
      run({"footprint", kConfig2d, "--load", "5478", "--set", "solver.max_iterations=1"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("5478"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << "no unconverged numbers may be printed";
}

TEST_F(FootprintCli, ImpossibleLoadsExitTwo) {
  auto r = run({"footprint", kConfig2d, "--load", "0"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--load"), std::string::npos) << r.err;
  r = run({"footprint", kConfig2d, "--load", "5000", "--fx", "1e7"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--fx"), std::string::npos) << r.err;
}

TEST_F(FootprintCli, ValidateJsonNamesCalibrationAndPredictedRows) {
  const auto r = run({"validate", kConfig2d, kTable3, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["rows"].size(), 6u);
  int calibration_rows = 0;
  for (const auto& row : j["rows"]) calibration_rows += row["calibration"].get<bool>() ? 1 : 0;
  EXPECT_EQ(calibration_rows, 2);
  EXPECT_TRUE(j["calibrated"].contains("tread.modulus_MPa"));
  EXPECT_TRUE(j["rms_rel_error"].contains("sinking_mm"));
  EXPECT_TRUE(j["rms_rel_error"].contains("length_mm"));
}

// Issue 16: `--set validation.calibrate=[]` calibrates nothing, so no row is a calibration row
// and every row counts (the config's calibration_rows name rows only for calibrated keys).
TEST_F(FootprintCli, ValidateWithoutCalibrationCountsEveryRow) {
  auto r = run({"validate", kConfig2d, kTable3, "--json", "--set", "validation.calibrate=[]"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["rows"].size(), 6u);
  for (const auto& row : j["rows"]) EXPECT_FALSE(row["calibration"].get<bool>()) << row;
  EXPECT_EQ(j["predicted_rows"]["sinking_mm"], 6);
  EXPECT_TRUE(j["calibration"]["rows"].empty());
  r = run({"validate", kConfig2d, kTable3, "--set", "validation.calibrate=[]"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("No calibration: every row is a prediction."), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("calibration "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("% (6 rows)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("(4 rows)"), std::string::npos) << r.out;
}

// Issue 16 item 6: a footprint outside the model's validity range is computed but flagged: a
// warning on stderr and "valid": false with the reason in JSON, in footprint and validate.
TEST_F(FootprintCli, OutsideTheValidityRangeIsFlaggedNotAnOrdinaryResult) {
  auto r = run({"footprint", kConfig2d, "--load", "5478", "--load", "30000", "--json", "--set",
                "contact.unit_length_mm=2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["cases"].size(), 2u);
  EXPECT_TRUE(j["cases"][0]["valid"].get<bool>());
  EXPECT_TRUE(j["cases"][0]["validity"].is_null());
  EXPECT_FALSE(j["cases"][1]["valid"].get<bool>());
  const std::string why = j["cases"][1]["validity"].get<std::string>();
  EXPECT_NE(why.find("of the free radius R0 = 295 mm; the linearised model holds up to 12 %"),
            std::string::npos)
      << why;
  EXPECT_EQ(r.err.find("load 5478 N"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("warning: load 30000 N is outside the model's validity range: sinking"),
            std::string::npos)
      << r.err;
  // The table too warns on stderr.
  r = run({"footprint", kConfig2d, "--load", "30000", "--set", "contact.unit_length_mm=2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("not a prediction"), std::string::npos) << r.err;

  const std::string rows = (dir_ / "rows.csv").string();
  std::ofstream(rows) << "load_N,sinking_mm\n3000,12\n30000,80\n";
  r = run({"validate", kConfig2d, rows, "--json", "--set", "contact.unit_length_mm=2", "--set",
           "validation.calibrate=[]", "--set", "validation.calibration_rows=[]"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["rows"][0]["valid"].get<bool>());
  EXPECT_FALSE(j["rows"][1]["valid"].get<bool>());
  EXPECT_NE(j["rows"][1]["validity"].get<std::string>().find("sinking"), std::string::npos);
  EXPECT_NE(r.err.find("warning: row 2 (load 30000 N) is outside the model's validity range"),
            std::string::npos)
      << r.err;
  r = run({"validate", kConfig2d, rows, "--set", "contact.unit_length_mm=2", "--set",
           "validation.calibrate=[]", "--set", "validation.calibration_rows=[]"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("outside the validity range"), std::string::npos) << r.out;
}

}  // namespace
