// Slip as terramechanics defines it (contact/rolling_radius.h, contact/traction_curve.h,
// contact/src/traction_kinematics.h, docs/soil.md section 5.1): the shear along the deformed
// contour, the rolling radius on the rigid road, the rolling-radius slip, the tractive efficiency
// and the towed and self-propelled points.
#include "modaltyre/contact/rolling_radius.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../../contact/src/traction_kinematics.h"
#include "../support/data_paths.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/contact/traction_curve.h"

namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;

TEST(ContourSlip, OnTheRigidWheelsCircleItIsWongsShearDisplacement) {
  // j(theta) = R [(theta1 - theta) - rho (sin theta1 - sin theta)], marched over chords of the
  // circle: second order in the step.
  const double R = 0.3, th1 = 0.4, rho = 0.8;
  for (int n : {50, 100}) {
    detail::ContourSlip path(R, rho, R * std::sin(th1), R * (1 - std::cos(th1)) * 0, th1);
    double worst = 0;
    for (int k = 1; k <= n; ++k) {
      const double th = th1 - 0.6 * k / n;
      // The circle's depth below its entry point: R (cos th - cos th1), measured downward.
      const double j = path.advance(R * std::sin(th), R * (std::cos(th) - std::cos(th1)), th);
      const double wong = R * ((th1 - th) - rho * (std::sin(th1) - std::sin(th)));
      worst = std::max(worst, std::abs(j - wong));
    }
    EXPECT_LT(worst, (n == 50 ? 4e-6 : 1e-6)) << n;
  }
}

TEST(ContourSlip, AFlatContourShorterThanItsArcRollsFreelyBelowTheOuterRadius) {
  // Points R0 dtheta apart along the arc but x = r dtheta apart on the flat road: j = 0 for all
  // of them at rho = r / R0 (the tread moves at omega r, as the ground).
  const double R0 = 0.3, r = 0.29, rho = r / R0;
  detail::ContourSlip path(R0, rho, 0.05, 0.0, 0.05 / r);
  for (int k = 1; k <= 20; ++k) {
    const double x = 0.05 - 0.005 * k;
    EXPECT_NEAR(path.advance(x, 0.0, x / r), 0.0, 1e-15);
  }
}

// Done-when (item 1): r_e between the loaded radius on the rigid road and R0. The model's own
// free rolling on the rigid road (Coulomb friction with the tread's stick stiffness, the rolling
// fixed point) lies at the rolling-radius slip 0.
TEST(RollingRadius, TheSF350RollsFreelyOnTheRoadBetweenItsLoadedAndOuterRadius) {
  const TyreModel m = build_tyre_model(load_tyre_config(kConfig2d, {"contact.unit_length_mm=1"}));
  const double R0 = m.config.outer_radius_m;
  modaltyre::ground::GroundSettings road;  // the rigid flat road
  for (double load : {2000.0, 4000.0}) {
    const RollingRadius re = rolling_radius(m, load);
    ASSERT_TRUE(re.ok()) << re.message;
    EXPECT_GT(re.radius_m, re.loaded_radius_m) << load;
    EXPECT_LT(re.radius_m, R0) << load;
    EXPECT_GT(re.deflection_m, 0.005) << load;
    TractionOptions o;  // rolling-radius slip (the default)
    const std::vector<TractionResult> at =
        steady_traction(m, road, {{load, -0.01}, {load, 0.0}, {load, 0.01}}, o);
    ASSERT_EQ(at.size(), 3u);
    for (const auto& r : at) ASSERT_TRUE(r.ok()) << r.message;
    // The brush's free rolling leaves out the sliding at the contact's edges and the carcass's
    // response to the shear forces: the model's own zero lies within 5e-4 of slip (0.15 mm of
    // r_e), where 1 % of slip pulls more than 1 % of the load.
    EXPECT_LT(at[0].drawbar_pull_N, -0.01 * load);
    EXPECT_GT(at[2].drawbar_pull_N, 0.01 * load);
    const double slope = (at[2].drawbar_pull_N - at[0].drawbar_pull_N) / 0.02;
    EXPECT_LT(std::abs(at[1].drawbar_pull_N / slope), 5e-4) << load;
    EXPECT_DOUBLE_EQ(at[1].rolling_radius_m, re.radius_m);
    EXPECT_DOUBLE_EQ(at[1].slip_radius_m, re.radius_m);
    // Against R0 the same free rolling lies at s = 1 - r_e / R0 > 0.
    o.slip_reference = SlipReference::unloaded;
    const double s0 = 1 - re.radius_m / R0;
    const std::vector<TractionResult> r0 = steady_traction(m, road, {{load, s0}}, o);
    ASSERT_TRUE(r0[0].ok());
    EXPECT_LT(std::abs(r0[0].drawbar_pull_N / slope), 5e-4) << load;
    EXPECT_DOUBLE_EQ(r0[0].slip_radius_m, R0);
  }
}

