// The identify -> tyre-config link as a library (studies/identified_config.h), without the CLI:
// planted rheology data are identified with modaltyre::rheology, mapped into the SF-350 config,
// and the composed config is run by the footprint model (contact::predict) in-process.
// The command-line round trips of the same mapping are in tests/rheology/identify_config_test.cc.
#include "modaltyre/studies/identified_config.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../rheology/rheology_test_support.h"
#include "../support/data_paths.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/rheology/contact_geometry.h"

namespace modaltyre::studies {
namespace {

namespace rh = modaltyre::rheology;
namespace fs = std::filesystem;

using modaltyre_test::kSrc;

// SF-350 as configs/sf350_2d_table3.yaml, on a 2 mm patch mesh (the mapping does not depend on the
// mesh; the footprints it runs are 16x cheaper), in a scratch folder with the hammer file absolute.
class studies_IdentifiedConfig : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("modaltyre_identified_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
    std::ifstream in(kSrc + "/configs/sf350_2d_table3.yaml");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    replace(text, "hammer_csv: data/", "hammer_csv: " + kSrc + "/configs/data/");
    replace(text, "unit_length_mm: 0.5", "unit_length_mm: 2");
    tyre_path_ = (dir_ / "tyre.yaml").string();
    std::ofstream(tyre_path_) << text;
  }
  void TearDown() override { fs::remove_all(dir_); }

  static void replace(std::string& text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }

  // OUT in its own folder, so that modal.hammer_csv must be re-anchored.
  ConfigTarget target() const {
    return {tyre_path_,
            (dir_ / "out" / "identified.yaml").string(),
            contact::load_tyre_config(tyre_path_),
            {}};
  }

  // Sinking of the composed config at a load and the tyre's own pressure.
  static double sinking_mm(const contact::TyreConfig& c, double load_N) {
    const contact::TyreModel model = contact::build_tyre_model(c);
    contact::OperatingConditions at = c.default_conditions(load_N);
    at.pressure_kPa = c.inflation_pressure_Pa * 1e-3;
    const contact::Prediction p = contact::predict(model, contact::parameters_of(c), at);
    EXPECT_TRUE(p.ok()) << p.message;
    return p.sinking_mm;
  }

  static double value_of(const ConfigMapping& m, const std::string& key) {
    for (const auto& [k, v] : m.values)
      if (k == key) return v;
    ADD_FAILURE() << "no value for " << key;
    return std::nan("");
  }

  static bool noted(const ConfigMapping& m, const std::string& text) {
    for (const auto& n : m.notes)
      if (n.find(text) != std::string::npos) return true;
    return false;
  }

