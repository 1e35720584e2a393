// `validate --uncertainty` (issue 35, docs/uncertainty.md section 7): the model's band at every
// row, and the rows outside it once their own stated noise (`*_std` columns) widens it. Rows
// planted at the model's prediction, at 6 model sigma from it, and at 6 model sigma with a
// stated noise of 10 model sigma: only the second is outside.
#include <nlohmann/json.hpp>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::CliFixture;

using modaltyre_test::kConfig2d;
using modaltyre_test::kTable3;
// Far outside a 95 % band (1.96 sigma) and far inside once 10 sigma of noise is added.
constexpr double kShiftSigma = 6.0, kNoiseSigma = 10.0;

class ValidateBands : public CliFixture {};

TEST_F(ValidateBands, MarksTheRowsOutsideTheBandWidenedByTheirNoise) {
  // Every row a prediction (no calibration): the band is the hammer shapes' noise only.
  const auto first = run({"validate", kConfig2d, kTable3, "--uncertainty", "--json", "--set",
                          "validation.calibrate=[]"});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const auto j = nlohmann::json::parse(first.out);
  ASSERT_EQ(j["uncertainty_method"], "linear") << j["uncertainty_check"];
  std::ostringstream csv;
  csv.precision(10);
  csv << "load_N,sinking_mm,sinking_std_mm\n";
  for (int i = 0; i < 3; ++i) {
    const auto& row = j["rows"][i];
    const auto& b = row["uncertainty"]["sinking_mm"];
    const double value = b["value"], sd = b["std"];
    ASSERT_GT(sd, 0.0);
    EXPECT_NEAR(value, row["predicted"]["sinking_mm"].get<double>(), 1e-6 * value);
    csv << row["load_N"].get<double>() << "," << value + (i == 0 ? 0.0 : kShiftSigma * sd) << ","
        << (i == 2 ? std::to_string(kNoiseSigma * sd) : "") << "\n";
  }
  const auto planted = dir_ / "planted.csv";
  std::ofstream(planted) << csv.str();
  const auto second = run({"validate", kConfig2d, planted.string(), "--uncertainty", "--json",
                           "--set", "validation.calibrate=[]"});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  const auto k = nlohmann::json::parse(second.out);
  EXPECT_TRUE(k["rows"][0]["outside_band"].empty()) << k["rows"][0];
  EXPECT_EQ(k["rows"][1]["outside_band"], nlohmann::json::array({"sinking_mm"})) << k["rows"][1];
  EXPECT_TRUE(k["rows"][2]["outside_band"].empty()) << k["rows"][2];
  // The table prints the measured noise as value +- 2 sigma, the band as value [p025, p975],
  // and the mark.
  const auto table = run({"validate", kConfig2d, planted.string(), "--uncertainty", "--set",
                          "validation.calibrate=[]"});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("+-"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("outside"), std::string::npos) << table.out;
}

TEST_F(ValidateBands, AStdWithoutItsMeasurementIsRefused) {
  const auto csv = dir_ / "bad.csv";
  std::ofstream(csv) << "load_N,sinking_mm,length_std_mm\n2131,8,1\n";
  const auto r = run({"validate", kConfig2d, csv.string()});
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("length_std_mm"), std::string::npos) << r.err;
}

}  // namespace
