// Issue 44, item 1: the free vibration's period and decrement and the force extremes come from
// the integrator's own steps (step_extremes.h, decay.h), not from the output grid, and the
// automatic output grid resolves what the scenario reports (output_grid.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "modaltyre/transient/transient.h"
#include "transient_models.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using test::model_with;

/// The extremes of a sampled signal over the output grid.
template <class F>
std::pair<double, double> sampled_range(const TransientResult& r, F get) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& s : r.samples) lo = std::min(lo, get(s)), hi = std::max(hi, get(s));
  return {lo, hi};
}

double rel_diff(double a, double b) { return std::abs(a - b) / std::abs(b); }

// The free vibration's period and decrement do not depend on the output grid, and equal the
// sampled definition on a grid fine enough (0.1 ms, where it has converged: 0.0004 % apart),
// while a 10 ms grid (five samples per period) reads the decrement 4 % high.
TEST(StepDecay, FreeVibrationFromTheStepsEqualsAFineGrid) {
  const std::vector<std::string> run = {"transient.free_vibration.duration_s=0.6"};
  auto with_step = [&](const char* dt) {
    auto o = run;
    o.push_back(std::string("transient.output_step_ms=") + dt);
    const TransientModel M = model_with(o);
    return run_transient(M, Scenario::free_vibration);
  };
  const TransientResult coarse = with_step("10"), fine = with_step("0.1");
  ASSERT_TRUE(coarse.ok() && fine.ok());
  const BounceDecay a = bounce_decay(coarse), b = bounce_decay(fine);
  ASSERT_TRUE(a.from_steps && b.from_steps);
  ASSERT_EQ(a.peaks, 8);
  // The same steps whatever the grid: the same figures to the last digit.
  EXPECT_EQ(a.period_s, b.period_s);
  EXPECT_EQ(a.log_decrement, b.log_decrement);
  const BounceDecay sampled_fine = sampled_bounce_decay(fine);
  const BounceDecay sampled_coarse = sampled_bounce_decay(coarse);
  // Within 0.05 % of the converged grid (the parabola through three step ends, ~40 a period).
  EXPECT_LT(rel_diff(a.period_s, sampled_fine.period_s), 5e-4);
  EXPECT_LT(rel_diff(a.log_decrement, sampled_fine.log_decrement), 5e-4);
  // The coarse grid's own reading is off by more than 1 % (what the steps mend).
  EXPECT_GT(rel_diff(sampled_coarse.log_decrement, sampled_fine.log_decrement), 0.01);
  // zeta = delta / sqrt(4 pi^2 + delta^2): a light damping's delta / 2 pi.
  EXPECT_NEAR(a.damping_ratio(), a.log_decrement / (2 * M_PI), 1e-3 * a.damping_ratio());
}

