// The flexible tyre on a soil (contact/ground_patch.h, contact/traction.h, docs/soil.md sections
// 4-5): the rigid-road and rigid-wheel limits, the soil_compliance identity, and steady rolling.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "../support/lete_sand.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/ground/rigid_wheel.h"

namespace {

using namespace modaltyre::contact;
namespace gr = modaltyre::ground;

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;
using modaltyre_test::kLeteBekkerShear;
using modaltyre_test::plus;
// A tyre a thousand times stiffer than the SF-350 (carcass and tread): its contour is the
// undeformed circle to ~0.1 % of the soil's sinkage.
const std::vector<std::string> kStiffTyre = {"modal.compliance_scale=0.001",
                                             "tread.modulus_MPa=10000"};

TyreModel model_with(std::vector<std::string> overrides, double unit_mm) {
  overrides.push_back("contact.unit_length_mm=" + std::to_string(unit_mm));
  return build_tyre_model(load_tyre_config(kConfig2d, overrides));
}

Prediction footprint(const TyreModel& m, double load_N) {
  Prediction p = predict(m, m.config.default_conditions(load_N));
  EXPECT_TRUE(p.ok()) << p.message;
  return p;
}

// Done-when: a very stiff soil reproduces the rigid-road footprint within 0.5 %. k = 1e9 kN/m^2
// (n = 1) sinks 0.5 um under 500 kPa, 2e-5 of the tyre's deflection.
TEST(TyreOnSoil, AVeryStiffSoilReproducesTheRigidRoadFootprint) {
  constexpr double kStiffSoilLimit = 0.005;  // the bound; the soil's share is ~2e-5
  const TyreModel road = model_with({}, 1);
  const TyreModel soil = model_with({"ground.model=bekker", "ground.bekker.n=1",
                                     "ground.bekker.k_c=0", "ground.bekker.k_phi=1e9"},
                                    1);
  for (double load : {2131.0, 8321.0}) {
    const Prediction a = footprint(road, load), b = footprint(soil, load);
    EXPECT_NEAR(b.sinking_mm, a.sinking_mm, kStiffSoilLimit * a.sinking_mm) << load;
    EXPECT_NEAR(b.length_mm, a.length_mm, kStiffSoilLimit * a.length_mm) << load;
    EXPECT_TRUE(b.on_soil);
    EXPECT_LT(b.soil_sinkage_mm, 1e-3 * a.sinking_mm);
    EXPECT_NEAR(b.tyre_deflection_mm + b.soil_sinkage_mm, b.sinking_mm, 1e-9);
  }
}

// The Kelvin-Voigt ground with k_E = 1 is the soil_compliance effect's Winkler layer (z = p H /
// E2): the same linear problem, reached by the soil's linearisation in two steps.
TEST(TyreOnSoil, AnElasticKelvinVoigtGroundIsTheSoilComplianceEffect) {
  constexpr double kSameProblem = 1e-6;  // the nonlinear solver's force tolerance 1e-9 F
  const TyreModel kv = model_with({"ground.model=kelvin_voigt", "ground.kelvin_voigt.E2_MPa=2",
                                   "ground.kelvin_voigt.layer_mm=200"},
                                  2);
  const TyreModel effect =
      model_with({"effects.soil_compliance.enabled=true", "effects.soil_compliance.modulus_MPa=2",
                  "effects.soil_compliance.layer_mm=200"},
                 2);
  OperatingConditions c = effect.config.default_conditions(4000);
  c.surface = Surface::soil;
  const Prediction a = predict(effect, c);
  const Prediction b = footprint(kv, 4000);
  ASSERT_TRUE(a.ok()) << a.message;
  EXPECT_NEAR(b.sinking_mm, a.sinking_mm, kSameProblem * a.sinking_mm);
  EXPECT_NEAR(b.length_mm, a.length_mm, kSameProblem * a.length_mm);
  // The soil carries the unit's pressure: z = p H / E2 at the deepest unit.
  double pmax = 0;
  for (const auto& u : b.footprint.units) pmax = std::max(pmax, u.pressure_Pa);
  EXPECT_NEAR(b.soil_sinkage_mm, pmax * 0.2 / 2e6 * 1e3, 1e-6 * b.soil_sinkage_mm);
}

// A tyre a thousand times stiffer is the rigid wheel: the static sinkage of the 2D patch on LETE
// sand against the rigid-wheel integral (ground/rigid_wheel.h) of the same radius and width.
TEST(TyreOnSoil, AStiffTyreSinksAsTheRigidWheel) {
  constexpr double kDiscretisation = 0.01;  // 1 mm units on a ~180 mm contact, tyre 0.1 %
  const TyreModel m = model_with(plus(kLeteBekkerShear, kStiffTyre), 1);
  const gr::RigidWheel wheel{m.config.outer_radius_m, m.config.tread.width_m};
  for (double load : {2000.0, 5000.0}) {
    const Prediction p = footprint(m, load);
    const gr::RigidWheelResult r = gr::rigid_wheel_static(m.config.ground, wheel, load);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_NEAR(p.soil_sinkage_mm, r.sinkage_m * 1e3, kDiscretisation * r.sinkage_m * 1e3);
    EXPECT_NEAR(p.length_mm, r.contact_length_m * 1e3, kDiscretisation * r.contact_length_m * 1e3);
  }
}

// Done-when: the flexible tyre sinks less than the rigid wheel and deflects.
TEST(TyreOnSoil, TheFlexibleTyreSinksLessThanTheRigidWheelAndDeflects) {
  const TyreModel m = model_with(kLeteBekkerShear, 2);
  const gr::RigidWheel wheel{m.config.outer_radius_m, m.config.tread.width_m};
  for (double load : {2000.0, 5000.0}) {
    const Prediction p = footprint(m, load);
    const gr::RigidWheelResult r = gr::rigid_wheel_static(m.config.ground, wheel, load);
    EXPECT_LT(p.soil_sinkage_mm, r.sinkage_m * 1e3) << load;
    EXPECT_GT(p.tyre_deflection_mm, 0.1 * p.soil_sinkage_mm) << load;
    EXPECT_GT(p.length_mm, r.contact_length_m * 1e3) << load;  // the tyre wraps the soil
    EXPECT_LT(p.footprint.equilibrium_residual, 1e-9);
  }
}

// Rolling on a purely elastic soil (Kelvin-Voigt, k_E = 1: the unloading branch is the loading
// one), frictionless: nothing is dissipated, so the motion resistance vanishes and the tyre sinks
// as it stands (the static footprint). What remains is second order: the normal forces'
// horizontal components on the sloped contact bend the carcass (vertical_from_horizontal) in
// rolling and not in the static solve.
TEST(TyreOnSoil, RollingOnAnElasticFrictionlessSoilDissipatesNothing) {
  constexpr double kSecondOrder = 5e-3;
  const TyreModel m =
      model_with({"ground.model=kelvin_voigt", "ground.kelvin_voigt.E2_MPa=2",
                  "ground.kelvin_voigt.layer_mm=200", "ground.kelvin_voigt.cohesion_kPa=0",
                  "ground.kelvin_voigt.friction_angle_deg=0"},
                 1);
  const Prediction p = footprint(m, 3000);
  const TractionResult r = traction_pass(m, m.config.ground, {3000, 0.1}, 0);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_LT(std::abs(r.motion_resistance_N), kSecondOrder * 3000);
  EXPECT_NEAR(r.soil_sinkage_m * 1e3, p.soil_sinkage_mm, kSecondOrder * p.soil_sinkage_mm);
  EXPECT_NEAR(r.sinking_m * 1e3, p.sinking_mm, kSecondOrder * p.sinking_mm);
  EXPECT_EQ(r.thrust_N, 0.0);
  EXPECT_NEAR(r.rut_depth_m, 0.0, 1e-12);  // the soil springs back
}

// The rolling tyre on LETE sand against the rigid wheel of its outer radius: the flexible tyre
// sinks less, resists less, and its rut is its sinkage (rigid-plastic soil).
TEST(TyreOnSoil, TheRollingTyreSinksAndResistsLessThanTheRigidWheel) {
  const TyreModel m = model_with(kLeteBekkerShear, 1);
  TractionOptions rigid;
  rigid.rigid = true;
  for (double s : {0.0, 0.2}) {
    const TractionResult f = traction_pass(m, m.config.ground, {3000, s}, 0);
    const TractionResult r = traction_pass(m, m.config.ground, {3000, s}, 0, rigid);
    ASSERT_TRUE(f.ok()) << f.message;
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_LT(f.soil_sinkage_m, r.soil_sinkage_m) << s;
    EXPECT_LT(f.motion_resistance_N, r.motion_resistance_N) << s;
    EXPECT_GT(f.tyre_deflection_m, 0) << s;
    EXPECT_NEAR(f.rut_depth_m, f.soil_sinkage_m, 1e-12) << s;
  }
}

// Done-when: drawbar pull rises monotonically with slip; a second pass adds less sinkage than the
// first; the rut is no deeper than the sinkage.
TEST(TyreOnSoil, DrawbarPullRisesWithSlipAndASecondPassSinksLess) {
  const TyreModel m = model_with(kLeteBekkerShear, 2);
  TractionOptions o;
  o.passes = 2;
  std::vector<TractionCase> cases;
  for (double s : {0.05, 0.1, 0.2, 0.3, 0.4}) cases.push_back({3000, s});
  const std::vector<TractionResult> r = steady_traction(m, m.config.ground, cases, o);
  ASSERT_EQ(r.size(), 10u);
  double last = -1e300;
  for (std::size_t k = 0; k < r.size(); k += 2) {
    const TractionResult &first = r[k], &second = r[k + 1];
    ASSERT_TRUE(first.ok()) << first.message;
    ASSERT_TRUE(second.ok()) << second.message;
    EXPECT_GT(first.drawbar_pull_N, last) << first.slip;
    last = first.drawbar_pull_N;
    EXPECT_LE(first.rut_depth_m, first.soil_sinkage_m + 1e-12);
    EXPECT_LE(second.rut_depth_m, second.soil_sinkage_m + 1e-12);
    EXPECT_LT(second.soil_sinkage_m - first.soil_sinkage_m, first.soil_sinkage_m) << first.slip;
    EXPECT_GE(second.soil_sinkage_m, first.soil_sinkage_m) << first.slip;
    EXPECT_GT(first.torque_Nm, 0);
  }
}

}  // namespace

