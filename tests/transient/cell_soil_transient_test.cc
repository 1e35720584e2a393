// The 3D transient on a deformable soil (transient/cell_soil.h, docs/soil.md section 8.3): the
// load-hold's end against the 3D static footprint on the same soil, a very stiff soil against the
// 3D road transient, a flat crown against the 2D soil transient of the tread width, and rolling
// onto the soil (compaction resistance, rut). Coarse meshes keep each run to about a second.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "../support/lete_sand.h"
#include "decay_metrics.h"
#include "modaltyre/contact/patch3d.h"
#include "modaltyre/transient/cell_soil.h"
#include "modaltyre/transient/transient.h"
#include "scenario_print.h"
#include "transient_models.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig3d;
using modaltyre_test::kLeteBekker;
using modaltyre_test::plus;
using test::build;
using test::Built;
using test::rel;

// Issue 33/37: the load-hold's end equals the 3D static footprint on the same soil (soil
// sinkage, sinking, length, width) within 0.5 %.
constexpr double kCellSoilStaticTol = 0.005;
// A very stiff soil (n = 1, k_phi = 1e9 kN/m^3) against the 3D road transient: the soil's share
// of the sinking is ~1e-3 of the tread's (soil_transient_test.cc); the 0.5 %.
constexpr double kCellStiffSoilTol = 0.005;
// The soil's share of the sinking on that stiff soil: below 1e-3 of it.
constexpr double kStiffSoilShare = 1e-3;
// A flat crown's 3D transient equals the 2D transient of the tread width (issue 33's bound): the
// same equations with the cells of a section merged into one class, on the same soil (the same
// b, areas in proportion).
constexpr double kCellSoilFlatCrownTol = 0.005;
// Rolling on a soil at three integrator tolerances (1e-5 to 1e-7): the same resistances within
// 0.3 % (the sweep of soil_contact.h; 6 % apart without it).
constexpr double kStepSequenceTol = 0.003;

const std::vector<std::string> kWongUnloading = {"ground.bekker.unloading.k0=0",
                                                 "ground.bekker.unloading.Au=5e5"};

std::vector<std::string> cell_soil_coarse(std::vector<std::string> extra = {}) {
  return plus({"contact.unit_length_mm=2", "footprint_3d.lateral_cell_mm=7.5",
               "transient.output_step_ms=5"},
              extra);
}

/// Mean of a sample field over the last `span_s` of a run (the hold's bounce averaged out).
template <class F>
double tail_mean(const TransientResult& r, double span_s, F field) {
  const double t1 = r.samples.back().t_s;
  double sum = 0;
  int n = 0;
  for (const auto& s : r.samples)
    if (s.t_s >= t1 - span_s) sum += field(s), ++n;
  return sum / n;
}

TEST(CellSoilTransient, LoadHoldEndsAtThe3dStaticFootprintOnTheSameSoil) {
  // Rigid-plastic LETE sand and the same with Wong's unloading; a slow ramp (1 kN/s, relaxation
  // off) keeps the bounce's overshoot, which a rigid-plastic soil keeps, small (docs/soil.md 8).
  for (const bool unloading : {false, true}) {
    SCOPED_TRACE(unloading ? "Wong's unloading" : "rigid-plastic");
    auto o = plus(cell_soil_coarse({"transient.relaxation=false", "transient.load_hold.load_N=4000",
                                    "transient.load_hold.ramp_rate_N_s=1000",
                                    "transient.load_hold.hold_s=1.0"}),
                  kLeteBekker);
    if (unloading) o = plus(o, kWongUnloading);
    const Built b = build(load_tyre_config(kConfig3d, o));
    const TransientResult r = run_scenario(b.model, Scenario::load_hold);
    ASSERT_TRUE(r.ok()) << r.message;
    ASSERT_TRUE(r.patch_3d && r.on_soil);
    // The 3D static footprint on the same soil at its own Bekker width (footprint's iteration).
    const CellModel cm = build_cell_model(b.model);
    double bw = 0;
    static_soil_cells(cm, 4000, 0.0, &bw);
    const auto law = b.tyre.config.ground.normal_law(bw);
    Patch3dPhysics physics;
    physics.soil = law.get();
    const Patch3dResult s = Patch3d(b.tyre, cm.patch, physics).solve(4000);
    ASSERT_TRUE(s.ok()) << s.message;
    auto mean = [&](auto field) { return tail_mean(r, 0.2, field); };
    const double sink = mean([](const TransientSample& x) { return x.soil_sinkage_m; });
    const double sinking = mean([](const TransientSample& x) { return x.sinking_m; });
    const double length = mean([](const TransientSample& x) { return x.contact_length_m; });
    const double width = mean([](const TransientSample& x) { return x.width_m; });
    EXPECT_LT(rel(sink, s.soil_sinkage_m), kCellSoilStaticTol) << sink << " " << s.soil_sinkage_m;
    EXPECT_LT(rel(sinking, s.sinking_m), kCellSoilStaticTol) << sinking << " " << s.sinking_m;
    EXPECT_LT(rel(length, s.length_m), kCellSoilStaticTol) << length << " " << s.length_m;
    EXPECT_LT(rel(width, s.width_m), kCellSoilStaticTol) << width << " " << s.width_m;
    RecordProperty(unloading ? "unloading" : "rigid_plastic",
                   std::to_string(sink / s.soil_sinkage_m - 1) + " " +
                       std::to_string(sinking / s.sinking_m - 1) + " " +
                       std::to_string(length / s.length_m - 1) + " " +
                       std::to_string(width / s.width_m - 1));
    // The soil sinks and the tyre deflects (both well above the tolerance of each other).
    EXPECT_GT(sink, 0.2 * sinking);
    EXPECT_LT(sink, 0.8 * sinking);
  }
}

