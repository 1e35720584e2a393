// The option effects of the catalogue (effects.h, option_effects.cc): options of the config that
// `effects` lists and `discover` switches. Off by default and bit for bit today's model when off
// (also with an option section that only states values, enabled: false); switched on, each moves
// the observables it lists and no other; at its strength's neutral value it vanishes (what the
// detection limits assume); the registry's switch, overrides and refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "modaltyre/contact/parameter_spec.h"
#include "modaltyre/contact/predictor.h"
#include "patch3d_fixture.h"

namespace modaltyre::contact::testing {
namespace {

const std::vector<EffectId> kOptions = {EffectId::lateral_belt, EffectId::pneumatic_share,
                                        EffectId::crown_shape, EffectId::sidewall_softening};

struct Outputs {
  std::vector<double> sinking, length, width, rolling;
};

Outputs predict_at(const TyreModel& model, const TyreConfig& c, const std::vector<double>& loads) {
  Outputs o;
  for (double F : loads) {
    const Prediction p = predict(model, parameters_of(c), c.default_conditions(F));
    EXPECT_TRUE(p.ok()) << p.message;
    o.sinking.push_back(p.sinking_mm);
    o.length.push_back(p.length_mm);
    o.width.push_back(p.width_mm);
    o.rolling.push_back(p.rolling_resistance_N);
  }
  return o;
}

const std::vector<double>& observable(const Outputs& o, const std::string& name) {
  if (name == "sinking_mm") return o.sinking;
  if (name == "length_mm") return o.length;
  if (name == "width_mm") return o.width;
  return o.rolling;
}

double largest_change(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    m = std::max(m, std::abs(a[k] - b[k]) / std::max(std::abs(b[k]), 1e-300));
  }
  return m;
}

TyreConfig switched(TyreConfig c, EffectId id) {
  enable_effect(c, id);
  return c;
}

TEST(OptionEffects, AreOffInTheBundledConfigsAndListedAfterTheEffectsOfSectionEffects) {
  const auto& cat = effect_catalogue();
  ASSERT_EQ(static_cast<int>(cat.size()), kEffectCount);
  for (int k = 0; k < kEffectCount; ++k) EXPECT_EQ(static_cast<int>(cat[k].id), k);
  for (const char* path : {"/configs/sf350.yaml", "/configs/sf350_2d_table3.yaml"}) {
    const TyreConfig c = load_tyre_config(std::string(MODALTYRE_SOURCE_DIR) + path);
    for (const auto& e : cat) EXPECT_FALSE(effect_enabled(c, e.id)) << path << " " << e.name;
  }
  for (EffectId id : kOptions) {
    const EffectInfo& e = effect_info(id);
    EXPECT_TRUE(e.is_option()) << e.name;
    EXPECT_EQ(e.regime, ConditionId::load_N) << e.name;
    // The flag of section effects: is not theirs: effects.NAME is an unknown key.
    EXPECT_THROW(load_tyre_config(kConfig, {"effects." + e.name + ".enabled=true"}), InputError)
        << e.name;
  }
}

TEST(OptionEffects, StatedButDisabledSectionsPredictTodaysModelBitForBit) {
  const Tyre3d s(kCoarse);
  const std::vector<double> loads = {2131, 8321};
  const Outputs base = predict_at(s.model, s.tyre, loads);
  const TyreConfig stated =
      load_tyre_config(kConfig, with(kCoarse, {"footprint_3d.lateral_belt.enabled=false",
                                               "footprint_3d.lateral_belt.bending_stiffness_Nm=0.5",
                                               "footprint_3d.sidewall.enabled=false",
                                               "footprint_3d.sidewall.meridian_chord_mm=90"}));
  for (EffectId id : kOptions) EXPECT_FALSE(effect_enabled(stated, id));
  const Outputs again = predict_at(s.model, stated, loads);
  EXPECT_EQ(again.sinking, base.sinking);
  EXPECT_EQ(again.length, base.length);
  EXPECT_EQ(again.width, base.width);
  // Switched on, the stated values are the ones used; the fitted ones the catalogue's.
  const TyreConfig belt = switched(stated, EffectId::lateral_belt);
  EXPECT_TRUE(belt.footprint_3d->lateral_belt.enabled);
  EXPECT_EQ(belt.footprint_3d->lateral_belt.bending_stiffness_Nm, 0.5);
  const TyreConfig wall = switched(stated, EffectId::sidewall_softening);
  EXPECT_EQ(wall.footprint_3d->sidewall.chord_m, 0.09);
}

// The check: each effect on with its parameters moves the observables it lists, and
// only those; the ones it does not list (a standing tyre's rolling resistance) stay exactly.
TEST(OptionEffects, EachMovesTheObservablesItListsAndNoOther) {
  const Tyre3d s(kCoarse);
  const std::vector<double> loads = {2131, 5478, 8321};
  const Outputs base = predict_at(s.model, s.tyre, loads);
  for (EffectId id : kOptions) {
    const EffectInfo& e = effect_info(id);
    SCOPED_TRACE(e.name);
    const TyreConfig on = switched(s.tyre, id);
    ASSERT_TRUE(effect_enabled(on, id));
    const Outputs moved = predict_at(s.model, on, loads);
    for (const auto& name : observable_names()) {
      const bool listed =
          std::find(e.observables.begin(), e.observables.end(), name) != e.observables.end();
      const double change = largest_change(observable(moved, name), observable(base, name));
      if (listed) {
        EXPECT_GT(change, 2e-3) << name;
      } else {
        EXPECT_EQ(change, 0.0) << name;
      }
    }
  }
}

// What the detection limits assume (EffectStrength): towards its neutral value each effect
// vanishes. Crown: n = 2 is the circular crown's parabola (within y^4 / 8 R^3 = 3 um at the
// tread edge); the others approach the baseline as the strength falls.
TEST(OptionEffects, EachVanishesAtItsStrengthsNeutralValue) {
  const Tyre3d s(kCoarse);
  const std::vector<double> loads = {2131, 8321};
  const Outputs base = predict_at(s.model, s.tyre, loads);
  for (EffectId id : kOptions) {
    const EffectInfo& e = effect_info(id);
    SCOPED_TRACE(e.name);
    const EffectParameterInfo& strength = e.parameters.front();
    const ParameterSpec* spec = find_parameter(e.key(strength));
    ASSERT_NE(spec, nullptr);
    auto at = [&](double v) {
      TyreConfig c = switched(s.tyre, id);
      spec->set(c, v);
      return predict_at(s.model, c, loads);
    };
    auto change = [&](const Outputs& o) {
      return std::max({largest_change(o.sinking, base.sinking),
                       largest_change(o.length, base.length), largest_change(o.width, base.width)});
    };
    const double d = strength.default_value;
    const double at_default = change(at(d));
    if (e.strength == EffectStrength::inverse) {
      const double weak = change(at(100 * d)), weaker = change(at(1e4 * d));
      EXPECT_LT(weak, 0.5 * at_default);
      EXPECT_LT(weaker, 0.2 * weak);
    } else {
      const double n = e.neutral;
      EXPECT_LT(change(at(n + 0.1 * (d - n))), 0.5 * at_default);
      EXPECT_LT(change(at(n + 1e-3 * (d - n))), 1e-4 + 1e-2 * at_default);
    }
  }
}

TEST(OptionEffects, OverridesWriteTheSwitchedConfigAsAFileWouldCarryIt) {
  const Tyre3d s(kCoarse);
  for (EffectId id : kOptions) {
    const EffectInfo& e = effect_info(id);
    SCOPED_TRACE(e.name);
    const TyreConfig on = switched(s.tyre, id);
    std::vector<std::string> sets = effect_switch_overrides(on, id);
    for (const auto& p : e.parameters) {
      if (p.fitted) sets.push_back(e.key(p) + "=" + std::to_string(p.option.get(on)));
    }
    const TyreConfig read = load_tyre_config(kConfig, with(kCoarse, sets));
    EXPECT_TRUE(effect_enabled(read, id));
    const Outputs a = predict_at(s.model, on, {5478}), b = predict_at(s.model, read, {5478});
    EXPECT_NEAR(a.sinking[0], b.sinking[0], 1e-6 * a.sinking[0]);
    EXPECT_NEAR(a.width[0], b.width[0], 1e-6 * a.width[0]);
  }
}

TEST(OptionEffects, ThreeDOptionsAreRefusedOnTheTwoDPatchWithTheirReason) {
  const TyreConfig flat =
      load_tyre_config(std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml");
  for (EffectId id :
       {EffectId::lateral_belt, EffectId::crown_shape, EffectId::sidewall_softening}) {
    EXPECT_NE(effect_refusal(flat, id).find("3D patch"), std::string::npos);
    TyreConfig c = flat;
    EXPECT_THROW(enable_effect(c, id), InputError);
  }
  EXPECT_EQ(effect_refusal(flat, EffectId::pneumatic_share), "");
  // A measured contour is stated: the crown's shape is no candidate on it.
  const TyreConfig contour = load_tyre_config(
      kConfig, {"footprint_3d.crown.shape=contour", "footprint_3d.crown.contour_y_mm=[0, 80]",
                "footprint_3d.crown.contour_drop_mm=[0, 4]"});
  EXPECT_NE(effect_refusal(contour, EffectId::crown_shape), "");
}

TEST(OptionEffects, TheSidewallsLengthCanBeGivenAsTheChordRatioOnce) {
  const TyreConfig a = load_tyre_config(kConfig, {"footprint_3d.sidewall.meridian_chord_mm=117",
                                                  "footprint_3d.sidewall.chord_over_length=0.85"});
  EXPECT_NEAR(a.footprint_3d->sidewall.length_m, 0.117 / 0.85, 1e-15);
  EXPECT_THROW(load_tyre_config(kConfig, {"footprint_3d.sidewall.meridian_chord_mm=117",
                                          "footprint_3d.sidewall.chord_over_length=0.85",
                                          "footprint_3d.sidewall.meridian_length_mm=140"}),
               InputError);
  EXPECT_THROW(load_tyre_config(kConfig, {"footprint_3d.sidewall.meridian_chord_mm=117"}),
               InputError);
}

}  // namespace
}  // namespace modaltyre::contact::testing