TEST(RollingRadius, TheDefault3DTyreRollsBetweenItsLoadedAndOuterRadius) {
  const TyreModel m = build_tyre_model(load_tyre_config(kConfig3d));
  const RollingRadius re = rolling_radius(m, 3000);
  ASSERT_TRUE(re.ok()) << re.message;
  EXPECT_GT(re.radius_m, re.loaded_radius_m);
  EXPECT_LT(re.radius_m, m.config.outer_radius_m);
}

TractionResult row(double load, double slip, double dp, double torque) {
  TractionResult r;
  r.status = modaltyre::SolveStatus::converged;
  r.load_N = load, r.slip = slip, r.drawbar_pull_N = dp, r.torque_Nm = torque;
  return r;
}

TEST(TractionCurve, TheTowedAndSelfPropelledPointsAreTheZeroCrossings) {
  // DP = -100 + 2000 s, T = 50 + 500 s on the slips given (unsorted, one failed row ignored):
  // towed at s = -0.1 with DP = -300, self-propelled at s = 0.05 with T = 75.
  std::vector<TractionResult> rs;
  for (double s : {0.2, -0.2, 0.0, 0.1, -0.05})
    rs.push_back(row(3000, s, -100 + 2000 * s, 50 + 500 * s));
  rs.push_back(row(3000, 0.15, 1e9, 1e9));
  rs.back().status = modaltyre::SolveStatus::failed;
  rs.push_back(row(4000, 0.1, 10, 10));  // a second curve: no crossing
  const std::vector<TractionCurve> c = traction_curves(rs);
  ASSERT_EQ(c.size(), 2u);
  ASSERT_TRUE(c[0].towed && c[0].self_propelled);
  EXPECT_NEAR(c[0].towed->slip, -0.1, 1e-12);
  EXPECT_NEAR(c[0].towed->value, -300, 1e-9);
  EXPECT_NEAR(c[0].self_propelled->slip, 0.05, 1e-12);
  EXPECT_NEAR(c[0].self_propelled->value, 75, 1e-9);
  EXPECT_EQ(c[0].rows.size(), 6u);
  EXPECT_FALSE(c[1].towed.has_value());
  EXPECT_FALSE(c[1].self_propelled.has_value());
}

TEST(TractionEfficiency, IsDrawbarPowerOverWheelPower) {
  // eta = DP V / (T omega) with V / omega = (1 - s) r_e (driven, rolling-radius slip).
  const TyreModel m = build_tyre_model(load_tyre_config(
      kConfig2d,
      {"contact.unit_length_mm=1", "ground.model=bekker", "ground.bekker.n=0.79",
       "ground.bekker.k_c=102", "ground.bekker.k_phi=5301", "ground.bekker.cohesion_kPa=1.3",
       "ground.bekker.friction_angle_deg=31.1", "ground.bekker.shear_modulus_K_mm=12"}));
  const std::vector<TractionResult> rs =
      steady_traction(m, m.config.ground, {{3000, -0.1}, {3000, 0.2}});
  ASSERT_TRUE(rs[0].ok() && rs[1].ok());
  EXPECT_EQ(rs[0].tractive_efficiency, 0.0);  // braked: no tractive efficiency
  const TractionResult& r = rs[1];
  EXPECT_NEAR(r.tractive_efficiency, r.drawbar_pull_N * 0.8 * r.rolling_radius_m / r.torque_Nm,
              1e-12);
  EXPECT_GT(r.tractive_efficiency, 0.3);
  EXPECT_LT(r.tractive_efficiency, 0.8);
}

}  // namespace