  fs::path dir_;
  std::string tyre_path_;
};

// The mapped force is eq. (14)'s Saint-Venant term: half the gap between the loading and the
// unloading branch of the static loop at any deflection, and chi E1 B_tr L_C for a short contact.
TEST(studies_DryFrictionForce, IsHalfTheStaticLoopGapOfEq14AndChiE1BLcForShortContacts) {
  const auto o = rh::test::sf350_three_element_options();
  const double E1 = 1.2e6, chi = 0.02;
  for (double h : {0.002, 0.01, 0.02, 0.04}) {
    const double gap =
        rh::static_loop_load(E1, chi, h, true, o) - rh::static_loop_load(E1, chi, h, false, o);
    const double phi1 = rh::half_contact_angle(h, o.r0_m);
    EXPECT_NEAR(dry_friction_force_N(chi, E1, o.tread_width_m, o.r0_m, phi1) / (gap / 2), 1.0,
                1e-12)
        << h;
  }
  const double phi1 = 1e-3, lc = 2 * o.r0_m * std::sin(phi1);
  EXPECT_NEAR(dry_friction_force_N(chi, E1, o.tread_width_m, o.r0_m, phi1) /
                  (chi * E1 * o.tread_width_m * lc),
              1.0, 1e-6);  // relative difference O(phi1^2)
}

// Planted loop (E1 = 1.2 MPa, chi = 0.02) and a free decay about h0 = 20 mm: the mapped force
// is F_f at the decay's contact length; only dry_friction is switched on.
TEST_F(studies_IdentifiedConfig, ThreeElementRoundTripMapsTheDryFrictionForce) {
  const auto o = rh::test::sf350_three_element_options();
  const double E1 = 1.2e6, chi = 0.02, h0 = 0.020;
  rh::StaticLoop loop;
  for (bool loading : {true, false})
    for (int i = 1; i <= 8; ++i)
      loop.rows.push_back(
          {rh::static_loop_load(E1, chi, 0.004 * i, loading, o), 0.004 * i, loading, 0});
  rh::DecaySignal decay;
  const double f = 8.0, zeta = 0.05, a0 = 0.005;
  const double wd = 2 * M_PI * f, wn = wd / std::sqrt(1 - zeta * zeta);
  for (int i = 0; i <= 1500; ++i) {
    const double t = 1e-3 * i;
    decay.t_s.push_back(t);
    decay.deflection_m.push_back(h0 + a0 * std::exp(-zeta * wn * t) * std::cos(wd * t));
    decay.line.push_back(i + 2);
  }
  const auto res = rh::identify_free_vibration(decay, &loop, o);
  ConfigTarget t = target();
  map_three_element(res, loop, o, t);
  const double phi1 = rh::half_contact_angle(h0, o.r0_m);
  const double planted = 2 * o.tread_width_m * chi * E1 * o.r0_m * phi1 * std::cos(phi1);
  EXPECT_NEAR(value_of(t.mapping, "effects.dry_friction.friction_force_N") / planted, 1.0, 1e-4);
  EXPECT_EQ(t.mapping.enabled, std::vector<std::string>{"dry_friction"});
  EXPECT_TRUE(noted(t.mapping, "identified chi = "));
  // Without the static loop's fit there is nothing to map: a caller's bug, not an input error.
  rh::FreeVibrationResult decay_only = res;
  decay_only.static_fit.reset();
  EXPECT_THROW(map_three_element(decay_only, loop, o, t), ComputationError);
}

TEST_F(studies_IdentifiedConfig, SoilRoundTripMapsModulusAndLayerDepth) {
  const rh::SoilData data = rh::test::planted_soil_rows();
  ConfigTarget t = target();
  map_soil(data, rh::identify_soil(data, rh::test::planted_soil_wheel()), t);
  EXPECT_NEAR(value_of(t.mapping, "effects.soil_compliance.modulus_MPa") / 3.0, 1.0, 1e-5);
  EXPECT_NEAR(value_of(t.mapping, "effects.soil_compliance.layer_mm"), 300.0, 1e-9);
  EXPECT_EQ(t.mapping.enabled, std::vector<std::string>{"soil_compliance"});
}

// A value the tyre config would refuse is refused at the mapping, naming the key and the config.
TEST_F(studies_IdentifiedConfig, IdentifiedValueOutsideTheKeysRangeIsAnInputErrorNamingIt) {
  rh::SoilData data;
  data.rows.push_back({});
  data.rows.back().layer_m = 0.3;
  rh::SoilResult res;
  res.E2_Pa = 5e9;  // 5000 MPa: above the range of effects.soil_compliance.modulus_MPa
  ConfigTarget t = target();
  try {
    map_soil(data, res, t);
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("effects.soil_compliance.modulus_MPa"), std::string::npos) << what;
    EXPECT_NE(what.find(tyre_path_), std::string::npos) << what;
  }
}

rh::LoadDeflectionData eq3_rows(double K_Z_m, const std::vector<double>& pressures_kPa) {
  rh::LoadDeflectionData d;
  for (double p : pressures_kPa)
    for (double P : {2000.0, 3000.0, 4000.0, 5000.0, 6000.0})
      d.rows.push_back({P, p * 1e3, rh::law_deflection(K_Z_m, P, p * 1e3), 0});
  return d;
}

