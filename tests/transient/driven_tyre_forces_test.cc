// DrivenTyre::vertical_forces (the pressure distribution along x that the FMU's tangential
// contact reads): its sum is the wheel load's F_z and its moment the wheel load's M_y, on the
// 2D patch, standing and rolling.
#include <gtest/gtest.h>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/transient/driven_tyre.h"

namespace modaltyre::transient {
namespace {

TEST(DrivenTyreForces, SumAndMomentAreTheWheelLoads) {
  auto config =
      contact::load_tyre_config(std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml",
                                {"contact.unit_length_mm=2"});
  const TransientModel M = build_transient_model(contact::build_tyre_model(config));
  DrivenTyreOptions opt;
  opt.max_step_s = 1e-3;
  DrivenTyre tyre(M, opt);
  tyre.reset(HubState{0.012, 0, 0});
  for (double t : {0.0, 0.05, 0.1}) {
    if (t > 0) {
      ASSERT_TRUE(tyre.advance(t, HubState{0.012, 10, 10 / 0.2948}).ok);
    }
    Eigen::VectorXd F;
    tyre.vertical_forces(F);
    ASSERT_EQ(F.size(), M.m);
    const WheelLoad w = tyre.load();
    double moment = 0;
    for (int i = 0; i < M.m; ++i) moment += F(i) * M.x_road(i);
    EXPECT_GT(F.sum(), 1000);
    EXPECT_NEAR(F.sum(), w.fz_N, 1e-9 * w.fz_N) << t;
    EXPECT_NEAR(-moment, w.my_Nm, 1e-9 * w.fz_N) << t;
    EXPECT_GE(F.minCoeff(), 0.0);
  }
}

}  // namespace
}  // namespace modaltyre::transient
