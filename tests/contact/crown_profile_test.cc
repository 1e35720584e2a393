// The tread's crown profile (contact/crown_profile.h): drops, their inverse (the lateral edge of
// a section pressed in by d), the shoulder arc's tangency and the config errors.
#include "modaltyre/contact/crown_profile.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(CrownProfile, HalfWidthInvertsTheDropOnEveryShape) {
  CrownProfile contour;
  contour.shape = CrownShape::contour;
  contour.contour_y_m = {0, 0.03, 0.06, 0.08};
  contour.contour_drop_m = {0, 0.0005, 0.003, 0.008};
  for (const CrownProfile& c : {circular(0.8), circular(0.8, 0.1, 0.05), contour}) {
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
}

}  // namespace
