// Tread states only for the units that can touch (tread_window.h): the range holds every unit
// that touches, the state is smaller, the trajectory is that of all units within the
// integration's own tolerance, and a unit outside the range reaching the road is caught.
#include "modaltyre/transient/tread_window.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "decay_metrics.h"
#include "modaltyre/transient/transient.h"
#include "transient_models.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using test::default_model;

// The range changes which states enter CVODE's RMS norms, not the error test (the driver scales
// the tolerances by sqrt(all / kept states)), but the step sequence of a run with contact kinks
// follows rounding (docs/transient.md section 2: 371-873 rolling steps across initial step
// sizes), so the two runs agree to the integration error, not to rounding. Measured on the
// default mesh: period 0.06 %, decrement 0.07 %, rolling resistance 0.01 %, cleat peak 0.07 %
// apart. Half of issue 21's limits (as for the tread tolerance, reference_test.cc):
constexpr double kWindowPeriodTol = 0.005;
constexpr double kWindowDecrementTol = 0.005;
constexpr double kWindowRollingTol = 0.005;
constexpr double kWindowCleatPeakTol = 0.015;

/// Runs a scenario on the touchable units and on all units.
std::pair<TransientResult, TransientResult> both(const TransientModel& M, Scenario s) {
  TransientRunOptions all;
  all.all_tread_states = true;
  return {run_transient(M, s), run_transient(M, s, all)};
}

void expect_fewer_states(const TransientModel& M, const TransientResult& a,
                         const TransientResult& b) {
  ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
  EXPECT_FALSE(a.units_escaped);
  EXPECT_EQ(b.states, M.state_size());
  EXPECT_EQ(a.states, M.e_index() + (a.units_hi - a.units_lo + 1));
  EXPECT_LT(a.units_hi - a.units_lo + 1, M.m / 2);  // the point: most units never touch
}

TEST(TreadWindow, TheRangeHoldsTheStaticPatchOfTheBoundingLoad) {
  const TransientModel M = default_model();
  for (Scenario s : {Scenario::load_hold, Scenario::free_vibration, Scenario::rolling}) {
    const ScenarioPlan plan = plan_scenario(M, s);
    const StaticContact initial = static_contact(M, plan.initial_load_N);
    const std::optional<StaticContact> bounded = bounding_contact(M, plan, initial);
    ASSERT_TRUE(bounded.has_value());
    const StaticContact& bound = *bounded;
    const UnitRange r = touchable_units(M, plan, bound);
    for (int i = 0; i < M.m; ++i) {
      if (initial.f(i) > 0 || bound.f(i) > 0) {
        EXPECT_TRUE(r.contains(i)) << to_string(s) << " unit " << i;
      }
    }
    // Free vibration is released downwards in load (5000 -> 4000 N): its bound is the start.
    if (s == Scenario::free_vibration) {
      EXPECT_EQ(bound.sinking_m, initial.sinking_m);
    } else if (s == Scenario::load_hold) {
      EXPECT_GT(bound.sinking_m, 0.0);
    }
  }
}

TEST(TreadWindow, FreeVibrationOnTheTouchableUnitsIsThatOfAllUnits) {
  const TransientModel M = default_model();
  const auto [a, b] = both(M, Scenario::free_vibration);
  expect_fewer_states(M, a, b);
  const auto [period_a, decrement_a] = period_and_decrement(a);
  const auto [period_b, decrement_b] = period_and_decrement(b);
  EXPECT_NEAR(period_a / period_b, 1.0, kWindowPeriodTol);
  EXPECT_NEAR(decrement_a / decrement_b, 1.0, kWindowDecrementTol);
  // At the end both have settled on the 4000 N footprint.
  EXPECT_NEAR(a.samples.back().load_N / b.samples.back().load_N, 1.0, 0.01);
}

TEST(TreadWindow, RollingAndCleatOnTheTouchableUnitsAreThoseOfAllUnits) {
  const TransientModel M = default_model();
  {
    const auto [a, b] = both(M, Scenario::rolling);
    expect_fewer_states(M, a, b);
    EXPECT_NEAR(a.rolling_resistance_N / b.rolling_resistance_N, 1.0, kWindowRollingTol);
    EXPECT_NEAR(a.samples.back().contact_length_m / b.samples.back().contact_length_m, 1.0,
                kWindowRollingTol);
  }
  {
    const auto [a, b] = both(M, Scenario::cleat);
    ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
    EXPECT_FALSE(a.units_escaped);
    EXPECT_LT(a.states, b.states);
    auto peak = [](const TransientResult& r) {
      double p = 0;
      for (const auto& s : r.samples) p = std::max(p, s.load_N);
      return p;
    };
    EXPECT_NEAR(peak(a) / peak(b), 1.0, kWindowCleatPeakTol);
  }
}

// A range that misses part of the patch: the system reports it (the driver would then repeat
// the run with all units), from the initial state and from the right-hand side alike.
TEST(TreadWindow, AUnitOutsideTheRangeTouchingTheRoadIsCaught) {
  const TransientModel M = default_model();
  const ScenarioPlan plan = plan_scenario(M, Scenario::free_vibration);
  const StaticContact initial = static_contact(M, plan.initial_load_N);
  int first = -1, last = -1;
  for (int i = 0; i < M.m; ++i)
    if (initial.f(i) > 0) last = i, first = first < 0 ? i : first;
  ASSERT_GT(last - first, 20);
  {
    const TransientSystem sys(M, plan, UnitRange{first + 5, last});
    sys.state_from(initial);
    EXPECT_TRUE(sys.escaped());
  }
  {
    // The state built on a range holding the patch, then evaluated by a system whose range
    // misses its front units: the right-hand side sees them touch.
    const TransientSystem holds(M, plan, UnitRange{first, last});
    const std::vector<double> y = holds.state_from(initial);
    EXPECT_FALSE(holds.escaped());
    std::vector<double> yd(y.size());
    holds.rhs(0.0, y.data(), yd.data());
    EXPECT_FALSE(holds.escaped());
    const TransientSystem misses(M, plan, UnitRange{first, last - 5});
    std::vector<double> y2(y.begin(), y.begin() + misses.size());
    std::vector<double> yd2(y2.size());
    misses.rhs(0.0, y2.data(), yd2.data());
    EXPECT_TRUE(misses.escaped());
  }
}

}  // namespace
}  // namespace modaltyre::transient
