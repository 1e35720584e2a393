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
#include <string>

#include "modaltyre/contact/parameter_spec.h"
#include "modaltyre/discover/discover.h"
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

TEST(DiscoverDefaultTyre, NoiseOnlyNamesNothing) {
  const Planted p = on_default_tyre(13);
  const DiscoverReport r = discover_default(p, "default_noise");
  EXPECT_TRUE(r.effects.empty()) << r.conclusion;
  for (const auto& [obs, before] : r.cv_gap_before) EXPECT_EQ(r.cv_gap_after.at(obs), before);
}

}  // namespace
}  // namespace modaltyre::discover
