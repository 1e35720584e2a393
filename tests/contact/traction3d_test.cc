// Steady rolling on the 3D patch (contact/src/traction3d.h, docs/soil.md section 9): a flat crown
// is the 2D patch at the same width, a very stiff soil the road's rolling footprint, the drawbar
// pull rises with slip, the rut is no deeper than the sinkage.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "../support/lete_sand.h"
#include "modaltyre/contact/patch3d.h"
#include "modaltyre/contact/traction.h"

namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig3d;
using modaltyre_test::kLeteBekkerShear;
using modaltyre_test::plus;

// The 3D config's 2D patch: its tread width as the contact width, no footprint_3d.
TyreConfig two_d(TyreConfig c) {
  c.tread.width_m = c.footprint_3d->tread_width_m;
  c.footprint_3d.reset();
  return c;
}

// Done-when (issue 37, step 1): a flat crown's cells all carry the same force, so the 3D patch's
// rolling is the 2D patch's at the tread width. What differs: the 3D cell's position includes its
// own tread only (the 2D unit's the tread's radial lag between units), and both fixed points stop
// at their tolerances (TractionOptions: 1e-5 of the load, 1e-4 of the sinkage).
TEST(Traction3D, AFlatCrownRollsAsThe2DPatchOfTheSameWidth) {
  constexpr double kSame = 0.005;  // the brief's 0.5 %
  const TyreConfig c3 = load_tyre_config(
      kConfig3d,
      plus(kLeteBekkerShear, {"footprint_3d.crown.shape=flat", "contact.unit_length_mm=1"}));
  const TyreModel m3 = build_tyre_model(c3), m2 = build_tyre_model(two_d(c3));
  std::vector<TractionCase> cases;
  for (double s : {0.0, 0.1, 0.3}) cases.push_back({3000, s});
  const auto r3 = steady_traction(m3, c3.ground, cases);
  const auto r2 = steady_traction(m2, c3.ground, cases);
  ASSERT_EQ(r3.size(), r2.size());
  for (std::size_t k = 0; k < r3.size(); ++k) {
    const TractionResult &a = r3[k], &b = r2[k];
    ASSERT_TRUE(a.ok()) << a.message;
    ASSERT_TRUE(b.ok()) << b.message;
    EXPECT_NEAR(a.soil_sinkage_m, b.soil_sinkage_m, kSame * b.soil_sinkage_m) << a.slip;
    EXPECT_NEAR(a.drawbar_pull_N, b.drawbar_pull_N, kSame * std::abs(b.drawbar_pull_N)) << a.slip;
    EXPECT_NEAR(a.torque_Nm, b.torque_Nm, kSame * std::abs(b.torque_Nm)) << a.slip;
    EXPECT_NEAR(a.motion_resistance_N, b.motion_resistance_N, kSame * b.motion_resistance_N)
        << a.slip;
    EXPECT_NEAR(a.sinking_m, b.sinking_m, kSame * b.sinking_m) << a.slip;
    EXPECT_NEAR(a.contact_length_m, b.contact_length_m, kSame * b.contact_length_m) << a.slip;
    // The 2D patch's b is its contact length (shorter than the width): so is the 3D's.
    EXPECT_NEAR(a.bekker_width_m, b.bekker_width_m, kSame * b.bekker_width_m) << a.slip;
  }
}

// Done-when (issue 37): a very stiff soil (n = 1, k_phi = 1e9 kN/m^3: 0.5 um under 500 kPa),
// frictionless, gives the road's footprint (the 3D patch's static one: on a rigid road without
// friction rolling changes nothing) within 0.5 % in sinking and length; nothing is dissipated in
// the soil beyond its vanishing sinkage.
TEST(Traction3D, AVeryStiffSoilRollsOnTheRoadsFootprint) {
  constexpr double kStiffSoilLimit = 0.005;
  const std::vector<std::string> mesh = {"contact.unit_length_mm=1",
                                         "footprint_3d.lateral_cell_mm=5"};
  const TyreConfig road = load_tyre_config(kConfig3d, mesh);
  const TyreConfig soil = load_tyre_config(
      kConfig3d, plus(mesh, {"ground.model=bekker", "ground.bekker.n=1", "ground.bekker.k_c=0",
                             "ground.bekker.k_phi=1e9", "ground.bekker.cohesion_kPa=0",
                             "ground.bekker.friction_angle_deg=0"}));
  const TyreModel mr = build_tyre_model(road), ms = build_tyre_model(soil);
  const Patch3d patch(mr, *road.footprint_3d);
  const Patch3dResult p = patch.solve(4000);
  ASSERT_TRUE(p.ok()) << p.message;
  const TractionResult r = traction_pass(ms, soil.ground, {4000, 0.1}, 0);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.sinking_m, p.sinking_m, kStiffSoilLimit * p.sinking_m);
  EXPECT_NEAR(r.contact_length_m, p.length_m, kStiffSoilLimit * p.length_m);
  EXPECT_LT(r.soil_sinkage_m, 1e-3 * p.sinking_m);
  EXPECT_LT(std::abs(r.motion_resistance_N), 1e-3 * 4000);
  EXPECT_EQ(r.thrust_N, 0.0);
}

// Done-when (issue 37): on LETE sand with the default crown the drawbar pull rises with slip,
// the rut (rigid-plastic: the deepest sinkage) is no deeper than the sinkage, a second pass adds
// less sinkage than the first; the crown's columns sink unequally (the centre deepest).
TEST(Traction3D, DrawbarPullRisesWithSlipAndTheRutIsNoDeeperThanTheSinkage) {
  const TyreConfig c = load_tyre_config(
      kConfig3d,
      plus(kLeteBekkerShear, {"contact.unit_length_mm=2", "footprint_3d.lateral_cell_mm=10"}));
  const TyreModel m = build_tyre_model(c);
  TractionOptions o;
  o.passes = 2;
  std::vector<TractionCase> cases;
  for (double s : {0.05, 0.1, 0.2, 0.3, 0.4}) cases.push_back({3000, s});
  const std::vector<TractionResult> r = steady_traction(m, c.ground, cases, o);
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
    EXPECT_GT(first.tyre_deflection_m, 0);
    const auto& z = first.column_z_max_m;
    ASSERT_EQ(z.size(), 15u);
    EXPECT_GT(z[7], z[0]) << first.slip;  // the crown: the centre column sinks deepest
    EXPECT_DOUBLE_EQ(z[0], z[14]);        // and the track is symmetric
  }
}

}  // namespace
