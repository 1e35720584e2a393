// The discrepancy workflow on the default tyre (configs/sf350.yaml, the 3D patch), issue 45:
// load_stiffening and belt_flattening hidden alone in six footprints at 1.5 % noise are named
// first among every candidate the 3D patch takes (the nine road effects but contact_width, and
// the four option effects), and a noise-only set names nothing.
//
// Coarse on purpose (each test a few seconds of CPU in Release): the data are made and
// evaluated on the same 4 mm units and 10 mm lateral cells, so the round trip measures the
// statistics and the candidates' confounding, not the mesh (the default mesh's figures:
// bench/discover_default_check.py, docs/discover.md); no detection limits.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numeric>
#include <string>

#include "modaltyre/contact/parameter_spec.h"
#include "modaltyre/discover/discover.h"
#include "modaltyre/discover/model_fit.h"
#include "modaltyre/discover/profile_band.h"
#include "planted_data.h"

namespace modaltyre::discover {
namespace {

using namespace planted;

const std::vector<std::string> kCoarse3d = {"footprint_3d.lateral_cell_mm=10"};

Planted on_default_tyre(unsigned seed) {
  Planted p;
  p.config = kConfig3d;
  p.overrides = kCoarse3d;
  p.unit_length_mm = 4;
  p.seed = seed;
  p.rows = grid({2000, 3300, 4600, 5900, 7200, 8500}, nullptr, 1);
  p.observables = {"sinking_mm", "length_mm", "width_mm"};
  return p;
}

DiscoverReport discover_default(const Planted& p, const std::string& name) {
  const auto data = make_data(p, name);
  DiscoverOptions opt;
  opt.unit_length_mm = p.unit_length_mm;
  opt.detection_limits = false;
  return discover(contact::load_tyre_config(p.config, p.overrides), data, opt);
}

// Named first, the cross-validated gap shrinking, the planted value within 3 standard errors.
void expect_named_first(const Planted& p, const DiscoverReport& r) {
  ASSERT_FALSE(r.effects.empty()) << r.conclusion;
  const NamedEffect& e = r.effects.front();
  ASSERT_EQ(e.name, p.effect) << r.conclusion;
  EXPECT_LT(e.cv_rms_after, e.cv_rms_before) << r.conclusion;
  for (const auto& [key, truth] : p.hidden)
    EXPECT_NEAR(e.parameters.at(key), truth, 3 * e.standard_errors.at(key)) << key;
  int tested = 0;
  for (const auto& c : r.rounds.front()) tested += c.testable;
  EXPECT_GE(tested, 7) << "every load-regime candidate of the 3D patch is scored";
}

// One effect hidden alone, switched on and its parameter `key` set as the config reader sets
// them (the effect and parameter catalogues).
Planted hidden_alone(unsigned seed, const std::string& effect, const std::string& key,
                     double value) {
  Planted p = on_default_tyre(seed);
  p.effect = effect;
  p.option_truth = [effect, key, value](TyreConfig& c) {
    contact::enable_effect(c, contact::find_effect(effect)->id);
    contact::find_parameter(key)->set(c, value);
  };
  p.hidden = {{key, value}};
  return p;
}

TEST(DiscoverDefaultTyre, LoadStiffeningHiddenAloneIsNamed) {
  const Planted p = hidden_alone(11, "load_stiffening", "effects.load_stiffening.exponent", 0.2);
  expect_named_first(p, discover_default(p, "default_stiffening"));
}

TEST(DiscoverDefaultTyre, BeltFlatteningHiddenAloneIsNamed) {
  const Planted p =
      hidden_alone(12, "belt_flattening", "effects.belt_flattening.stiffness_MPa", 20);
  expect_named_first(p, discover_default(p, "default_flattening"));
}

// A planted set on twelve loads as discover evaluates it (its evaluation mesh, every row), with
// the baseline's fit: for the tests that look into one candidate's fit or limit.
struct Evaluated {
  studies::MeasurementSet data;
  TyreConfig config;
  std::unique_ptr<const contact::TyreModel> model;
  std::unique_ptr<const Evaluator> ev;
  std::vector<int> rows;
  FitResult base;

