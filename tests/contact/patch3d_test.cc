// The 3D contact patch (contact/patch3d.h): the laterally rigid reduction against the full cell
// solve, the 2D patch as the flat-crown limit, symmetry in y, a rigid torus and a rigid power
// crown on a Winkler tread (analytic), mesh convergence in x and y, equilibrium and
// complementarity.
#include "modaltyre/contact/patch3d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>

#include "modaltyre/contact/footprint.h"
#include "patch3d_fixture.h"

namespace {

using namespace modaltyre::contact;
using namespace modaltyre::contact::testing;

TEST(Patch3d, LaterallyRigidReductionEqualsTheFullCellSolve) {
  const Tyre3d s(kCoarse);
  expect_reduction_equals_full_cell_solve(Patch3d(s.model, s.patch), {2131, 8321});
}

TEST(Patch3d, FlatCrownReproducesThe2DPatchTimesWidth) {
  // Tread width = the 2D contact width: every section's cells share its force equally and the
  // section's tread is the 2D unit's (k_r = E b ds / h).
  const Tyre3d s(with(kCoarse, {"footprint_3d.crown.shape=flat", "footprint_3d.tread_width_mm=150",
                                "tread.contact_width_mm=150"}));
  const Patch3d patch(s.model, s.patch);
  for (double F : {2131.0, 5478.0, 8321.0}) {
    const Patch3dResult r3 = patch.solve(F);
    const FootprintResult r2 = solve_footprint(s.model, {F, 0});
    ASSERT_TRUE(r3.ok()) << r3.message;
    ASSERT_TRUE(r2.ok()) << r2.message;
    EXPECT_NEAR(r3.sinking_m, r2.sinking_m, kExact * r2.sinking_m);
    EXPECT_DOUBLE_EQ(r3.width_m, 0.150);
    // Unit forces and pressures: the 2D units in contact are the 3D sections in contact.
    std::vector<double> sections;
    for (int i = 0; i < r3.sections; ++i) {
      if (r3.section_force_N[i] > 0) sections.push_back(i);
    }
    ASSERT_EQ(sections.size(), r2.units.size());
    for (std::size_t k = 0; k < sections.size(); ++k) {
      const int i = static_cast<int>(sections[k]);
      EXPECT_NEAR(r3.section_force_N[i], r2.units[k].fz_N, kExact * F);
      for (int j = 0; j < r3.columns; ++j) {
        EXPECT_NEAR(r3.pressure_Pa(i, j), r2.units[k].pressure_Pa,
                    kExact * r2.units[k].pressure_Pa);
      }
    }
    // The edges interpolate another (equally second-order) level function than the 2D patch's
    // (tread compression instead of force x own compliance): they agree within a fraction of a
    // unit.
    EXPECT_NEAR(r3.length_m, r2.contact_length_m, 0.25 * s.model.unit_length_m);
  }
}

TEST(Patch3d, SymmetricAcrossTheTread) {
  const Tyre3d s(kCoarse);
  expect_symmetric_in_y(Patch3d(s.model, s.patch).solve(5478));
}

TEST(Patch3d, EquilibriumComplementarityNoTensionNoPenetration) {
  const Tyre3d s({});
  const Patch3d patch(s.model, s.patch);
  for (const Patch3dResult& r : patch.solve_all({2131, 5478, 8321})) {
    expect_equilibrium_and_complementarity(r);
  }
}

TEST(Patch3d, RigidTorusOnAWinklerTreadGivesTheEllipse) {
  // Carcass removed (kernels zero): a rigid body with curvatures 1/R0 along and 1/Rc across on
  // independent springs of stiffness k = E/h per area. For the paraboloid gap x^2/2R0 + y^2/2Rc
  // the patch is an ellipse with semi-axes sqrt(2 R0 delta), sqrt(2 Rc delta) and F = k pi
  // delta^2 sqrt(R0 Rc). The arcs differ from the parabolas by O(delta / R) (~0.3 % here).
  Tyre3d s(with(kCoarse, {"contact.unit_length_mm=0.5", "footprint_3d.lateral_cell_mm=1",
                          "footprint_3d.crown.radius_mm=300", "footprint_3d.tread_width_mm=200",
                          "tread.modulus_MPa=6"}));
  for (auto* k : {&s.model.kernels.r_from_r, &s.model.kernels.r_from_t, &s.model.kernels.t_from_r,
                  &s.model.kernels.t_from_t}) {
    std::fill(k->begin(), k->end(), 0.0);
  }
  const Patch3d patch(s.model, s.patch);
  const double F = 3000, R0 = s.tyre.outer_radius_m, Rc = 0.3;
  const auto& T = s.tyre.tread;
  const double k = T.modulus_Pa / T.thickness_m;
  const double delta = std::sqrt(F / (k * M_PI * std::sqrt(R0 * Rc)));
  const Patch3dResult r = patch.solve(F);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.sinking_m, delta, 0.01 * delta);
  EXPECT_NEAR(r.length_m, 2 * std::sqrt(2 * R0 * delta), 0.01 * r.length_m);
  EXPECT_NEAR(r.width_m, 2 * std::sqrt(2 * Rc * delta), 0.01 * r.width_m);
}