TEST(CellSoilTransient, AVeryStiffSoilReproducesThe3dRoadTransient) {
  // Stiff and elastic (Wong's unloading line as steep as the loading one, k_0 = k_phi), so that
  // the soil keeps nothing of the fast ramp's bounce. The sinking is compared sample by sample;
  // the load sample by sample differs by up to 0.53 % (measured: 22 N at t = 0.34 s and 0.45 s,
  // 2 ms wide): on the road a section's cells entering contact at the bounce's rise give the
  // summed force a 25 N ripple that the soil's series compliance (1e-3 of the tread's) smooths,
  // the sinking then agreeing to 6 um of 15 mm. The load is compared over the hold's mean and
  // at the end. The hold ends in the bounce (+-130 N at 0.5 s), where the integrator's phase
  // error moves a sample by 0.4 % at the default tolerance 1e-5 (measured on the road run: 4100
  // against 4115 N at 1e-7): both runs at 1e-7 compare the models, not two step sequences.
  const auto o = cell_soil_coarse(
      {"transient.load_hold.load_N=4000", "transient.load_hold.ramp_rate_N_s=20000",
       "transient.load_hold.hold_s=0.3", "transient.relative_tolerance=1e-7"});
  const Built road = build(load_tyre_config(kConfig3d, o));
  const Built stiff = build(load_tyre_config(
      kConfig3d, plus(o, {"ground.model=bekker", "ground.bekker.n=1", "ground.bekker.k_c=0",
                          "ground.bekker.k_phi=1e9", "ground.bekker.unloading.k0=1e9",
                          "ground.bekker.unloading.Au=0"})));
  const TransientResult a = run_scenario(road.model, Scenario::load_hold);
  const TransientResult s = run_scenario(stiff.model, Scenario::load_hold);
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_TRUE(s.ok()) << s.message;
  ASSERT_EQ(a.samples.size(), s.samples.size());
  double sinking_scale = 0, worst_sinking = 0, worst_share = 0;
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    const TransientSample &x = a.samples[k], &y = s.samples[k];
    sinking_scale = std::max(sinking_scale, x.sinking_m);
    worst_sinking = std::max(worst_sinking, std::abs(y.sinking_m - x.sinking_m));
    worst_share = std::max(worst_share, y.soil_sinkage_m);
  }
  EXPECT_LT(worst_sinking, kCellStiffSoilTol * sinking_scale);
  auto load = [](const TransientSample& x) { return x.load_N; };
  EXPECT_LT(rel(tail_mean(s, 0.1, load), tail_mean(a, 0.1, load)), kCellStiffSoilTol);
  EXPECT_LT(worst_share, kStiffSoilShare * sinking_scale);
  const TransientSample &x = a.samples.back(), &y = s.samples.back();
  EXPECT_LT(rel(y.load_N, x.load_N), kCellStiffSoilTol);
  EXPECT_LT(rel(y.contact_length_m, x.contact_length_m), kCellStiffSoilTol);
  EXPECT_LT(rel(y.width_m, x.width_m), kCellStiffSoilTol);
}

class FlatCrownOnSoil : public ::testing::TestWithParam<Scenario> {};

