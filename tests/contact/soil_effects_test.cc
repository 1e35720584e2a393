// The soil effects of the catalogue (effects.h, soil_effects.cc): the ground keys of the
// terramechanics work as switchable effects. Off in every bundled soil and bit for bit today's
// traction when off (also where a soil file states their values with enabled: false); switched
// on, each moves the traction outputs it lists and no other; refused where the config's ground
// has no soil of the right model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::contact {
namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kSrc;
const std::vector<EffectId> kSoilFx = {EffectId::slip_sinkage, EffectId::wong_reece_stress,
                                       EffectId::bulldozing, EffectId::soil_unloading};

// The 2D SF-350 at 2 mm units on a soil file with `--set ground...` overrides.
TyreConfig soilfx_config(const std::string& soil, const std::vector<std::string>& sets = {}) {
  TyreConfig c = load_tyre_config(kConfig2d, {"contact.unit_length_mm=2"});
  c.ground = ground::load_ground_file(kSrc + "/configs/soils/" + soil, sets);
  return c;
}

struct SoilFxCurve {
  std::vector<double> soil_sinkage_mm, drawbar_pull_N, torque_Nm;
};

// Free rolling and 30 % slip at 3 kN (the rigid wheel of the tyre's radius with `rigid`), at the
// travel speed V.
SoilFxCurve soilfx_traction(const TyreConfig& c, bool rigid = false, double V_m_s = 0) {
  const TyreModel m = build_tyre_model(c);
  TractionOptions o;
  o.rigid = rigid;
  o.speed_m_per_s = V_m_s;
  SoilFxCurve out;
  for (const TractionResult& r : steady_traction(m, c.ground, {{3000, 0.0}, {3000, 0.3}}, o)) {
    EXPECT_TRUE(r.ok()) << r.message;
    out.soil_sinkage_mm.push_back(r.soil_sinkage_m * 1e3);
    out.drawbar_pull_N.push_back(r.drawbar_pull_N);
    out.torque_Nm.push_back(r.torque_Nm);
  }
  return out;
}

const std::vector<double>& soilfx_output(const SoilFxCurve& c, const std::string& name) {
  if (name == "soil_sinkage_mm") return c.soil_sinkage_mm;
  if (name == "drawbar_pull_N") return c.drawbar_pull_N;
  if (name == "torque_Nm") return c.torque_Nm;
  throw std::invalid_argument("not a traction output: " + name);
}

TyreConfig soilfx_switched(TyreConfig c, EffectId id) {
  enable_effect(c, id);
  return c;
}

