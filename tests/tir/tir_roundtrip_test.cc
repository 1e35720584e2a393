// Round trips through the .tir bridge on the 2D config (configs/sf350_2d_table3.yaml, the default
// before issue 18): export -> parse the text -> evaluate the MF formulas (Pacejka 2012 App. 3) ->
// the model's own footprints, at loads between the fitted ones over 0.5-1.5 x FNOMIN (issue 20 item
// 4); and compare on hand-made files whose laws are known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "modaltyre/tir/mf_tyre.h"
#include "modaltyre/tir/tir_compare.h"
#include "modaltyre/tir/tir_export.h"

namespace {

using namespace modaltyre;
using namespace modaltyre::tir;

const contact::TyreModel& default_model() {
  static const contact::TyreModel model = contact::build_tyre_model(contact::load_tyre_config(
      std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml"));
  return model;
}

struct Exported {
  TirFit fit;
  MfTyre read_back;
};

const Exported& exported() {
  static const Exported e = [] {
    TirExportOptions o;
    o.config_label = "configs/sf350_2d_table3.yaml";
    Exported out;
    out.fit = fit_tir(default_model(), o);
    out.read_back =
        interpret_tir(parse_tir(tir_text(out.fit, default_model().config, o), "exported.tir"));
    return out;
  }();
  return e;
}

TEST(TirRoundTrip, ReadBackCarriesTheFittedLaws) {
  const Exported& e = exported();
  EXPECT_EQ(e.read_back.fittyp, 62);
  EXPECT_FALSE(e.read_back.table_law);  // MF 6.2: the formula, not the exported table
  EXPECT_NEAR(e.read_back.vertical.q_fz1, e.fit.q_fz1, 1e-8 * e.fit.q_fz1);  // via (A3.4)
  EXPECT_DOUBLE_EQ(e.read_back.vertical.fnomin_N, e.fit.fnomin_N);
  EXPECT_DOUBLE_EQ(e.read_back.unloaded_radius_m, default_model().config.outer_radius_m);
}

TEST(TirRoundTrip, VerticalStiffnessIsTheModelsTangentAtFnomin) {
  const Exported& e = exported();
  const double model_tangent = model_tangent_stiffness_N_m(default_model(), e.fit.fnomin_N);
  const double rel = e.read_back.vertical_stiffness_N_m() / model_tangent - 1;
  RecordProperty("stiffness_rel_diff", std::to_string(rel));
  EXPECT_LT(std::abs(rel), 0.05) << "VERTICAL_STIFFNESS " << e.read_back.vertical_stiffness_N_m()
                                 << " N/m, model tangent " << model_tangent << " N/m";
}

TEST(TirRoundTrip, MfLawsReproduceSinkingAndLengthOverHalfToOneAndAHalfFnomin) {
  const Exported& e = exported();
  // 11 loads over 0.5-1.5 x FNOMIN, none of them a fitted load (the fit grid is 0.25 + k 0.159).
  const ModelCurve model = sample_model(default_model(), load_grid(e.fit.fnomin_N, 0.5, 1.5, 11));
  double worst_sinking = 0, worst_length = 0;
  for (const auto& p : model.points) {
    const auto rho =
        mf_deflection_m(e.read_back.vertical, p.load_N, e.read_back.inflation_pressure_Pa);
    ASSERT_TRUE(rho);
    const auto length = e.read_back.length_m(p.load_N);
    ASSERT_TRUE(length);
    worst_sinking = std::max(worst_sinking, std::abs(*rho / p.sinking_m - 1));
    worst_length = std::max(worst_length, std::abs(*length / p.length_m - 1));
  }
  RecordProperty("max_sinking_rel_diff", std::to_string(worst_sinking));
  RecordProperty("max_length_rel_diff", std::to_string(worst_length));
  EXPECT_LT(worst_sinking, 0.03);
  EXPECT_LT(worst_length, 0.03);
}

TEST(TirRoundTrip, WidthIsNullWithAReasonWhenThePredictionHasNone) {
  const Exported& e = exported();
  EXPECT_FALSE(e.fit.q_rb1);
  EXPECT_FALSE(e.read_back.width_at_m(4000));
  EXPECT_NE(e.fit.curve.width_reason.find("fixed width"), std::string::npos);
}

// A same-size file with a linear law (Q_FZ2 = 0) and a pure square-root length law: the
// comparison's .tir columns are the closed forms at the model's deflections, and its RMS the
// one computed here from the model's own footprints.
TEST(TirCompare, HandMadeFileGivesTheExpectedComparison) {
  const double cz = 3.0e5, r0 = default_model().config.outer_radius_m;
  std::ostringstream text;
  text << "[MODEL]\nFITTYP = 62\n[DIMENSION]\nUNLOADED_RADIUS = " << r0 * 1e3
       << "\nWIDTH = 195\n[UNITS]\nLENGTH = 'mm'\nFORCE = 'newton'\n[VERTICAL]\nFNOMIN = 5000\n"
          "VERTICAL_STIFFNESS = "
       << cz * 1e-3 << "\nQ_FZ2 = 0\n[CONTACT_PATCH]\nQ_RA1 = 1.0\nQ_RA2 = 0\n";
  const MfTyre t = interpret_tir(parse_tir(text.str(), "hand.tir"));
  CompareOptions o;
  o.points = 6;
  const TirComparison c = compare_tir(default_model(), t, o);
  EXPECT_FALSE(c.dimensionless) << c.basis;
  ASSERT_EQ(c.rows.size(), 6u);
  double sum_load = 0, sum_length = 0;
  for (const auto& r : c.rows) {
    ASSERT_TRUE(r.tir_load_N && r.tir_length_m);
    EXPECT_NEAR(*r.tir_load_N, cz * r.rho_m, 1e-9 * cz * r.rho_m);
    EXPECT_NEAR(*r.tir_length_m, 2 * r0 * std::sqrt(r.rho_m / r0), 1e-12);  // rho_z = F/C_z = rho
    sum_load += std::pow(cz * r.rho_m / r.load_N - 1, 2);
    sum_length += std::pow(2 * r0 * std::sqrt(r.rho_m / r0) / r.model_length_m - 1, 2);
  }
  EXPECT_NEAR(*c.rms_load, std::sqrt(sum_load / 6), 1e-12);
  EXPECT_NEAR(*c.rms_length, std::sqrt(sum_length / 6), 1e-12);
  EXPECT_FALSE(c.rms_width);
  EXPECT_FALSE(c.width_reason.empty());
}

// The dimensionless comparison is blind to size: the exported tyre scaled by 1.5 in length
// (loads by 2, stiffness by 2/1.5) compares with the model exactly as the exported one does.
TEST(TirCompare, DimensionlessComparisonIsInvariantUnderScaling) {
  const Exported& e = exported();
  MfTyre scaled = e.read_back;
  scaled.unloaded_radius_m *= 1.5;
  scaled.width_m = *scaled.width_m * 1.5;
  scaled.vertical.unloaded_radius_m *= 1.5;
  scaled.vertical.fnomin_N *= 2;
  scaled.vertical.vertical_stiffness_N_m *= 2 / 1.5;
  CompareOptions o;
  o.points = 5;
  o.fnomin_N = e.fit.fnomin_N;
  const TirComparison same = compare_tir(default_model(), e.read_back, o);
  const TirComparison other = compare_tir(default_model(), scaled, o);
  EXPECT_FALSE(same.dimensionless);
  EXPECT_TRUE(other.dimensionless);
  for (std::size_t i = 0; i < same.rows.size(); ++i) {
    EXPECT_NEAR(*other.rows[i].tir_load_N, *same.rows[i].tir_load_N, 1e-9 * same.rows[i].load_N);
    EXPECT_NEAR(*other.rows[i].tir_length_m, *same.rows[i].tir_length_m, 1e-12);
  }
  EXPECT_NEAR(*other.rms_load, *same.rms_load, 1e-12);
  EXPECT_NEAR(*other.rms_length, *same.rms_length, 1e-12);
}

// With a predicted width (the crown-profile contact_width effect) the export carries Q_RB1 and
// Q_RB2, and they are the least-squares optimum of the relative width residuals: moving either
// by 1 % makes the RMS worse.
TEST(TirRoundTrip, PredictedWidthIsExportedAsTheLeastSquaresWidthLaw) {
  auto config =
      contact::load_tyre_config(std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml",
                                {"effects.contact_width.enabled=true", "contact.unit_length_mm=2"});
  const contact::TyreModel model = contact::build_tyre_model(config);
  TirExportOptions o;
  o.loads_N = load_grid(5226, 0.25, 2, 8);
  const TirFit f = fit_tir(model, o);
  ASSERT_TRUE(f.q_rb1 && f.q_rb2 && f.width);
  const MfTyre t = interpret_tir(parse_tir(tir_text(f, config, o), "w.tir"));
  const auto rms = [&](double rb1, double rb2) {
    double sum = 0;
    for (const auto& p : f.curve.points) {
      const double rho_z = p.load_N / f.vertical_stiffness_N_m;
      const double w = 2 * mf_half_width_m(f.unloaded_radius_m, f.width_m, rb1, rb2, rho_z);
      sum += std::pow(w / *p.width_m - 1, 2);
    }
    return std::sqrt(sum / static_cast<double>(f.curve.points.size()));
  };
  const double best = rms(*t.q_rb1, *t.q_rb2);
  EXPECT_NEAR(best, f.width->rms_rel, 1e-8);
  for (double s : {0.99, 1.01}) {
    EXPECT_GT(rms(*t.q_rb1 * s, *t.q_rb2), best);
    EXPECT_GT(rms(*t.q_rb1, *t.q_rb2 * s), best);
  }
  EXPECT_TRUE(t.width_at_m(f.fnomin_N));
}

// With the inflation_pressure effect on, PFZ1 carries the model's stiffness to other pressures
// through (A3.5): the read-back law's C_z at 0.8 and 1.2 x the config's pressure against the
// model's tangent stiffness there.
TEST(TirRoundTrip, PressureEffectIsExportedAsPfz1) {
  auto config = contact::load_tyre_config(
      std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml",
      {"effects.inflation_pressure.enabled=true", "contact.unit_length_mm=2"});
  const contact::TyreModel model = contact::build_tyre_model(config);
  TirExportOptions o;
  o.loads_N = load_grid(5226, 0.25, 2, 8);
  const TirFit f = fit_tir(model, o);
  ASSERT_TRUE(f.pfz1);
  MfTyre t = interpret_tir(parse_tir(tir_text(f, config, o), "p.tir"));
  EXPECT_NEAR(t.vertical.pfz1, *f.pfz1, 1e-9);
  for (double s : {0.8, 1.2}) {
    t.inflation_pressure_Pa = s * config.inflation_pressure_Pa;
    const double model_cz =
        model_tangent_stiffness_N_m(model, f.fnomin_N, s * config.inflation_pressure_Pa);
    const double rel = t.vertical_stiffness_N_m() / model_cz - 1;
    RecordProperty(s < 1 ? "cz_rel_diff_at_0.8p" : "cz_rel_diff_at_1.2p", std::to_string(rel));
    EXPECT_LT(std::abs(rel), 0.05) << "at " << s << " x the pressure";
  }
}

// With the effect off the pressure still acts through the ring's pressure terms (issue 36,
// docs/ring_model.md): the default config's .tir carries PFZ1, inside MF 6.x's range for
// passenger tyres (0.5-1.0), and the read-back law carries the stiffness to 0.8 and 1.2 x the
// pressure as the model does.
TEST(TirRoundTrip, RingPressureTermsAreExportedAsPfz1WithTheEffectOff) {
  auto config = contact::load_tyre_config(std::string(MODALTYRE_SOURCE_DIR) +
                                          "/configs/sf350_2d_table3.yaml");
  ASSERT_FALSE(config.effects.inflation_pressure.enabled);
  const contact::TyreModel model = contact::build_tyre_model(config);
  ASSERT_TRUE(model.carcass.fit.valid) << model.carcass.fit.reason;
  TirExportOptions o;
  o.loads_N = load_grid(5226, 0.25, 2, 8);
  const TirFit f = fit_tir(model, o);
  ASSERT_TRUE(f.pfz1) << f.pfz1_reason;
  RecordProperty("pfz1", std::to_string(*f.pfz1));
  EXPECT_GT(*f.pfz1, 0.5);
  EXPECT_LT(*f.pfz1, 1.0);
  MfTyre t = interpret_tir(parse_tir(tir_text(f, config, o), "p.tir"));
  for (double s : {0.8, 1.2}) {
    t.inflation_pressure_Pa = s * config.inflation_pressure_Pa;
    const double model_cz =
        model_tangent_stiffness_N_m(model, f.fnomin_N, s * config.inflation_pressure_Pa);
    EXPECT_LT(std::abs(t.vertical_stiffness_N_m() / model_cz - 1), 0.05) << "at " << s << " p";
  }
}

}  // namespace
