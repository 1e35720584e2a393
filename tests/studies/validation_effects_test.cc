// validate with effects and operating conditions: effect-free files keep their reader and
// results; a sweep's output (conditions per row) validates at its own conditions; a hidden
// effect shows as a discrepancy that grows with the condition it acts through; the width is
// compared where measured; calibration works through the predictor.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/studies/sweep.h"
#include "modaltyre/studies/validation.h"

namespace {

using namespace modaltyre::contact;
using namespace modaltyre::studies;
using modaltyre::InputError;
namespace fs = std::filesystem;

using modaltyre_test::kConfig2d;
using modaltyre_test::kSrc;
using modaltyre_test::kSweepName;
using modaltyre_test::kTable3;
// Every row is a prediction (no calibration), so that rows compare the model as configured.
const std::vector<std::string> kNoCalibration = {"validation.calibrate=[]",
                                                 "validation.calibration_rows=[]"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

class ValidationEffects : public ::testing::Test {
 protected:
  void TearDown() override {
    for (const auto& f : files_) fs::remove(f);
  }

  /// Runs a sweep (YAML body after base:) and writes its CSV; returns the path.
  std::string sweep_csv_file(const std::string& body) {
    const auto plan =
        plan_sweep(parse_sweep_spec("base: ../sf350_2d_table3.yaml\n" + body, kSweepName));
    SweepOptions opt;
    opt.threads = 2;
    const auto res = run_sweep(plan, opt);
    EXPECT_EQ(res.failed, 0u);
    const fs::path p =
        fs::temp_directory_path() / ("validation_effects_" + std::to_string(::getpid()) + "_" +
                                     std::to_string(files_.size()) + ".csv");
    std::ofstream(p, std::ios::binary) << sweep_csv(plan, res);
    files_.push_back(p);
    return p.string();
  }

  std::vector<fs::path> files_;
};

TEST_F(ValidationEffects, EffectFreeFilesKeepTheirReaderAndResults) {
  const TyreConfig config = load_tyre_config(kConfig2d);
  const auto rows = read_validation_measurements(kTable3, config);
  const auto plain = read_measurements(kTable3, config);
  ASSERT_EQ(rows.rows.size(), plain.rows.size());
  for (std::size_t i = 0; i < rows.rows.size(); ++i) {
    EXPECT_FALSE(rows_at_own_conditions(rows, config));
    EXPECT_EQ(rows.rows[i].conditions.load_N, plain.rows[i].conditions.load_N);
    EXPECT_EQ(rows.rows[i].value("sinking_mm"), plain.rows[i].value("sinking_mm"));
  }
  const auto rep = validate_footprints(load_tyre_config(kConfig2d, kNoCalibration), rows);
  EXPECT_FALSE(rep.with_conditions);
  // The measured width is compared with the config's (the 2D model takes it as an input).
  for (const auto& r : rep.rows) {
    EXPECT_DOUBLE_EQ(r.width_mm, 130);
    ASSERT_TRUE(r.width_rel_error.has_value());
    EXPECT_DOUBLE_EQ(*r.width_rel_error, 130 / *r.measured.value("width_mm") - 1);
  }
  EXPECT_EQ(rep.predicted_rows.at("width_mm"), 6);
}

TEST_F(ValidationEffects, SweepOutputValidatesAtItsOwnConditions) {
  // Data with a hidden effect: tread creep under held loads.
  const std::string csv = sweep_csv_file(
      "set:\n  effects.tread_relaxation.enabled: true\n"
      "grid:\n  hold_s: [0, 60, 600]\n  load_N: [3000, 6000]\n");
  // The model with the same effect reproduces every row (to the CSV's 10 digits).
  const auto on = with(kNoCalibration, {"effects.tread_relaxation.enabled=true"});
  const auto rows = read_validation_measurements(csv, load_tyre_config(kConfig2d, on));
  ASSERT_EQ(rows.rows.size(), 6u);
  EXPECT_EQ(rows.rows[5].conditions.hold_s, 600);
  const auto rep = validate_footprints(load_tyre_config(kConfig2d, on), rows);
  EXPECT_TRUE(rep.with_conditions);
  for (const auto& r : rep.rows) {
    EXPECT_LT(std::abs(*r.sinking_rel_error), 1e-8) << "row " << r.measured.row;
    EXPECT_LT(std::abs(*r.length_rel_error), 1e-8) << "row " << r.measured.row;
  }

  // The effect-free model still reads the conditions but cannot follow them: its error is nil
  // at hold 0 and grows with the hold time (the discrepancy discover looks for).
  const TyreConfig off_config = load_tyre_config(kConfig2d, kNoCalibration);
  const auto off_rows = read_validation_measurements(csv, off_config);
  ASSERT_TRUE(rows_at_own_conditions(off_rows, off_config));  // condition columns in the file
  const auto off = validate_footprints(load_tyre_config(kConfig2d, kNoCalibration), off_rows);
  for (std::size_t load = 0; load < 2; ++load) {
    const double e0 = *off.rows[load].sinking_rel_error;
    const double e60 = *off.rows[2 + load].sinking_rel_error;
    const double e600 = *off.rows[4 + load].sinking_rel_error;
    EXPECT_LT(std::abs(e0), 1e-8);
    EXPECT_LT(e60, -0.01);  // the model sinks less than the creeping tyre
    EXPECT_LT(e600, e60);
  }
}

TEST_F(ValidationEffects, ContactWidthPredictsAWidthGrowingWithLoad) {
  const auto on = with(kNoCalibration, {"effects.contact_width.enabled=true"});
  // With an effect on, even a file without condition columns is read with the conditions.
  const TyreConfig config_on = load_tyre_config(kConfig2d, on);
  const auto rows = read_validation_measurements(kTable3, config_on);
  ASSERT_TRUE(rows_at_own_conditions(rows, config_on));
  EXPECT_EQ(rows.rows[0].conditions.pressure_kPa, 230);
  const auto rep = validate_footprints(load_tyre_config(kConfig2d, on), rows);
  // The crown is pressed in deeper under more load, up to the tread width (max_width_mm 160).
  for (std::size_t i = 1; i < rep.rows.size(); ++i) {
    EXPECT_GE(rep.rows[i].width_mm, rep.rows[i - 1].width_mm);
  }
  EXPECT_GT(rep.rows[1].width_mm, rep.rows[0].width_mm);
  EXPECT_LE(rep.rows.back().width_mm, 160 + 1e-9);
  EXPECT_TRUE(rep.rms_rel_error.count("width_mm"));
}

TEST_F(ValidationEffects, CalibrationRunsThroughThePredictor) {
  // Planted: tread modulus 3 MPa, data at two pressures with the inflation-pressure effect on;
  // the modulus is calibrated back from two rows at different pressures.
  const std::string csv = sweep_csv_file(
      "set:\n  effects.inflation_pressure.enabled: true\n  tread.modulus_MPa: 3\n"
      "grid:\n  pressure_kPa: [180, 280]\n  load_N: [3000, 6000]\n");
  const std::vector<std::string> ov = {"effects.inflation_pressure.enabled=true",
                                       "validation.calibrate=[tread.modulus_MPa]",
                                       "validation.calibration_rows=[1, 4]"};
  const auto rows = read_validation_measurements(csv, load_tyre_config(kConfig2d, ov));
  const auto rep = validate_footprints(load_tyre_config(kConfig2d, ov), rows);
  ASSERT_EQ(rep.calibration.values.size(), 1u);
  EXPECT_NEAR(rep.calibration.values[0], 3.0, 1e-3 * 3.0);
  EXPECT_LT(rep.rms_rel_error.at("sinking_mm"), 1e-4);
}

TEST_F(ValidationEffects, ConditionColumnsAreCheckedWithFileLineAndColumn) {
  const fs::path p =
      fs::temp_directory_path() / ("validation_effects_bad_" + std::to_string(::getpid()) + ".csv");
  files_.push_back(p);
  std::ofstream(p) << "load_N,branch,sinking_mm\n3000,load,10\n4000,sideways,12\n";
  try {
    read_validation_measurements(p.string(), load_tyre_config(kConfig2d));
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3) << e.what();
    EXPECT_EQ(e.where().key, "branch") << e.what();
  }
}

}  // namespace

