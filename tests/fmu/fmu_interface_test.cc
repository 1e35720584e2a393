// The packaged FMU through its fmi2 functions, loaded with dlopen from the unzipped archive
// (fmu_host.h): what a host outside the project sees.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "fmu_host.h"

namespace modaltyre::fmu::test {
namespace {

TEST(FmuInterface, ArchiveHoldsTheDescriptionTheLibraryAndTheResources) {
  const std::filesystem::path f = road_2d_fmu().folder();
  EXPECT_TRUE(std::filesystem::is_regular_file(f / "modelDescription.xml"));
  EXPECT_TRUE(std::filesystem::is_regular_file(f / "binaries/linux64/ModalTyre.so"));
  EXPECT_TRUE(std::filesystem::is_regular_file(f / "resources/tyre.yaml"));
  EXPECT_TRUE(std::filesystem::is_regular_file(f / "resources/data/sf350_hammer_12pt.csv"));
  EXPECT_TRUE(std::filesystem::is_regular_file(f / "resources/fmu.yaml"));
  EXPECT_NE(road_2d_fmu().description().find("fmiVersion=\"2.0\""), std::string::npos);
  // The packed config names its data beside it, not the source tree.
  std::ifstream in(f / "resources/tyre.yaml");
  const std::string yaml((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(yaml.find("hammer_csv: data/sf350_hammer_12pt.csv"), std::string::npos);
}

TEST(FmuInterface, LibraryExportsEveryCoSimulationFunction) {
  for (std::size_t k = 0; k < kFmi2CoSimulationFunctionCount; ++k)
    EXPECT_NE(dlsym(road_2d_fmu().api().handle, kFmi2CoSimulationFunctions[k]), nullptr)
        << kFmi2CoSimulationFunctions[k];
  EXPECT_STREQ(road_2d_fmu().api().get_version(), "2.0");
  EXPECT_STREQ(road_2d_fmu().api().get_types_platform(), "default");
  // Nothing of the project leaks out of the library: a symbol of the transient is not visible.
  EXPECT_EQ(dlsym(road_2d_fmu().api().handle,
                  "_ZN9modaltyre9transient21build_transient_modelERKNS_"
                  "7contact9TyreModelE"),
            nullptr);
}

TEST(FmuInterface, RefusesAnotherGuidOrModelExchangeWithTheReasonLogged) {
  FmuInstance ok(road_2d_fmu());
  EXPECT_TRUE(ok.ok());
  FmuInstance other(road_2d_fmu(), "tyre", "{not-this-one}");
  EXPECT_FALSE(other.ok());
  EXPECT_TRUE(other.logged("GUID"));
  FmuInstance me(road_2d_fmu(), "tyre", "", fmi2ModelExchange);
  EXPECT_FALSE(me.ok());
  EXPECT_TRUE(me.logged("co-simulation FMU only"));
}

TEST(FmuInterface, ValuesOutsideTheirRangeAreDiscardedWithTheirReasonLogged) {
  // FMI 2.0 section 2.2.7: a parameter outside its declared [min, max] is fmi2Discard; so is an
  // input here. The value is not taken and the instance goes on.
  FmuInstance inst(road_2d_fmu());
  ASSERT_TRUE(inst.ok());
  EXPECT_EQ(inst.set("step_size", -1e-3), fmi2Discard);
  EXPECT_TRUE(inst.logged("step_size")) << (inst.messages().empty() ? "" : inst.messages().back());
  FmuInstance mu(road_2d_fmu());
  EXPECT_EQ(mu.set("terrain_mu", -0.5), fmi2Discard);
  EXPECT_TRUE(mu.logged("terrain_mu"));
  FmuInstance nan(road_2d_fmu());
  EXPECT_EQ(nan.set("wheel_state.pos.z", std::nan("")), fmi2Discard);
  EXPECT_TRUE(nan.logged("not finite"));
  EXPECT_EQ(nan.initialize(), fmi2OK);  // a discarded value leaves the instance usable
  FmuInstance road(road_2d_fmu());
  const fmi2ValueReference r = road_2d_fmu().vr("road_profile");
  const fmi2String missing = "no_such_profile.csv";
  EXPECT_EQ(road_2d_fmu().api().set_string(road.component(), &r, 1, &missing), fmi2OK);
  EXPECT_EQ(road.initialize(), fmi2Error);
  EXPECT_TRUE(road.logged("road_profile"))
      << (road.messages().empty() ? "" : road.messages().back());
  // Outputs cannot be set, and a step before initialization is refused.
  FmuInstance out(road_2d_fmu());
  EXPECT_EQ(out.set("wheel_load.force.z", 1.0), fmi2Error);
  EXPECT_TRUE(out.logged("outputs cannot be set"));
  FmuInstance early(road_2d_fmu());
  EXPECT_EQ(early.step(1e-3), fmi2Error);
  EXPECT_TRUE(early.logged("not allowed"));
}

/// A short drive: pressed 12 mm in 20 ms, then rolling forward at `speed` with a spin of 1 %
/// slip; steps k0 .. k0 + steps - 1 of 1 ms; returns F_x, F_z, M_y after each step.
std::vector<double> drive(FmuInstance& f, int k0, int steps, double speed = 5) {
  std::vector<double> out;
  const double R0 = 0.2948, depth = 0.012, press_s = 0.02;
  for (int k = k0; k < k0 + steps; ++k) {
    const double t = k * 1e-3;
    f.set("wheel_state.pos.z", R0 - depth * std::min(t / press_s, 1.0));
    f.set("wheel_state.lin_vel.z", t < press_s ? -depth / press_s : 0.0);
    f.set("wheel_state.lin_vel.x", speed);
    f.set("wheel_state.ang_vel.y", 1.01 * speed / 0.2868);
    if (f.step(1e-3) != fmi2OK) return out;
    out.push_back(f.get("wheel_load.force.x"));
    out.push_back(f.get("wheel_load.force.z"));
    out.push_back(f.get("wheel_load.moment.y"));
  }
  return out;
}

TEST(FmuInterface, TwoInstancesGiveIdenticalIndependentResults) {
  FmuInstance a(road_2d_fmu(), "a"), b(road_2d_fmu(), "b"), c(road_2d_fmu(), "c");
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  ASSERT_EQ(a.initialize(), fmi2OK);
  ASSERT_EQ(b.initialize(), fmi2OK);
  ASSERT_EQ(c.initialize(), fmi2OK);
  // a and b see the same inputs, stepped alternately with c (other inputs) in between.
  std::vector<double> ra, rb, rc;
  for (int k = 0; k < 60; ++k) {
    const auto x = drive(a, k, 1), y = drive(b, k, 1), z = drive(c, k, 1, 9.0);
    ASSERT_EQ(x.size(), 3u);
    ra.insert(ra.end(), x.begin(), x.end());
    rb.insert(rb.end(), y.begin(), y.end());
    rc.insert(rc.end(), z.begin(), z.end());
  }
  EXPECT_EQ(ra, rb);  // bit for bit
  EXPECT_NE(ra, rc);
  EXPECT_GT(ra[ra.size() - 2], 1000);  // pressed: a load
}

TEST(FmuInterface, ResetStartsOverAndRepeatsTheRun) {
  FmuInstance f(road_2d_fmu());
  ASSERT_EQ(f.initialize(), fmi2OK);
  const std::vector<double> first = drive(f, 0, 40);
  ASSERT_EQ(first.size(), 120u);
  ASSERT_EQ(f.reset(), fmi2OK);
  ASSERT_EQ(f.initialize(), fmi2OK);
  EXPECT_DOUBLE_EQ(f.get("wheel_load.force.z"), 0);  // start values: touching, no load
  EXPECT_EQ(drive(f, 0, 40), first);
  ASSERT_EQ(road_2d_fmu().api().terminate(f.component()), fmi2OK);
  EXPECT_EQ(f.step(1e-3), fmi2Error);  // no step after fmi2Terminate
}

}  // namespace
}  // namespace modaltyre::fmu::test