TEST(SoilEffects, AreOptionsOfGroundOffInEveryBundledSoilAndRefusedOnARoad) {
  for (EffectId id : kSoilFx) {
    const EffectInfo& e = effect_info(id);
    EXPECT_TRUE(e.is_option()) << e.name;
    EXPECT_FALSE(e.option->needs_3d) << e.name;
    for (const auto& p : e.parameters) EXPECT_EQ(p.option.key.rfind("ground.bekker.", 0), 0u);
  }
  EXPECT_EQ(effect_info(EffectId::slip_sinkage).regime, ConditionId::slip);
  EXPECT_EQ(effect_info(EffectId::wong_reece_stress).regime, ConditionId::slip);
  EXPECT_EQ(effect_info(EffectId::bulldozing).regime, ConditionId::load_N);
  EXPECT_EQ(effect_info(EffectId::soil_unloading).regime, ConditionId::load_N);
  for (const auto& f : std::filesystem::directory_iterator(kSrc + "/configs/soils")) {
    TyreConfig c = load_tyre_config(kConfig2d);
    c.ground = ground::load_ground_file(f.path().string());
    for (EffectId id : kSoilFx)
      EXPECT_FALSE(effect_enabled(c, id)) << f.path() << " " << effect_info(id).name;
  }
  // The default tyre on its rigid road: every soil effect refused, naming the road.
  const TyreConfig road = load_tyre_config(kSrc + "/configs/sf350.yaml");
  for (EffectId id : kSoilFx) {
    EXPECT_NE(effect_refusal(road, id).find("rigid road"), std::string::npos)
        << effect_refusal(road, id);
    EXPECT_FALSE(effect_enabled(soilfx_switched(road, id), id)) << effect_info(id).name;
  }
  // A Kelvin-Voigt soil is not a Bekker soil.
  TyreConfig kv =
      load_tyre_config(kConfig2d, {"ground.model=kelvin_voigt", "ground.kelvin_voigt.E2_MPa=2",
                                   "ground.kelvin_voigt.layer_mm=200"});
  EXPECT_NE(effect_refusal(kv, EffectId::slip_sinkage).find("kelvin_voigt soil"),
            std::string::npos);
  // Wong and Reece's distribution is a candidate of the rigid wheel and of the flexible tyre
  // (docs/soil.md sections 3.1 and 10).
  TyreConfig sand = soilfx_config("lete_sand.yaml");
  EXPECT_EQ(effect_refusal(sand, EffectId::slip_sinkage), "");
  EXPECT_EQ(effect_refusal(sand, EffectId::wong_reece_stress), "");
  sand.rigid = true;
  EXPECT_EQ(effect_refusal(sand, EffectId::wong_reece_stress), "");
}

// Off: the soil's law as before. A file stating the effects' values with enabled: false runs
// bit for bit as the file without them, and switching on takes the stated values.
TEST(SoilEffects, StatedButDisabledKeysAreTodaysTractionBitForBit) {
  const TyreConfig plain = soilfx_config("lete_sand.yaml", {});
  const std::vector<std::string> stated = {"ground.bekker.slip_sinkage.k1=2",
                                           "ground.bekker.bulldozing.enabled=false",
                                           "ground.bekker.bulldozing.unit_weight_kN_m3=18",
                                           "ground.bekker.unloading.enabled=false",
                                           "ground.bekker.unloading.k0=1000",
                                           "ground.bekker.unloading.Au=4e5",
                                           "ground.bekker.wong_reece.enabled=false",
                                           "ground.bekker.wong_reece.c1=0.18"};
  const TyreConfig off = soilfx_config("lete_sand.yaml", stated);
  for (EffectId id : kSoilFx) EXPECT_FALSE(effect_enabled(off, id)) << effect_info(id).name;
  const SoilFxCurve a = soilfx_traction(plain), b = soilfx_traction(off);
  EXPECT_EQ(a.soil_sinkage_mm, b.soil_sinkage_mm);
  EXPECT_EQ(a.drawbar_pull_N, b.drawbar_pull_N);
  EXPECT_EQ(a.torque_Nm, b.torque_Nm);
  EXPECT_EQ(soilfx_switched(off, EffectId::slip_sinkage).ground.slip_sinkage.k1, 2);
  EXPECT_EQ(soilfx_switched(off, EffectId::bulldozing).ground.bulldozing.unit_weight_kN_m3, 18);
  EXPECT_EQ(soilfx_switched(off, EffectId::wong_reece_stress).ground.wong_reece.c1, 0.18);
  const TyreConfig unloading = soilfx_switched(off, EffectId::soil_unloading);
  ASSERT_TRUE(unloading.ground.bekker.unloading.has_value());
  EXPECT_EQ(unloading.ground.bekker.unloading->k0_kN_m3, 1000);
  EXPECT_EQ(unloading.ground.bekker.unloading->Au_kN_m4, 4e5);
  // Without a stated block: the catalogue's values (k0 = 0, Au its default).
  const TyreConfig fresh = soilfx_switched(plain, EffectId::soil_unloading);
  EXPECT_EQ(fresh.ground.bekker.unloading->k0_kN_m3, 0);
  EXPECT_EQ(fresh.ground.bekker.unloading->Au_kN_m4,
            effect_info(EffectId::soil_unloading).parameters.front().default_value);
  // The overrides write the switched soil as --set would: the same config again.
  for (EffectId id : kSoilFx) {
    TyreConfig on = soilfx_switched(off, id);
    const TyreConfig again = soilfx_config("lete_sand.yaml", [&] {
      std::vector<std::string> s = stated;
      for (const auto& o : effect_switch_overrides(on, id)) s.push_back(o);
      return s;
    }());
    EXPECT_TRUE(effect_enabled(again, id)) << effect_info(id).name;
    for (const auto& p : effect_info(id).parameters)
      EXPECT_EQ(p.option.get(again), p.option.get(on)) << p.option.key;
  }
}

