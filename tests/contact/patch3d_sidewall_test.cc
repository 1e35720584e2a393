// The sidewalls' pneumatic softening (contact/sidewall_membrane.h, footprint_3d.sidewall): the
// membrane law against its parametric closed form, the lost force's limits, the 3D patch's fixed
// point (equilibrium, complementarity, e(u) consistent with the result), the p -> 0 limit and the
// absent key (the patch of today, bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "modaltyre/contact/sidewall_membrane.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "patch3d_fixture.h"

namespace {

using namespace modaltyre;
using namespace modaltyre::contact;
using namespace modaltyre::contact::testing;

constexpr double kP = 230e3;  // SF-350's inflation pressure [Pa]
constexpr double kL = 0.130;  // meridian length [m]

// The arc in its half-angle a (no bisection): chord L sin(a)/a, pull (p L/2) cos(a)/a,
// stiffness dF/dc = (dF/da) / (dc/da).
double chord_at(double a) { return kL * std::sin(a) / a; }
double pull_at(double a) { return 0.5 * kP * kL * std::cos(a) / a; }
double stiffness_at(double a) {
  const double dF = 0.5 * kP * kL * (-a * std::sin(a) - std::cos(a)) / (a * a);
  const double dc = kL * (a * std::cos(a) - std::sin(a)) / (a * a);
  return dF / dc;
}

SidewallMembrane wall_at(double a0) { return {true, chord_at(a0), kL}; }

TEST(SidewallMembrane, HalfAngleInvertsSinOverAngle) {
  for (double a : {0.05, 0.4, 0.79, 1.13, 2.0, 3.0}) {
    EXPECT_NEAR(meridian_half_angle(std::sin(a) / a), a, 1e-12 * a);
  }
  EXPECT_TRUE(std::isnan(meridian_half_angle(1.0)));
  EXPECT_TRUE(std::isnan(meridian_half_angle(0.0)));
}

TEST(SidewallMembrane, PullAndStiffnessMatchTheArc) {
  for (double a : {0.5, 0.79, 1.13}) {
    const double c = chord_at(a);
    EXPECT_NEAR(sidewall_pull_N_per_m(kP, kL, c), pull_at(a), 1e-10 * pull_at(a));
    EXPECT_NEAR(sidewall_stiffness_N_per_m2(kP, kL, c), stiffness_at(a), 1e-10 * stiffness_at(a));
    // And the stiffness is the pull's derivative (central differences, O(h^2)).
    const double h = 1e-6;
    const double fd =
        (sidewall_pull_N_per_m(kP, kL, c + h) - sidewall_pull_N_per_m(kP, kL, c - h)) / (2 * h);
    EXPECT_NEAR(sidewall_stiffness_N_per_m2(kP, kL, c), fd, 1e-6 * fd);
  }
}

TEST(SidewallMembrane, LostForceEqualsTheHandComputedArcValue) {
  // Rest c0/L = sin(a0)/a0 at a0 = 0.79 (c0/L = 0.899); the belt pressed in to a1 = 0.95
  // (u = 10 % of c0) and pulled out to a1 = 0.70 (u < 0): e = 2 [F'(c0) u - (F(c0) - F(c1))].
  const double a0 = 0.79;
  const SidewallMembrane w = wall_at(a0);
  for (double a1 : {0.95, 0.70}) {
    const double u = chord_at(a0) - chord_at(a1);
    const double hand = 2 * (stiffness_at(a0) * u - (pull_at(a0) - pull_at(a1)));
    const double e = sidewall_lost_force_N_per_m(w, kP, u);
    EXPECT_NEAR(e, hand, 1e-9 * std::abs(hand)) << "a1 = " << a1;
    // F is convex in c: the softening sidewalls carry less than the linear ones either way.
    EXPECT_GT(e, 0.0);
  }
}

TEST(SidewallMembrane, LostForceIsSecondOrderAndVanishesWithPressure) {
  const SidewallMembrane w = wall_at(0.79);
  // e(u) = F''(c0) u^2 - F'''(c0) u^3 / 3 + O(u^4): e(2u) / e(u) = 4 (1 - b u) + O(u^2), so
  // its distance from 4 halves with u.
  auto e = [&](double u) { return sidewall_lost_force_N_per_m(w, kP, u); };
  const double e1 = e(2e-4);
  const double gap_a = 4 - e(4e-4) / e(2e-4), gap_b = 4 - e(2e-4) / e(1e-4);
  EXPECT_GT(gap_b, 0.0);
  EXPECT_NEAR(gap_a / gap_b, 2.0, 0.05);
  // Linear in p (the membrane's tension is p rho): zero at p = 0.
  EXPECT_NEAR(sidewall_lost_force_N_per_m(w, kP * 1e-6, 2e-4), e1 * 1e-6, 1e-9 * e1 * 1e-6);
  EXPECT_EQ(sidewall_lost_force_N_per_m(w, 0, 2e-4), 0.0);
  EXPECT_EQ(sidewall_lost_force_N_per_m(SidewallMembrane{}, kP, 2e-4), 0.0);
  // Beyond the meridian's range: NaN (the 3D patch fails with its reason).
  EXPECT_TRUE(std::isnan(sidewall_lost_force_N_per_m(w, kP, w.chord_m)));
  EXPECT_TRUE(std::isnan(sidewall_lost_force_N_per_m(w, kP, w.chord_m - kL)));
}

// c0 / L = 0.8: 2 F'(c0) = 0.79 MN/m^2, inside the modes' foundation (docs/validation.md).
const std::vector<std::string> kSidewall = {"footprint_3d.sidewall.meridian_chord_mm=117",
                                            "footprint_3d.sidewall.meridian_length_mm=146.25"};

TEST(Patch3dSidewall, FixedPointIsInEquilibriumComplementaryAndConsistent) {
  const Tyre3d s(with(kCoarse, kSidewall));
  const Patch3d patch(s.model, s.patch);
  const double ds = s.model.unit_length_m;
  for (const Patch3dResult& r : patch.solve_all({2131, 8321})) {
    expect_equilibrium_and_complementarity(r);
    EXPECT_GT(r.sidewall_iterations, 1);
    ASSERT_EQ(static_cast<int>(r.sidewall_force_N.size()), r.sections);
    // The fixed point: the lost force the result carries is e(u) of its own displacement.
    double emax = 0;
    for (double e : r.sidewall_force_N) emax = std::max(emax, std::abs(e));
    ASSERT_GT(emax, 0.0);
    for (int i = 0; i < r.sections; ++i) {
      const double u = r.sinking_m - s.model.sag(i) - r.section_approach_m[i];
      EXPECT_NEAR(r.sidewall_force_N[i], sidewall_lost_force_N_per_m(s.patch.sidewall, kP, u) * ds,
                  1e-8 * emax)
          << "section " << i;
    }
  }
}

TEST(Patch3dSidewall, AndersonMixingReachesThePlainIterationsFixedPointInFewerSteps) {
  // c0 / L = 0.85 (the stronger softening of the measured band): the same fixed point by the
  // plain iteration x <- G(x) and by Anderson mixing, which needs fewer contact solves.
  const Tyre3d s(with(kCoarse, {"footprint_3d.sidewall.meridian_chord_mm=117",
                                "footprint_3d.sidewall.meridian_length_mm=137.65"}));
  Patch3dSettings plain_settings = s.patch;
  plain_settings.sidewall_anderson_depth = 0;
  ASSERT_GT(s.patch.sidewall_anderson_depth, 0);
  const auto plain = Patch3d(s.model, plain_settings).solve_all({2131, 8321});
  const auto mixed = Patch3d(s.model, s.patch).solve_all({2131, 8321});
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(plain[k].ok() && mixed[k].ok()) << plain[k].message << " / " << mixed[k].message;
    expect_equilibrium_and_complementarity(mixed[k]);
    // Both stop within 1e-11 of the sinking of the fixed point (the offset's change).
    EXPECT_NEAR(mixed[k].sinking_m, plain[k].sinking_m, 1e-9 * plain[k].sinking_m);
    ASSERT_EQ(mixed[k].section_force_N.size(), plain[k].section_force_N.size());
    for (std::size_t i = 0; i < plain[k].section_force_N.size(); ++i) {
      EXPECT_NEAR(mixed[k].section_force_N[i], plain[k].section_force_N[i], 1e-6 * mixed[k].load_N)
          << "section " << i;
    }
    EXPECT_LT(mixed[k].sidewall_iterations, plain[k].sidewall_iterations);
  }
}

