// validate on the seed's measured Table 3: declared calibration, bound flags, planted round
// trip (moved from tests/contact/footprint_test.cc with the module).
#include "modaltyre/studies/validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/data_paths.h"
#include "modaltyre/contact/footprint.h"

namespace {

using namespace modaltyre::contact;
using namespace modaltyre::studies;

using modaltyre_test::kConfig2d;
using modaltyre_test::kTable3;

TyreModel model_with(const std::vector<std::string>& overrides) {
  return build_tyre_model(load_tyre_config(kConfig2d, overrides));
}

MeasurementSet table3() {
  return read_validation_measurements(kTable3, load_tyre_config(kConfig2d));
}

TEST(Validation, Table3DeclaredCalibrationMeetsTheSinkingAndLengthTargets) {
  // Calibration declared in sf350_2d_table3.yaml: compliance scale and tread modulus on rows 1 and
  // 6; rows 2-5 are predictions. Issue targets over the predicted rows: sinking RMS <= 5 %, length
  // RMS <= 10 % (measured: 3.7 % and 7.8 %).
  const auto rep = validate_footprints(load_tyre_config(kConfig2d, {}), table3());
  ASSERT_EQ(rep.calibration.rows, (std::vector<int>{1, 6}));
  ASSERT_EQ(rep.calibration.keys.size(), 2u);
  EXPECT_EQ(rep.predicted_rows.at("sinking_mm"), 4);
  EXPECT_EQ(rep.predicted_rows.at("length_mm"), 4);
  EXPECT_LE(rep.rms_rel_error.at("sinking_mm"), 0.05);
  EXPECT_LE(rep.rms_rel_error.at("length_mm"), 0.10);
  for (const auto& row : rep.rows) {
    EXPECT_EQ(row.calibration, row.measured.row == 1 || row.measured.row == 6);
  }
}

TEST(Validation, CalibratedValueAtTheBoundOfItsRangeIsFlagged) {
  // The extension's bending term calibrated from 10 rad^2/s^2 with the tread modulus on rows 1
  // and 6 has no interior optimum: from the default config's values it runs to the upper bound
  // of its range (1e6), from the extended carcass's old calibration (compliance 0.94, tread
  // 2.33 MPa) to the lower one (1e-3). Either way the value must be flagged with its side, the
  // interior tread modulus not.
  const auto rep = validate_footprints(
      load_tyre_config(
          kConfig2d,
          {"modal.extend_orders=true",
           "validation.calibrate=[modal.extension_bending_s2_rad2_s2, tread.modulus_MPa]"}),
      table3());
  ASSERT_EQ(rep.calibration.values.size(), 2u);
  const double s2 = rep.calibration.values[0];
  ASSERT_TRUE(s2 < 1.01e-3 || s2 > 0.99e6) << s2;
  EXPECT_EQ(rep.calibration.at_bound, (std::vector<std::string>{s2 < 1 ? "lower" : "upper", ""}));
  const auto plain = validate_footprints(load_tyre_config(kConfig2d, {}), table3());
  EXPECT_EQ(plain.calibration.at_bound, (std::vector<std::string>{"", ""}));
}

TEST(Validation, RangeBoundSideUsesOneThousandthOfTheSpan) {
  EXPECT_EQ(range_bound_side(0.0005, 0, 1, false), "lower");  // linear span 1
  EXPECT_EQ(range_bound_side(0.002, 0, 1, false), "");
  EXPECT_EQ(range_bound_side(0.9995, 0, 1, false), "upper");
  // Log span of [1e-3, 1e6] is ln 1e9 = 20.7: the threshold is a factor exp(0.0207) = 1.021.
  EXPECT_EQ(range_bound_side(1.02e-3, 1e-3, 1e6, true), "lower");
  EXPECT_EQ(range_bound_side(1.03e-3, 1e-3, 1e6, true), "");
  EXPECT_EQ(range_bound_side(0.985e6, 1e-3, 1e6, true), "upper");
}

TEST(Validation, CalibrationRecoversPlantedParameters) {
  // Round trip: "measurements" made by the model itself with planted tread modulus and
  // compliance scale are calibrated back from two rows.
  const TyreModel planted = model_with({"tread.modulus_MPa=4.0", "modal.compliance_scale=1.1"});
  MeasurementSet meas;
  meas.loads_only = true;  // rows at the config's conditions
  meas.observables = {"sinking_mm", "length_mm"};
  const TyreConfig config = load_tyre_config(kConfig2d);
  int row = 1;
  for (double F : {2500.0, 5000.0, 7500.0}) {
    const auto r = solve_footprint(planted, {F, 0});
    ASSERT_TRUE(r.ok());
    MeasuredRow m;
    m.row = row++;
    m.conditions = config.default_conditions(F);
    m.observed["sinking_mm"] = r.sinking_m * 1e3;
    m.observed["length_mm"] = r.contact_length_m * 1e3;
    meas.rows.push_back(m);
  }
  const auto rep = validate_footprints(
      load_tyre_config(kConfig2d, {"validation.calibration_rows=[1, 3]"}), meas);
  ASSERT_EQ(rep.calibration.values.size(), 2u);
  // Least-squares stopping tolerance on log-parameters is 1e-6; 1e-3 covers the finite-difference
  // Jacobian and the flat direction of the cost.
  EXPECT_NEAR(rep.calibration.values[0], 1.1, 1e-3 * 1.1);
  EXPECT_NEAR(rep.calibration.values[1], 4.0, 1e-3 * 4.0);
  EXPECT_LT(rep.rms_rel_error.at("sinking_mm"), 1e-4);
}

}  // namespace