namespace {

// Seed Table 3 with the rigid-belt structure discover names (configs/sf350_rigid_belt.yaml):
// the same declared calibration as sf350_2d_table3.yaml (two scalars on rows 1 and 6); rows 2-5 are
// predictions of the scalars (the structure itself was chosen on all six rows, see the config).
// It reaches sinking <= 5 % and length <= 10 % RMS over the predicted rows (the footprint
// issue's target figures; that rule against per-order scaling excludes this config from
// counting for it, see the config's header).
TEST(ValidationTable3, RigidBeltConfigMeetsTheFootprintTargetsOnThePredictedRows) {
  const auto rows = read_validation_measurements(kTable3, load_tyre_config(kConfig2d));
  const auto rep =
      validate_footprints(load_tyre_config(kSrc + "/configs/sf350_rigid_belt.yaml"), rows);
  ASSERT_TRUE(rep.calibration.ok());
  EXPECT_EQ(rep.predicted_rows.at("sinking_mm"), 4);
  EXPECT_LE(rep.rms_rel_error.at("sinking_mm"), 0.05);
  EXPECT_LE(rep.rms_rel_error.at("length_mm"), 0.10);
  // And it beats the default carcass, whose belt flattens as the measured orders 2-5 say, on
  // both observables.
  const auto plain = validate_footprints(load_tyre_config(kConfig2d, {}), rows);
  EXPECT_LT(rep.rms_rel_error.at("sinking_mm"), plain.rms_rel_error.at("sinking_mm"));
  EXPECT_LT(rep.rms_rel_error.at("length_mm"), plain.rms_rel_error.at("length_mm"));
}

}  // namespace