// The check: each on with the catalogue's parameters moves the outputs it lists, and only
// those. The slip effects leave free rolling exactly as it was and move the 30 % slip case.
TEST(SoilEffects, EachMovesTheTractionOutputsItListsAndNoOther) {
  for (EffectId id : kSoilFx) {
    const EffectInfo& e = effect_info(id);
    SCOPED_TRACE(e.name);
    TyreConfig base = soilfx_config("lete_sand.yaml");
    const bool rigid = id == EffectId::wong_reece_stress;
    base.rigid = rigid;
    const TyreConfig on = soilfx_switched(base, id);
    ASSERT_TRUE(effect_enabled(on, id));
    const SoilFxCurve before = soilfx_traction(base, rigid), after = soilfx_traction(on, rigid);
    for (const char* name : {"soil_sinkage_mm", "drawbar_pull_N", "torque_Nm"}) {
      const bool listed =
          std::find(e.observables.begin(), e.observables.end(), name) != e.observables.end();
      const auto& b = soilfx_output(before, name);
      const auto& a = soilfx_output(after, name);
      for (std::size_t k = 0; k < a.size(); ++k) {
        const double change = std::abs(a[k] - b[k]) / std::max(std::abs(b[k]), 1.0);
        const bool at_free_rolling = k == 0;
        if (e.regime == ConditionId::slip && at_free_rolling && id == EffectId::slip_sinkage) {
          EXPECT_EQ(a[k], b[k]) << name << ": f(0) = 1";
        } else if (listed && !at_free_rolling) {
          EXPECT_GT(change, 2e-3) << name << " at slip 0.3";
        } else if (!listed) {
          EXPECT_EQ(a[k], b[k]) << name;
        }
      }
    }
  }
  // The directions the laws say: slip sinkage deepens the 30 % slip case, bulldozing lowers the
  // pull, the rebounding soil carries the rear and resists less.
  const TyreConfig sand = soilfx_config("lete_sand.yaml");
  const SoilFxCurve base = soilfx_traction(sand);
  EXPECT_GT(soilfx_traction(soilfx_switched(sand, EffectId::slip_sinkage)).soil_sinkage_mm[1],
            1.1 * base.soil_sinkage_mm[1]);
  EXPECT_LT(soilfx_traction(soilfx_switched(sand, EffectId::bulldozing)).drawbar_pull_N[1],
            base.drawbar_pull_N[1]);
  EXPECT_GT(soilfx_traction(soilfx_switched(sand, EffectId::soil_unloading)).drawbar_pull_N[0],
            base.drawbar_pull_N[0]);
}