TEST(Patch3dSidewall, SofteningSinksDeeperAndLinearisesTheStiffness) {
  const Tyre3d plain(kCoarse), soft(with(kCoarse, kSidewall));
  const auto a = Patch3d(plain.model, plain.patch).solve_all({2131, 8321});
  const auto b = Patch3d(soft.model, soft.patch).solve_all({2131, 8321});
  for (int k = 0; k < 2; ++k) EXPECT_GT(b[k].sinking_m, a[k].sinking_m);
  const double rise_plain = a[1].vertical_stiffness_N_m() / a[0].vertical_stiffness_N_m();
  const double rise_soft = b[1].vertical_stiffness_N_m() / b[0].vertical_stiffness_N_m();
  EXPECT_LT(rise_soft, rise_plain);
}

TEST(Patch3dSidewall, VanishesAsThePressureGoesToZero) {
  const Tyre3d plain(kCoarse), soft(with(kCoarse, kSidewall));
  const Patch3dResult ref = Patch3d(plain.model, plain.patch).solve(5478);
  auto at = [&](double p_Pa) {
    Patch3dPhysics physics;
    physics.inflation_pressure_Pa = p_Pa;
    return Patch3d(soft.model, soft.patch, physics).solve(5478);
  };
  const Patch3dResult r0 = at(0), r1 = at(230), r2 = at(23);
  ASSERT_TRUE(ref.ok() && r0.ok() && r1.ok() && r2.ok());
  // p = 0: the linear model's solve, bit for bit.
  EXPECT_EQ(r0.sinking_m, ref.sinking_m);
  EXPECT_EQ(r0.cell_force_N, ref.cell_force_N);
  EXPECT_TRUE(r0.sidewall_force_N.empty());
  // p -> 0: the extra sinking is O(p) (e is linear in p at fixed u): a tenth of the pressure,
  // a tenth of it.
  const double d1 = r1.sinking_m - ref.sinking_m, d2 = r2.sinking_m - ref.sinking_m;
  EXPECT_GT(d1, 0.0);
  EXPECT_NEAR(d1 / d2, 10.0, 0.01 * 10.0);
}

