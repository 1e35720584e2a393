// The spreads of what a config assumes (issue 44 item 2, docs/uncertainty.md section 2): the
// tread width (tread.contact_width_std_percent) moves the 2D contact width and the 3D tread
// width together, linearly; a flat crown with footprint_3d.crown.round_limit_radius_mm spans
// crowns from flat to that circle, uniform in the curvature, on outputs whose law is known in
// closed form (evaluators that return the perturbed quantities themselves).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::uncertainty {
namespace {

using modaltyre_test::kConfig3d;
constexpr double kZ975 = 1.959963984540054;

TEST(AssumedSpreads, TheTreadWidthMovesBothWidthsLinearly) {
  const auto config = contact::load_tyre_config(kConfig3d, {"tread.contact_width_std_percent=5"});
  ASSERT_DOUBLE_EQ(config.uncertainty.tread_width_rel_std, 0.05);
  const Evaluator widths = [](const contact::TyreConfig& c, const modal::ModeIdentification&,
                              const std::string&) {
    return std::vector<std::vector<double>>{
        {c.tread.width_m * 1e3, c.footprint_3d->tread_width_m * 1e3}};
  };
  const OutputSet outputs{{"contact_width_mm", "tread_width_mm"}, {}, {"row"}, {}};
  PropagationOptions o;
  o.method = Method::linear;
  const auto r = propagate_outputs(config, modal::ModeIdentification{}, widths, outputs, o);
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(r.inputs[0].input.source, "tread.contact_width_std_percent");
  const double w2d = config.tread.width_m * 1e3, w3d = config.footprint_3d->tread_width_m * 1e3;
  EXPECT_NEAR(r.cases[0].bands[0].std, 0.05 * w2d, 1e-9 * w2d);
  EXPECT_NEAR(r.cases[0].bands[1].std, 0.05 * w3d, 1e-9 * w3d);
  EXPECT_NEAR(r.cases[0].bands[1].p975 - w3d, kZ975 * 0.05 * w3d, 1e-9 * w3d);
  EXPECT_EQ(r.inputs[0].nonlinearity, 0.0);
}

// The drop of the crown at y = 75 mm: 0 flat, R - sqrt(R^2 - y^2) on a circle of radius R. With
// no continuous input the band is the crowns' weighted points: the flat crown (weight 1/8) at
// the 2.5 % point and the limit's circle (weight 1/8) at the 97.5 % point; four crowns
// evaluated.
TEST(AssumedSpreads, AFlatCrownsBandSpansFlatToTheRoundLimit) {
  const double limit_mm = 600, y = 0.075;
  const auto config = contact::load_tyre_config(
      kConfig3d, {"footprint_3d.crown.shape=flat", "footprint_3d.crown.radius_mm=1000",
                  "footprint_3d.crown.round_limit_radius_mm=600"});
  const Evaluator drop = [&](const contact::TyreConfig& c, const modal::ModeIdentification&,
                             const std::string&) {
    return std::vector<std::vector<double>>{{c.footprint_3d->crown.drop_m(y) * 1e3}};
  };
  const OutputSet outputs{{"drop_mm"}, {}, {"row"}, {}};
  const auto r = propagate_outputs(config, modal::ModeIdentification{}, drop, outputs);
  const Band& b = r.cases[0].bands[0];
  const double R = limit_mm * 1e-3, full = (R - std::sqrt(R * R - y * y)) * 1e3;
  EXPECT_EQ(b.value, 0.0);
  EXPECT_EQ(b.p025, 0.0);
  EXPECT_NEAR(b.p975, full, 1e-12);
  EXPECT_EQ(r.evaluations, 1 + 4);
  EXPECT_NE(r.check.find("round_limit_radius_mm"), std::string::npos) << r.check;
  // The drop is nearly the parabola y^2 u / 2 R, linear in the curvature u: over the trapezoid
  // weights (1, 2, 2, 2, 1) / 8 at u = 0, 1/4, .., 1 the spread is sqrt(11/32 - 1/4) of the
  // limit's drop.
  EXPECT_NEAR(r.cases[0].bands[0].std, std::sqrt(11.0 / 32 - 0.25) * full, 0.01 * full);
}

TEST(AssumedSpreads, ARoundLimitInsideTheTreadOrOnARoundCrownIsRefused) {
  const auto config = contact::load_tyre_config(
      kConfig3d, {"footprint_3d.crown.shape=flat", "footprint_3d.crown.round_limit_radius_mm=60"});
  const Evaluator none = [](const contact::TyreConfig&, const modal::ModeIdentification&,
                            const std::string&) { return std::vector<std::vector<double>>{{1.0}}; };
  try {
    (void)propagate_outputs(config, modal::ModeIdentification{}, none, {{"x"}, {}, {"r"}, {}});
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "footprint_3d.crown.round_limit_radius_mm");
  }
  // On a circular crown the key is unknown: the band of a measured crown is its own.
  EXPECT_THROW(
      (void)contact::load_tyre_config(kConfig3d, {"footprint_3d.crown.round_limit_radius_mm=600"}),
      InputError);
}

}  // namespace
}  // namespace modaltyre::uncertainty
