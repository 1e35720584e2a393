// The window of a group of traction rows decided from its measured sinkage
// (discover/evidence_window.h): the rim's chord at the sinkage plus the road deflection, +10 %,
// rounded up to 10 mm, between the config's window and the largest the config reader allows.
#include "modaltyre/discover/evidence_window.h"

#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/contact/footprint.h"

namespace modaltyre::discover {
namespace {

// The chord by Pythagoras in the wheel's frame: the circle's point at height R - d above the
// centre's foot lies sqrt(R^2 - (R - d)^2) ahead.
double pythagoras_half_chord(double R, double d) { return std::sqrt(R * R - (R - d) * (R - d)); }

TEST(EvidenceWindow, TheRimsHalfChordIsThePythagoreanOne) {
  EXPECT_NEAR(rim_half_chord_m(0.3, 0.06), 0.18, 1e-15);  // a 3-4-5 triangle scaled
  for (double d : {0.001, 0.02, 0.075, 0.2})
    EXPECT_NEAR(rim_half_chord_m(0.2948, d), pythagoras_half_chord(0.2948, d), 1e-14) << d;
  EXPECT_EQ(rim_half_chord_m(0.3, 0), 0);
  EXPECT_NEAR(rim_half_chord_m(0.3, 0.5), 0.3, 1e-15);  // past the centre: the diameter
}

contact::TyreConfig config_with_window(double window_m) {
  contact::TyreConfig c;
  c.outer_radius_m = 0.2948;
  c.mesh.unit_length_m = 0.004;
  c.mesh.window_m = window_m;
  return c;
}

TEST(EvidenceWindow, ADeepRowGetsTheChordAtItsSinkagePlusDeflectionWithTheMargin) {
  // SF-350 (R 294.8 mm) on sandy loam at 3.5 kN, slip 0.5: 60.45 mm of soil sinkage, 14.77 mm
  // road deflection (the 3D default's footprint at 3.5 kN, 4 mm units): depth 75.22 mm, chord
  // 2 x 196.7 = 393.4 mm, x 1.1 = 432.7 -> 440 mm (`traction` needs more than 360, 400 is enough).
  const contact::TyreConfig c = config_with_window(0.36);
  const EvidenceWindow w = evidence_window(c, 0.06045, 0.01477);
  const double chord = 2 * pythagoras_half_chord(0.2948, 0.06045 + 0.01477);
  EXPECT_NEAR(chord, 0.3934, 1e-4);
  EXPECT_TRUE(w.grown) << w.why;
  EXPECT_NEAR(w.window_m, std::ceil(chord * (1 + kWindowMargin) * 100) / 100, 1e-12);
  EXPECT_NEAR(w.window_m, 0.44, 1e-12);
  // Without the deflection: chord 2 x 178.3 = 356.6 mm, x 1.1 -> 400 mm.
  EXPECT_NEAR(evidence_window(c, 0.06045, 0).window_m, 0.40, 1e-12);
}

TEST(EvidenceWindow, ShallowOrUnmeasuredRowsKeepTheConfigsWindow) {
  const contact::TyreConfig c = config_with_window(0.36);
  // 20 mm + 10 mm: chord 2 x 129.6 mm x 1.1 = 285 mm < 360.
  const EvidenceWindow shallow = evidence_window(c, 0.02, 0.01);
  EXPECT_FALSE(shallow.grown);
  EXPECT_EQ(shallow.window_m, c.mesh.window_m);
  const EvidenceWindow none = evidence_window(c, 0, 0.01);
  EXPECT_FALSE(none.grown);
  EXPECT_EQ(none.window_m, c.mesh.window_m);
}

TEST(EvidenceWindow, TheWindowIsCappedAtTheLargestTheConfigReaderAllows) {
  // 250 mm + 20 mm: chord 2 x 293.8 mm = 587.5 mm, x 1.1 -> 650 mm, below pi R = 926 mm.
  const contact::TyreConfig c = config_with_window(0.36);
  const EvidenceWindow w = evidence_window(c, 0.25, 0.02);
  EXPECT_NEAR(w.window_m, 0.65, 1e-12);
  EXPECT_EQ(w.why.find("capped"), std::string::npos) << w.why;
  // On 0.02 mm units the reader allows 20000 units = 400 mm at most.
  contact::TyreConfig fine = c;
  fine.mesh.unit_length_m = 0.00002;
  const EvidenceWindow capped = evidence_window(fine, 0.25, 0.02);
  EXPECT_NEAR(contact::max_window_m(fine), 0.4, 1e-12);
  EXPECT_NEAR(capped.window_m, 0.4, 1e-12);
  EXPECT_TRUE(capped.grown);
  EXPECT_NE(capped.why.find("capped"), std::string::npos) << capped.why;
}

}  // namespace
}  // namespace modaltyre::discover
