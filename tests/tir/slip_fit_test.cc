// The longitudinal laws of `tir export` (tir/slip_fit.h, tir/model_slip.h):
//  - planted round trip: curves made from known MF 6.2 coefficients come back through the fits;
//  - the model's runs on the 2D config (configs/sf350_2d_table3.yaml, fast): free rolling is
//    where the hub moment vanishes, the force rises with |kappa| and stays below mu F_z, R_e
//    lies just above the tread base's radius (the rolling resistance's slip), and a hold twice
//    as long moves no force (the holds are steady).
#include "modaltyre/tir/slip_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/tir/model_curve.h"
#include "modaltyre/transient/model.h"
#include "planted_slip.h"

namespace {

using namespace modaltyre;
using namespace modaltyre::tir;
using namespace modaltyre_test;

TEST(SlipFit, PlantedCoefficientsComeBack) {
  const Planted p = planted();
  std::vector<SlipCurve> curves, free;
  for (double share : {0.5, 0.75, 1.0, 1.25, 1.5})
    curves.push_back(planted_run(p, share * 4000, basis().longvl_m_s, default_slips()));
  for (double v : default_rolling_speeds_m_s()) free.push_back(planted_run(p, 4000, v, {}));
  const TirSlipFit f = fit_slip_laws(basis(), 1.0, curves, free);
  // F_x: the planted law is in the fitted family; it comes back to 0.1 % of F_z everywhere.
  EXPECT_LT(f.fx_over_fz.max, 1e-3);
  EXPECT_NEAR(f.longitudinal.pkx1, p.fx.pkx1, 0.02 * p.fx.pkx1);
  EXPECT_NEAR(f.longitudinal.pdx1, p.fx.pdx1, 0.02 * p.fx.pdx1);
  EXPECT_LE(f.max_curvature, 1.0);
  // M_y: linear but for QSY7; exact.
  EXPECT_LT(f.rolling_rel.max, 1e-6);
  EXPECT_LT(f.rolling_slip_rel.max, 1e-6);
  EXPECT_NEAR(f.rolling.qsy1, p.my.qsy1, 1e-6 * p.my.qsy1);
  EXPECT_NEAR(f.rolling.qsy2, p.my.qsy2, 1e-4 * p.my.qsy2);
  EXPECT_NEAR(f.rolling.qsy3, p.my.qsy3, 1e-5 * p.my.qsy3);
  EXPECT_NEAR(f.rolling.qsy4, p.my.qsy4, 1e-4 * p.my.qsy4);
  EXPECT_NEAR(f.rolling.qsy7, p.my.qsy7, 1e-6);
  // R_e: BREFF on a grid (5 % apart), DREFF and FREFF fitted to it: within a micrometre.
  EXPECT_LT(f.radius_m.max, 1e-6);
  EXPECT_EQ(f.kappa_min, -0.3);
  EXPECT_EQ(f.kappa_max, 0.3);
}

// A negative quartic speed term would turn the moment propulsive beyond the runs: the bound
// QSY4 >= 0 holds where the unconstrained optimum is negative.
TEST(SlipFit, QuarticSpeedTermIsNotNegative) {
  Planted p = planted();
  p.my.qsy4 = -2e-4;
  std::vector<SlipCurve> curves, free;
  for (double share : {0.5, 1.0, 1.5})
    curves.push_back(planted_run(p, share * 4000, basis().longvl_m_s, {-0.1, 0.1}));
  for (double v : default_rolling_speeds_m_s()) free.push_back(planted_run(p, 4000, v, {}));
  const TirSlipFit f = fit_slip_laws(basis(), 1.0, curves, free);
  EXPECT_EQ(f.rolling.qsy4, 0.0);
  EXPECT_GT(f.rolling_rel.max, 1e-3);  // the planted law is out of reach
}

TEST(SlipFit, FewerThanThreeLoadsAreRefused) {
  const Planted p = planted();
  std::vector<SlipCurve> curves = {planted_run(p, 3000, 16, {0.1}), planted_run(p, 3000, 16, {0.1}),
                                   planted_run(p, 5000, 16, {0.1})};
  EXPECT_THROW(fit_slip_laws(basis(), 1.0, curves, {}), InputError);
}

struct ModelRuns {
  std::shared_ptr<const transient::TransientModel> model;
  double deflection_m = 0;
  SlipSettings settings;
  SlipCurve curve;
};

constexpr double kLoad_N = 4000;

const ModelRuns& model_runs() {
  static const ModelRuns runs = [] {
    ModelRuns r;
    const auto tyre = contact::build_tyre_model(contact::load_tyre_config(
        std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml"));
    r.model =
        std::make_shared<const transient::TransientModel>(transient::build_transient_model(tyre));
    r.deflection_m = sample_model(tyre, {kLoad_N}).points[0].sinking_m;
    r.settings.slips = {-0.3, -0.05, -0.005, 0.005, 0.05, 0.3};
    r.curve = model_slip_curve(r.model, r.deflection_m, kLoad_N, r.settings);
    return r;
  }();
  return runs;
}

TEST(ModelSlip, FreeRollingIsWhereTheHubMomentVanishes) {
  const SlipCurve& c = model_runs().curve;
  // The FMU's hub moment M_r - r F_x is zero: F_x = M_r / r, the rolling resistance.
  const double rr = c.free.rolling_moment_Nm / c.free.loaded_radius_m;
  EXPECT_NEAR(c.free.fx_N, rr, 1e-3 * c.free.fz_N);
  EXPECT_LT(c.free.fx_N, 0);  // a drag
  // The rolling tyre at the static sinking carries about the static load.
  EXPECT_NEAR(c.free.fz_N, kLoad_N, 0.05 * kLoad_N);
  // R_e just above the tread base's radius: free rolling needs a small braking slip against
  // it to make the drag (F_x = C_kappa kappa_b).
  const auto& cfg = model_runs().model->tyre.config;
  const double base = cfg.outer_radius_m - cfg.tread.thickness_m;
  EXPECT_GT(c.effective_radius_m, base);
  EXPECT_LT(c.effective_radius_m, 1.03 * base);
}

TEST(ModelSlip, ForceRisesWithSlipAndStaysBelowFriction) {
  const ModelRuns& r = model_runs();
  const auto& pts = r.curve.points;
  for (const auto& p : pts) EXPECT_LE(std::abs(p.fx_N), r.settings.mu * p.fz_N * 1.001) << p.kappa;
  // Braking -0.3, -0.05, -0.005 and driving 0.005, 0.05, 0.3: monotone through free rolling.
  EXPECT_LT(pts[0].fx_N, pts[1].fx_N);
  EXPECT_LT(pts[1].fx_N, pts[2].fx_N);
  EXPECT_LT(pts[2].fx_N, r.curve.free.fx_N);
  EXPECT_LT(r.curve.free.fx_N, pts[3].fx_N);
  EXPECT_LT(pts[3].fx_N, pts[4].fx_N);
  EXPECT_LT(pts[4].fx_N, pts[5].fx_N);
}

TEST(ModelSlip, TwiceTheHoldMovesNoForce) {
  const ModelRuns& r = model_runs();
  SlipSettings longer = r.settings;
  longer.hold_m *= 2, longer.average_m *= 2;
  const SlipCurve c = model_slip_curve(r.model, r.deflection_m, kLoad_N, longer);
  // R_e to a slip of 1e-5 (a force of 1e-4 F_z at this tyre's C_kappa / F_z of 3.3).
  EXPECT_NEAR(c.effective_radius_m, r.curve.effective_radius_m, 1e-5 * c.effective_radius_m);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    EXPECT_NEAR(c.points[i].fx_N, r.curve.points[i].fx_N, 3e-3 * c.points[i].fz_N)
        << c.points[i].kappa;
  }
}

TEST(ModelSlip, SettingsOutOfRangeAreRefusedNamingTheOption) {
  SlipSettings s;
  s.mu = 0;
  EXPECT_THROW(slip_run_steps(s), InputError);
  s = {};
  s.speed_m_s = 0.5;
  EXPECT_THROW(slip_run_steps(s), InputError);
  s = {};
  s.slips = {2.0};
  EXPECT_THROW(slip_run_steps(s), InputError);
  s = {};
  s.slips.assign(kMaxSlips + 1, 0.1);
  EXPECT_THROW(slip_run_steps(s), InputError);
}

}  // namespace
