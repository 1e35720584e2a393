// rolling_speed and tread_coupling on the 3D patch (patch3d.h, patch3d_coupled.cc,
// patch3d_tread.cc). Rolling: the non-symmetric section problem, against the 2D patch's rolling
// result on a flat crown (issue 45: within 0.5 %), and its physics (the static patch at speed
// 0, resistance growing with speed and damping, none without damping). Coupling: the layer's
// Green's function solves its difference equation, a flat crown gives the 2D patch's coupled
// footprint, a vanishing coupling length the exact section reduction, and the layer shortens
// and narrows the patch while keeping equilibrium and symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../../contact/src/patch3d_operators.h"
#include "modaltyre/contact/predictor.h"
#include "patch3d_fixture.h"

namespace modaltyre::contact::testing {
namespace {

const std::vector<std::string> kFlat = {"footprint_3d.crown.shape=flat"};

// The same tyre on the 2D patch: the 3D config without footprint_3d:, its 150 mm tread as the
// contact width (= the 3D tread width), on the same mesh.
struct Tyre2d {
  TyreConfig tyre;
  TyreModel model;
  explicit Tyre2d(const std::vector<std::string>& overrides)
      : tyre(flat_config(overrides)), model(build_tyre_model(tyre)) {}
  static TyreConfig flat_config(const std::vector<std::string>& overrides) {
    TyreConfig c = load_tyre_config(kConfig, overrides);
    c.tread.width_m = c.footprint_3d->tread_width_m;
    c.footprint_3d.reset();
    return c;
  }
};

Prediction predict_at(const TyreModel& m, TyreConfig c, double load_N, double speed_kmh,
                      const std::vector<std::string>& effects) {
  for (const auto& e : effects) {
    const auto eq = e.find('=');
    const std::string key = e.substr(0, eq), value = e.substr(eq + 1);
    if (key == "effects.rolling_speed.enabled") c.effects.rolling_speed.enabled = value == "true";
    if (key == "effects.rolling_speed.damping_scale")
      c.effects.rolling_speed.damping_scale = std::stod(value);
    if (key == "effects.tread_coupling.enabled") c.effects.tread_coupling.enabled = value == "true";
    if (key == "effects.tread_coupling.coupling_length_mm")
      c.effects.tread_coupling.coupling_length_mm = std::stod(value);
  }
  OperatingConditions oc = c.default_conditions(load_N);
  oc.speed_kmh = speed_kmh;
  const Prediction p = predict(m, parameters_of(c), oc);
  EXPECT_TRUE(p.ok()) << p.message;
  return p;
}

const std::vector<std::string> kRolling = {"effects.rolling_speed.enabled=true",
                                           "effects.rolling_speed.damping_scale=3"};

TEST(Patch3dRolling, AFlatCrownRollsAsTheTwoDPatchWithinHalfAPercent) {
  const Tyre3d t3(with(kCoarse, kFlat));
  const Tyre2d t2(with(kCoarse, kFlat));
  for (double F : {2500.0, 6000.0}) {
    const Prediction a = predict_at(t3.model, t3.tyre, F, 60, kRolling);
    const Prediction b = predict_at(t2.model, t2.tyre, F, 60, kRolling);
    ASSERT_GT(b.rolling_resistance_N, 1.0);
    EXPECT_NEAR(a.sinking_mm, b.sinking_mm, 5e-3 * b.sinking_mm);
    EXPECT_NEAR(a.rolling_resistance_N, b.rolling_resistance_N, 5e-3 * b.rolling_resistance_N);
    EXPECT_NEAR(a.length_mm, b.length_mm, 5e-3 * b.length_mm);
    // Only the edges' interpolation differs: the problem is the same one.
    EXPECT_NEAR(a.sinking_mm, b.sinking_mm, 1e-9 * b.sinking_mm);
    EXPECT_NEAR(a.rolling_resistance_N, b.rolling_resistance_N, 1e-7 * b.rolling_resistance_N);
  }
}

TEST(Patch3dRolling, TheCrownedPatchRollsWithResistanceFromDampingOnly) {
  const Tyre3d s(kCoarse);
  const double F = 5000;
  const Prediction standing = predict_at(s.model, s.tyre, F, 0, kRolling);
  const Prediction static_ = predict_at(s.model, s.tyre, F, 0, {});
  EXPECT_EQ(standing.sinking_mm, static_.sinking_mm);  // speed 0: the static patch
  EXPECT_EQ(standing.rolling_resistance_N, 0.0);
  double previous = 0;
  for (double v : {30.0, 60.0, 100.0}) {
    const Prediction p = predict_at(s.model, s.tyre, F, v, kRolling);
    EXPECT_GT(p.rolling_resistance_N, previous) << v;
    previous = p.rolling_resistance_N;
    // Exact on its contact set: load and complementarity over every cell.
    EXPECT_LT(p.patch3d->equilibrium_residual, 1e-9);
    EXPECT_LT(p.patch3d->complementarity_residual, 1e-9);
    EXPECT_LT(p.patch3d->max_penetration_m, 1e-9 * p.patch3d->sinking_m);
  }
  const Prediction more =
      predict_at(s.model, s.tyre, F, 60,
                 {"effects.rolling_speed.enabled=true", "effects.rolling_speed.damping_scale=6"});
  EXPECT_GT(more.rolling_resistance_N,
            predict_at(s.model, s.tyre, F, 60, kRolling).rolling_resistance_N);
  // Without damping the rolling carcass is conservative (seed 001 eq. 5).
  const Prediction undamped =
      predict_at(s.model, s.tyre, F, 60,
                 {"effects.rolling_speed.enabled=true", "effects.rolling_speed.damping_scale=0"});
  EXPECT_LT(std::abs(undamped.rolling_resistance_N), 1e-6 * F);
}

// T is the inverse of the layer's lattice operator k (u - a_x D_xx u - a_y D_yy u), D_yy with
// free edges: applied to a column of T it gives the unit vector (away from the window's ends).
TEST(Patch3dCoupling, TheLayersGreensFunctionSolvesItsDifferenceEquation) {
  const int S = 120, n = 12;
  const double k = 2e5, l = 0.008, ds = 0.002, dy = 0.005;
  const detail::CoupledTread T(k, l, ds, dy, S, n, std::vector<double>(S, 1.0));
  const double ax = (l / ds) * (l / ds), ay = (l / dy) * (l / dy);
  auto t = [&](int i, int j, int a) { return T.entry(i * n + j, a); };
  for (int source : {60 * n + 0, 60 * n + 5, 61 * n + 11}) {
    for (int i = 50; i <= 70; ++i) {
      for (int j = 0; j < n; ++j) {
        double lap_y = 0;  // free edges: the missing neighbour mirrors the cell
        if (j > 0) lap_y += t(i, j - 1, source) - t(i, j, source);
        if (j < n - 1) lap_y += t(i, j + 1, source) - t(i, j, source);
        const double lap_x = t(i - 1, j, source) - 2 * t(i, j, source) + t(i + 1, j, source);
        const double f = k * (t(i, j, source) - ax * lap_x - ay * lap_y);
        EXPECT_NEAR(f, i * n + j == source ? 1.0 : 0.0, 1e-9) << i << " " << j;
      }
    }
  }
  // The product is the matrix of the entries.
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(S * n, 1), y = Eigen::MatrixXd::Zero(S * n, 1);
  x(60 * n + 3, 0) = 2.0;
  x(64 * n + 7, 0) = -1.0;
  T.add_product(0, S * n, 0, S * n, x, y);
  for (int a : {55 * n + 1, 60 * n + 3, 62 * n + 9}) {
    EXPECT_NEAR(y(a, 0), 2 * T.entry(a, 60 * n + 3) - T.entry(a, 64 * n + 7), 1e-15 / k);
  }
}

const std::vector<std::string> coupled(double l_mm) {
  return {"effects.tread_coupling.enabled=true",
          "effects.tread_coupling.coupling_length_mm=" + std::to_string(l_mm)};
}

TEST(Patch3dCoupling, AFlatCrownGivesTheTwoDPatchsCoupledFootprint) {
  const Tyre3d t3(with(kCoarse, kFlat));
  const Tyre2d t2(with(kCoarse, kFlat));
  for (double l : {5.0, 20.0}) {
    const Prediction a = predict_at(t3.model, t3.tyre, 5000, 0, coupled(l));
    const Prediction b = predict_at(t2.model, t2.tyre, 5000, 0, coupled(l));
    EXPECT_NEAR(a.sinking_mm, b.sinking_mm, 1e-8 * b.sinking_mm) << l;
    ASSERT_EQ(a.footprint.units.size(), b.footprint.units.size()) << l;
    for (std::size_t k = 0; k < a.footprint.units.size(); ++k)
      EXPECT_NEAR(a.footprint.units[k].fz_N, b.footprint.units[k].fz_N, 1e-6 * 5000) << l;
    // The edges are interpolated differently (the 2D level function counts the carcass's own
    // compliance inside the patch, the 3D one the cell's tread alone): 2 %.
    EXPECT_NEAR(a.length_mm, b.length_mm, 0.02 * b.length_mm) << l;
  }
}

TEST(Patch3dCoupling, AVanishingCouplingIsTheExactSectionReduction) {
  const Tyre3d s(kCoarse);
  const Prediction reduced = predict_at(s.model, s.tyre, 5000, 0, {});
  const Prediction tiny = predict_at(s.model, s.tyre, 5000, 0, coupled(1e-4));
  EXPECT_NEAR(tiny.sinking_mm, reduced.sinking_mm, 1e-7 * reduced.sinking_mm);
  EXPECT_NEAR(tiny.length_mm, reduced.length_mm, 1e-5 * reduced.length_mm);
  EXPECT_NEAR(tiny.width_mm, reduced.width_mm, 1e-5 * reduced.width_mm);
}

TEST(Patch3dCoupling, TheLayerShortensAndNarrowsThePatchInEquilibriumAndSymmetric) {
  const Tyre3d s(kCoarse);
  double length = INFINITY, width = INFINITY;
  for (double l : {0.0, 5.0, 15.0}) {
    const Prediction p = predict_at(s.model, s.tyre, 5000, 0, coupled(l));
    const Patch3dResult& r = *p.patch3d;
    EXPECT_LT(p.length_mm, length) << l;
    EXPECT_LT(p.width_mm, width) << l;
    length = p.length_mm, width = p.width_mm;
    EXPECT_LT(r.equilibrium_residual, 1e-9) << l;
    EXPECT_LT(r.complementarity_residual, 1e-9) << l;
    EXPECT_LT(r.max_penetration_m, 1e-9 * r.sinking_m) << l;
    double asym = 0;
    for (int i = 0; i < r.sections; ++i)
      for (int j = 0; j < r.columns; ++j)
        asym = std::max(asym, std::abs(r.cell_force(i, j) - r.cell_force(i, r.columns - 1 - j)));
    EXPECT_LT(asym, 1e-9 * 5000) << l;
  }
}

TEST(Patch3dCoupling, ACoupledTreadOnARollingCarcassIsRefusedWithItsReason) {
  const Tyre3d s(kCoarse);
  TyreConfig c = s.tyre;
  c.effects.tread_coupling.enabled = true;
  c.effects.rolling_speed.enabled = true;
  OperatingConditions oc = c.default_conditions(5000);
  oc.speed_kmh = 60;
  const Prediction p = predict(s.model, parameters_of(c), oc);
  EXPECT_FALSE(p.ok());
  EXPECT_NE(p.message.find("rolling"), std::string::npos) << p.message;
}

}  // namespace
}  // namespace modaltyre::contact::testing
