// Static footprint of the SF-350 model: equilibrium, symmetry, monotonicity, mesh convergence,
// limits and the seed's Fig. 5 (Table 3 validation: tests/studies/validation_test.cc).
#include "modaltyre/contact/footprint.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/data_paths.h"
#include "modaltyre/modal/hammer_data.h"

namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig2d;
const std::string kFig5 = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_fig5.yaml";

// Sum of forces and symmetry are exact up to rounding in direct solves.
constexpr double kFootprintEquilibrium = 1e-9;
constexpr double kSymmetry = 1e-9;
// The mesh-convergence requirement: doubling n changes sinking and length < 0.5 %.
constexpr double kMeshChange = 0.005;

TyreModel model_with(const std::vector<std::string>& overrides) {
  return build_tyre_model(load_tyre_config(kConfig2d, overrides));
}

TEST(Footprint, EquilibriumAndComplementarityAtEveryTable3Load) {
  const TyreModel m = model_with({});
  for (double F : {2131.0, 5478.0, 8321.0}) {
    const auto r = solve_footprint(m, {F, 0});
    ASSERT_TRUE(r.ok()) << r.message;
    double sum = 0;
    for (const auto& u : r.units) {
      sum += u.fz_N;
      EXPECT_GE(u.fz_N, 0.0);  // no tension
    }
    EXPECT_NEAR(sum, F, kFootprintEquilibrium * F);
    EXPECT_LT(r.complementarity_residual, 1e-9);
    for (double h : r.contour_height_m) EXPECT_GE(h, 0.0);  // no penetration
  }
}

TEST(Footprint, SymmetricAboutTheContactCentreWithoutHorizontalForce) {
  const auto r = solve_footprint(model_with({}), {5478, 0});
  ASSERT_TRUE(r.ok());
  const std::size_t n = r.units.size();
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(r.units[i].fz_N, r.units[n - 1 - i].fz_N, kSymmetry * 5478);
    EXPECT_NEAR(r.units[i].x_m, -r.units[n - 1 - i].x_m, 1e-12);
  }
}

TEST(Footprint, HorizontalForceShiftsThePatchAndKeepsEquilibrium) {
  const TyreModel m = model_with({});
  const auto r = solve_footprint(m, {5478, 800});
  ASSERT_TRUE(r.ok()) << r.message;
  double fz = 0, fx = 0, moment = 0;
  for (const auto& u : r.units) fz += u.fz_N, fx += u.fx_N, moment += u.fz_N * u.x_m;
  EXPECT_NEAR(fz, 5478, kFootprintEquilibrium * 5478);
  EXPECT_NEAR(fx, 800, kFootprintEquilibrium * 5478);
  EXPECT_GT(std::abs(moment / fz), 1e-5);  // the pressure centre moves off the centre
}

TEST(Footprint, SinkingAndLengthGrowWithLoad) {
  const TyreModel m = model_with({});
  std::vector<LoadCase> loads;
  for (double F = 1000; F <= 9000; F += 1000) loads.push_back({F, 0});
  const auto res = solve_footprints(m, loads);
  for (std::size_t i = 1; i < res.size(); ++i) {
    ASSERT_TRUE(res[i].ok());
    EXPECT_GT(res[i].sinking_m, res[i - 1].sinking_m);
    EXPECT_GT(res[i].contact_length_m, res[i - 1].contact_length_m);
  }
}

TEST(Footprint, MeshConvergenceDoublingUnits) {
  const auto coarse = solve_footprint(model_with({"contact.unit_length_mm=0.5"}), {5478, 0});
  const auto fine = solve_footprint(model_with({"contact.unit_length_mm=0.25"}), {5478, 0});
  ASSERT_TRUE(coarse.ok() && fine.ok());
  EXPECT_LT(std::abs(coarse.sinking_m / fine.sinking_m - 1), kMeshChange);
  EXPECT_LT(std::abs(coarse.contact_length_m / fine.contact_length_m - 1), kMeshChange);
}

TEST(Footprint, StiffTreadLimitConvergesToTheRingContact) {
  // A ring that can flatten at every order (the dispersion extension up to the mesh's Nyquist
  // order): as the tread stiffens its series compliance vanishes, so successive tenfold
  // stiffenings change the sinking by less and less (the tread's share falls like 1/E).
  double prev = 0, prev_change = 1e9;
  for (double E : {10.0, 100.0, 1000.0, 10000.0}) {
    const auto r = solve_footprint(
        model_with({"modal.extend_orders=true", "tread.modulus_MPa=" + std::to_string(E)}),
        {5478, 0});
    ASSERT_TRUE(r.ok());
    if (prev > 0) {
      const double change = std::abs(r.sinking_m - prev);
      EXPECT_LT(change, 0.5 * prev_change);
      prev_change = change;
    }
    prev = r.sinking_m;
  }
  EXPECT_LT(prev_change / prev, 1e-3);
}