TEST(Patch3d, RigidPowerCrownOnAWinklerTreadGivesItsAnalyticPatch) {
  // As above with the power crown z = c|y|^n (crown_profile.h, c = y_r^(2-n) / 2R): the gap
  // x^2/2R0 + c|y|^n on springs k = E/h per area. The patch is x^2/2R0 + c|y|^n <= delta:
  // length 2 sqrt(2 R0 delta), width 2 (delta/c)^(1/n), and F = (8/3) k sqrt(2 R0) delta^(3/2)
  // (delta/c)^(1/n) I_n with I_n = int_0^1 (1 - t^n)^(3/2) dt = G(1+1/n) G(5/2) / G(5/2+1/n)
  // (n = 2: the ellipse above).
  for (double n : {1.5, 3.0}) {
    Tyre3d s(with(kCoarse, {"contact.unit_length_mm=0.5", "footprint_3d.lateral_cell_mm=1",
                            "footprint_3d.crown.shape=power", "footprint_3d.crown.radius_mm=300",
                            "footprint_3d.crown.exponent=" + std::to_string(n),
                            "footprint_3d.crown.reference_half_width_mm=60",
                            "footprint_3d.tread_width_mm=200", "tread.modulus_MPa=6"}));
    for (auto* k : {&s.model.kernels.r_from_r, &s.model.kernels.r_from_t, &s.model.kernels.t_from_r,
                    &s.model.kernels.t_from_t}) {
      std::fill(k->begin(), k->end(), 0.0);
    }
    const Patch3d patch(s.model, s.patch);
    const double F = 3000, R0 = s.tyre.outer_radius_m, yr = 0.06;
    const double c = std::pow(yr, 2 - n) / (2 * 0.3);
    const auto& T = s.tyre.tread;
    const double k = T.modulus_Pa / T.thickness_m;
    const double I = std::tgamma(1 + 1 / n) * std::tgamma(2.5) / std::tgamma(2.5 + 1 / n);
    const double A = 8.0 / 3 * k * std::sqrt(2 * R0) * std::pow(c, -1 / n) * I;
    const double delta = std::pow(F / A, 1 / (1.5 + 1 / n));
    const Patch3dResult r = patch.solve(F);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_NEAR(r.sinking_m, delta, 0.01 * delta) << "n = " << n;
    EXPECT_NEAR(r.length_m, 2 * std::sqrt(2 * R0 * delta), 0.01 * r.length_m) << "n = " << n;
    EXPECT_NEAR(r.width_m, 2 * std::pow(delta / c, 1 / n), 0.01 * r.width_m) << "n = " << n;
  }
}

struct Spacing {
  std::string name;
  std::vector<std::string> coarse, fine;
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const Spacing& c, std::ostream* os) { *os << c.name; }

class Patch3dMesh : public ::testing::TestWithParam<Spacing> {};

TEST_P(Patch3dMesh, HalvingTheSpacingChangesSinkingLengthWidthByLessThanHalfAPercent) {
  expect_mesh_converged(GetParam().coarse, GetParam().fine);
}

// The default mesh of configs/sf350.yaml (0.5 mm x 2.5 mm) against half of each spacing.
INSTANTIATE_TEST_SUITE_P(
    DefaultMesh, Patch3dMesh,
    ::testing::Values(Spacing{"AlongX", {}, {"contact.unit_length_mm=0.25"}},
                      Spacing{"AcrossY", {}, {"footprint_3d.lateral_cell_mm=1.25"}}),
    [](const auto& info) { return info.param.name; });

TEST(Patch3d, PressureMapRowsPerYAndCroppedToTheContact) {
  const Tyre3d s(kCoarse);
  const Patch3d patch(s.model, s.patch);
  const Patch3dResult r = patch.solve(5478);
  ASSERT_TRUE(r.ok());
  const PressureMap map = pressure_map(r, 2);
  ASSERT_EQ(map.y_mm.size(), std::size_t(r.columns));
  ASSERT_EQ(map.pressure_kPa.size(), map.y_mm.size());
  double force = 0;
  for (std::size_t j = 0; j < map.y_mm.size(); ++j) {
    ASSERT_EQ(map.pressure_kPa[j].size(), map.x_mm.size());
    EXPECT_EQ(map.pressure_kPa[j].front(), 0.0);  // the margin is outside the patch
    EXPECT_EQ(map.pressure_kPa[j].back(), 0.0);
  }
  // The map integrates to the load (pressure x cell area).
  int first = 0;
  while (!(r.section_force_N[first] > 0)) ++first;
  first -= 2;
  for (std::size_t j = 0; j < map.y_mm.size(); ++j) {
    for (std::size_t i = 0; i < map.x_mm.size(); ++i) {
      force += map.pressure_kPa[j][i] * 1e3 * r.dx_m[first + i] * r.dy_m;
    }
  }
  EXPECT_NEAR(force, 5478, kExact * 5478);
}

TEST(Patch3d, WidthGrowsWithLoadUpToTheTreadWidth) {
  const Tyre3d s(with(kCoarse, {"footprint_3d.crown.radius_mm=2000"}));
  const Patch3d patch(s.model, s.patch);
  double last = 0;
  for (const auto& r : patch.solve_all({1000, 3000, 6000, 12000, 20000})) {
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_GE(r.width_m, last);
    EXPECT_LE(r.width_m, s.patch.tread_width_m + 1e-15);
    last = r.width_m;
  }
  EXPECT_DOUBLE_EQ(last, s.patch.tread_width_m);  // the shoulder limit
}

}  // namespace
