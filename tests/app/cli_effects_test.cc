// `modaltyre effects` end to end: the documented JSON shape, keys the config reader accepts,
// and exit 2 naming the key for a value outside the catalogue's range.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;

class EffectsCli : public modaltyre_test::CliFixture {
 protected:
  nlohmann::json catalogue() {
    const auto r = run({"effects", "--json"});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  }

  // A coarse mesh: only the config reader is under test here, not the solve.
  modaltyre_test::CliRun footprint_with(const std::vector<std::string>& sets) {
    std::vector<std::string> args{
        "footprint", kConfig2d, "--load", "4000", "--json", "--set", "contact.unit_length_mm=2"};
    for (const auto& s : sets) {
      args.push_back("--set");
      args.push_back(s);
    }
    return run(args);
  }
};

TEST_F(EffectsCli, JsonListsEighteenEffectsWithTheDocumentedShape) {
  const auto j = catalogue();
  ASSERT_TRUE(j.contains("effects"));
  ASSERT_EQ(j["effects"].size(), 18u);
  std::set<std::string> names;
  int options = 0;
  for (const auto& e : j["effects"]) {
    for (const char* k : {"name", "description", "observables", "regime", "enabled_key", "switch",
                          "option", "strength", "parameters"}) {
      ASSERT_TRUE(e.contains(k)) << k;
    }
    const auto name = e["name"].get<std::string>();
    names.insert(name);
    if (e["option"].get<bool>()) {
      // An option of the config: its own keys, listed as the switch and the parameters.
      ++options;
      for (const auto& p : e["parameters"]) {
        const auto key = p["key"].get<std::string>();
        EXPECT_TRUE(key.rfind("footprint_3d.", 0) == 0 || key.rfind("modal.", 0) == 0 ||
                    key.rfind("ground.", 0) == 0)
            << key;
      }
      continue;
    }
    EXPECT_EQ(e["enabled_key"], "effects." + name + ".enabled");
    EXPECT_EQ(e["switch"], nlohmann::json::array({"effects." + name + ".enabled=true"}));
    EXPECT_FALSE(e["observables"].empty()) << name;
    EXPECT_FALSE(e["regime"].get<std::string>().empty()) << name;
    ASSERT_FALSE(e["parameters"].empty()) << name;
    for (const auto& p : e["parameters"]) {
      for (const char* k : {"key", "unit", "default", "min", "max", "fitted", "meaning"}) {
        ASSERT_TRUE(p.contains(k)) << name << " " << k;
      }
      EXPECT_EQ(p["key"].get<std::string>().rfind("effects." + name + ".", 0), 0u) << p["key"];
      EXPECT_TRUE(p["fitted"].is_boolean());
      const double lo = p["min"], hi = p["max"], def = p["default"];
      EXPECT_LE(lo, def) << p["key"];
      EXPECT_LE(def, hi) << p["key"];
    }
  }
  EXPECT_EQ(names.size(), 18u) << "effect names must be unique";
  EXPECT_EQ(options, 9);
}

