// TransientRunOptions::summary_samples (issue 47 item 2): samples between the first and the last
// with what the printed outputs read. Each of them (every sample's hub, the forces over the
// rolling resistance's last tenth, the whole final sample, the rolling resistance, the extremes,
// the free vibration's decays) has the bits of the run with whole samples, on the 3D patch and
// the 2D patch, in every scenario; the run itself (steps, iterations) is the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/transient/transient.h"
#include "scenario_print.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

enum class Patch { cells_3d, units_2d };

struct Case {
  Patch patch;
  Scenario scenario;
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << (c.patch == Patch::cells_3d ? "3d " : "2d ") << to_string(c.scenario);
}

TransientModel model_of(Patch patch) {
  // Short scenarios on coarse meshes (2 mm sections, 7.5 mm columns on the 3D default).
  std::vector<std::string> o = {"contact.unit_length_mm=2",
                                "transient.load_hold.hold_s=0.3",
                                "transient.free_vibration.duration_s=0.4",
                                "transient.rolling.duration_s=1.2",
                                "transient.rolling.ramp_s=0.6",
                                "transient.cleat.ramp_s=0.2"};
  std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/";
  if (patch == Patch::cells_3d) {
    config += "sf350.yaml";
    o.push_back("footprint_3d.lateral_cell_mm=7.5");
  } else {
    config += "sf350_2d_table3.yaml";
  }
  return build_transient_model(build_tyre_model(load_tyre_config(config, o)));
}

class SummarySamples : public ::testing::TestWithParam<Case> {};

TEST_P(SummarySamples, GiveTheWholeRunsForcesFinalSampleAndDecayToTheBit) {
  const Case c = GetParam();
  const TransientModel M = model_of(c.patch);
  TransientRunOptions summary;
  summary.summary_samples = true;
  const TransientResult whole = run_scenario(M, c.scenario);
  const TransientResult part = run_scenario(M, c.scenario, summary);
  ASSERT_TRUE(whole.ok()) << whole.message;
  ASSERT_TRUE(part.ok()) << part.message;
  EXPECT_EQ(part.stats.steps, whole.stats.steps);
  EXPECT_EQ(part.stats.nonlin_iters, whole.stats.nonlin_iters);
  ASSERT_EQ(part.samples.size(), whole.samples.size());
  int lengths_left_out = 0, loads_left_out = 0;
  for (std::size_t k = 0; k < whole.samples.size(); ++k) {
    const TransientSample &a = part.samples[k], &b = whole.samples[k];
    EXPECT_EQ(a.t_s, b.t_s) << k;
    EXPECT_EQ(a.applied_load_N, b.applied_load_N) << k;
    EXPECT_EQ(a.hub_displacement_m, b.hub_displacement_m) << k;
    EXPECT_EQ(a.speed_m_s, b.speed_m_s) << k;
    if (a.contact_length_m != b.contact_length_m) ++lengths_left_out;
    // The forces in the rolling resistance's window (the last tenth of the run).
    if (!(b.t_s >= 0.9 * whole.simulated_s)) {
      if (a.load_N != b.load_N) ++loads_left_out;
      continue;
    }
    EXPECT_EQ(a.load_N, b.load_N) << k;
    EXPECT_EQ(a.longitudinal_force_N, b.longitudinal_force_N) << k;
    EXPECT_EQ(a.pressure_centre_m, b.pressure_centre_m) << k;
    EXPECT_EQ(a.contact_units, b.contact_units) << k;
  }
  // The option took its path: samples between the ends without their length, and before the
  // window without their load.
  EXPECT_GT(lengths_left_out, 0);
  EXPECT_GT(loads_left_out, 0);
  // The final sample whole, with the bits of the whole run's (computed there, or repeating the
  // last computed sample in a settled stretch).
  const TransientSample &a = part.samples.back(), &b = whole.samples.back();
  EXPECT_EQ(a.sinking_m, b.sinking_m);
  EXPECT_EQ(a.contact_length_m, b.contact_length_m);
  EXPECT_EQ(a.width_m, b.width_m);
  EXPECT_EQ(a.contact_area_m2, b.contact_area_m2);
  EXPECT_EQ(a.load_N, b.load_N);
  EXPECT_EQ(part.rolling_resistance_N, whole.rolling_resistance_N);
  EXPECT_EQ(part.extremes.load_N.max, whole.extremes.load_N.max);
  EXPECT_EQ(part.extremes.longitudinal_force_N.min, whole.extremes.longitudinal_force_N.min);
  if (c.scenario == Scenario::free_vibration) {
    const BounceDecay da = bounce_decay(part), db = bounce_decay(whole);
    ASSERT_GE(db.peaks, 2);
    EXPECT_EQ(da.peaks, db.peaks);
    EXPECT_EQ(da.period_s, db.period_s);
    EXPECT_EQ(da.log_decrement, db.log_decrement);
    // The decay on the output samples reads only their hub displacement.
    const BounceDecay sa = sampled_bounce_decay(part), sb = sampled_bounce_decay(whole);
    EXPECT_EQ(sa.period_s, sb.period_s);
    EXPECT_EQ(sa.log_decrement, sb.log_decrement);
  }
}

std::vector<Case> cases() {
  std::vector<Case> v;
  for (Patch p : {Patch::cells_3d, Patch::units_2d})
    for (Scenario s :
         {Scenario::load_hold, Scenario::free_vibration, Scenario::rolling, Scenario::cleat})
      v.push_back({p, s});
  return v;
}

INSTANTIATE_TEST_SUITE_P(EveryScenario, SummarySamples, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name =
                               std::string(info.param.patch == Patch::cells_3d ? "3d_" : "2d_") +
                               to_string(info.param.scenario);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace modaltyre::transient