namespace modaltyre::contact::testing {
namespace {

// Patch3d::solve's warm lateral patterns (the pneumatic share's load split solves the same patch
// 5-6 times): the same solution as a cold start, on the rigid and the flexible belt.
TEST(OptionEffects, WarmLateralPatternsChangeTheStepsNotTheSolution) {
  for (const auto& belt : std::vector<std::vector<std::string>>{
           {},
           {"footprint_3d.lateral_belt.supports=free",
            "footprint_3d.lateral_belt.bending_stiffness_Nm=0.27",
            "footprint_3d.lateral_belt.foundation_MPa_per_m=300"}}) {
    const Tyre3d s(with(kCoarse, belt));
    const Patch3d patch(s.model, s.patch);
    const Patch3dResult from = patch.solve(6000);
    ASSERT_TRUE(from.ok()) << from.message;
    const Patch3dResult cold = patch.solve(5000);
    const Patch3dResult warm = patch.solve(5000, from.section_active, from.cell_force_N);
    ASSERT_TRUE(warm.ok()) << warm.message;
    EXPECT_LE(warm.pattern_iterations, cold.pattern_iterations);
    EXPECT_NEAR(warm.sinking_m, cold.sinking_m, kExact * cold.sinking_m);
    EXPECT_NEAR(warm.width_m, cold.width_m, kExact * cold.width_m);
    EXPECT_LT(max_abs([&] {
                std::vector<double> d(cold.cell_force_N.size());
                for (std::size_t k = 0; k < d.size(); ++k)
                  d[k] = warm.cell_force_N[k] - cold.cell_force_N[k];
                return d;
              }()),
              kExact * 5000);
  }
}

}  // namespace
}  // namespace modaltyre::contact::testing
