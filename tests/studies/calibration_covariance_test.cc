// Issue 35: validate's calibrated scalars carry standard errors (Jacobian at the fit, residual
// variance) that match a parametric bootstrap within a factor 1.5: rows simulated from the
// calibrated model with the fit's residual noise, recalibrated, and the spread of the values.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/studies/validation.h"

namespace {

using namespace modaltyre::contact;
using namespace modaltyre::studies;
namespace fs = std::filesystem;

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
// The tolerance between the stated standard error and the bootstrap's spread.
constexpr double kFactor = 1.5;
// Replicates of the bootstrap: their spread is itself uncertain by about 1 / sqrt(2 (B - 1)),
// 16 % at 20.
constexpr int kReplicates = 20;
const std::vector<double> kLoads = {3000, 7000};

const std::vector<std::string> kCalibrateScale = {
    "contact.unit_length_mm=2", "contact.window_mm=300",
    "validation.calibrate=[modal.compliance_scale]", "validation.calibration_rows=[1, 2]",
    "validation.calibration_observables=[sinking_mm, length_mm]"};

class CalibrationCovariance : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("modaltyre_cov_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Two rows: sinking and length at each load, as given.
  ValidationReport validate(const std::vector<double>& sinking, const std::vector<double>& length,
                            int k) {
    const fs::path csv = dir_ / ("rows" + std::to_string(k) + ".csv");
    std::ofstream out(csv);
    out.precision(12);
    out << "load_N,sinking_mm,length_mm\n";
    for (std::size_t i = 0; i < kLoads.size(); ++i)
      out << kLoads[i] << "," << sinking[i] << "," << length[i] << "\n";
    out.close();
    const TyreConfig c = load_tyre_config(kConfig, kCalibrateScale);
    return validate_footprints(c, read_validation_measurements(csv.string(), c));
  }
  fs::path dir_;
};

TEST_F(CalibrationCovariance, StandardErrorMatchesAParametricBootstrap) {
  // "Measured" rows: the model at compliance scale 1.1 with 3 % noise on each value.
  const TyreModel truth = build_tyre_model(load_tyre_config(
      kConfig,
      {"contact.unit_length_mm=2", "contact.window_mm=300", "modal.compliance_scale=1.1"}));
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 0.03);
  std::vector<double> s, l;
  for (double F : kLoads) {
    const Prediction p = predict(truth, truth.config.default_conditions(F));
    s.push_back(p.sinking_mm * (1 + noise(rng)));
    l.push_back(p.length_mm * (1 + noise(rng)));
  }
  const ValidationReport fit = validate(s, l, 0);
  ASSERT_EQ(fit.calibration.std_errors.size(), 1u) << fit.calibration.covariance_note;
  const double value = fit.calibration.values[0], stated = fit.calibration.std_errors[0];
  // The residual noise the fit saw (4 residuals, 1 scalar): the bootstrap's noise level.
  const double sigma = fit.calibration.rms_rel_residual * std::sqrt(4.0 / 3.0);

  const TyreModel at_fit = build_tyre_model(
      load_tyre_config(kConfig, {"contact.unit_length_mm=2", "contact.window_mm=300",
                                 "modal.compliance_scale=" + std::to_string(value)}));
  std::vector<Prediction> base;
  for (double F : kLoads) base.push_back(predict(at_fit, at_fit.config.default_conditions(F)));
  std::normal_distribution<double> boot(0.0, sigma);
  std::vector<double> values;
  for (int b = 0; b < kReplicates; ++b) {
    std::vector<double> bs, bl;
    for (const auto& p : base) {
      bs.push_back(p.sinking_mm * (1 + boot(rng)));
      bl.push_back(p.length_mm * (1 + boot(rng)));
    }
    values.push_back(validate(bs, bl, b + 1).calibration.values[0]);
  }
  double mean = 0, var = 0;
  for (double v : values) mean += v / kReplicates;
  for (double v : values) var += (v - mean) * (v - mean) / (kReplicates - 1);
  const double spread = std::sqrt(var);
  EXPECT_GT(stated, spread / kFactor) << stated << " vs bootstrap " << spread;
  EXPECT_LT(stated, spread * kFactor) << stated << " vs bootstrap " << spread;
}

TEST_F(CalibrationCovariance, NoDegreeOfFreedomIsSaidNotGuessed) {
  // One row, one observable, one scalar: the noise cannot be estimated.
  const fs::path csv = dir_ / "one.csv";
  std::ofstream(csv) << "load_N,sinking_mm\n4000,14\n";
  const TyreConfig c = load_tyre_config(
      kConfig, {"contact.unit_length_mm=2", "contact.window_mm=300",
                "validation.calibrate=[modal.compliance_scale]", "validation.calibration_rows=[1]",
                "validation.calibration_observables=[sinking_mm]"});
  const ValidationReport r = validate_footprints(c, read_validation_measurements(csv.string(), c));
  EXPECT_TRUE(r.calibration.std_errors.empty());
  EXPECT_NE(r.calibration.covariance_note.find("no degree of freedom"), std::string::npos)
      << r.calibration.covariance_note;
}

}  // namespace