// Over the cleat the force extremes from the steps bound every output sample, do not depend on
// the grid, and equal the extremes sampled on a 0.01 ms grid within 0.5 %; the grid of 2 ms
// under-reports the longitudinal force's extremes.
TEST(StepExtremes, CleatExtremesBoundTheSamplesAndEqualAVeryFineGrid) {
  auto with_step = [&](const char* dt) {
    const TransientModel M =
        model_with({"transient.cleat.ramp_s=0.2", std::string("transient.output_step_ms=") + dt});
    return run_transient(M, Scenario::cleat);
  };
  const TransientResult coarse = with_step("2"), fine = with_step("0.01");
  ASSERT_TRUE(coarse.ok() && fine.ok());
  ASSERT_TRUE(coarse.extremes.valid);
  const auto load = [](const TransientSample& s) { return s.load_N; };
  const auto fx = [](const TransientSample& s) { return s.longitudinal_force_N; };
  for (const TransientResult* r : {&coarse, &fine}) {
    const auto [l0, l1] = sampled_range(*r, load);
    const auto [x0, x1] = sampled_range(*r, fx);
    // Every sample inside the extremes (to rounding of the interpolant's states).
    EXPECT_LE(r->extremes.load_N.min, l0 + 1e-6 * l1);
    EXPECT_GE(r->extremes.load_N.max, l1 - 1e-6 * l1);
    EXPECT_LE(r->extremes.longitudinal_force_N.min, x0 + 1e-6 * l1);
    EXPECT_GE(r->extremes.longitudinal_force_N.max, x1 - 1e-6 * l1);
  }
  EXPECT_EQ(coarse.extremes.load_N.max, fine.extremes.load_N.max);
  EXPECT_EQ(coarse.extremes.longitudinal_force_N.min, fine.extremes.longitudinal_force_N.min);
  const auto [fl0, fl1] = sampled_range(fine, load);
  const auto [fx0, fx1] = sampled_range(fine, fx);
  EXPECT_LT(rel_diff(coarse.extremes.load_N.max, fl1), 5e-3);
  EXPECT_LT(rel_diff(coarse.extremes.load_N.min, fl0), 5e-3);
  EXPECT_LT(rel_diff(coarse.extremes.longitudinal_force_N.min, fx0), 5e-3);
  EXPECT_LT(rel_diff(coarse.extremes.longitudinal_force_N.max, fx1), 5e-3);
  const auto [cx0, cx1] = sampled_range(coarse, fx);
  EXPECT_GT(rel_diff(cx0, fx0) + rel_diff(cx1, fx1), 0.01);
}

// The chosen grid: 25 samples per hub-bounce period (the estimate bounds the measured bounce's
// frequency from above), a tenth of the cleat's passage while it crosses, the run's end last,
// and times that only increase.
TEST(OutputGrid, ChosenGridResolvesTheBounceAndTheCleat) {
  const TransientModel M = model_with({"transient.output_step_ms=auto"});
  const TransientResult fv = run_transient(M, Scenario::free_vibration);
  ASSERT_TRUE(fv.ok());
  const OutputGrid& g = fv.output_grid;
  ASSERT_TRUE(g.chosen);
  const BounceDecay d = bounce_decay(fv);
  EXPECT_GE(g.bounce_hz, 1 / d.period_s);  // an upper bound of the measured frequency
  EXPECT_LE(g.step_s, d.period_s / 25);
  for (std::size_t k = 1; k < fv.samples.size(); ++k)
    ASSERT_GT(fv.samples[k].t_s, fv.samples[k - 1].t_s);
  EXPECT_EQ(fv.samples.back().t_s, fv.simulated_s);

  const TransientResult cl = run_transient(M, Scenario::cleat);
  ASSERT_TRUE(cl.ok());
  const OutputGrid& c = cl.output_grid;
  const auto& C = M.settings.cleat;
  EXPECT_NEAR(c.fine_step_s, C.length_m / C.speed_m_s / 10, 1e-15);
  ASSERT_GT(c.fine_until_s, c.fine_from_s);
  int inside = 0;
  for (const auto& s : cl.samples) inside += s.t_s >= c.fine_from_s && s.t_s < c.fine_until_s;
  EXPECT_NEAR(inside, (c.fine_until_s - c.fine_from_s) / c.fine_step_s, 2);
}

TEST(OutputGrid, NextAfterWalksTheCoarseAndTheFineStepsToTheEnd) {
  OutputGrid g;
  g.step_s = 0.01, g.fine_step_s = 0.001, g.fine_from_s = 0.025, g.fine_until_s = 0.03;
  g.end_s = 0.055;
  std::vector<double> t = {0};
  while (t.back() < g.end_s) t.push_back(g.next_after(t.back()));
  const std::vector<double> expect = {0,     0.01,  0.02, 0.025, 0.026, 0.027,
                                      0.028, 0.029, 0.03, 0.04,  0.05,  0.055};
  ASSERT_EQ(t.size(), expect.size());
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(t[k], expect[k], 1e-12) << k;
}

}  // namespace
}  // namespace modaltyre::transient
