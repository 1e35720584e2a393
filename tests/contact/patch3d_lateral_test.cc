// The lateral belt of the 3D patch (contact/patch3d.h LateralBelt): the beam operator against
// beam theory (simply supported span under a uniform load; a free strip's rigid motion left to
// the carcass), a stiff belt equal to the laterally rigid patch, the reduction equal to the full
// cell solve, a flat crown on a rigid carcass against the analytic beam on the tread's Winkler
// foundation, symmetry, mesh convergence across y, equilibrium and complementarity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/core/errors.h"
#include "patch3d_fixture.h"

namespace {

using namespace modaltyre;
using namespace modaltyre::contact;
using namespace modaltyre::contact::testing;

// A flexible belt whose width stays inside the tread (free strip on the belt's foundation).
const std::vector<std::string> kFlexible = {"footprint_3d.crown.radius_mm=300",
                                            "footprint_3d.lateral_belt.supports=free",
                                            "footprint_3d.lateral_belt.bending_stiffness_Nm=0.5",
                                            "footprint_3d.lateral_belt.foundation_MPa_per_m=100"};
// The strip's bending needs 2.5 mm columns (docs/footprint.md section 7): at the default
// config's 5 mm the 8321 N width of kFlexible reaches the tread edge (150 mm against 145.4 mm
// at 1.25 mm).
const std::vector<std::string> kFlexibleMesh = {"footprint_3d.lateral_cell_mm=2.5"};
LateralBelt belt(BeltSupports supports, double D, double k = 0) {
  LateralBelt b;
  b.enabled = true;
  b.supports = supports;
  b.bending_stiffness_Nm = D;
  b.foundation_Pa_m = k;
  return b;
}

TEST(LateralBelt, SimplySupportedStripUnderUniformLoadHasTheBeamDeflection) {
  // Uniform pressure q on a span L simply supported: v = q (L^3 y' - 2 L y'^3 + y'^4) / 24 D
  // (y' from a support), whose mean is q L^4 / (120 D).
  const double W = 0.15, ds = 5e-4, D = 2.0, q = 1e5;
  const int ny = 60;
  const Eigen::MatrixXd G = lateral_belt_compliance(belt(BeltSupports::shoulders, D), W, ny, ds);
  const Eigen::VectorXd f = Eigen::VectorXd::Constant(ny, q * ds * W / ny);
  const Eigen::VectorXd v = G * f;
  EXPECT_NEAR(v.mean(), q * std::pow(W, 4) / (120 * D), 1e-6 * v.mean());
  // Each cell's mean deflection: the integral of the quartic over the cell.
  auto integral = [&](double y) {  // of v from 0 to y
    return q / (24 * D) * (W * W * W * y * y / 2 - W * std::pow(y, 4) / 2 + std::pow(y, 5) / 5);
  };
  for (int j = 0; j < ny; ++j) {
    const double a = j * W / ny, b = (j + 1) * W / ny;
    EXPECT_NEAR(v(j), (integral(b) - integral(a)) / (b - a), 1e-6 * v.maxCoeff()) << "cell " << j;
  }
}

TEST(LateralBelt, OperatorIsSymmetricPositiveSemidefiniteAndVanishesForAStiffBelt) {
  const double W = 0.15, ds = 5e-4;
  for (const LateralBelt& b :
       {belt(BeltSupports::shoulders, 0.5), belt(BeltSupports::free, 0.5, 1e8)}) {
    LateralBelt wide = b;
    if (b.supports == BeltSupports::shoulders) wide.support_span_m = 0.19;
    for (const LateralBelt& c : {b, wide}) {
      const Eigen::MatrixXd G = lateral_belt_compliance(c, W, 30, ds);
      EXPECT_LT((G - G.transpose()).cwiseAbs().maxCoeff(), 1e-15 * G.cwiseAbs().maxCoeff());
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(G).eigenvalues();
      EXPECT_GT(ev.minCoeff(), -1e-12 * ev.maxCoeff());
      // A stiff belt's own deflection is bending-limited: it falls as 1/D towards zero.
      LateralBelt stiff = c, stiffer = c;
      stiff.bending_stiffness_Nm = 1e6 * c.bending_stiffness_Nm;
      stiffer.bending_stiffness_Nm = 1e7 * c.bending_stiffness_Nm;
      const double gs = lateral_belt_compliance(stiff, W, 30, ds).cwiseAbs().maxCoeff();
      const double gss = lateral_belt_compliance(stiffer, W, 30, ds).cwiseAbs().maxCoeff();
      EXPECT_LT(gs, 1e-3 * G.cwiseAbs().maxCoeff());
      EXPECT_NEAR(gss / gs, 0.1, 1e-3);
    }
  }
}

TEST(LateralBelt, FreeStripLeavesItsRigidMotionToTheCarcass) {
  // On a uniform foundation a free strip under a uniform load translates rigidly: nothing of
  // it is the belt's own deflection. Under any load the belt's own deflection has no mean (the
  // foundation's reaction to it has no resultant: the carcass carries the section's force).
  const double W = 0.15, ds = 5e-4;
  const int ny = 40;
  const Eigen::MatrixXd G = lateral_belt_compliance(belt(BeltSupports::free, 0.5, 1e8), W, ny, ds);
  Eigen::VectorXd uniform = Eigen::VectorXd::Ones(ny), bump(ny), ramp(ny);
  for (int j = 0; j < ny; ++j) {
    const double y = -0.5 * W + (j + 0.5) * W / ny;
    bump(j) = std::exp(-y * y / (2 * 0.02 * 0.02));
    ramp(j) = std::max(y, 0.0);
  }
  const Eigen::VectorXd vb = G * bump, vr = G * ramp;
  const double scale = vb.cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.0);
  EXPECT_LT((G * uniform).cwiseAbs().maxCoeff(), 1e-10 * scale);
  EXPECT_LT(std::abs(vb.sum()), 1e-10 * scale * ny);
  EXPECT_LT(std::abs(vr.sum()), 1e-10 * vr.cwiseAbs().maxCoeff() * ny);
  EXPECT_GT(vb(ny / 2), 0.0);  // pressed in where the bump pushes, out at the edges
  EXPECT_LT(vb(0), 0.0);
}

