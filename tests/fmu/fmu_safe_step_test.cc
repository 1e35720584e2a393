// Safe communication steps (issue 46 item 4): a long communication step is integrated at
// internal steps of at most step_size (it gives what as many short steps give), and a hub
// motion that puts the rim on the road raises tyre.rim_contact with a warning each time it
// starts, the load staying finite. configs/sf350_2d_table3.yaml: section height 294.8 - 177.8 =
// 117 mm.
#include <gtest/gtest.h>

#include <cmath>

#include "fmu_host.h"

namespace modaltyre::fmu::test {
namespace {

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
constexpr double kR0 = 0.2948, kSectionHeight = 0.117;

bool rim(FmuInstance& f) {
  const fmi2ValueReference r = road_2d_fmu().vr("tyre.rim_contact");
  fmi2Boolean b = -1;
  EXPECT_EQ(road_2d_fmu().api().get_boolean(f.component(), &r, 1, &b), fmi2OK);
  return b == fmi2True;
}

int warnings(const FmuInstance& f) {
  int n = 0;
  for (const std::string& m : f.messages())
    n += m.find("the rim reaches the road") != std::string::npos;
  return n;
}

TEST(FmuSafeStep, ALongStepGivesWhatAsManyStepsOfStepSizeGive) {
  // The hub pressed 20 mm in one 0.2 s communication step, and in 200 steps of 1 ms.
  const double depth = 0.020, duration = 0.2, w = -depth / duration;
  FmuInstance one(road_2d_fmu()), many(road_2d_fmu());
  ASSERT_EQ(one.initialize(), fmi2OK);
  ASSERT_EQ(many.initialize(), fmi2OK);
  one.set("wheel_state.lin_vel.z", w);
  ASSERT_EQ(one.step(duration), fmi2OK);
  for (int k = 0; k < 200; ++k) {
    many.set("wheel_state.pos.z", kR0 + w * k * 1e-3);
    many.set("wheel_state.lin_vel.z", w);
    ASSERT_EQ(many.step(1e-3), fmi2OK);
  }
  const double fz = many.get("wheel_load.force.z");
  EXPECT_GT(fz, 3000);
  EXPECT_NEAR(one.get("wheel_load.force.z"), fz, 1e-6 * fz);
  EXPECT_NEAR(one.get("tyre.deflection"), depth, 1e-9);
}

TEST(FmuSafeStep, TheRimOnTheRoadRaisesAFlagAndAWarningEachTimeItStarts) {
  // Issue 46: a 0.5 s communication step that carries the hub 145 mm down returned OK with
  // F_z 64 kN and no word.
  FmuInstance f(road_2d_fmu());
  ASSERT_EQ(f.initialize(), fmi2OK);
  EXPECT_FALSE(rim(f));
  f.set("wheel_state.lin_vel.z", -0.145 / 0.5);
  EXPECT_EQ(f.step(0.5), fmi2Warning);
  EXPECT_TRUE(rim(f));
  EXPECT_EQ(warnings(f), 1);
  EXPECT_TRUE(f.logged("section height 117")) << f.messages().back();
  const double fz = f.get("wheel_load.force.z");
  EXPECT_TRUE(std::isfinite(fz) && fz > 0) << fz;
  EXPECT_GT(f.get("tyre.deflection"), kSectionHeight);
  // Held there: still on the rim, no new warning.
  f.set("wheel_state.pos.z", kR0 - 0.145);
  f.set("wheel_state.lin_vel.z", 0);
  EXPECT_EQ(f.step(0.01), fmi2OK);
  EXPECT_TRUE(rim(f));
  EXPECT_EQ(warnings(f), 1);
  // Lifted to 50 mm: off the rim.
  f.set("wheel_state.lin_vel.z", 0.095 / 0.1);
  EXPECT_EQ(f.step(0.1), fmi2OK);
  f.set("wheel_state.pos.z", kR0 - 0.050);
  f.set("wheel_state.lin_vel.z", 0);
  EXPECT_EQ(f.step(0.01), fmi2OK);
  EXPECT_FALSE(rim(f));
  // Down again through the section height within one step: the second warning.
  f.set("wheel_state.lin_vel.z", -0.1 / 0.1);
  EXPECT_EQ(f.step(0.1), fmi2Warning);
  EXPECT_EQ(warnings(f), 2);
  EXPECT_TRUE(std::isfinite(f.get("wheel_load.force.z")));
}

}  // namespace
}  // namespace modaltyre::fmu::test