// Eq. (3) over loads and pressures switches both laws on; the carcass level makes the composed
// config sink eq. (3)'s h_Z at the mean test load, and a stiffer tested tyre a stiffer carcass.
TEST_F(studies_IdentifiedConfig, LoadDeflectionMapsBothLawsAndTheCarcassLevelToEq3) {
  std::vector<double> scales;
  for (double K_Z_m : {0.13e-3, 0.10e-3}) {
    const auto data = eq3_rows(K_Z_m, {150, 230, 300});
    rh::LoadDeflectionOptions o;
    o.r0_m = 0.2948;
    const auto res = rh::identify_load_deflection(data, o);
    ConfigTarget t = target();
    const IdentifiedSource source{"load-deflection", "ld.csv"};
    map_load_deflection(source, data, res, t);
    EXPECT_EQ(value_of(t.mapping, "effects.load_stiffening.exponent"), 0.25);
    EXPECT_NEAR(value_of(t.mapping, "effects.load_stiffening.reference_load_N"), 4000, 1e-9);
    EXPECT_EQ(value_of(t.mapping, "effects.inflation_pressure.exponent"), 1.0);
    EXPECT_EQ(value_of(t.mapping, "effects.inflation_pressure.modal_test_pressure_kPa"), 230.0);
    EXPECT_TRUE(noted(t.mapping, "calibrated on all 15 rows of ld.csv"));
    const IdentifiedConfig out = compose_identified_config(source, t);
    scales.push_back(out.config.compliance_scale);
    EXPECT_NEAR(out.config.compliance_scale / value_of(t.mapping, "modal.compliance_scale"), 1.0,
                1e-9);  // written with 10 digits
    EXPECT_NEAR(sinking_mm(out.config, 4000) / (rh::law_deflection(K_Z_m, 4000, 230e3) * 1e3), 1.0,
                1e-5);
  }
  EXPECT_LT(scales[1], scales[0]) << "a stiffer tested tyre must give a stiffer carcass";
}

TEST_F(studies_IdentifiedConfig, LoadDeflectionAtOnePressureLeavesThePressureLawAlone) {
  const auto data = eq3_rows(0.13e-3, {230});
  rh::LoadDeflectionOptions o;
  o.r0_m = 0.2948;
  ConfigTarget t = target();
  map_load_deflection({"load-deflection", "ld.csv"}, data, rh::identify_load_deflection(data, o),
                      t);
  EXPECT_EQ(t.mapping.enabled, std::vector<std::string>{"load_stiffening"});
  EXPECT_TRUE(noted(t.mapping, "one pressure only"));
}

// A contact-stress profile is one operating point: the composed config sinks its h_Z under the
// load P_Z eq. (8) integrates from it.
TEST_F(studies_IdentifiedConfig, ContactStressCarcassLevelSinksTheProfilesDeflection) {
  const double r0_m = 0.2948, h_m = 0.018, K1 = 3.0e7;
  rh::StressData data;
  const double a = std::sqrt(r0_m * r0_m - (r0_m - h_m) * (r0_m - h_m));
  for (int i = -40; i <= 40; ++i) {
    const double x = 1.25 * a * i / 40;
    data.rows.push_back({x, rh::contact_stress_law(K1, x, h_m, r0_m), 0});
  }
  rh::ContactStressOptions o;
  o.r0_m = r0_m;
  o.tread_width_m = 0.13;
  const auto res = rh::identify_contact_stress(data, o);
  ConfigTarget t = target();
  const IdentifiedSource source{"contact-stress", "cs.csv"};
  map_contact_stress(source, res, r0_m, t);
  EXPECT_TRUE(t.mapping.enabled.empty()) << "a carcass level, no effect";
  EXPECT_TRUE(noted(t.mapping, "predicted by OUT at that load"));
  const IdentifiedConfig out = compose_identified_config(source, t);
  EXPECT_NEAR(sinking_mm(out.config, res.load_N) / (h_m * 1e3), 1.0, 1e-4);
}

// No carcass level reaches a deflection below the tread's own: an input error naming the key.
TEST_F(studies_IdentifiedConfig, CarcassLevelBelowTheTreadAloneIsAnInputErrorNamingTheKey) {
  try {
    calibrate_carcass_level({"load-deflection", "ld.csv"}, target(), 4000, 0.01);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("modal.compliance_scale"), std::string::npos) << e.what();
  }
}