TEST(LateralBelt, StiffBeltEqualsTheLaterallyRigidPatch) {
  const Tyre3d s(kCoarse);
  Patch3dSettings stiff = s.patch;
  stiff.lateral_belt = belt(BeltSupports::shoulders, 1e16);
  const Patch3d rigid(s.model, s.patch), flex(s.model, stiff);
  for (double F : {2131.0, 8321.0}) {
    const Patch3dResult a = rigid.solve(F), b = flex.solve(F);
    ASSERT_TRUE(a.ok() && b.ok()) << a.message << " / " << b.message;
    EXPECT_NEAR(b.sinking_m, a.sinking_m, kExact * a.sinking_m);
    const double fmax = *std::max_element(a.cell_force_N.begin(), a.cell_force_N.end());
    for (std::size_t k = 0; k < a.cell_force_N.size(); ++k) {
      EXPECT_NEAR(b.cell_force_N[k], a.cell_force_N[k], 1e-8 * fmax) << "cell " << k;
    }
    EXPECT_NEAR(b.width_m, a.width_m, 1e-3 * a.width_m);  // the edge interpolated vs exact
    EXPECT_NEAR(b.length_m, a.length_m, kExact * a.length_m);
  }
}

TEST(LateralBelt, ReductionEqualsTheFullCellSolve) {
  const std::vector<std::string> shoulders = {"footprint_3d.lateral_belt.bending_stiffness_Nm=50",
                                              "footprint_3d.lateral_belt.tension_N_per_m=12000",
                                              "footprint_3d.lateral_belt.support_span_mm=170"};
  for (const auto& variant : {kFlexible, shoulders}) {
    const Tyre3d s(with(kCoarse, variant));
    expect_reduction_equals_full_cell_solve(Patch3d(s.model, s.patch), {2131, 8321});
  }
}