TEST_P(FlatCrownOnSoil, Equals2dSoilTransientOfTheTreadWidth) {
  TyreConfig cfg = load_tyre_config(
      kConfig3d,
      plus(cell_soil_coarse({"transient.load_hold.hold_s=0.3",
                             "transient.free_vibration.duration_s=0.4",
                             "transient.rolling.duration_s=1.0", "transient.rolling.ramp_s=0.5",
                             "transient.rolling.load_N=3000"}),
           plus(kLeteBekker, kWongUnloading)));
  // 1 mm sections, as the road's flat-crown test (cell_transient_test.cc): the two patches
  // interpolate the edge with different level functions, the same to O(unit).
  cfg.mesh.unit_length_m = 1e-3;
  cfg.footprint_3d->crown.shape = CrownShape::flat;
  ASSERT_DOUBLE_EQ(cfg.tread.width_m, cfg.footprint_3d->tread_width_m);
  const Built b = build(cfg);
  const Scenario sc = GetParam();
  const TransientResult r3 = run_transient_3d(b.model, sc);
  const TransientResult r2 = run_transient(b.model, sc);
  ASSERT_TRUE(r3.ok()) << r3.message;
  ASSERT_TRUE(r2.ok()) << r2.message;
  // Rolling, the contact forces ripple by +-20 N from sample to sample in both runs (units and
  // cells crossing the patch's ends over the soil's moved memory, 1 mm apart), the ripples of
  // the two drifting apart after 0.3 s: the rolling quantities are compared as means over the
  // last 0.4 s (the steady part after the 0.5 s ramp), the held ones as the last 0.2 s.
  const double span = sc == Scenario::rolling ? 0.4 : 0.2;
  auto both = [&](auto field, const char* name) {
    const double x3 = tail_mean(r3, span, field), x2 = tail_mean(r2, span, field);
    EXPECT_LT(rel(x3, x2), kCellSoilFlatCrownTol) << name << ": 3D " << x3 << ", 2D " << x2;
    RecordProperty(name, std::to_string(x3 / x2 - 1));
  };
  both([](const TransientSample& x) { return x.sinking_m; }, "sinking");
  both([](const TransientSample& x) { return x.soil_sinkage_m; }, "soil_sinkage");
  both([](const TransientSample& x) { return x.load_N; }, "load");
  both([](const TransientSample& x) { return x.contact_length_m; }, "length");
  const TransientSample& a = r3.samples.back();
  EXPECT_DOUBLE_EQ(a.width_m, cfg.footprint_3d->tread_width_m);
  ASSERT_EQ(r3.samples.size(), r2.samples.size());
  // Along the run (at rest: rolling's ripples, above, are as large as the bound and the 3D run
  // carries tread states on fewer sections than the 2D one, which repeats with every unit).
  double worst = 0, scale = 0;
  for (std::size_t k = 0; k < r2.samples.size(); ++k) {
    worst = std::max(worst, std::abs(r3.samples[k].sinking_m - r2.samples[k].sinking_m));
    scale = std::max(scale, std::abs(r2.samples[k].sinking_m));
  }
  if (sc != Scenario::rolling) {
    EXPECT_LT(worst, kCellSoilFlatCrownTol * scale);
  }
  RecordProperty("worst_sinking_sample", std::to_string(worst / scale));
  if (sc == Scenario::free_vibration) {
    const BounceDecay d3 = bounce_decay(r3, 6), d2 = bounce_decay(r2, 6);
    ASSERT_GE(d2.peaks, 4);
    EXPECT_LT(rel(d3.period_s, d2.period_s), kCellSoilFlatCrownTol);
    EXPECT_LT(rel(d3.log_decrement, d2.log_decrement), kCellSoilFlatCrownTol);
    RecordProperty("period", std::to_string(d3.period_s / d2.period_s - 1));
    RecordProperty("log_decrement", std::to_string(d3.log_decrement / d2.log_decrement - 1));
  }
  if (sc == Scenario::rolling) {
    ASSERT_GT(r2.samples.back().soil_resistance_N, 0);
    both([](const TransientSample& x) { return x.soil_resistance_N; }, "compaction_resistance");
    // The rolling resistance as the other rolling quantities: the mean over the last 0.4 s
    // (the driver's rolling_resistance_N averages the run's last tenth, 0.1 s here, over which
    // the two runs' ripples have drifted apart by up to 0.6 %).
    both([](const TransientSample& x) { return -x.longitudinal_force_N; }, "rolling_resistance");
  }
}