// OUT: the header names the method and files, the mapped keys are set, the rest is TYRE's, and
// modal.hammer_csv is re-anchored to OUT's folder (read back as OUT, it is TYRE's file).
TEST_F(studies_IdentifiedConfig, ComposedConfigSetsTheMappingAndReanchorsTheHammerFile) {
  ConfigTarget t = target();
  t.mapping.enabled = {"dry_friction"};
  t.mapping.values = {{"effects.dry_friction.friction_force_N", 123.5}};
  t.mapping.notes = {"a note"};
  const IdentifiedConfig out = compose_identified_config({"free-vibration", "decay.csv"}, t);
  EXPECT_EQ(out.text.rfind("# Written by modaltyre identify free-vibration from " + tyre_path_ +
                               " and decay.csv",
                           0),
            0u)
      << out.text;
  EXPECT_NE(out.text.find("\n# a note\n"), std::string::npos);
  EXPECT_TRUE(out.config.effects.dry_friction.enabled);
  EXPECT_EQ(out.config.effects.dry_friction.friction_force_N, 123.5);
  EXPECT_EQ(out.config.tread.modulus_Pa, t.tyre.tread.modulus_Pa);
  EXPECT_TRUE(fs::equivalent(out.config.hammer_csv, t.tyre.hammer_csv));
  const std::string written =
      ConfigTree::from_string(out.text, t.out_path).root().section("modal").text("hammer_csv", "");
  EXPECT_TRUE(fs::path(written).is_relative()) << written;
}

// Issue 16 item 8: OUT keeps TYRE's comments; a key the mapping sets leaves
// validation.calibrate (validate would overwrite it), with calibration_rows when none is left.
TEST_F(studies_IdentifiedConfig, ComposedConfigKeepsCommentsAndDropsRecalibratedKeys) {
  ConfigTarget t = target();
  t.mapping.values = {{"modal.compliance_scale", 1.25}};
  const IdentifiedConfig out = compose_identified_config({"load-deflection", "ld.csv"}, t);
  EXPECT_NE(out.text.find("\n  # Nominal from the size designation"), std::string::npos);
  EXPECT_NE(out.text.find("\n  compliance_scale: 1.25  # set by modaltyre identify\n"),
            std::string::npos)
      << out.text;
  EXPECT_EQ(out.config.compliance_scale, 1.25);
  EXPECT_EQ(out.config.validation.calibrate, std::vector<std::string>{"tread.modulus_MPa"});
  EXPECT_EQ(out.config.validation.calibration_rows, (std::vector<int>{1, 6}));
  ASSERT_FALSE(out.notes.empty());
  EXPECT_NE(out.notes.back().find("modal.compliance_scale removed"), std::string::npos);
  EXPECT_NE(out.text.find("# " + out.notes.back() + "\n"), std::string::npos);

  t.mapping.values.emplace_back("tread.modulus_MPa", 2.0);
  const IdentifiedConfig both = compose_identified_config({"load-deflection", "ld.csv"}, t);
  EXPECT_TRUE(both.config.validation.calibrate.empty());
  EXPECT_TRUE(both.config.validation.calibration_rows.empty());
  EXPECT_NE(both.notes.back().find("nothing is calibrated"), std::string::npos);
}

// A key that cannot be set in TYRE's text (here inside a flow mapping): OUT is TYRE's tree
// re-emitted, the same values, and the header says that the comments are not kept.
TEST_F(studies_IdentifiedConfig, ComposedConfigSaysWhenCommentsCannotBeKept) {
  std::ofstream(tyre_path_, std::ios::app) << "effects: {dry_friction: {enabled: false}}\n";
  ConfigTarget t = target();
  t.mapping.enabled = {"dry_friction"};
  t.mapping.values = {{"effects.dry_friction.friction_force_N", 300}};
  const IdentifiedConfig out = compose_identified_config({"free-vibration", "decay.csv"}, t);
  EXPECT_NE(out.text.find("its comments are not kept"), std::string::npos) << out.text;
  EXPECT_EQ(out.text.find("# Nominal from the size designation"), std::string::npos);
  EXPECT_TRUE(out.config.effects.dry_friction.enabled);
  EXPECT_EQ(out.config.effects.dry_friction.friction_force_N, 300);
  EXPECT_EQ(out.config.tread.modulus_Pa, t.tyre.tread.modulus_Pa);
}

TEST(studies_UnmappedReason, OnlyBFactorsAndAFreeDecayWithoutItsStaticLoopHaveNoPlace) {
  EXPECT_NE(unmapped_reason("b-factors", false).find("uses nothing"), std::string::npos);
  EXPECT_NE(unmapped_reason("free-vibration", false).find("static loop"), std::string::npos);
  for (const char* m : {"load-deflection", "contact-stress", "soil-rolling"})
    EXPECT_EQ(unmapped_reason(m, false), "") << m;
  EXPECT_EQ(unmapped_reason("free-vibration", true), "");
}

}  // namespace
}  // namespace modaltyre::studies