TEST(Footprint, MeasuredModeCarcassUnderAStiffTreadIsARigidArcOnWinkler) {
  // The default carcass has the measured orders only (<= 5): over a patch of a few centimetres
  // it barely flattens, so a stiff tread meets a rigid arc. Winkler on an arc of radius R:
  // F = (4/3) sqrt(2R) (E b / h) d^(3/2), so the tread's share of the sinking d falls as
  // E^(-2/3) and the chord 2 sqrt(2 R d) as E^(-1/3): tenfold stiffenings shrink the change of
  // sinking by 10^(-2/3) = 0.215 and the length by 10^(-1/3) = 0.464.
  std::vector<double> sinking, length;
  for (double E : {10.0, 100.0, 1000.0, 10000.0}) {
    const auto r =
        solve_footprint(model_with({"tread.modulus_MPa=" + std::to_string(E)}), {5478, 0});
    ASSERT_TRUE(r.ok());
    sinking.push_back(r.sinking_m);
    length.push_back(r.contact_length_m);
  }
  const double winkler_sinking = std::pow(10.0, -2.0 / 3),
               winkler_length = std::pow(10.0, -1.0 / 3);
  for (std::size_t i = 2; i < sinking.size(); ++i) {
    const double ratio = (sinking[i] - sinking[i - 1]) / (sinking[i - 1] - sinking[i - 2]);
    EXPECT_NEAR(ratio, winkler_sinking, 0.03 * winkler_sinking) << "E step " << i;
  }
  // The 10 GPa chord is 6 mm, 12 units: compare lengths down to 1 GPa (25 units and more).
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_NEAR(length[i] / length[i - 1], winkler_length, 0.05 * winkler_length) << "E step " << i;
  }
}

TEST(Footprint, NearlyRigidCarcassGivesWinklerPressureOnTheChord) {
  // Carcass 1000x stiffer than measured: the tread alone deforms, so each unit carries
  // k (delta - sag) and the patch is the chord of the approach (rigid ring on Winkler).
  const TyreModel m = model_with({"modal.compliance_scale=0.001"});
  const auto r = solve_footprint(m, {3000, 0});
  ASSERT_TRUE(r.ok());
  const double R = m.config.outer_radius_m, d = r.sinking_m;
  const double chord = 2 * std::sqrt(2 * R * d - d * d);
  // Edges are interpolated (exact for a pure Winkler layer); the residual carcass compliance
  // shortens the patch by about a third of a unit here, so half a unit bounds it.
  EXPECT_NEAR(r.contact_length_m, chord, 0.5 * m.unit_length_m);
  // Centre unit: tread spring k_r against the approach; the residual carcass compliance is
  // 0.1 % of the measured one, small against the tread's, hence 2 % tolerance.
  const auto& centre = r.units[r.units.size() / 2];
  EXPECT_NEAR(centre.fz_N, m.k_radial_N_m * d, 0.02 * centre.fz_N);
}

TEST(Footprint, NonConvergenceIsReported) {
  const auto r = solve_footprint(model_with({"solver.max_iterations=1"}), {5478, 0});
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.message.empty());
}

TEST(Footprint, VerticalStiffnessNearlyConstantOverTable3Loads) {
  // Seed 001 Fig. 9: stiffness basically unchanged between 2131 and 8321 N. The measured
  // secant stiffness rises 8 %; the model's (17 %) must stay within 25 % (the tread's chord
  // geometry stiffens it).
  const TyreModel m = model_with({});
  const auto lo = solve_footprint(m, {2131, 0});
  const auto hi = solve_footprint(m, {8321, 0});
  const double rise = hi.vertical_stiffness_N_m() / lo.vertical_stiffness_N_m() - 1;
  EXPECT_GT(rise, 0.0);
  EXPECT_LT(rise, 0.25);
}

TEST(Fig5, ShapesAndLengthsOfTheSeedsFigure) {
  const TyreModel m = build_tyre_model(load_tyre_config(kFig5));
  const auto res = solve_footprints(m, {{2100, 0}, {5400, 0}, {8300, 0}});
  const double target_mm[3] = {70, 110, 130};
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(res[i].ok());
    EXPECT_NEAR(res[i].contact_length_m * 1e3, target_mm[i], 0.15 * target_mm[i]);
  }
  auto centre_over_max = [](const FootprintResult& r) {
    double mx = 0;
    for (const auto& u : r.units) mx = std::max(mx, u.pressure_Pa);
    return r.units[r.units.size() / 2].pressure_Pa / mx;
  };
  EXPECT_GT(centre_over_max(res[0]), 0.999);  // 2.1 kN: single peak at the centre
  EXPECT_LT(centre_over_max(res[1]), 0.98);   // 5.4 kN: slight dip at the centre
  EXPECT_GT(centre_over_max(res[1]), 0.85);
  EXPECT_GT(centre_over_max(res[2]), 0.85);  // 8.3 kN: flat ladder, no deep dip
}

}  // namespace
