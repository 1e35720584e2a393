// Detection limits (issue 23): the naming rule as discover applies it, and the limit of a
// candidate on planted data behaving as a limit should: the simulated power rises through 80 %
// at it, and it shrinks when rows are added or the noise falls. The power curve of discover
// itself against the reported limit is DiscoverPowerCurve (discover_power_test.cc).
#include "modaltyre/discover/detection_limit.h"
#include "modaltyre/discover/discover.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planted_data.h"

namespace modaltyre::discover {
namespace {

using namespace planted;

TEST(NamingRule, NamesOnlyWithEvidenceAndACrossValidatedGain) {
  const NamingRule rule;  // Delta BIC > 10, CV gain >= 25 % (on 12 entries also under z = 2),
                          // loss <= 10 %, pooled not up
  EXPECT_TRUE(rule.names(12, {0.04, 0.02}, {0.02, 0.021}, {12, 12}, 0.032, 0.021));
  EXPECT_FALSE(rule.names(9.9, {0.04, 0.02}, {0.02, 0.021}, {12, 12}, 0.032, 0.021));  // evidence
  EXPECT_FALSE(rule.names(12, {0.04, 0.02}, {0.031, 0.02}, {12, 12}, 0.032, 0.028));  // gain 22.5 %
  EXPECT_FALSE(
      rule.names(12, {0.04, 0.02}, {0.02, 0.0225}, {12, 12}, 0.032, 0.021));          // loss 12.5 %
  EXPECT_FALSE(rule.names(12, {0.04, 0.02}, {0.02, 0.021}, {12, 12}, 0.032, 0.033));  // pooled up
  EXPECT_TRUE(
      rule.names(12, {0, 0.02}, {0.5, 0.01}, {12, 12}, 0.02, 0.01));  // a zero "before" skipped
}

// The alternative rule (docs/discover.md, "The naming rule's power"): the gain needed is the
// one at which a paired test on n entries reaches z, 1 - 1 / sqrt(1 + 4 z^2 / n), capped at 25 %.
TEST(NamingRule, ScaledGainFallsWithTheEntriesAndNeverExceedsTheFixedOne) {
  const NamingRule fixed{10, 0.25, 0.10, 0};
  const NamingRule scaled{10, 0.25, 0.10, 2};
  EXPECT_DOUBLE_EQ(NamingRule{}.cv_gain_z, 2);  // discover's default since issue 23
  EXPECT_DOUBLE_EQ(DiscoverOptions{}.cv_gain_z, NamingRule{}.cv_gain_z);
  EXPECT_DOUBLE_EQ(fixed.gain_needed(1000), 0.25);
  EXPECT_DOUBLE_EQ(scaled.gain_needed(12), 0.25);  // 1 - 1/sqrt(1 + 16/12) = 0.35, capped
  EXPECT_NEAR(scaled.gain_needed(48), 1 - 1 / std::sqrt(1 + 16.0 / 48), 1e-15);
  EXPECT_NEAR(scaled.gain_needed(1600), 1 - 1 / std::sqrt(1.01), 1e-15);  // s/sigma = 0.1
  // A 15 % gain on 48 entries per observable names under the scaled rule only.
  EXPECT_FALSE(fixed.names(12, {0.04, 0.02}, {0.034, 0.02}, {48, 48}, 0.032, 0.028));
  EXPECT_TRUE(scaled.names(12, {0.04, 0.02}, {0.034, 0.02}, {48, 48}, 0.032, 0.028));
}

// Two loads (so that no load-driven effect is testable) x four hold times, repeated `copies`
// times; tread_relaxation is the one testable candidate.
Planted creep_grid(double noise, int copies, double creep_ratio, unsigned seed) {
  Planted p;
  p.effect = creep_ratio > 0 ? "tread_relaxation" : "";
  p.truth = [creep_ratio](auto& e) {
    e.tread_relaxation.enabled = creep_ratio > 0;
    e.tread_relaxation.creep_ratio = creep_ratio;
  };
  const double hold[] = {0, 20, 60, 300};
  for (int c = 0; c < copies; ++c) {
    const auto g = grid(
        {3000, 6500}, [&](auto& r, int l) { r.hold_s = hold[l]; }, 4);
    p.rows.insert(p.rows.end(), g.begin(), g.end());
  }
  p.noise = noise;
  p.seed = seed;
  return p;
}

struct Limit {
  DetectionLimit limit;
  std::vector<double> power;  // at 0.6, 1 and 1.5 x the limit
};

Limit limit_on(const Planted& p, const std::string& name) {
  const auto data = make_data(p, name);
  const TyreConfig cfg = contact::load_tyre_config(kConfig, {"contact.unit_length_mm=2"});
  const contact::TyreModel model = contact::build_tyre_model(cfg);
  const Evaluator ev(model, data);
  std::vector<int> all(data.rows.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  const Variant base = make_variant(cfg, {});
  const FitResult fit = fit_variant(ev, cfg, base, all);
  const LimitFinder finder(ev, fit.config, base, fit, NamingRule{});
  Limit out;
  out.limit = finder.limit(contact::EffectId::tread_relaxation);
  if (out.limit.computed()) {
    for (double f : {0.6, 1.0, 1.5}) {
      out.power.push_back(
          finder.power(contact::EffectId::tread_relaxation, f * out.limit.magnitude));
    }
  }
  return out;
}

TEST(DetectionLimit, PowerCrossesEightyPercentAtTheLimitAndTheLimitShrinksWithRowsAndNoise) {
  const Limit base = limit_on(creep_grid(0.025, 1, 0, 3), "limit_base");
  ASSERT_TRUE(base.limit.computed()) << base.limit.reason;
  EXPECT_EQ(base.limit.parameter, "effects.tread_relaxation.creep_ratio");
  EXPECT_NEAR(base.limit.value, 0.5 * base.limit.magnitude, 1e-12);  // default 0.5, off at 0
  ASSERT_EQ(base.power.size(), 3u);
  EXPECT_LT(base.power[0], 0.8);
  EXPECT_GE(base.power[1], 0.8);
  EXPECT_GT(base.power[2], base.power[1]);
  // What the effect does at the limit beyond the re-fitted baseline: it is a sinking and length
  // effect, of the order of the noise (2.5 %) on these 8 rows.
  ASSERT_TRUE(base.limit.observable_rms_rel.count("sinking_mm"));
  EXPECT_GT(base.limit.observable_rms_rel.at("sinking_mm"), 0.005);
  EXPECT_LT(base.limit.observable_rms_rel.at("sinking_mm"), 0.1);

  const Limit more_rows = limit_on(creep_grid(0.025, 3, 0, 3), "limit_rows");
  ASSERT_TRUE(more_rows.limit.computed()) << more_rows.limit.reason;
  EXPECT_LT(more_rows.limit.value, base.limit.value);

  const Limit less_noise = limit_on(creep_grid(0.008, 1, 0, 3), "limit_noise");
  ASSERT_TRUE(less_noise.limit.computed()) << less_noise.limit.reason;
  EXPECT_LT(less_noise.limit.value, 0.6 * base.limit.value);
}

}  // namespace
}  // namespace modaltyre::discover