TEST(Patch3dSidewall, AbsentKeyIsTodaysPatch) {
  const Tyre3d s(kCoarse);
  EXPECT_FALSE(s.patch.sidewall.enabled);
  const Patch3dResult r = Patch3d(s.model, s.patch).solve(5478);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.sidewall_iterations, 0);
  EXPECT_TRUE(r.sidewall_force_N.empty());
}

TEST(Patch3dSidewall, ConfigErrorsNameTheKey) {
  auto read = [](const std::string& yaml) {
    const ConfigTree t = ConfigTree::from_string(yaml, "wall.yaml");
    return read_patch3d_settings(t.root().section("footprint_3d"));
  };
  const Patch3dSettings ok =
      read("footprint_3d: {sidewall: {meridian_chord_mm: 117, meridian_length_mm: 130}}");
  EXPECT_TRUE(ok.sidewall.enabled);
  EXPECT_DOUBLE_EQ(ok.sidewall.chord_m, 0.117);
  EXPECT_DOUBLE_EQ(ok.sidewall.length_m, 0.130);
  const std::pair<const char*, const char*> bad[] = {
      {"footprint_3d: {sidewall: {meridian_length_mm: 130}}", "meridian_chord_mm"},
      {"footprint_3d: {sidewall: {meridian_chord_mm: 117}}", "meridian_length_mm"},
      {"footprint_3d: {sidewall: {meridian_chord_mm: 117, meridian_length_mm: 117}}",
       "meridian_length_mm"},
      {"footprint_3d: {sidewall: {meridian_chord_mm: -1, meridian_length_mm: 130}}",
       "meridian_chord_mm"}};
  expect_refused_naming_the_key(bad);
}

}  // namespace