namespace {

using namespace modaltyre::contact;
namespace gr = modaltyre::ground;

// The 3D patch (the default config) on soil: a very stiff soil is the rigid road (the issue's
// 0.5 %), and on LETE sand the tyre deflects and sinks less than the rigid wheel of its radius
// and tread width.
TEST(TyreOnSoil3D, AVeryStiffSoilReproducesTheRigidRoadFootprint) {
  constexpr double kStiffSoilLimit = 0.005;
  const TyreConfig road_config = load_tyre_config(kConfig3d);
  const TyreConfig soil_config =
      load_tyre_config(kConfig3d, {"ground.model=bekker", "ground.bekker.n=1",
                                   "ground.bekker.k_c=0", "ground.bekker.k_phi=1e9"});
  const TyreModel road = build_tyre_model(road_config), soil = build_tyre_model(soil_config);
  const Prediction a = predict(road, road_config.default_conditions(4000));
  const Prediction b = predict(soil, soil_config.default_conditions(4000));
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_TRUE(b.ok()) << b.message;
  EXPECT_NEAR(b.sinking_mm, a.sinking_mm, kStiffSoilLimit * a.sinking_mm);
  EXPECT_NEAR(b.length_mm, a.length_mm, kStiffSoilLimit * a.length_mm);
  EXPECT_NEAR(b.width_mm, a.width_mm, kStiffSoilLimit * a.width_mm);
  EXPECT_TRUE(b.on_soil);
  EXPECT_LT(b.soil_sinkage_mm, 1e-3 * a.sinking_mm);
  EXPECT_LT(b.footprint.equilibrium_residual, 1e-9);
}

TEST(TyreOnSoil3D, TheDefaultTyreSinksLessThanTheRigidWheelAndDeflects) {
  const TyreConfig c =
      load_tyre_config(kConfig3d, {"ground.model=bekker", "ground.bekker.n=0.79",
                                   "ground.bekker.k_c=102", "ground.bekker.k_phi=5301"});
  const TyreModel m = build_tyre_model(c);
  const Prediction p = predict(m, c.default_conditions(4000));
  ASSERT_TRUE(p.ok()) << p.message;
  const gr::RigidWheelResult r =
      gr::rigid_wheel_static(c.ground, {c.outer_radius_m, c.footprint_3d->tread_width_m}, 4000);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_LT(p.soil_sinkage_mm, r.sinkage_m * 1e3);
  EXPECT_GT(p.tyre_deflection_mm, 0.3 * p.soil_sinkage_mm);
  EXPECT_NEAR(p.tyre_deflection_mm + p.soil_sinkage_mm, p.sinking_mm, 1e-9);
  EXPECT_LT(p.footprint.equilibrium_residual, 1e-9);
  // The soil spreads the load: a longer, lower-pressure footprint than on the road.
  const TyreModel road = build_tyre_model(load_tyre_config(kConfig3d));
  const Prediction q = predict(road, road.config.default_conditions(4000));
  EXPECT_GT(p.length_mm, q.length_mm);
}

}  // namespace

