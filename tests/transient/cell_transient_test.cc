// The transient on the 3D patch (cell_model.h, docs/transient.md section 7): the load-hold ends
// at the 3D static footprint, a flat crown equals the 2D transient of the whole tread width in
// every scenario, and the column classes equal the full per-cell model. Coarse meshes (2 mm
// sections, 7.5 mm columns) keep each run to a fraction of a second.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "../support/data_paths.h"
#include "modaltyre/contact/patch3d.h"
#include "modaltyre/transient/transient.h"
#include "scenario_print.h"
#include "transient_models.h"

namespace modaltyre::transient {

namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig3d;
using test::build;
using test::Built;
using test::coarse_3d;
using test::rel;

// Issue 33: the load-hold's end equals the 3D static footprint within 0.5 % (sinking, length,
// width). Measured at the default 0.5 mm / 2.5 mm mesh after a 2 s hold: +0.001 % / +0.004 % /
// -0.010 %; the remainder is the truncated residual (docs/transient.md section 1) and the
// bounce's last micrometres.
constexpr double kCellStaticTol = 0.005;
// Issue 33: a flat crown's 3D transient equals the 2D transient of the tread width within 0.5 %
// (the same equations with the cells of a section merged into one class: the difference is
// the integration's, the two error tests running over differently sized state vectors).
constexpr double kFlatCrownTol = 0.005;
// The column classes (mirror pairs) against one class per column: the same trajectories up to
// the integration tolerance (the RMS error test counts the states differently).
constexpr double kClassTol = 1e-3;

double peak_load(const TransientResult& r) {
  double p = 0;
  for (const auto& s : r.samples) p = std::max(p, s.load_N);
  return p;
}

TEST(CellTransient, LoadHoldEndsAtThe3dStaticFootprint) {
  const Built b = build(load_tyre_config(kConfig3d, coarse_3d({"transient.load_hold.hold_s=1"})));
  const TransientResult r = run_transient_3d(b.model, Scenario::load_hold);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_TRUE(r.patch_3d);
  const Patch3d patch(b.tyre, *b.tyre.config.footprint_3d);
  const Patch3dResult s = patch.solve(b.model.settings.load_hold.load_N);
  ASSERT_TRUE(s.ok()) << s.message;
  const TransientSample& fin = r.samples.back();
  EXPECT_LT(rel(fin.sinking_m, s.sinking_m), kCellStaticTol) << fin.sinking_m << " " << s.sinking_m;
  EXPECT_LT(rel(fin.contact_length_m, s.length_m), kCellStaticTol)
      << fin.contact_length_m << " " << s.length_m;
  EXPECT_LT(rel(fin.width_m, s.width_m), kCellStaticTol) << fin.width_m << " " << s.width_m;
  EXPECT_LT(rel(fin.load_N, s.load_N), kCellStaticTol);
  // The crown lets the cells enter at different times across the width: the width grows with
  // the load during the ramp.
  const TransientSample* early = nullptr;
  for (const auto& x : r.samples)
    if (!early && x.load_N > 0.25 * s.load_N) early = &x;
  ASSERT_NE(early, nullptr);
  EXPECT_LT(early->width_m, 0.95 * s.width_m);
  EXPECT_LT(early->width_m, 0.999 * b.tyre.config.footprint_3d->tread_width_m);
}

class FlatCrown : public ::testing::TestWithParam<Scenario> {};

TEST_P(FlatCrown, Equals2dTransientOfTheTreadWidth) {
  TyreConfig cfg = load_tyre_config(
      // (One stated output grid for both patches: the chosen one follows each patch's initial
      // contact, output_grid.h.)
      kConfig3d,
      coarse_3d({"transient.output_step_ms=2", "transient.load_hold.hold_s=0.3",
                 "transient.free_vibration.duration_s=0.4", "transient.rolling.duration_s=1.2",
                 "transient.rolling.ramp_s=0.6", "transient.cleat.ramp_s=0.2"}));
  // 1 mm sections: the two patches interpolate the patch edge with different level functions
  // (the 2D footprint's f C_ii, the 3D patch's tread compression f t_i; the same at the edge to
  // O(unit)): at 2 mm they differ by 0.9 % in the held length, at 1 mm by less than half.
  cfg.mesh.unit_length_m = 1e-3;
  cfg.footprint_3d->crown.shape = CrownShape::flat;
  // The 2D patch's width is the tread's (tread.contact_width_mm = tread_width_mm = 150 mm).
  ASSERT_DOUBLE_EQ(cfg.tread.width_m, cfg.footprint_3d->tread_width_m);
  const Built b = build(cfg);
  const Scenario sc = GetParam();
  const TransientResult r3 = run_transient_3d(b.model, sc);
  const TransientResult r2 = run_transient(b.model, sc);
  ASSERT_TRUE(r3.ok()) << r3.message;
  ASSERT_TRUE(r2.ok()) << r2.message;
  const TransientSample &a = r3.samples.back(), &c = r2.samples.back();
  EXPECT_LT(rel(a.sinking_m, c.sinking_m), kFlatCrownTol);
  EXPECT_LT(rel(a.load_N, c.load_N), kFlatCrownTol);
  // The lengths to the edge interpolations' O(unit) difference (above): half a unit, 0.5 mm
  // (0.46 % of the held 109 mm; the cleat run ends mid-bounce at 78 mm, where the same 0.46 mm
  // is 0.59 %, over kFlatCrownTol on this machine's build of main at 85c03c5 too).
  EXPECT_LT(std::abs(a.contact_length_m - c.contact_length_m), 0.5 * cfg.mesh.unit_length_m)
      << a.contact_length_m << " " << c.contact_length_m;
  EXPECT_DOUBLE_EQ(a.width_m, cfg.footprint_3d->tread_width_m);
  // Along the run: the sinking at every sample within the tolerance of the largest.
  ASSERT_EQ(r3.samples.size(), r2.samples.size());
  double worst = 0, scale = 0;
  for (std::size_t k = 0; k < r2.samples.size(); ++k) {
    worst = std::max(worst, std::abs(r3.samples[k].sinking_m - r2.samples[k].sinking_m));
    scale = std::max(scale, std::abs(r2.samples[k].sinking_m));
  }
  EXPECT_LT(worst, kFlatCrownTol * scale);
  if (sc == Scenario::free_vibration) {
    const BounceDecay d3 = bounce_decay(r3, 6), d2 = bounce_decay(r2, 6);
    ASSERT_GE(d2.peaks, 4);
    EXPECT_LT(rel(d3.period_s, d2.period_s), kFlatCrownTol);
    EXPECT_LT(rel(d3.log_decrement, d2.log_decrement), kFlatCrownTol);
  }
  if (sc == Scenario::rolling) {
    EXPECT_GT(r2.rolling_resistance_N, 0);
    EXPECT_LT(rel(r3.rolling_resistance_N, r2.rolling_resistance_N), kFlatCrownTol);
  }
  if (sc == Scenario::cleat) {
    EXPECT_LT(rel(peak_load(r3), peak_load(r2)), kFlatCrownTol);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryScenario, FlatCrown,
                         ::testing::Values(Scenario::load_hold, Scenario::free_vibration,
                                           Scenario::rolling, Scenario::cleat),
                         [](const ::testing::TestParamInfo<Scenario>& info) {
                           std::string name = to_string(info.param);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// The column classes are an exact reduction: the mirror columns of the crown have the same
// equations and initial state. One class per column gives the same run.
TEST(CellTransient, ColumnClassesEqualThePerCellModel) {
  const Built b = build(load_tyre_config(
      kConfig3d, coarse_3d({"transient.rolling.duration_s=0.4", "transient.rolling.ramp_s=0.2"})));
  TransientRunOptions all;
  all.per_column_cells = true;
  const TransientResult merged = run_transient_3d(b.model, Scenario::rolling);
  const TransientResult cells = run_transient_3d(b.model, Scenario::rolling, all);
  ASSERT_TRUE(merged.ok() && cells.ok());
  EXPECT_GT(cells.states, merged.states);  // twice the tread states, less the centre pair's
  const TransientSample &a = merged.samples.back(), &c = cells.samples.back();
  EXPECT_LT(rel(a.sinking_m, c.sinking_m), kClassTol);
  EXPECT_LT(rel(a.contact_length_m, c.contact_length_m), kClassTol);
  EXPECT_LT(rel(a.width_m, c.width_m), kClassTol);
  EXPECT_LT(rel(merged.rolling_resistance_N, cells.rolling_resistance_N), kClassTol);
}

// A cleat narrower than the tread loads only the sections' middle columns: a smaller peak than
// the full-width cleat's, and more than the flat road's load.
TEST(CellTransient, NarrowCleatLoadsLessThanAFullWidthOne) {
  const auto base = coarse_3d({"transient.cleat.ramp_s=0.2"});
  auto narrow = base;
  narrow.push_back("transient.cleat.width_mm=45");
  const Built full = build(load_tyre_config(kConfig3d, base));
  const Built part = build(load_tyre_config(kConfig3d, narrow));
  const TransientResult rf = run_transient_3d(full.model, Scenario::cleat);
  const TransientResult rp = run_transient_3d(part.model, Scenario::cleat);
  ASSERT_TRUE(rf.ok() && rp.ok()) << rf.message << rp.message;
  const double F = full.model.settings.cleat.load_N;
  EXPECT_GT(peak_load(rp), 1.05 * F);
  EXPECT_LT(peak_load(rp), peak_load(rf));
  // The 2D patch refuses a narrow cleat (its road is uniform across).
  EXPECT_THROW(run_transient(part.model, Scenario::cleat), InputError);
}

}  // namespace
}  // namespace modaltyre::transient