  Evaluated(Planted p, const std::string& name) {
    p.rows =
        grid({2000, 2600, 3200, 3800, 4400, 5000, 5600, 6200, 6800, 7400, 8000, 8600}, nullptr, 1);
    data = make_data(p, name);
    config = contact::load_tyre_config(p.config, p.overrides);
    config.mesh.unit_length_m = p.unit_length_mm * 1e-3;
    model = std::make_unique<const contact::TyreModel>(contact::build_tyre_model(config));
    ev = std::make_unique<const Evaluator>(*model, data);
    rows.resize(data.rows.size());
    std::iota(rows.begin(), rows.end(), 0);
    base = fit_variant(*ev, config, make_variant(config, {}), rows);
  }
};

// The lateral belt's foundation hidden alone in twelve footprints
// (bench/discover_default_check.py's grid for the option effects and seed 45's drawn 447.7 MPa/m),
// on the default's 5 mm lateral cells: the profile cost is flat from 10 to ~250 MPa/m and the basin
// narrow around the truth, and before the interior scouts (model_fit.cc) the candidate's fit ended
// at the range's bound 10 MPa/m (Delta BIC 17 against 57 at the truth on the default mesh). Its
// profile band (profile_band.h) holds the truth where value +- 2 Gauss-Newton standard errors did
// not there (387.6 +- 2 x 28.0). Naming is not asked here: on these rows crown_shape at its
// exponent's bound 1.05 explains the width's growth about as well (docs/discover.md).
TEST(DiscoverDefaultTyre, LateralBeltHiddenAloneFitFindsItsBasin) {
  const std::string key = "footprint_3d.lateral_belt.foundation_MPa_per_m";
  Planted p = hidden_alone(45, "lateral_belt", key, 447.7);
  p.overrides = {};
  const Evaluated e(p, "default_lateral_belt");
  const Evaluator& ev = *e.ev;
  const FitResult& base = e.base;
  const std::vector<int>& rows = e.rows;
  const Variant v = make_variant(e.config, {contact::EffectId::lateral_belt});
  const FitResult fit = fit_variant(ev, base.config, v, rows, std::nullopt, true);
  const int i = static_cast<int>(v.parameters.size()) - 1;
  ASSERT_EQ(v.parameters[i].key, key);
  EXPECT_GT(base.bic - fit.bic, 30) << "the planted basin, not the plateau";
  const ParameterBand band = profile_band(ev, base.config, v, fit, rows, i);
  EXPECT_LT(band.lower, 447.7);
  EXPECT_GT(band.upper, 447.7);
  EXPECT_FALSE(band.lower_at_bound || band.upper_at_bound);
  EXPECT_LT(band.lower, fit.values[i]);
  EXPECT_GT(band.upper, fit.values[i]);
  // Near the optimum the profile is the linearised model's: a statistic of (d / se)^2 at d;
  // Its mean over both sides (the cubic terms cancel) at a fifth of a standard error.
  double mean = 0;
  for (double d : {-0.2, 0.2})
    mean += 0.5 * profile_statistic(ev, base.config, v, fit, rows, i,
                                    fit.values[i] + d * fit.standard_errors[i]);
  EXPECT_NEAR(mean, 0.04, 0.01);
}

// crown_shape planted just below the circular crown's n = 2 (1.9, twelve loads): too weak to be
// named (the re-fitted crown radius absorbs most of it), and its detection limit says so on its
// own side: "n <= a" below 2 with a < 1.9, where before only "n >= b" above 2 was searched
// (bench/discover_default_check.py's seed 45 crown at 1.686 on the default mesh: not named,
// Delta BIC 4.2, reported limit n >= 2.88).
TEST(DiscoverDefaultTyre, CrownShapeHiddenAloneBelowTheCircleIsLimitedOnItsSide) {
  const std::string key = "footprint_3d.crown.exponent";
  const Evaluated e(hidden_alone(45, "crown_shape", key, 1.9), "default_crown_low");
  const Evaluator& ev = *e.ev;
  const FitResult& base = e.base;
  const Variant baseline = make_variant(e.config, {});
  const FitResult crown = fit_variant(
      ev, base.config, make_variant(e.config, {contact::EffectId::crown_shape}), e.rows);
  EXPECT_LT(base.bic - crown.bic, 10) << "not named: below the rule's Delta BIC";
  const LimitFinder finder(ev, base.config, baseline, base, NamingRule{});
  const DetectionLimit l = finder.limit(contact::EffectId::crown_shape);
  ASSERT_TRUE(l.computed()) << l.reason;
  EXPECT_GT(l.value, 2);
  EXPECT_FALSE(l.at_most);
  ASSERT_TRUE(l.two_sided);
  ASSERT_TRUE(l.lower_reason.empty()) << l.lower_reason;
  EXPECT_LT(l.lower_value, 1.9) << "the planted value is inside what these rows cannot name";
  EXPECT_GT(l.lower_value, 1.05);
  EXPECT_DOUBLE_EQ(l.lower_reference_value, 0.5 * (1.05 + 2));
}

TEST(DiscoverDefaultTyre, NoiseOnlyNamesNothing) {
  const Planted p = on_default_tyre(13);
  const DiscoverReport r = discover_default(p, "default_noise");
  EXPECT_TRUE(r.effects.empty()) << r.conclusion;
  for (const auto& [obs, before] : r.cv_gap_before) EXPECT_EQ(r.cv_gap_after.at(obs), before);
}

}  // namespace
}  // namespace modaltyre::discover