// soil_viscosity: the Kelvin-Voigt soil's rate term under the rolling rigid wheel (docs/soil.md
// 3.2) and the flexible tyre (9.1). Off (eta2 = 0) and standing (V = 0) are the elastic law bit
// for bit; on at 5 km/h it moves every output it lists; refused on a Bekker soil.
// The 2D SF-350 (or the default 3D config, 10 mm columns) at 2 mm units on section 3.2's soil.
TyreConfig soilfx_kelvin_voigt(const std::string& config = kConfig2d) {
  std::vector<std::string> sets = {"contact.unit_length_mm=2",
                                   "ground.model=kelvin_voigt",
                                   "ground.kelvin_voigt.E2_MPa=2",
                                   "ground.kelvin_voigt.layer_mm=200",
                                   "ground.kelvin_voigt.elastic_share=0.7",
                                   "ground.kelvin_voigt.cohesion_kPa=1",
                                   "ground.kelvin_voigt.friction_angle_deg=30",
                                   "ground.kelvin_voigt.shear_modulus_K_mm=25"};
  // (on the 2D config a footprint_3d key would make it a 3D one)
  if (config != kConfig2d) sets.push_back("footprint_3d.lateral_cell_mm=10");
  return load_tyre_config(config, sets);
}

void soilfx_viscosity_moves_its_outputs(const TyreConfig& kv, bool rigid) {
  const EffectInfo& e = effect_info(EffectId::soil_viscosity);
  EXPECT_EQ(effect_refusal(kv, EffectId::soil_viscosity), "");
  const TyreConfig on = soilfx_switched(kv, EffectId::soil_viscosity);
  ASSERT_TRUE(effect_enabled(on, EffectId::soil_viscosity));
  EXPECT_EQ(on.ground.kelvin_voigt.eta2_kPa_s, e.parameters.front().default_value);
  const double V = 5 / 3.6;
  const SoilFxCurve elastic = soilfx_traction(kv, rigid, V);
  const SoilFxCurve standing = soilfx_traction(on, rigid, 0);
  const SoilFxCurve rolling = soilfx_traction(on, rigid, V);
  for (const char* name : {"soil_sinkage_mm", "drawbar_pull_N", "torque_Nm"}) {
    ASSERT_NE(std::find(e.observables.begin(), e.observables.end(), name), e.observables.end());
    EXPECT_EQ(soilfx_output(standing, name), soilfx_output(elastic, name)) << name;
    for (std::size_t k = 0; k < 2; ++k) {
      const double b = soilfx_output(elastic, name)[k], a = soilfx_output(rolling, name)[k];
      EXPECT_GT(std::abs(a - b), 2e-3 * std::max(std::abs(b), 1.0)) << name << " " << k;
    }
  }
  // The soil stiffens with speed and resists more.
  EXPECT_LT(rolling.soil_sinkage_mm[1], elastic.soil_sinkage_mm[1]);
  EXPECT_LT(rolling.drawbar_pull_N[1], elastic.drawbar_pull_N[1]);
}

TEST(SoilEffects, SoilViscosityIsRefusedOffAKelvinVoigtSoil) {
  const EffectInfo& e = effect_info(EffectId::soil_viscosity);
  EXPECT_EQ(e.regime, ConditionId::speed_kmh);
  EXPECT_FALSE(effect_enabled(soilfx_kelvin_voigt(), EffectId::soil_viscosity));
  EXPECT_NE(
      effect_refusal(soilfx_config("lete_sand.yaml"), EffectId::soil_viscosity).find("bekker soil"),
      std::string::npos);
}

TEST(SoilEffects, SoilViscosityActsThroughTheSpeedOnTheRigidWheel) {
  TyreConfig kv = soilfx_kelvin_voigt();
  kv.rigid = true;
  soilfx_viscosity_moves_its_outputs(kv, true);
}

TEST(SoilEffects, SoilViscosityActsThroughTheSpeedOnTheFlexibleTyre) {
  const TyreConfig two_d = soilfx_kelvin_voigt();
  ASSERT_FALSE(two_d.footprint_3d.has_value());
  soilfx_viscosity_moves_its_outputs(two_d, false);
  const TyreConfig three_d = soilfx_kelvin_voigt(kSrc + "/configs/sf350.yaml");
  ASSERT_TRUE(three_d.footprint_3d.has_value());  // the default tyre's 3D patch
  soilfx_viscosity_moves_its_outputs(three_d, false);
}

}  // namespace
}  // namespace modaltyre::contact
