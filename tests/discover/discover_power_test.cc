// Discover's own power against the detection limit it reports (issue 23 item 4): for two
// effects, the probability that the whole workflow names the effect first, planted at 0.7 and
// 1.3 x the reported limit, must cross 80 % between the two; and the false-name rate of the
// naming rule on noise-only data. Kept cheap: 8-row data sets with one testable candidate, on a
// 4 mm evaluation mesh (the data generated on the same mesh), 20 draws per point.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "modaltyre/discover/discover.h"
#include "planted_data.h"

namespace modaltyre::discover {
namespace {

using namespace planted;

constexpr double kUnitMm = 4;
constexpr int kDraws = 20;

struct PowerCase {
  std::string effect;
  std::string label;
  std::function<void(contact::EffectsConfig&, double)> plant;  // at m x the default strength
  std::vector<OperatingConditions> rows;
};

void PrintTo(const PowerCase& c, std::ostream* os) {
  *os << c.effect << ", " << c.rows.size() << " rows";
}

Planted planted(const PowerCase& c, double m, unsigned seed) {
  Planted p;
  p.effect = m > 0 ? c.effect : "";
  p.truth = [&c, m](auto& e) { c.plant(e, m); };
  p.rows = c.rows;
  p.noise = 0.025;
  p.seed = seed;
  p.unit_length_mm = kUnitMm;
  return p;
}

DiscoverReport run(const studies::MeasurementSet& data, bool limits) {
  DiscoverOptions opt;
  opt.unit_length_mm = kUnitMm;
  opt.threads = 1;
  opt.detection_limits = limits;
  opt.max_effects = 1;
  return discover(contact::load_tyre_config(kConfig), data, opt);
}

// Named first in `draws` fresh data sets planted at m x the default.
int named_first(const PowerCase& c, double m, unsigned seed0) {
  make_data(planted(c, m, seed0), c.label + "_warm");  // builds the generator outside the loop
  int named = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : named)
  for (int k = 0; k < kDraws; ++k) {
    const auto r = run(make_data(planted(c, m, seed0 + k), c.label + std::to_string(k)), false);
    named += !r.effects.empty() && r.effects.front().name == c.effect;
  }
  return named;
}

class DiscoverPowerCurve : public ::testing::TestWithParam<PowerCase> {};

// The limit is the 80 % point of the simulated rule on the model linearised at the fit; the
// workflow itself (its nonlinear search and re-fits on fresh noise) must agree to +-30 % in
// magnitude. Tolerance from the binomial spread of kDraws draws: a count whose 80 % expectation
// lies beyond two standard deviations (2 sqrt(20 x 0.8 x 0.2) = 3.6 draws) fails: at 1.3 x at
// least 13 of 20 named, at 0.7 x at most 19; and the power must rise between the two.
TEST_P(DiscoverPowerCurve, CrossesEightyPercentWithinThirtyPercentOfTheReportedLimit) {
  const PowerCase& c = GetParam();
  // The limit one data set reports scales with its noise estimate, which scatters by ~25 % on 8
  // entries per observable: the median of the limits 5 noise-only sets report.
  std::vector<double> limits;
  for (unsigned seed = 11; seed < 16; ++seed) {
    const auto report = run(make_data(planted(c, 0, seed), c.label + "_noise"), true);
    ASSERT_TRUE(report.effects.empty());
    for (const auto& s : report.rounds.back()) {
      if (s.name != c.effect) continue;
      ASSERT_TRUE(s.limit.computed()) << s.limit.reason;
      limits.push_back(s.limit.magnitude);
    }
  }
  ASSERT_EQ(limits.size(), 5u);
  std::sort(limits.begin(), limits.end());
  const double limit = limits[2];
  const double spread = 2 * std::sqrt(kDraws * 0.8 * 0.2);
  const int low = named_first(c, 0.7 * limit, 300);
  const int high = named_first(c, 1.3 * limit, 400);
  EXPECT_GE(high, 0.8 * kDraws - spread) << "median limit " << limit << " x default";
  EXPECT_LE(low, 0.8 * kDraws + spread) << "median limit " << limit << " x default";
  EXPECT_LT(low, high);
}

std::vector<PowerCase> power_cases() {
  const double hold[] = {0, 20, 60, 300};
  return {
      {"tread_relaxation", "pc_creep",
       [](auto& e, double m) {
         e.tread_relaxation.enabled = m > 0;
         e.tread_relaxation.creep_ratio = 0.5 * m;
       },
       grid(
           {3000, 6500}, [&](auto& r, int l) { r.hold_s = hold[l]; }, 4)},
      {"dry_friction", "pc_friction",
       [](auto& e, double m) {
         e.dry_friction.enabled = m > 0;
         e.dry_friction.friction_force_N = 200 * m;
       },
       grid(
           {3000, 6500},
           [](auto& r, int l) { r.branch = l % 2 ? Branch::unloading : Branch::loading; }, 8)},
  };
}

INSTANTIATE_TEST_SUITE_P(TwoEffects, DiscoverPowerCurve, ::testing::ValuesIn(power_cases()),
                         [](const auto& info) { return info.param.effect; });

// Noise-only sets of 12 rows (3 loads x 2 pressures x 2 hold times, 2.5 % noise) with six
// testable candidates; bench/discover_power_study measures the rate on 50 such sets.
// Allowed: a false-name rate of 5 %; with 12 sets the count may exceed its expectation 0.6 by
// two binomial standard deviations (2 sqrt(12 x 0.05 x 0.95) = 1.5): at most 2 named.
TEST(DiscoverFalseNames, NoiseOnlySetsRarelyNameAnEffect) {
  constexpr int kSets = 12;
  const double hold[] = {0, 120}, kpa[] = {200, 260};
  PowerCase none{"", "fn", [](auto&, double) {},
                 grid(
                     {2500, 5500, 8500},
                     [&](auto& r, int l) {
                       r.hold_s = hold[l % 2];
                       r.pressure_kPa = kpa[l / 2];
                     },
                     4)};
  make_data(planted(none, 0, 1), "fn_warm");
  int named = 0, testable = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : named)
  for (int k = 0; k < kSets; ++k) {
    const auto r = run(make_data(planted(none, 0, 500 + k), "fn" + std::to_string(k)), false);
    named += !r.effects.empty();
    if (k == 0) {
      for (const auto& c : r.rounds.front()) testable += c.testable;
    }
  }
  EXPECT_GE(testable, 5);
  EXPECT_LE(named, 2);
}

}  // namespace
}  // namespace modaltyre::discover
