// The static footprint solved matrix-free (FFT products with the carcass kernels) against the
// same load cases solved with the assembled vertical compliance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/data_paths.h"
#include "modaltyre/contact/footprint.h"

namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig2d;
// The problem's solution is unique; both routes solve it to CG/rounding accuracy.
constexpr double kMatrixFreeSame = 1e-9;

TEST(MatrixFreeFootprint, OperatorEqualsTheAssembledCompliance) {
  const TyreModel m = build_tyre_model(load_tyre_config(kConfig2d, {}));
  const Eigen::MatrixXd C = vertical_compliance_operator(m).dense();
  const double scale = m.vertical_compliance.cwiseAbs().maxCoeff();
  EXPECT_LE((C - m.vertical_compliance).cwiseAbs().maxCoeff(), 1e-14 * scale);
  EXPECT_EQ(m.vertical_compliance, m.vertical_compliance.transpose());  // exactly symmetric
}

TEST(MatrixFreeFootprint, Table3LoadsEqualTheAssembledRoute) {
  for (const char* unit : {"0.5", "0.25"}) {
    const TyreModel m = build_tyre_model(
        load_tyre_config(kConfig2d, {std::string("contact.unit_length_mm=") + unit}));
    for (double F : m.config.loads_N) {
      const FootprintResult a = solve_patch(m, static_operator(m, 0), {F, 0});
      const FootprintResult b = solve_footprint(m, {F, 0});
      ASSERT_TRUE(a.ok() && b.ok()) << a.message << " / " << b.message;
      EXPECT_NEAR(b.sinking_m, a.sinking_m, kMatrixFreeSame * a.sinking_m) << unit << " " << F;
      EXPECT_NEAR(b.contact_length_m, a.contact_length_m, kMatrixFreeSame * a.contact_length_m);
      ASSERT_EQ(b.units.size(), a.units.size());
      for (std::size_t i = 0; i < a.units.size(); ++i) {
        EXPECT_NEAR(b.units[i].fz_N, a.units[i].fz_N, kMatrixFreeSame * F);
        EXPECT_NEAR(b.units[i].x_m, a.units[i].x_m, kMatrixFreeSame * a.contact_length_m);
      }
      for (std::size_t i = 0; i < a.contour_height_m.size(); ++i) {
        EXPECT_NEAR(b.contour_height_m[i], a.contour_height_m[i], kMatrixFreeSame * a.sinking_m);
      }
    }
  }
}

}  // namespace
