// Issue 44: `init` writes a transient: section, so that a config it wrote runs the time-domain
// scenarios at the tyre's nominal load on a grid that resolves its hub bounce (the default
// 10 ms grid read five samples per period).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/init/init_tyre.h"
#include "modaltyre/transient/transient.h"

namespace modaltyre::init {
namespace {

const std::string kInitTransientSrc = MODALTYRE_SOURCE_DIR;

TEST(InitTransient, ScenariosAtFnominOnAGridThatResolvesTheBounce) {
  InitInputs in;
  in.size = "195/60R14";
  in.test_pressure_kPa = 230;
  in.frequencies_hz = {112.839, 113.661, 125.580, 133.580, 135.528, 155.739, 156.657, 180.092,
                       182.454, 207.977, 210.787, 238.917, 241.519, 274.594, 312.030};
  in.orders = {1, 1, 0, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 8};
  in.two_d = true;
  in.fnomin_N = 3500;
  const InitResult r = init_tyre(in);
  ASSERT_NE(r.yaml.find("\ntransient:\n"), std::string::npos);
  const ConfigTree tree = ConfigTree::from_string(r.yaml, kInitTransientSrc + "/configs/init.yaml",
                                                  {"transient.free_vibration.duration_s=0.5"});
  const contact::TyreConfig cfg = contact::read_tyre_config(tree);
  EXPECT_EQ(cfg.transient.output_step_s, 0);  // auto
  EXPECT_DOUBLE_EQ(cfg.transient.free_vibration.load_N, 3500);
  EXPECT_DOUBLE_EQ(cfg.transient.rolling.load_N, 3500);
  EXPECT_DOUBLE_EQ(cfg.transient.cleat.load_N, 3500);
  const auto model = transient::build_transient_model(contact::build_tyre_model(cfg));
  const transient::TransientResult fv =
      transient::run_transient(model, transient::Scenario::free_vibration);
  ASSERT_TRUE(fv.ok()) << fv.message;
  const transient::BounceDecay d = transient::bounce_decay(fv);
  ASSERT_GE(d.peaks, 4);
  EXPECT_GE(d.period_s / fv.output_grid.step_s, 20.0);
}

}  // namespace
}  // namespace modaltyre::init
