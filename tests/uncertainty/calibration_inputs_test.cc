// The calibrated scalars' covariance as independent inputs (docs/uncertainty.md section 7): the
// principal directions rebuild Cov(ln x) exactly, and applying one moves every key along it.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/data_paths.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/uncertainty/inputs.h"

namespace modaltyre::uncertainty {
namespace {

constexpr double kRound = 1e-12;  // eigen-decomposition rounding of O(1e-2) variances
using modaltyre_test::kConfig2d;

TEST(CalibrationInputs, PrincipalDirectionsRebuildTheCovarianceAndMoveTheKeys) {
  const std::vector<std::string> keys = {"modal.compliance_scale", "tread.modulus_MPa"};
  const std::vector<double> values = {0.9, 6.0}, se = {0.09, 1.2};
  const double corr = -0.8;
  const auto inputs = calibration_inputs(keys, values, se, {{1.0, corr}, {corr, 1.0}});
  ASSERT_EQ(inputs.size(), 2u);
  // sum_d lambda_d v_d v_d^T = Cov(ln x), Cov_ij = (se_i/x_i)(se_j/x_j) corr_ij.
  const double r0 = se[0] / values[0], r1 = se[1] / values[1];
  double c00 = 0, c01 = 0, c11 = 0;
  for (const auto& in : inputs) {
    EXPECT_EQ(in.kind, InputKind::calibration);
    const double l = in.rel_std * in.rel_std;
    c00 += l * in.direction[0] * in.direction[0];
    c01 += l * in.direction[0] * in.direction[1];
    c11 += l * in.direction[1] * in.direction[1];
  }
  EXPECT_NEAR(c00, r0 * r0, kRound);
  EXPECT_NEAR(c11, r1 * r1, kRound);
  EXPECT_NEAR(c01, corr * r0 * r1, kRound);
  EXPECT_GE(inputs[0].rel_std, inputs[1].rel_std);  // largest variance first

  // Applying x along direction d multiplies key k by exp(x v_dk).
  auto config = contact::load_tyre_config(kConfig2d, {});
  const double cs = config.compliance_scale, e = config.tread.modulus_Pa;
  modal::ModeIdentification modes;
  apply(inputs[0], 0.1, config, modes);
  EXPECT_NEAR(config.compliance_scale / cs, std::exp(0.1 * inputs[0].direction[0]), 1e-12);
  EXPECT_NEAR(config.tread.modulus_Pa / e, std::exp(0.1 * inputs[0].direction[1]), 1e-12);
}

TEST(CalibrationInputs, NoStandardErrorsNoInputs) {
  EXPECT_TRUE(calibration_inputs({"modal.compliance_scale"}, {1.0}, {}, {}).empty());
}

}  // namespace
}  // namespace modaltyre::uncertainty