TEST(LateralBelt, FlatCrownOnARigidCarcassIsABeamOnTheTreadFoundation) {
  // Carcass removed, flat crown, belt simply supported at the tread edges y = +-c: the centre
  // section (sag 0) pressed in by the sinking d is the beam D v'''' + k v = k d on the tread's
  // Winkler foundation k = E/h, v(+-c) = v''(+-c) = 0. With A = cosh(by) cos(by),
  // B = sinh(by) sin(by), b^4 = k / 4D: the pressure is k d (C1 A + C2 B) with
  // C1 A + C2 B = 1 and (A'' ~ -B, B'' ~ A) C1 B - C2 A = 0 at y = c.
  const double bc = 1.2, c = 0.075;
  Tyre3d s(with(kCoarse, {"footprint_3d.crown.shape=flat", "footprint_3d.lateral_cell_mm=1",
                          "contact.unit_length_mm=1"}));
  for (auto* k : {&s.model.kernels.r_from_r, &s.model.kernels.r_from_t, &s.model.kernels.t_from_r,
                  &s.model.kernels.t_from_t}) {
    std::fill(k->begin(), k->end(), 0.0);
  }
  const auto& T = s.tyre.tread;
  const double kf = T.modulus_Pa / T.thickness_m, beta = bc / c;
  Patch3dSettings set = s.patch;
  set.lateral_belt = belt(BeltSupports::shoulders, kf / (4 * std::pow(beta, 4)));
  const Patch3d patch(s.model, set);
  const Patch3dResult r = patch.solve(3000);
  ASSERT_TRUE(r.ok()) << r.message;
  int i0 = 0;
  for (int i = 0; i < r.sections; ++i) {
    if (std::abs(s.model.theta[i]) < std::abs(s.model.theta[i0])) i0 = i;
  }
  ASSERT_EQ(s.model.sag(i0), 0.0);
  const double d = r.sinking_m;
  const double A = std::cosh(bc) * std::cos(bc), B = std::sinh(bc) * std::sin(bc);
  const double C1 = A / (A * A + B * B), C2 = B / (A * A + B * B);
  auto p = [&](double y) {
    const double x = beta * y;
    return kf * d * (C1 * std::cosh(x) * std::cos(x) + C2 * std::sinh(x) * std::sin(x));
  };
  // Cell means by 3-point Gauss.
  const double g = std::sqrt(0.6);
  for (int j = 0; j < r.columns; ++j) {
    const double y = r.y_m[j], h = 0.5 * r.dy_m;
    const double mean = (5 * p(y - g * h) + 8 * p(y) + 5 * p(y + g * h)) / 18;
    EXPECT_NEAR(r.pressure_Pa(i0, j), mean, 1e-4 * kf * d) << "column " << j;
  }
  EXPECT_LT(p(0), 0.5 * p(c));  // the belt bows in: the shoulders carry more than the centre
}

TEST(LateralBelt, SymmetricAcrossTheTread) {
  const Tyre3d s(with(kCoarse, kFlexible));
  expect_symmetric_in_y(Patch3d(s.model, s.patch).solve(5478));
}

TEST(LateralBelt, EquilibriumComplementarityNoTensionNoPenetration) {
  const Tyre3d s(with(kFlexible, kFlexibleMesh));
  const Patch3d patch(s.model, s.patch);
  for (const Patch3dResult& r : patch.solve_all({2131, 5478, 8321})) {
    expect_equilibrium_and_complementarity(r);
    EXPECT_GT(r.width_m, 0.0);
    EXPECT_LT(r.width_m, s.patch.tread_width_m);  // the edge is inside the tread here
  }
}

TEST(LateralBelt, HalvingTheLateralCellChangesSinkingLengthWidthByLessThanHalfAPercent) {
  expect_mesh_converged(with(kFlexible, kFlexibleMesh),
                        with(kFlexible, {"footprint_3d.lateral_cell_mm=1.25"}));
}

TEST(LateralBelt, ConfigErrorsNameTheKey) {
  auto read = [](const std::string& yaml) {
    const ConfigTree t = ConfigTree::from_string(yaml, "belt.yaml");
    return read_patch3d_settings(t.root().section("footprint_3d"));
  };
  EXPECT_FALSE(read("footprint_3d: {tread_width_mm: 150}").lateral_belt.enabled);
  EXPECT_TRUE(read("footprint_3d: {lateral_belt: {bending_stiffness_Nm: 1}}").lateral_belt.enabled);
  const std::pair<const char*, const char*> bad[] = {
      {"footprint_3d: {lateral_belt: {supports: free}}", "foundation_MPa_per_m"},
      {"footprint_3d: {lateral_belt: {support_span_mm: 100}}", "support_span_mm"},
      {"footprint_3d: {lateral_belt: {bending_stiffness_Nm: 0}}", "bending_stiffness_Nm"},
      {"footprint_3d: {lateral_cell_mm: 0.25, lateral_belt: {}}", "bending_stiffness_Nm"},
      {"footprint_3d: {lateral_belt: {supports: hinged}}", "supports"}};
  expect_refused_naming_the_key(bad);
}

}  // namespace
