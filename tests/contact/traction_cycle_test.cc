// Steady rolling caught in a limit cycle (contact/src/traction_cycle.h, docs/soil.md section 10,
// "Runs that do not settle"): the guard finds an orbit that returns with its contact switching and
// never takes a run creeping to its fixed point for one; a stiff tyre whose Anderson-mixed rolling
// cycled for its whole budget fails at the cycle, or, with plain_steps_on_cycle, settles on plain
// steps at a state that is the fixed point (rolled again from it, it stays).
#include "../../contact/src/traction_cycle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/ground/ground_settings.h"

namespace modaltyre::contact {
namespace {

using detail::CycleGuard;

using modaltyre_test::kSrc;

Eigen::VectorXd vec(double a, double b) { return (Eigen::VectorXd(2) << a, b).finished(); }

TEST(RollingCycle, TheGuardFindsAnOrbitReturningWithItsContactSwitching) {
  // Three states visited in turn, the third with one unit out of contact, their distance from
  // the cycle shrinking tenfold a turn: period 3, found once it has held for kHold steps.
  const std::vector<Eigen::VectorXd> orbit = {vec(0, 0), vec(50, 20), vec(80, -30)};
  const std::vector<std::vector<char>> contact = {{1, 1}, {1, 1}, {1, 0}};
  const Eigen::VectorXd scale = vec(1, 1);
  CycleGuard guard;
  int found = 0, step = 0;
  for (; step < 60 && !found; ++step) {
    const double off = 40 * std::pow(0.1, step / 3);
    found = guard.repeat(orbit[step % 3] + vec(off, -off), scale, contact[step % 3], 100);
  }
  EXPECT_EQ(found, 3);
  EXPECT_LE(step, 20);
}

TEST(RollingCycle, TheGuardFindsANoisyOrbitReturningWithinAPerCentOfItsSwing) {
  // A swing of ~5000 tolerances with rounding noise of 20 (0.4 % of it): period 3.
  const std::vector<Eigen::VectorXd> orbit = {vec(0, 0), vec(5000, 2000), vec(8000, -3000)};
  const std::vector<std::vector<char>> contact = {{1, 1}, {1, 1}, {1, 0}};
  CycleGuard guard;
  int found = 0, step = 0;
  for (; step < 60 && !found; ++step) {
    const double noise = 20 * std::sin(1.7 * step);
    found = guard.repeat(orbit[step % 3] + vec(noise, noise), vec(1, 1), contact[step % 3], 1e3);
  }
  EXPECT_EQ(found, 3);
  EXPECT_LE(step, 3 + 8);  // its first period, then kHold returns
}

TEST(RollingCycle, TheGuardNeverTakesACreepADampedOscillationOrAWobbleForACycle) {
  const Eigen::VectorXd scale = vec(1, 1);
  const std::vector<char> in = {1, 1}, out = {1, 0};
  // A geometric creep to the fixed point (the plain step's ratio, 0.7) failing the settle test.
  CycleGuard creep;
  for (int t = 0; t < 200; ++t) {
    const double r = 1e4 * std::pow(0.7, t);
    EXPECT_EQ(creep.repeat(vec(r, -r), scale, in, std::max(r, 2.0)), 0) << t;
  }
  // A creep that passes a contact switch on the way (one unit out, then in for good).
  CycleGuard passing;
  for (int t = 0; t < 200; ++t)
    EXPECT_EQ(passing.repeat(vec(1e3 * std::pow(0.9, t), 0), scale, t < 5 ? out : in, 100), 0);
  // A wobble of 2 tolerances in one contact set: below the cycle's least step (kAmplitude).
  CycleGuard wobble;
  for (int t = 0; t < 200; ++t)
    EXPECT_EQ(wobble.repeat(vec(t % 2 ? 2.0 : 0.0, 0), scale, in, 5), 0) << t;
  // A damped oscillation losing 10 % of its swing a period (Anderson's mixing settling).
  CycleGuard damped;
  for (int t = 0; t < 200; ++t) {
    const double x = 1e3 * std::pow(0.9, t / 2.0) * (t % 2 ? 1 : -1);
    EXPECT_EQ(damped.repeat(vec(x, 0), scale, t % 2 ? in : out, std::max(2 * std::abs(x), 2.0)), 0)
        << t;
  }
  // An exact cycle whose settle test fails by less than kMargin: it may settle; not taken.
  CycleGuard marginal;
  for (int t = 0; t < 200; ++t)
    EXPECT_EQ(marginal.repeat(vec(t % 2 ? 50.0 : 0.0, 0), scale, t % 2 ? in : out, 1.5), 0) << t;
}

// The 2D SF-350 on 4 mm units on LETE sand (Wong, Table 2.3), 20 times stiffer in its carcass
// and with a 100 MPa tread: the corner of discover's baseline fit where its traction rows' rolling
// cycled (docs/soil.md section 10). Its rear unit rides on the rut's rigid floor and leaves it.
TyreConfig stiff_tyre_on_lete_sand() {
  TyreConfig c = load_tyre_config(
      kSrc + "/configs/sf350_2d_table3.yaml",
      {"contact.unit_length_mm=4", "modal.compliance_scale=0.05", "tread.modulus_MPa=100"});
  c.ground = ground::load_ground_file(kSrc + "/configs/soils/lete_sand.yaml", {});
  return c;
}

TEST(RollingCycle, AStiffTyreWhoseMixingCyclesFailsAtTheCycleNotAtItsBudget) {
  // The default: the run fails as it did at its 200th step, once the cycle is found.
  const TyreConfig c = stiff_tyre_on_lete_sand();
  const TyreModel model = build_tyre_model(c);
  const auto r = steady_traction(model, c.ground, {{2500, 0.05}}, TractionOptions{});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r.front().ok());
  EXPECT_EQ(r.front().status, SolveStatus::max_iterations);
  EXPECT_NE(r.front().message.find("did not settle: at step"), std::string::npos)
      << r.front().message;
  EXPECT_NE(r.front().message.find("orbits a cycle of 10 steps"), std::string::npos)
      << r.front().message;
}

TEST(RollingCycle, AStiffTyreWhoseMixingCycledSettlesOnPlainStepsAtItsFixedPoint) {
  const TyreConfig c = stiff_tyre_on_lete_sand();
  const TyreModel model = build_tyre_model(c);
  TractionOptions o;
  o.plain_steps_on_cycle = true;
  // Cold, slip 0.05: with Anderson's mixing alone it cycled with a period of 10 steps for its
  // 200 (a unit at the rear switching in and out of contact) and failed.
  const auto once = steady_traction(model, c.ground, {{2500, 0.05}}, o);
  ASSERT_EQ(once.size(), 1u);
  const TractionResult& r = once.front();
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_GT(r.soil_sinkage_m, 0.01);
  // Its state is the fixed point: the same case rolled again from it (the warm start of a second
  // case at the same slip) settles where it stands, within the settle tests' tolerances (1e-5 of
  // the load on the forces, 1e-4 of the sinkage on depths) times the plain step's stopping
  // error 1 / (1 - 0.7).
  const auto twice = steady_traction(model, c.ground, {{2500, 0.05}, {2500, 0.05}}, o);
  ASSERT_EQ(twice.size(), 2u);
  const TractionResult& again = twice.back();
  ASSERT_TRUE(again.ok()) << again.message;
  const double force_tol_N = 1e-5 * 2500 / (1 - 0.7);
  EXPECT_NEAR(again.drawbar_pull_N, r.drawbar_pull_N, force_tol_N);
  EXPECT_NEAR(again.torque_Nm, r.torque_Nm, force_tol_N * c.outer_radius_m);
  EXPECT_NEAR(again.soil_sinkage_m, r.soil_sinkage_m, 1e-4 * r.soil_sinkage_m / (1 - 0.7));
  // The curve rolls on, each slip warm from the last (0.2 cycled at 20 steps, then 0.5 failed).
  const auto curve = steady_traction(model, c.ground, {{2500, 0.05}, {2500, 0.2}, {2500, 0.5}}, o);
  for (const auto& t : curve) EXPECT_TRUE(t.ok()) << t.slip << ": " << t.message;
  EXPECT_LT(curve[0].drawbar_pull_N, curve[1].drawbar_pull_N);
  EXPECT_LT(curve[1].drawbar_pull_N, curve[2].drawbar_pull_N);
}

}  // namespace
}  // namespace modaltyre::contact
