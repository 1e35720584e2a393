// The discrepancy workflow on data with planted effects (issue: discover must name the hidden
// effect, shrink the cross-validated gap by at least half and recover its parameters), a
// negative control (noise only: name nothing), two hidden effects, and the seed's Table 3.
//
// Data are generated on discover's evaluation mesh (2 mm), so that the 3-standard-error check
// of the recovered parameters measures the statistics alone; the mesh's own bias is measured
// separately (docs/discover.md: below 0.2 % except with a strongly coupled tread). Noise is
// relative Gaussian, seeded; the truth is never seen by discover.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "modaltyre/discover/discover.h"
#include "planted_data.h"

namespace modaltyre::discover {
namespace {

using namespace planted;

std::vector<Planted> planted_cases() {
  std::vector<Planted> v;
  {
    Planted p;
    p.effect = "inflation_pressure";
    p.truth = [](auto& e) {
      e.inflation_pressure.enabled = true;
      e.inflation_pressure.exponent = 1.0;
    };
    p.hidden = {{"effects.inflation_pressure.exponent", 1.0}};
    const double kpa[] = {160, 200, 240, 280};
    p.rows = grid(
        kLoads5, [&](auto& c, int l) { c.pressure_kPa = kpa[l]; }, 4);
    v.push_back(p);
  }
  {
    Planted p;
    p.effect = "tread_relaxation";
    p.truth = [](auto& e) {
      e.tread_relaxation.enabled = true;
      e.tread_relaxation.creep_ratio = 0.8;
      e.tread_relaxation.time_constant_s = 40;
    };
    p.hidden = {{"effects.tread_relaxation.creep_ratio", 0.8},
                {"effects.tread_relaxation.time_constant_s", 40}};
    const double hold[] = {0, 15, 60, 180};
    p.rows = grid(
        kLoads5, [&](auto& c, int l) { c.hold_s = hold[l]; }, 4);
    v.push_back(p);
  }
  {
    Planted p;
    p.effect = "dry_friction";
    p.truth = [](auto& e) {
      e.dry_friction.enabled = true;
      e.dry_friction.friction_force_N = 300;
    };
    p.hidden = {{"effects.dry_friction.friction_force_N", 300}};
    p.rows = grid(
        kLoads5, [](auto& c, int l) { c.branch = l ? Branch::unloading : Branch::loading; }, 2);
    v.push_back(p);
  }
  {
    Planted p;
    p.effect = "load_stiffening";
    p.truth = [](auto& e) {
      e.load_stiffening.enabled = true;
      e.load_stiffening.exponent = 0.25;
    };
    p.hidden = {{"effects.load_stiffening.exponent", 0.25}};
    p.rows = grid(kLoads9, nullptr, 1);
    v.push_back(p);
  }
  {
    Planted p;
    p.effect = "tread_coupling";
    p.truth = [](auto& e) {
      e.tread_coupling.enabled = true;
      e.tread_coupling.coupling_length_mm = 25;
    };
    p.hidden = {{"effects.tread_coupling.coupling_length_mm", 25}};
    // Its signature (3.5 % RMS at 25 mm) is only about twice 1.5 % noise, so halving the
    // cross-validated gap is out of reach there (named at 1.5 %, 3.5 % -> 1.9 %); 1 % noise.
    p.noise = 0.01;
    p.rows = grid(kLoads9, nullptr, 1);
    v.push_back(p);
  }
  {
    Planted p;
    p.effect = "soil_compliance";
    p.truth = [](auto& e) {
      e.soil_compliance.enabled = true;
      e.soil_compliance.modulus_MPa = 8;
    };
    p.hidden = {{"effects.soil_compliance.modulus_MPa", 8}};
    p.rows = grid(
        kLoads5, [](auto& c, int l) { c.surface = l ? Surface::soil : Surface::rigid; }, 2);
    v.push_back(p);
  }
  {
    Planted p;
    p.effect = "rolling_speed";
    p.truth = [](auto& e) {
      e.rolling_speed.enabled = true;
      e.rolling_speed.damping_scale = 3;
    };
    p.hidden = {{"effects.rolling_speed.damping_scale", 3}};
    const double kmh[] = {10, 40, 70, 100};
    p.rows = grid(
        kLoads5, [&](auto& c, int l) { c.speed_kmh = kmh[l]; }, 4);
    p.observables = {"sinking_mm", "length_mm", "rolling_resistance_N"};
    v.push_back(p);
  }
  {
    Planted p;
    p.effect = "contact_width";
    p.truth = [](auto& e) {
      e.contact_width.enabled = true;
      e.contact_width.crown_radius_mm = 120;
    };
    p.hidden = {{"effects.contact_width.crown_radius_mm", 120}};
    p.rows = grid(kLoads9, nullptr, 1);
    p.observables = {"sinking_mm", "length_mm", "width_mm"};
    v.push_back(p);
  }
  {
    Planted p;
    p.effect = "belt_flattening";
    p.truth = [](auto& e) {
      e.belt_flattening.enabled = true;
      e.belt_flattening.stiffness_MPa = 15;
    };
    p.hidden = {{"effects.belt_flattening.stiffness_MPa", 15}};
    // On the extended carcass, where the belt flattens at every order >= 2: a 3.1 % signature,
    // as for tread_coupling, named at 1.5 % noise (3.1 % -> 1.6 %); 1 % noise. On the default
    // carcass (orders 2-5 only, nearly uniform over a patch) the foundation mostly rescales the
    // compliance, which the baseline scalars absorb: named, but kappa not pinned down.
    p.overrides = {kExtended};
    p.noise = 0.01;
    p.rows = grid(kLoads9, nullptr, 1);
    v.push_back(p);
  }
  return v;
}

class HiddenEffect : public ::testing::TestWithParam<Planted> {};

TEST_P(HiddenEffect, IsNamedShrinksTheCrossValidatedGapAndRecoversItsParameters) {
  const Planted& p = GetParam();
  const auto data = make_data(p, p.effect);
  const auto cfg = contact::load_tyre_config(kConfig, p.overrides);
  const DiscoverReport r = discover(cfg, data, {});
  ASSERT_FALSE(r.effects.empty()) << r.conclusion;
  const NamedEffect& e = r.effects.front();
  EXPECT_EQ(e.name, p.effect) << r.conclusion;
  if (e.name != p.effect) return;
  // The criterion: the cross-validated gap shrinks by at least half.
  EXPECT_LE(e.cv_rms_after, 0.5 * e.cv_rms_before) << r.conclusion;
  for (const auto& [key, truth] : p.hidden) {
    const double fitted = e.parameters.at(key), se = e.standard_errors.at(key);
    // Within 3 standard errors of the planted value, and the data must pin it down (a
    // parameter with a standard error near its value would pass the first check vacuously).
    EXPECT_NEAR(fitted, truth, 3 * se) << key;
    EXPECT_LT(se, 0.25 * truth) << key << " = " << fitted;
  }
}

INSTANTIATE_TEST_SUITE_P(Discover, HiddenEffect, ::testing::ValuesIn(planted_cases()),
                         [](const auto& info) { return info.param.effect; });

TEST(DiscoverNegativeControl, NoiseOnlyNamesNothingAndTheGapNeverGrows) {
  Planted p;
  p.seed = 7;
  const double kpa[] = {190, 270};
  const double hold[] = {0, 120};
  p.rows = grid(
      {2000, 4000, 6000, 8000},
      [&](auto& c, int l) { c.pressure_kPa = kpa[l % 2], c.hold_s = hold[l / 2]; }, 4);
  const auto data = make_data(p, "control");
  const DiscoverReport r = discover(contact::load_tyre_config(kConfig), data, {});
  EXPECT_TRUE(r.effects.empty()) << r.conclusion;
  for (const auto& [obs, before] : r.cv_gap_before) EXPECT_EQ(r.cv_gap_after.at(obs), before);
  // Every testable candidate was scored (the control is not passed by testing nothing).
  int tested = 0;
  for (const auto& c : r.rounds.front()) tested += c.testable;
  EXPECT_GE(tested, 6);
}

TEST(DiscoverTwoEffects, FindsBothHiddenEffects) {
  Planted p;
  p.seed = 3;
  p.truth = [](auto& e) {
    e.inflation_pressure.enabled = true;
    e.inflation_pressure.exponent = 1.2;
    e.tread_relaxation.enabled = true;
    e.tread_relaxation.creep_ratio = 0.8;
    e.tread_relaxation.time_constant_s = 40;
  };
  const double kpa[] = {180, 260};
  const double hold[] = {0, 30, 180};
  p.rows = grid(
      {2500, 5000, 7500},
      [&](auto& c, int l) { c.pressure_kPa = kpa[l % 2], c.hold_s = hold[l / 2]; }, 6);
  const auto data = make_data(p, "two");
  const DiscoverReport r = discover(contact::load_tyre_config(kConfig), data, {});
  std::set<std::string> named;
  for (const auto& e : r.effects) named.insert(e.name);
  EXPECT_EQ(named, (std::set<std::string>{"inflation_pressure", "tread_relaxation"}))
      << r.conclusion;
  for (const auto& [obs, before] : r.cv_gap_before) EXPECT_LT(r.cv_gap_after.at(obs), 0.5 * before);
}

// The seed's measured Table 3. On the default carcass (the measured orders only, seed 001's
// model) the baseline leaves a gap no candidate explains significantly (README: nothing is
// named; the width gap of a fixed-width 2D patch stays), and naming never grows it.
TEST(DiscoverTable3, MeasuredModeCarcassLeavesNoGapACandidateExplains) {
  const auto cfg = contact::load_tyre_config(kConfig);
  const auto data = studies::read_measurements(
      std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_footprint_table3.csv", cfg);
  const DiscoverReport r = discover(cfg, data, {});
  for (const auto& [obs, before] : r.cv_gap_before)
    EXPECT_LE(r.cv_gap_after.at(obs), before) << obs;
  EXPECT_TRUE(r.effects.empty()) << r.conclusion;
}

// With the dispersion extension the ring flattens at every order and leaves a length gap of
// about 10 % RMS: whatever is named must not grow the cross-validated gap on any observable,
// and the length gap must shrink.
TEST(DiscoverTable3, ExtendedCarcassLengthGapIsNamedAndShrinks) {
  const auto cfg = contact::load_tyre_config(kConfig, {kExtended});
  const auto data = studies::read_measurements(
      std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_footprint_table3.csv", cfg);
  const DiscoverReport r = discover(cfg, data, {});
  EXPECT_GT(r.gap_before.at("length_mm"), 0.08);
  for (const auto& [obs, before] : r.cv_gap_before)
    EXPECT_LE(r.cv_gap_after.at(obs), before) << obs;
  ASSERT_FALSE(r.effects.empty()) << r.conclusion;
  EXPECT_LT(r.cv_gap_after.at("length_mm"), 0.6 * r.cv_gap_before.at("length_mm"));
}

TEST(DiscoverStatistics, BicBehavesAsDefined) {
  // One observable, residuals 0.02 everywhere: BIC = n ln(0.02^2) + k ln n.
  std::vector<Evaluator::Entry> e(10);
  const std::vector<double> r(10, 0.02);
  EXPECT_NEAR(bic(e, r, 1, 2), 10 * std::log(4e-4) + 2 * std::log(10.0), 1e-12);
  // Halving every residual lowers BIC by n ln 4 at equal k.
  const std::vector<double> half(10, 0.01);
  EXPECT_NEAR(bic(e, r, 1, 2) - bic(e, half, 1, 2), 10 * std::log(4.0), 1e-12);
}

}  // namespace
}  // namespace modaltyre::discover
