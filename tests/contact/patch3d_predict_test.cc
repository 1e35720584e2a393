// The 3D patch on the single prediction path (predictor.h): a config with footprint_3d: is
// predicted on it, bit for bit as Patch3d itself; the effects that act on the carcass, the tread
// cells, the applied load or the road compose with it as their definitions say; the ones it
// cannot take are refused by the config reader, naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/errors.h"
#include "patch3d_fixture.h"

namespace modaltyre::contact::testing {
namespace {

Prediction predict_with(const Tyre3d& s, const std::vector<std::string>& effects, double load_N,
                        const OperatingConditions* conditions = nullptr) {
  const TyreConfig c = load_tyre_config(kConfig, with(kCoarse, effects));
  OperatingConditions oc = conditions ? *conditions : c.default_conditions(load_N);
  oc.load_N = load_N;
  return predict(s.model, parameters_of(c), oc);
}

TEST(Patch3dPredict, AConfigWithFootprint3dIsPredictedOnThePatchBitForBit) {
  const Tyre3d s(kCoarse);
  const std::vector<double> loads = {2131, 5478, 8321};
  const auto direct = Patch3d(s.model, s.patch).solve_all(loads);
  std::vector<OperatingConditions> cases;
  for (double F : loads) cases.push_back(s.tyre.default_conditions(F));
  const auto predicted = predict_all(s.model, cases);
  for (std::size_t k = 0; k < loads.size(); ++k) {
    const Prediction& p = predicted[k];
    ASSERT_TRUE(p.ok()) << p.message;
    ASSERT_NE(p.patch3d, nullptr);
    EXPECT_EQ(p.sinking_mm, direct[k].sinking_m * 1e3);
    EXPECT_EQ(p.length_mm, direct[k].length_m * 1e3);
    EXPECT_EQ(p.width_mm, direct[k].width_m * 1e3);
    EXPECT_EQ(p.patch3d->cell_force_N, direct[k].cell_force_N);
    // The footprint's units are the sections in contact: they carry the load.
    double sum = 0;
    for (const auto& u : p.footprint.units) sum += u.fz_N;
    EXPECT_NEAR(sum, loads[k], 1e-9 * loads[k]);
    EXPECT_EQ(p.footprint.contact_length_m, direct[k].length_m);
    EXPECT_NEAR(p.footprint.front_edge_x_m - p.footprint.rear_edge_x_m, direct[k].length_m, 1e-15);
  }
  // The width is the model's, not the 2D patch's input.
  EXPECT_LT(predicted.front().width_mm, predicted.back().width_mm);
}

TEST(Patch3dPredict, EffectsOnTheCarcassLevelEqualTheScaledCompliance) {
  const Tyre3d s(kCoarse);
  const double F = 6000, gamma = 0.25, F_ref = 4000;
  // load_stiffening: carcass compliance x (F / F_ref)^-gamma, i.e. the compliance scale.
  const Prediction stiffened = predict_with(
      s, {"effects.load_stiffening.enabled=true", "effects.load_stiffening.exponent=0.25"}, F);
  // The config's own scale (its declared calibration), to the digits of the stiffened run.
  std::ostringstream scale;
  scale.precision(17);
  scale << s.tyre.compliance_scale * std::pow(F / F_ref, -gamma);
  const Prediction scaled = predict_with(s, {"modal.compliance_scale=" + scale.str()}, F);
  ASSERT_TRUE(stiffened.ok() && scaled.ok());
  EXPECT_NEAR(stiffened.sinking_mm, scaled.sinking_mm, 1e-5 * scaled.sinking_mm);
  EXPECT_NEAR(stiffened.width_mm, scaled.width_mm, 1e-5 * scaled.width_mm);
  // inflation_pressure at the modal test's pressure changes nothing.
  const Prediction at_test = predict_with(s, {"effects.inflation_pressure.enabled=true"}, F);
  const Prediction plain = predict_with(s, {}, F);
  EXPECT_EQ(at_test.sinking_mm, plain.sinking_mm);
  EXPECT_EQ(at_test.width_mm, plain.width_mm);
}

TEST(Patch3dPredict, TreadCreepEqualsASofterCompound) {
  const Tyre3d s(kCoarse);
  const double creep_ratio = 0.5, tau_s = 30, hold_s = 60;
  const double creep = 1 + creep_ratio * (1 - std::exp(-hold_s / tau_s));  // seed 001 eq. (10)
  OperatingConditions held = s.tyre.default_conditions(5000);
  held.hold_s = hold_s;
  const Prediction crept = predict_with(s, {"effects.tread_relaxation.enabled=true"}, 5000, &held);
  const Prediction softer =
      predict_with(s, {"tread.modulus_MPa=" + std::to_string(3.0 / creep)}, 5000);
  ASSERT_TRUE(crept.ok() && softer.ok());
  EXPECT_NEAR(crept.sinking_mm, softer.sinking_mm, 1e-6 * softer.sinking_mm);
  EXPECT_NEAR(crept.width_mm, softer.width_mm, 1e-6 * softer.width_mm);
  EXPECT_GT(crept.sinking_mm, predict_with(s, {}, 5000).sinking_mm);
}

TEST(Patch3dPredict, DryFrictionShiftsTheElasticLoad) {
  const Tyre3d s(kCoarse);
  const Prediction loading = predict_with(
      s, {"effects.dry_friction.enabled=true", "effects.dry_friction.friction_force_N=300"}, 5000);
  const Prediction elastic = predict_with(s, {}, 4700);
  ASSERT_TRUE(loading.ok() && elastic.ok());
  EXPECT_EQ(loading.sinking_mm, elastic.sinking_mm);
  EXPECT_EQ(loading.width_mm, elastic.width_mm);
  EXPECT_EQ(loading.elastic_load_N, 4700);
}

TEST(Patch3dPredict, SoilActsOnlyOnRowsOnSoilAndSinksTheTyreFurther) {
  const Tyre3d s(kCoarse);
  const std::vector<std::string> soil = {"effects.soil_compliance.enabled=true",
                                         "effects.soil_compliance.modulus_MPa=5"};
  OperatingConditions on_soil = s.tyre.default_conditions(5000);
  on_soil.surface = Surface::soil;
  const Prediction rigid = predict_with(s, soil, 5000);
  const Prediction soft = predict_with(s, soil, 5000, &on_soil);
  ASSERT_TRUE(rigid.ok() && soft.ok());
  EXPECT_EQ(rigid.sinking_mm, predict_with(s, {}, 5000).sinking_mm);
  EXPECT_GT(soft.sinking_mm, rigid.sinking_mm);
  EXPECT_GE(soft.width_mm, rigid.width_mm);  // a softer foundation under the cells spreads them
}

TEST(Patch3dPredict, BeltFlatteningStiffensTheCarcass) {
  const Tyre3d s(kCoarse);
  const Prediction stiff = predict_with(
      s, {"effects.belt_flattening.enabled=true", "effects.belt_flattening.stiffness_MPa=5"}, 5000);
  const Prediction plain = predict_with(s, {}, 5000);
  ASSERT_TRUE(stiff.ok() && plain.ok());
  EXPECT_LT(stiff.sinking_mm, plain.sinking_mm);
}

struct RefusedCase {
  std::string name;
  std::vector<std::string> overrides;
  std::string key;  ///< the key the error must name
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const RefusedCase& c, std::ostream* os) { *os << c.name; }

class Patch3dRefuses : public ::testing::TestWithParam<RefusedCase> {};

TEST_P(Patch3dRefuses, TheConfigReaderNamesTheKeyAndTheReason) {
  try {
    load_tyre_config(kConfig, GetParam().overrides);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(GetParam().key), std::string::npos) << what;
    EXPECT_NE(what.find("footprint_3d"), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Effects, Patch3dRefuses,
    ::testing::Values(
        RefusedCase{"ContactWidth", {"effects.contact_width.enabled=true"}, "contact_width"},
        RefusedCase{"HorizontalForce", {"horizontal_force_N=500"}, "horizontal_force_N"}),
    [](const auto& info) { return info.param.name; });

TEST(Patch3dPredict, APredictionAskedForARefusedEffectFailsWithTheReason) {
  const Tyre3d s(kCoarse);
  TyreParameters p = parameters_of(s.tyre);
  p.effects.contact_width.enabled = true;  // as a discover variant would
  const Prediction r = predict(s.model, p, s.tyre.default_conditions(5000));
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("superseded"), std::string::npos) << r.message;
  OperatingConditions pulled = s.tyre.default_conditions(5000);
  pulled.horizontal_force_N = 500;
  const Prediction h = predict(s.model, pulled);
  EXPECT_FALSE(h.ok());
  EXPECT_NE(h.message.find("horizontal force"), std::string::npos) << h.message;
}

}  // namespace
}  // namespace modaltyre::contact::testing