TEST_F(EffectsCli, TextTableNamesEveryKeyAndWhetherItIsFitted) {
  const auto j = catalogue();
  const auto r = run({"effects"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const auto& e : j["effects"]) {
    EXPECT_NE(r.out.find(e["enabled_key"].get<std::string>()), std::string::npos);
    EXPECT_NE(r.out.find("regime variable: " + e["regime"].get<std::string>()), std::string::npos);
    for (const auto& p : e["parameters"]) {
      EXPECT_NE(r.out.find(p["key"].get<std::string>()), std::string::npos) << p["key"];
    }
  }
  EXPECT_NE(r.out.find("stated"), std::string::npos);
  EXPECT_NE(r.out.find("fitted"), std::string::npos);
}

TEST_F(EffectsCli, EveryListedKeyIsAcceptedAtItsDefault) {
  // Every key of every effect in one run: the reader rejects unknown keys, so exit 0 means each
  // listed key is a real one.
  std::vector<std::string> sets;
  const nlohmann::json all = catalogue();  // not a temporary: the loop keeps references into it
  for (const auto& e : all["effects"]) {
    if (e["option"].get<bool>()) continue;  // options of the 3D config: below
    sets.push_back(e["enabled_key"].get<std::string>() + "=true");
    for (const auto& p : e["parameters"]) {
      sets.push_back(p["key"].get<std::string>() + "=" + p["default"].dump());
    }
  }
  const auto r = footprint_with(sets);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(r.out)["cases"][0]["converged"].get<bool>());
  // A misspelt key is not silently ignored.
  const auto bad = footprint_with({"effects.dry_friction.friction_force=200"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("friction_force"), std::string::npos) << bad.err;
}

// An option's switch and its parameters at their defaults, as `--set` arguments.
std::vector<std::string> option_sets(const nlohmann::json& e) {
  std::vector<std::string> sets = e["switch"].get<std::vector<std::string>>();
  for (const auto& p : e["parameters"]) {
    const std::string key = p["key"].get<std::string>();
    bool in_switch = false;  // a stated value the switch already sets
    for (const auto& s : sets) in_switch = in_switch || s.rfind(key + "=", 0) == 0;
    if (!in_switch) sets.push_back(key + "=" + p["default"].dump());
  }
  return sets;
}

bool soil_option(const nlohmann::json& e) {
  return e["parameters"][0]["key"].get<std::string>().rfind("ground.", 0) == 0;
}

// The soil effects' switches and keys at their defaults, on a soil file under the rigid wheel
// (which takes all five): the Bekker ones at once on LETE sand, the viscosity on a Kelvin-Voigt
// soil.
TEST_F(EffectsCli, EverySoilSwitchIsAcceptedByTractionOnItsSoilAtItsDefaults) {
  const nlohmann::json all = catalogue();
  const std::string soils = std::string(MODALTYRE_SOURCE_DIR) + "/configs/soils/";
  std::vector<std::string> bekker{"traction", kConfig2d, "--ground",       soils + "lete_sand.yaml",
                                  "--load",   "3000",    "--slip",         "0.2",
                                  "--json",   "--set",   "tyre.rigid=true"};
  // Without --ground the `ground.*` sets go to the tyre config: a Kelvin-Voigt soil there.
  std::vector<std::string> kv{"traction", kConfig2d, "--load",       "3000", "--slip",
                              "0.2",      "--json",  "--speed-km-h", "5"};
  for (const char* k :
       {"tyre.rigid=true", "ground.model=kelvin_voigt", "ground.kelvin_voigt.E2_MPa=2",
        "ground.kelvin_voigt.layer_mm=200", "ground.kelvin_voigt.cohesion_kPa=1",
        "ground.kelvin_voigt.friction_angle_deg=30", "ground.kelvin_voigt.shear_modulus_K_mm=25"}) {
    kv.push_back("--set");
    kv.push_back(k);
  }
  int soil = 0;
  for (const auto& e : all["effects"]) {
    if (!e["option"].get<bool>() || !soil_option(e)) continue;
    ++soil;
    const bool viscous = e["name"] == "soil_viscosity";
    for (const auto& s : option_sets(e)) {
      (viscous ? kv : bekker).push_back("--set");
      (viscous ? kv : bekker).push_back(s);
    }
  }
  EXPECT_EQ(soil, 5);
  for (const auto& args : {bekker, kv}) {
    const auto r = run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(nlohmann::json::parse(r.out)["cases"][0]["converged"].get<bool>()) << r.out;
  }
}

// The options' switches and keys at their defaults, all of the tyre's at once on the 3D default
// (the soil effects' keys need a soil: above).
TEST_F(EffectsCli, EveryOptionSwitchIsAcceptedByTheThreeDConfigAtItsDefaults) {
  std::vector<std::string> args{"footprint",
                                std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml",
                                "--load",
                                "4000",
                                "--json",
                                "--set",
                                "contact.unit_length_mm=2"};
  const nlohmann::json all = catalogue();
  for (const auto& e : all["effects"]) {
    if (!e["option"].get<bool>() || soil_option(e)) continue;
    for (const auto& s : option_sets(e)) {
      args.push_back("--set");
      args.push_back(s);
    }
  }
  const auto r = run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(r.out)["cases"][0]["converged"].get<bool>());
}

TEST_F(EffectsCli, OutOfRangeValueExitsTwoNamingTheKey) {
  const nlohmann::json all = catalogue();  // not a temporary: the loop keeps references into it
  for (const auto& e : all["effects"]) {
    if (e["option"].get<bool>()) continue;  // the option's reader bounds its keys
    const auto& p = e["parameters"][0];
    const std::string key = p["key"];
    const double above = p["max"].get<double>() * 2 + 1;
    const auto r = footprint_with(
        {e["enabled_key"].get<std::string>() + "=true", key + "=" + nlohmann::json(above).dump()});
    EXPECT_EQ(r.exit_code, 2) << key << ": " << r.err;
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << key;
  }
}

}  // namespace

namespace {

class EffectsWith3dPatchCli : public modaltyre_test::CliFixture {};

// Each effect states what it acts on and whether the 3D patch takes it; the refused ones are
// refused by the config reader with exit 2, naming the key and the reason.
TEST_F(EffectsWith3dPatchCli, CatalogueStatesWhichEffectsComposeAndRefusedOnesExitTwo) {
  const auto r = run({"effects", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::set<std::string> refused;
  const auto catalogue = nlohmann::json::parse(r.out);
  for (const auto& e : catalogue["effects"]) {
    EXPECT_FALSE(e["acts_on"].get<std::string>().empty()) << e["name"];
    const auto& w = e["with_footprint_3d"];
    if (!w["composes"].get<bool>()) {
      refused.insert(e["name"].get<std::string>());
      EXPECT_FALSE(w["refused_because"].get<std::string>().empty());
    }
  }
  // rolling_speed and tread_coupling act on the 3D patch too (patch3d.h); contact_width is
  // superseded by its crown.
  EXPECT_EQ(refused, (std::set<std::string>{"contact_width"}));
  for (const auto& name : refused) {
    const auto f = run({"footprint", kConfig3d, "--load", "4000", "--set",
                        "contact.unit_length_mm=2", "--set", "effects." + name + ".enabled=true"});
    EXPECT_EQ(f.exit_code, 2) << name;
    EXPECT_NE(f.err.find("effects." + name + ".enabled"), std::string::npos) << f.err;
    EXPECT_NE(f.err.find("footprint_3d"), std::string::npos) << f.err;
    EXPECT_TRUE(f.out.empty());
  }
  const auto table = run({"effects"});
  EXPECT_NE(table.out.find("refused, superseded: the 3D patch computes the width"),
            std::string::npos);
}

}  // namespace
