// The parameter specification: every entry sets a key as the config reader sets it (a round
// trip through the reader), the effect entries are the effect catalogue's, and the search
// ranges and transforms are consistent with their users' assumptions.
#include "modaltyre/contact/parameter_spec.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/effects.h"

namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;

// A value inside a search range: its geometric mean when positive, else its midpoint.
double inside(const SearchRange& r) {
  return r.min > 0 ? std::sqrt(r.min * r.max) : 0.5 * (r.min + r.max);
}

std::string exact(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// The settings a key needs beside the config's (a power crown for its exponent).
// What a config needs besides `key` to state it: the switch of the option effect it belongs to
// (the crown's exponent needs a power crown, a foundation a lateral belt, ...).
std::vector<std::string> needed_by(const std::string& key) {
  for (const auto& e : effect_catalogue()) {
    if (!e.is_option()) continue;
    for (const auto& p : e.parameters) {
      if (e.key(p) != key) continue;
      std::vector<std::string> out;
      // A soil effect's keys need a soil of their model (LETE sand's law; a layer of 2 MPa).
      if (key.rfind("ground.bekker.", 0) == 0)
        out = {"ground.model=bekker", "ground.bekker.n=0.79", "ground.bekker.k_c=102",
               "ground.bekker.k_phi=5301"};
      if (key.rfind("ground.kelvin_voigt.", 0) == 0)
        out = {"ground.model=kelvin_voigt", "ground.kelvin_voigt.E2_MPa=2",
               "ground.kelvin_voigt.layer_mm=200"};
      for (auto& s : effect_catalogue_switch(e.id))
        if (s.rfind(key + "=", 0) != 0) out.push_back(s);
      return out;
    }
  }
  return {};
}

// The same with `key` at a value of its range, for a config to set it in.
std::vector<std::string> stated_with(const std::string& key, double v) {
  std::vector<std::string> out = needed_by(key);
  if (!out.empty()) out.push_back(key + "=" + exact(v));
  return out;
}

TEST(ParameterSpec, SetAndGetAgreeWithTheConfigReaderForEverySearchedKey) {
  for (const auto& p : parameter_catalogue()) {
    const auto& range = p.calibration ? p.calibration : p.fit;
    if (!range) continue;
    const double v = inside(*range);
    const std::string& path = p.key.rfind("footprint_3d.", 0) == 0 ? kConfig3d : kConfig2d;
    std::vector<std::string> sets = needed_by(p.key);
    sets.push_back(p.key + "=" + exact(v));
    const TyreConfig read = load_tyre_config(path, sets);
    EXPECT_NEAR(p.get(read), v, 1e-12 * std::abs(v)) << p.key;
    TyreConfig set = load_tyre_config(path, stated_with(p.key, 0.5 * (v + range->max)));
    p.set(set, v);
    EXPECT_NEAR(p.get(set), p.get(read), 1e-12 * std::abs(v)) << p.key;
  }
}

TEST(ParameterSpec, ThreeDimensionalKeysRefuseATwoDimensionalConfig) {
  TyreConfig c = load_tyre_config(kConfig2d);
  for (const char* key : {"footprint_3d.crown.radius_mm", "footprint_3d.tread_width_mm"}) {
    const ParameterSpec* p = find_parameter(key);
    ASSERT_NE(p, nullptr) << key;
    EXPECT_THROW(p->get(c), modaltyre::InputError) << key;
    EXPECT_THROW(p->set(c, 150), modaltyre::InputError) << key;
  }
}

TEST(ParameterSpec, EffectEntriesAreTheEffectCatalogues) {
  for (const auto& e : effect_catalogue()) {
    for (const auto& ep : e.parameters) {
      const ParameterSpec* p = find_parameter(e.key(ep));
      ASSERT_NE(p, nullptr) << e.key(ep);
      EXPECT_EQ(p->unit, ep.unit) << p->key;
      if (e.is_option()) {
        // An option's key: the option's reader bounds what a config states; discover searches
        // the catalogue's range (a key validate calibrates keeps its calibration range).
        ASSERT_EQ(p->fit.has_value(), ep.fitted) << p->key;
        if (ep.fitted) {
          EXPECT_EQ(p->fit->min, ep.min) << p->key;
          EXPECT_EQ(p->fit->max, ep.max) << p->key;
        }
        continue;
      }
      EXPECT_FALSE(p->calibration) << p->key;
      ASSERT_EQ(p->fit.has_value(), ep.fitted) << p->key;
      if (ep.fitted) {
        EXPECT_EQ(p->fit->min, ep.min) << p->key;
        EXPECT_EQ(p->fit->max, ep.max) << p->key;
      }
      // The entry reads and writes the catalogue's field.
      TyreConfig c;
      p->set(c, 0.5 * (ep.min + ep.max));
      EXPECT_EQ(ep.ref(static_cast<const EffectsConfig&>(c.effects)), 0.5 * (ep.min + ep.max));
      EXPECT_EQ(p->get(c), 0.5 * (ep.min + ep.max)) << p->key;
    }
  }
}

TEST(ParameterSpec, SearchRangesAreOrderedAndLogarithmicOnlyWhenPositive) {
  int keys = 0;
  for (const auto& p : parameter_catalogue()) {
    ++keys;
    EXPECT_EQ(find_parameter(p.key), &p) << "duplicate key " << p.key;
    for (const auto& r : {p.calibration, p.fit}) {
      if (!r) continue;
      EXPECT_LT(r->min, r->max) << p.key;
      if (r->transform != SearchTransform::logistic) {
        EXPECT_GT(r->min, 0) << p.key;
      }
    }
    if (p.calibration) {
      EXPECT_EQ(p.calibration->transform, SearchTransform::log) << p.key;
    }
    if (p.fit) {
      EXPECT_NE(p.fit->transform, SearchTransform::log) << p.key;
    }
  }
  EXPECT_GT(keys, 8);
  EXPECT_EQ(find_parameter("tread.no_such_key"), nullptr);
}

// The reader accepts a key's whole declared range, refuses the values just outside it (naming
// the key), and every search range lies inside it (a fit never proposes a value the reader
// would refuse).
TEST(ParameterSpec, TheConfigReaderAcceptsExactlyTheDeclaredRange) {
  int bounded = 0;
  for (const auto& p : parameter_catalogue()) {
    if (!p.accepted) continue;
    ++bounded;
    const ValueRange& a = *p.accepted;
    EXPECT_EQ(&accepted_range(p.key), &a) << p.key;
    EXPECT_LT(a.min, a.max) << p.key;
    for (const auto& r : {p.calibration, p.fit}) {
      if (!r) continue;
      EXPECT_LE(a.min, r->min) << p.key;
      EXPECT_GE(a.max, r->max) << p.key;
    }
    const std::string& path = p.key.rfind("footprint_3d.", 0) == 0 ? kConfig3d : kConfig2d;
    // At a bound another check may refuse the config (a 50 mm radius is shorter than the
    // candidate window), never the range check.
    for (double v : {a.min, a.max}) {
      try {
        load_tyre_config(path, {p.key + "=" + exact(v)});
      } catch (const modaltyre::InputError& e) {
        EXPECT_EQ(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
      }
    }
    const double below = std::nextafter(a.min, -HUGE_VAL);
    const double above = std::nextafter(a.max, HUGE_VAL);
    for (double v : {below, above}) {
      try {
        load_tyre_config(path, {p.key + "=" + exact(v)});
        ADD_FAILURE() << p.key << "=" << exact(v) << " accepted";
      } catch (const modaltyre::InputError& e) {
        const std::string leaf = p.key.substr(p.key.rfind('.') + 1);
        EXPECT_NE(std::string(e.what()).find(leaf), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_GE(bounded, 7);  // the tyre scalars but the crown radius, and every effect parameter
  EXPECT_FALSE(find_parameter("footprint_3d.crown.radius_mm")->accepted);
  EXPECT_THROW(accepted_range("footprint_3d.crown.radius_mm"), std::logic_error);
  EXPECT_THROW(accepted_range("tread.no_such_key"), std::logic_error);
}

TEST(ParameterSpec, DiscoverSearchesInLogarithmsFromAFactorOfOneHundred) {
  EXPECT_EQ(logistic_search(0.05, 20).transform, SearchTransform::log_logistic);  // 400x
  EXPECT_EQ(logistic_search(1, 100).transform, SearchTransform::log_logistic);
  EXPECT_EQ(logistic_search(1, 99).transform, SearchTransform::logistic);
  EXPECT_EQ(logistic_search(0, 4).transform, SearchTransform::logistic);
  EXPECT_EQ(logistic_search(-0.9, 0.9).transform, SearchTransform::logistic);
}

TEST(ParameterSpec, EveryEffectActsThroughACatalogueCondition) {
  EXPECT_EQ(effect_info(EffectId::dry_friction).regime, modaltyre::ConditionId::branch);
  EXPECT_EQ(effect_info(EffectId::soil_compliance).regime, modaltyre::ConditionId::surface);
  for (const auto& e : effect_catalogue()) {
    EXPECT_FALSE(modaltyre::condition_info(e.regime).name.empty()) << e.name;
  }
}

}  // namespace