INSTANTIATE_TEST_SUITE_P(EverySoilScenario, FlatCrownOnSoil,
                         ::testing::Values(Scenario::load_hold, Scenario::free_vibration,
                                           Scenario::rolling),
                         [](const ::testing::TestParamInfo<Scenario>& info) {
                           std::string name = to_string(info.param);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(CellSoilTransient, RollingCompactsTheSoilAndLeavesARutNoDeeperThanTheSinkage) {
  // The crowned default tyre rolling onto LETE sand with Wong's unloading (the soil rebounds):
  // the normal forces lean back on the rut's slope (R_c > 0), and the rut is the surface's
  // rebound from the deepest sinkage, so shallower than it.
  const Built b = build(load_tyre_config(
      kConfig3d,
      plus(cell_soil_coarse({"transient.rolling.load_N=3000", "transient.rolling.speed_km_h=5",
                             "transient.rolling.ramp_s=0.5", "transient.rolling.duration_s=1.0"}),
           plus(kLeteBekker, kWongUnloading))));
  const TransientResult r = run_scenario(b.model, Scenario::rolling);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_TRUE(r.on_soil);
  const TransientSample& fin = r.samples.back();
  EXPECT_GT(fin.soil_resistance_N, 0);
  EXPECT_GT(r.rolling_resistance_N, 0);
  double deepest = 0;
  for (const auto& s : r.samples) deepest = std::max(deepest, s.soil_sinkage_m);
  EXPECT_GT(r.rut_depth_m, 0);
  EXPECT_LT(r.rut_depth_m, deepest);
  // The load is carried (the hub settles on the soil).
  EXPECT_LT(rel(fin.load_N, 3000), 0.02);
}

TEST(CellSoilTransient, TheCleatOnASoilIsRefusedNamingTheKey) {
  const Built b = build(load_tyre_config(kConfig3d, plus(cell_soil_coarse(), kLeteBekker)));
  try {
    run_scenario(b.model, Scenario::cleat);
    FAIL() << "the cleat on a soil ran";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ground.model"), std::string::npos) << e.what();
  }
}

TEST(CellSoilTransient, RollingResistanceOnSoilDoesNotDependOnTheStepSequence) {
  // At 60 km/h a step carries a ground point past tens of units; the soil's memory of the
  // deepest sinkage a point reached must not depend on where the steps end (soil_contact.h,
  // the sweep). Measured without the sweep: compaction resistance 13.81-13.98 N (2D) and
  // 13.74-14.11 N (3D, 2.7 %) over these tolerances; on the flat crown 13.5-14.4 N.
  const std::vector<std::vector<std::string>> tolerances = {
      {"transient.relative_tolerance=1e-5", "transient.tread_tolerance_um=1"},
      {"transient.relative_tolerance=1e-6", "transient.tread_tolerance_um=1"},
      {"transient.relative_tolerance=1e-7", "transient.tread_tolerance_um=0.1"}};
  // Per patch (2D, 3D): the smallest and largest compaction and rolling resistances.
  double lo_c[2] = {1e300, 1e300}, hi_c[2] = {0, 0}, lo_r[2] = {1e300, 1e300}, hi_r[2] = {0, 0};
  for (const auto& tol : tolerances) {
    const Built b = build(load_tyre_config(
        kConfig3d,
        plus(cell_soil_coarse({"transient.rolling.duration_s=1.0", "transient.rolling.ramp_s=0.5",
                               "transient.rolling.load_N=3000"}),
             plus(plus(kLeteBekker, kWongUnloading), tol))));
    for (const int cells : {0, 1}) {
      SCOPED_TRACE(cells ? "3D patch" : "2D patch");
      const TransientResult r = cells ? run_transient_3d(b.model, Scenario::rolling)
                                      : run_transient(b.model, Scenario::rolling);
      ASSERT_TRUE(r.ok()) << r.message;
      const double c =
          tail_mean(r, 0.4, [](const TransientSample& x) { return x.soil_resistance_N; });
      const double rr =
          tail_mean(r, 0.4, [](const TransientSample& x) { return -x.longitudinal_force_N; });
      ASSERT_GT(c, 0);
      lo_c[cells] = std::min(lo_c[cells], c), hi_c[cells] = std::max(hi_c[cells], c);
      lo_r[cells] = std::min(lo_r[cells], rr), hi_r[cells] = std::max(hi_r[cells], rr);
    }
  }
  for (const int cells : {0, 1}) {
    SCOPED_TRACE(cells ? "3D patch" : "2D patch");
    EXPECT_LT(hi_c[cells] / lo_c[cells] - 1, kStepSequenceTol)
        << lo_c[cells] << " - " << hi_c[cells] << " N";
    EXPECT_LT(hi_r[cells] / lo_r[cells] - 1, kStepSequenceTol)
        << lo_r[cells] << " - " << hi_r[cells] << " N";
  }
}

}  // namespace
}  // namespace modaltyre::transient