namespace {

using namespace modaltyre::contact;

// tyre.rigid on a soil: the footprint is the rigid wheel's static symmetric contact; on a road
// the key is refused (the reference wheel needs a soil).
TEST(TyreOnSoil, TheRigidTyreIsTheRigidWheelsStaticContact) {
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
  const TyreConfig c = load_tyre_config(
      config, {"tyre.rigid=true", "ground.model=bekker", "ground.bekker.n=0.79",
               "ground.bekker.k_c=102", "ground.bekker.k_phi=5301", "contact.unit_length_mm=2"});
  const TyreModel m = build_tyre_model(c);
  const Prediction p = predict(m, c.default_conditions(3000));
  ASSERT_TRUE(p.ok()) << p.message;
  const modaltyre::ground::RigidWheelResult r =
      modaltyre::ground::rigid_wheel_static(c.ground, {c.outer_radius_m, c.tread.width_m}, 3000);
  EXPECT_EQ(p.soil_sinkage_mm, r.sinkage_m * 1e3);
  EXPECT_EQ(p.sinking_mm, p.soil_sinkage_mm);
  EXPECT_EQ(p.tyre_deflection_mm, 0.0);
  EXPECT_THROW(load_tyre_config(config, {"tyre.rigid=true"}), modaltyre::InputError);
}

}  // namespace
