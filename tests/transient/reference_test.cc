// The transient scenarios at the default 0.5 mm mesh against a stored reference: the code at the
// start of issue 21's third round (commit 48d75b4), run at 0.25 mm
// (tests/data/transient/reference_0p25mm.json says how; it keeps the values before issue 21 too).
// Issue 21 lets the formulation change for speed, not the answers: free-vibration period and
// logarithmic decrement within 1 %, rolling resistance and rolling contact length at 60 km/h
// within 1 %, cleat peak load within 3 %, the load-hold creep curve within 0.5 % of the static
// sinking at every stored output, and the end of the hold equal to the static footprint.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../support/data_paths.h"
#include "decay_metrics.h"
#include "modaltyre/contact/footprint.h"
#include "modaltyre/transient/transient.h"
#include "transient_models.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig2d;
using test::default_model;
const std::string kReference =
    std::string(MODALTYRE_SOURCE_DIR) + "/tests/data/transient/reference_0p25mm.json";

// Issue 21, "accuracy must not move". The 0.5 mm mesh itself (tread tolerance 0.1 um, the code of
// commit 48d75b4) differs from the 0.25 mm reference by -0.04 % (period), -0.08 % (decrement),
// -0.002 % (resistance), +0.32 % (length), -0.01 % (cleat peak) and 0.07 % of the sinking (hold
// curve); with the 1 um tread tolerance by +0.09 %, -0.38 %, -0.005 %, +0.32 %, -0.10 % and
// 0.11-0.29 % (docs/transient.md section 6).
constexpr double kPeriodTol = 0.01;
constexpr double kDecrementTol = 0.01;
constexpr double kRollingTol = 0.01;
constexpr double kCleatPeakTol = 0.03;
constexpr double kCreepTol = 0.005;  // of the static sinking
// A settled hold ends at the static footprint (the tread relaxes to its static spring).
constexpr double kRestTol = 1e-5;

nlohmann::json reference() {
  std::ifstream in(kReference);
  EXPECT_TRUE(in.good()) << kReference;
  return nlohmann::json::parse(in);
}

TEST(TransientReference, FreeVibrationPeriodAndDecrementMatchTheFineMeshReference) {
  const auto ref = reference()["free_vibration"];
  const TransientResult r = run_transient(default_model(), Scenario::free_vibration);
  ASSERT_TRUE(r.ok()) << r.message;
  const auto [period_s, decrement] = period_and_decrement(r);
  EXPECT_NEAR(period_s / ref["period_s"].get<double>(), 1.0, kPeriodTol);
  EXPECT_NEAR(decrement / ref["log_decrement"].get<double>(), 1.0, kDecrementTol);
}

// The tread states' tolerance (transient.tread_tolerance_um, 1 um) against the displacement
// tolerance (0.1 um): the bounce's period and decrement move by less than half the 1 %.
TEST(TransientReference, TreadToleranceMovesTheDecayByLessThanHalfTheLimit) {
  const TransientModel loose = default_model();
  ASSERT_DOUBLE_EQ(loose.settings.tread_tolerance_m, 1e-6);
  const TransientModel tight = build_transient_model(
      build_tyre_model(load_tyre_config(kConfig2d, {"transient.tread_tolerance_um=0.1"})));
  const TransientResult a = run_transient(loose, Scenario::free_vibration);
  const TransientResult b = run_transient(tight, Scenario::free_vibration);
  ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
  const auto [period_a, decrement_a] = period_and_decrement(a);
  const auto [period_b, decrement_b] = period_and_decrement(b);
  EXPECT_NEAR(period_a / period_b, 1.0, 0.5 * kPeriodTol);
  EXPECT_NEAR(decrement_a / decrement_b, 1.0, 0.5 * kDecrementTol);
  EXPECT_LT(a.stats.steps, b.stats.steps);  // what the looser tolerance is for
}

TEST(TransientReference, RollingResistanceAndLengthMatchTheFineMeshReference) {
  const auto ref = reference()["rolling"];
  const TransientResult r = run_transient(default_model(), Scenario::rolling);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.rolling_resistance_N / ref["rolling_resistance_N"].get<double>(), 1.0, kRollingTol);
  EXPECT_NEAR(r.samples.back().contact_length_m * 1e3 / ref["contact_length_mm"].get<double>(), 1.0,
              kRollingTol);
}

TEST(TransientReference, CleatPeakLoadMatchesTheFineMeshReference) {
  const auto ref = reference()["cleat"];
  const TransientResult r = run_transient(default_model(), Scenario::cleat);
  ASSERT_TRUE(r.ok()) << r.message;
  double peak = 0;
  for (const auto& s : r.samples) peak = std::max(peak, s.load_N);
  EXPECT_NEAR(peak / ref["peak_load_N"].get<double>(), 1.0, kCleatPeakTol);
}

TEST(TransientReference, LoadHoldCreepFollowsTheReferenceAndEndsAtTheStaticFootprint) {
  const auto ref = reference()["load_hold"];
  const TransientModel M = default_model();
  const TransientResult r = run_transient(M, Scenario::load_hold);
  ASSERT_TRUE(r.ok()) << r.message;
  const FootprintResult st = solve_footprint(M.tyre, LoadCase{M.settings.load_hold.load_N, 0});
  ASSERT_TRUE(st.ok());
  EXPECT_NEAR(r.samples.back().sinking_m / st.sinking_m, 1.0, kRestTol);
  // The outputs share the reference's 2 ms grid (the load-hold's chosen grid: it starts
  // unloaded, output_grid.h): compare at its stored times.
  const double dt = r.output_grid.step_s;
  ASSERT_DOUBLE_EQ(dt, 0.002);
  const auto& t = ref["t_s"];
  const auto& sink = ref["sinking_mm"];
  double worst = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const auto i = static_cast<std::size_t>(std::lround(t[k].get<double>() / dt));
    ASSERT_LT(i, r.samples.size());
    ASSERT_NEAR(r.samples[i].t_s, t[k].get<double>(), 1e-9);
    worst = std::max(worst, std::abs(r.samples[i].sinking_m * 1e3 - sink[k].get<double>()));
  }
  EXPECT_LT(worst / (st.sinking_m * 1e3), kCreepTol);
}

}  // namespace
}  // namespace modaltyre::transient
