// The default tyre (configs/sf350.yaml, the 3D patch) against issue 18's done-when criteria that
// it meets: the real-tyre length laws and a compound-range tread. Its misses on Table 3 (sinking
// 5.9 %, width 8.5 % RMS over the predicted rows; targets 5 % and 7 %) are reported in
// docs/validation.md, not asserted here with a loosened tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/studies/validation.h"

namespace {

using namespace modaltyre::contact;
using namespace modaltyre::studies;

using modaltyre_test::kConfig3d;
using modaltyre_test::kTable3;

// Least-squares slope of ln y against ln x.
double log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]), my += std::log(y[i]);
  mx /= x.size(), my /= y.size();
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

std::vector<Prediction> predicted_at(const TyreModel& model, const std::vector<double>& loads_N) {
  std::vector<OperatingConditions> cases;
  for (double F : loads_N) cases.push_back(model.config.default_conditions(F));
  auto out = predict_all(model, cases);
  for (const auto& p : out) EXPECT_TRUE(p.ok()) << p.message;
  return out;
}

class DefaultConfig : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    config_ = new TyreConfig(load_tyre_config(kConfig3d));
    model_ = new TyreModel(build_tyre_model(*config_));
  }
  static void TearDownTestSuite() {
    delete model_;
    delete config_;
  }
  static TyreConfig* config_;
  static TyreModel* model_;
};
TyreConfig* DefaultConfig::config_ = nullptr;
TyreModel* DefaultConfig::model_ = nullptr;

TEST_F(DefaultConfig, IsThe3dPatchWithATreadInTheCompoundRange) {
  ASSERT_TRUE(config_->footprint_3d.has_value());
  EXPECT_GE(config_->tread.modulus_Pa, 3e6);  // a tread compound's static modulus: 3-8 MPa
}

// Real passenger tyres grow in length as F^0.55-0.67 (issue 18); the accepted band is 0.45-0.70.
TEST_F(DefaultConfig, LengthExponentOverTable3LoadsLiesInTheRealTyreBand) {
  const std::vector<double> loads = {2131, 3261, 5478, 6502, 7322, 8321};
  std::vector<double> lengths;
  for (const auto& p : predicted_at(*model_, loads)) lengths.push_back(p.length_mm);
  const double exponent = log_slope(loads, lengths);
  EXPECT_GE(exponent, 0.45);
  EXPECT_LE(exponent, 0.70);
}

// MF-Tool contact-length law of a real passenger tyre in dimensionless form (Pacejka 2012
// eq. A3.7, TNO 205/60R15 MF-Swift 6.2 example): 2a/R0 = 2 (Q_RA2 rho/R0 + Q_RA1 sqrt(rho/R0)),
// at the model's own deflection rho, 1.5-9.5 kN: within 6 % RMS.
TEST_F(DefaultConfig, ContactLengthFollowsTheTnoLawWithinSixPercentRms) {
  const double q_ra1 = 0.6715, q_ra2 = 0.7308, R0 = config_->outer_radius_m;
  std::vector<double> loads;
  for (double F = 1500; F <= 9500; F += 1000) loads.push_back(F);
  double sq = 0;
  for (const auto& p : predicted_at(*model_, loads)) {
    const double x = p.sinking_mm * 1e-3 / R0;
    const double law = 2 * (q_ra2 * x + q_ra1 * std::sqrt(x));
    const double e = p.length_mm * 1e-3 / R0 / law - 1;
    sq += e * e;
  }
  EXPECT_LE(std::sqrt(sq / loads.size()), 0.06);
}

// The declared calibration (two scalars on sinking and width of rows 1 and 6) reproduces the
// config's values: they are the fit, not tuned by hand.
TEST_F(DefaultConfig, DeclaredCalibrationReproducesTheConfigsValues) {
  const auto set = read_validation_measurements(kTable3, *config_);
  const auto rep = validate_footprints(*config_, set);
  const auto& c = rep.calibration;
  ASSERT_EQ(c.keys,
            (std::vector<std::string>{"modal.compliance_scale", "footprint_3d.crown.radius_mm"}));
  EXPECT_EQ(c.rows, (std::vector<int>{1, 6}));
  EXPECT_EQ(c.observables, (std::vector<std::string>{"sinking_mm", "width_mm"}));
  for (std::size_t k = 0; k < c.keys.size(); ++k) {
    EXPECT_NEAR(c.values[k], c.initial_values[k], 1e-3 * c.initial_values[k]) << c.keys[k];
  }
  EXPECT_EQ(rep.predicted_rows.at("width_mm"), 4);
}

}  // namespace
