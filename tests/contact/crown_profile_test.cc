// The tread's crown profile (contact/crown_profile.h): drops, their inverse (the lateral edge of
// a section pressed in by d), the shoulder arc's tangency, the power crown's limits and the config
// errors.
#include "modaltyre/contact/crown_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "modaltyre/core/errors.h"

namespace {

using namespace modaltyre;
using namespace modaltyre::contact;

CrownProfile circular(double r1, double r2 = 0, double y1 = 0) {
  CrownProfile c;
  c.radius_m = r1;
  c.shoulder_radius_m = r2;
  c.shoulder_start_m = y1;
  return c;
}

CrownProfile power(double r, double n, double y_ref) {
  CrownProfile c;
  c.shape = CrownShape::power;
  c.radius_m = r;
  c.exponent = n;
  c.reference_half_width_m = y_ref;
  return c;
}

TEST(CrownProfile, HalfWidthInvertsTheDropOnEveryShape) {
  CrownProfile contour;
  contour.shape = CrownShape::contour;
  contour.contour_y_m = {0, 0.03, 0.06, 0.08};
  contour.contour_drop_m = {0, 0.0005, 0.003, 0.008};
  for (const CrownProfile& c : {circular(0.8), circular(0.8, 0.1, 0.05), contour,
                                power(0.8, 1.3, 0.06), power(0.8, 3.5, 0.06)}) {
    c.validate();
    for (double y = 0.005; y < 0.09; y += 0.005) {
      EXPECT_NEAR(c.half_width_m(c.drop_m(y)), y, 1e-12) << "y = " << y;
      EXPECT_DOUBLE_EQ(c.drop_m(-y), c.drop_m(y));  // symmetric
    }
  }
}

TEST(CrownProfile, CircularCrownIsTheArcAndItsChord) {
  const CrownProfile c = circular(0.5);
  EXPECT_NEAR(c.drop_m(0.1), 0.5 - std::sqrt(0.25 - 0.01), 1e-15);
  const double d = 0.002;
  EXPECT_NEAR(c.half_width_m(d), std::sqrt(2 * 0.5 * d - d * d), 1e-15);
}

TEST(CrownProfile, ShoulderArcJoinsTheCrownArcWithTheSameHeightAndSlope) {
  const CrownProfile c = circular(0.8, 0.1, 0.05);
  const double y1 = 0.05, h = 1e-7;
  EXPECT_NEAR(c.drop_m(y1 - 1e-12), c.drop_m(y1 + 1e-12), 1e-12);
  const double left = (c.drop_m(y1) - c.drop_m(y1 - h)) / h;
  const double right = (c.drop_m(y1 + h) - c.drop_m(y1)) / h;
  EXPECT_NEAR(left, right, 1e-5 * left);
  // Rounder than the crown: beyond y1 it drops faster than the crown arc would.
  EXPECT_GT(c.drop_m(0.07), circular(0.8).drop_m(0.07));
  EXPECT_NEAR(c.reach_m(), 0.05 + 0.1 * (1 - 0.05 / 0.8), 1e-15);
}

TEST(CrownProfile, PowerCrownOfExponentTwoIsTheCircularCrownsParabola) {
  // n = 2: z = y^2 / 2R whatever the reference half-width, the circular crown's small-drop
  // limit (R - sqrt(R^2 - y^2) = y^2 / 2R + y^4 / 8R^3 + ...).
  const double r = 1.06;
  for (double y_ref : {0.03, 0.075}) {
    const CrownProfile p = power(r, 2, y_ref);
    for (double y = 0.01; y <= 0.075; y += 0.005) {
      EXPECT_NEAR(p.drop_m(y), y * y / (2 * r), 1e-15);
      const double arc = circular(r).drop_m(y);
      EXPECT_NEAR(p.drop_m(y), arc, std::pow(y, 4) / (8 * r * r * r) * 1.01);
    }
    const double d = 0.002;
    EXPECT_NEAR(p.half_width_m(d), std::sqrt(2 * r * d), 1e-15);
  }
}

TEST(CrownProfile, PowerCrownSharesTheDropAtTheReferenceHalfWidth) {
  // Every exponent passes through the parabola's drop at y_ref; a larger exponent is flatter
  // inside y_ref and steeper outside it, and the flat crown is its limit n -> infinity inside.
  const double r = 1.0, y_ref = 0.06, z_ref = y_ref * y_ref / (2 * r);
  for (double n : {1.2, 2.0, 4.0}) EXPECT_NEAR(power(r, n, y_ref).drop_m(y_ref), z_ref, 1e-15);
  EXPECT_LT(power(r, 4, y_ref).drop_m(0.03), power(r, 2, y_ref).drop_m(0.03));
  EXPECT_GT(power(r, 4, y_ref).drop_m(0.07), power(r, 2, y_ref).drop_m(0.07));
  EXPECT_LT(power(r, 200, y_ref).drop_m(0.05), 1e-15);
  // The edge of a section pressed in by d grows as d^(1/n).
  const double d1 = 0.001, d2 = 0.002;
  for (double n : {1.2, 3.0}) {
    const CrownProfile c = power(r, n, y_ref);
    EXPECT_NEAR(std::log(c.half_width_m(d2) / c.half_width_m(d1)) / std::log(d2 / d1), 1 / n,
                1e-12);
  }
  EXPECT_TRUE(std::isinf(power(r, 1.5, y_ref).reach_m()));
}

TEST(CrownProfile, FlatCrownPutsTheEdgeAtTheShoulder) {
  CrownProfile c;
  c.shape = CrownShape::flat;
  EXPECT_EQ(c.drop_m(0.07), 0.0);
  EXPECT_TRUE(std::isinf(c.half_width_m(1e-6)));
}

TEST(CrownProfile, ConfigErrorsNameTheKey) {
  auto read = [](const std::string& yaml) {
    const ConfigTree t = ConfigTree::from_string(yaml, "crown.yaml");
    return read_crown_profile(t.root().section("crown"));
  };
  EXPECT_NO_THROW(read("crown: {shape: circular, radius_mm: 900}"));
  try {
    read("crown: {shape: contour, contour_y_mm: [0, 10, 20], contour_drop_mm: [0, 2, 1]}");
    FAIL() << "a falling contour was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("crown.contour_drop_mm"), std::string::npos) << e.what();
  }
  try {
    read("crown: {radius_mm: 900, shoulder_radius_mm: 100}");
    FAIL() << "a shoulder without its start was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("shoulder_start_mm"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read("crown: {shape: oval}"), InputError);
  const CrownProfile p =
      read("crown: {shape: power, radius_mm: 900, exponent: 3, reference_half_width_mm: 60}");
  EXPECT_EQ(p.shape, CrownShape::power);
  EXPECT_DOUBLE_EQ(p.exponent, 3);
  EXPECT_DOUBLE_EQ(p.reference_half_width_m, 0.06);
  for (const auto& [yaml, key] : std::vector<std::pair<std::string, std::string>>{
           {"crown: {shape: power, radius_mm: 900, exponent: 3}", "reference_half_width_mm"},
           {"crown: {shape: power, exponent: 1, reference_half_width_mm: 60}", "exponent"},
           {"crown: {shape: power, exponent: 0.5, reference_half_width_mm: 60}", "exponent"},
           {"crown: {shape: power, reference_half_width_mm: 0}", "reference_half_width_mm"}}) {
    try {
      read(yaml);
      FAIL() << "accepted: " << yaml;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("crown." + key), std::string::npos) << e.what();
    }
  }
}

}  // namespace
