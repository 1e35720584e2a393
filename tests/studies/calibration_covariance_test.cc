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

#include "../support/data_paths.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/studies/validation.h"

namespace {

using namespace modaltyre::contact;
using namespace modaltyre::studies;
namespace fs = std::filesystem;

using modaltyre_test::kConfig2d;
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
  // With `rel_std` (sinking, length), the rows state their noise in the *_std columns.
  ValidationReport validate(const std::vector<double>& sinking, const std::vector<double>& length,
                            int k, const std::vector<double>& rel_std = {}) {
    const fs::path csv = dir_ / ("rows" + std::to_string(k) + ".csv");
    std::ofstream out(csv);
    out.precision(12);
    out << "load_N,sinking_mm,length_mm" << (rel_std.empty() ? "" : ",sinking_std_mm,length_std_mm")
        << "\n";
    for (std::size_t i = 0; i < kLoads.size(); ++i) {
      out << kLoads[i] << "," << sinking[i] << "," << length[i];
      if (!rel_std.empty()) out << "," << rel_std[0] * sinking[i] << "," << rel_std[1] * length[i];
      out << "\n";
    }
    out.close();
    const TyreConfig c = load_tyre_config(kConfig2d, kCalibrateScale);
    return validate_footprints(c, read_validation_measurements(csv.string(), c));
  }
  fs::path dir_;
};

TEST_F(CalibrationCovariance, StandardErrorMatchesAParametricBootstrap) {
  // "Measured" rows: the model at compliance scale 1.1 with 3 % noise on each value.
  const TyreModel truth = build_tyre_model(load_tyre_config(
      kConfig2d,
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
      load_tyre_config(kConfig2d, {"contact.unit_length_mm=2", "contact.window_mm=300",
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
  const TyreConfig c =
      load_tyre_config(kConfig2d, {"contact.unit_length_mm=2", "contact.window_mm=300",
                                   "validation.calibrate=[modal.compliance_scale]",
                                   "validation.calibration_rows=[1]",
                                   "validation.calibration_observables=[sinking_mm]"});
  const ValidationReport r = validate_footprints(c, read_validation_measurements(csv.string(), c));
  EXPECT_TRUE(r.calibration.std_errors.empty());
  EXPECT_NE(r.calibration.covariance_note.find("no degree of freedom"), std::string::npos)
      << r.calibration.covariance_note;
}

// With the rows' stated noise (the *_std columns: sinking 1 %, length 5 %) the calibration weighs
// each residual by it (chi-square), and its standard error is the known noise's: it matches a
// parametric bootstrap drawn with that noise within the same factor.
TEST_F(CalibrationCovariance, StatedNoiseWeighsTheFitAndMatchesItsBootstrap) {
  const std::vector<double> rel = {0.01, 0.05};
  const TyreModel truth = build_tyre_model(load_tyre_config(
      kConfig2d,
      {"contact.unit_length_mm=2", "contact.window_mm=300", "modal.compliance_scale=1.1"}));
  std::vector<Prediction> base;
  for (double F : kLoads) base.push_back(predict(truth, truth.config.default_conditions(F)));
  std::mt19937 rng(7);
  std::normal_distribution<double> ns(0.0, rel[0]), nl(0.0, rel[1]);
  const auto draw = [&](std::vector<double>& s, std::vector<double>& l) {
    s.clear(), l.clear();
    for (const auto& p : base) {
      s.push_back(p.sinking_mm * (1 + ns(rng)));
      l.push_back(p.length_mm * (1 + nl(rng)));
    }
  };
  std::vector<double> s, l;
  draw(s, l);
  const ValidationReport fit = validate(s, l, 100, rel);
  ASSERT_TRUE(fit.calibration.noise_weighted);
  ASSERT_EQ(fit.calibration.std_errors.size(), 1u) << fit.calibration.covariance_note;
  EXPECT_NE(fit.calibration.covariance_note.find("stated noise"), std::string::npos);
  const double stated = fit.calibration.std_errors[0];
  std::vector<double> values;
  for (int b = 0; b < kReplicates; ++b) {
    draw(s, l);
    values.push_back(validate(s, l, 101 + b, rel).calibration.values[0]);
  }
  double mean = 0, var = 0;
  for (double v : values) mean += v / kReplicates;
  for (double v : values) var += (v - mean) * (v - mean) / (kReplicates - 1);
  const double spread = std::sqrt(var);
  RecordProperty("stated_se", std::to_string(stated));
  RecordProperty("bootstrap_spread", std::to_string(spread));
  EXPECT_GT(stated, spread / kFactor) << stated << " vs bootstrap " << spread;
  EXPECT_LT(stated, spread * kFactor) << stated << " vs bootstrap " << spread;
}

// A precise observable governs a weighted fit: sinking from the scale 1.1 stated at 0.1 %, the
// lengths 10 % long stated at 10 %: the weighted scale stays within 0.5 % of 1.1, the unweighted
// one is pulled off by the lengths.
TEST_F(CalibrationCovariance, ThePreciseObservableGovernsAWeightedFit) {
  const TyreModel truth = build_tyre_model(load_tyre_config(
      kConfig2d,
      {"contact.unit_length_mm=2", "contact.window_mm=300", "modal.compliance_scale=1.1"}));
  std::vector<double> s, l;
  for (double F : kLoads) {
    const Prediction p = predict(truth, truth.config.default_conditions(F));
    s.push_back(p.sinking_mm);
    l.push_back(p.length_mm * 1.1);
  }
  const ValidationReport weighted = validate(s, l, 200, {0.001, 0.1});
  const ValidationReport plain = validate(s, l, 201);
  ASSERT_TRUE(weighted.calibration.noise_weighted);
  EXPECT_FALSE(plain.calibration.noise_weighted);
  EXPECT_NEAR(weighted.calibration.values[0], 1.1, 0.005 * 1.1);
  EXPECT_GT(std::abs(plain.calibration.values[0] - 1.1),
            4 * std::abs(weighted.calibration.values[0] - 1.1));
}

}  // namespace
