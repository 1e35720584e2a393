// What the EMA front end says when it is unsure (issue 38): a DOF no FRF measured is noted per
// point and left out of the shapes (NaN, empty in the hammer CSV), a poor MPC or stabilisation
// and a band that cuts modes are warned about, an FRF type most modes contradict is named with
// the type the data fit, and unscaled shapes are marked in the hammer CSV for its reader.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>

#include "ema_test_support.h"
#include "modaltyre/ema/ema.h"
#include "modaltyre/modal/hammer_data.h"
#include "planted_models.h"

namespace modaltyre::ema {
namespace {

using modaltyre_test::SynthOptions;

bool has(const std::vector<std::string>& v, const std::string& needle) {
  for (const auto& s : v) {
    if (s.find(needle) != std::string::npos) return true;
  }
  return false;
}

std::string all(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

EmaOptions band(double lo, double hi) {
  EmaOptions o;
  o.band_lo_hz = lo;
  o.band_hi_hz = hi;
  return o;
}

// The ring model's tangential FRF at point 5 was never measured: a note names the point, its
// tangential value is NaN in every mode (not 0), the radial ones are there, and the hammer CSV
// leaves the cell empty, which the hammer reader refuses naming the point.
TEST(EmaUnsure, UnmeasuredDofIsNotedAndLeftOutOfTheShapes) {
  SynthOptions so;
  so.noise = 0.001;
  FrfSet set = modaltyre_test::synthesise(modaltyre_test::ring_model(), so);
  std::erase_if(set.channels, [](const FrfChannel& c) {
    return c.response == Dof{5, Direction::tangential};
  });
  const EmaResult r = run_ema(set, band(60, 330));
  ASSERT_FALSE(r.modes.empty());
  EXPECT_TRUE(has(r.notes, "point 5 tangential: no FRF measured")) << all(r.notes);
  for (const auto& m : r.modes) {
    EXPECT_TRUE(std::isnan(m.tangential[4])) << m.freq_hz;
    EXPECT_FALSE(std::isnan(m.radial[4])) << m.freq_hz;
    EXPECT_FALSE(std::isnan(m.tangential[3])) << m.freq_hz;
  }
  const std::string csv = hammer_csv(r);
  EXPECT_NE(csv.find(",5,120.000000,"), std::string::npos);
  EXPECT_EQ(csv.find("nan"), std::string::npos) << csv.substr(0, 400);
  const auto path = std::filesystem::temp_directory_path() /
                    ("modaltyre_ema_missing_dof_" + std::to_string(::getpid()) + ".csv");
  std::ofstream(path) << csv;
  try {
    modal::read_hammer_csv(path.string());
    ADD_FAILURE() << "an empty shape cell was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().key, "tangential");
    EXPECT_NE(std::string(e.what()).find("measured no FRF at point 5"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove(path);
}

// The bundled SF-350 modes with 1 % noise on the default band (0.25-400 Hz): the close pairs
// come out with MPC far below 1 (0.12 and 0.81 for the order-1 pair), which is warned about per
// mode, with a suggested band around the modes; on that band no MPC warning remains.
TEST(EmaUnsure, PoorMpcOnTheDefaultBandIsWarnedWithABandThatFixesIt) {
  SynthOptions so;
  so.noise = 0.01;
  const FrfSet set = modaltyre_test::synthesise(modaltyre_test::bundled_model(), so);
  const EmaResult wide = run_ema(set, EmaOptions{});
  EXPECT_TRUE(has(wide.warnings, "MPC 0.1")) << all(wide.warnings);
  EXPECT_TRUE(has(wide.warnings, "with the default band")) << all(wide.warnings);
  EXPECT_TRUE(has(wide.warnings, "try --band ")) << all(wide.warnings);
  // The suggested band, read back from the warning.
  std::string suggestion;
  for (const auto& w : wide.warnings) {
    const auto at = w.find("try --band ");
    if (at != std::string::npos) suggestion = w.substr(at + 11, w.find(' ', at + 11) - at - 11);
  }
  const auto colon = suggestion.find(':');
  ASSERT_NE(colon, std::string::npos) << suggestion;
  const EmaResult narrow = run_ema(
      set, band(std::stod(suggestion.substr(0, colon)), std::stod(suggestion.substr(colon + 1))));
  EXPECT_FALSE(has(narrow.warnings, "MPC")) << all(narrow.warnings);
  EXPECT_EQ(narrow.modes.size(), 14u);
}

// A band whose upper edge sits inside a mode's resonance: warned, naming the mode.
TEST(EmaUnsure, BandEdgeCuttingAModeIsWarned) {
  SynthOptions so;
  so.noise = 0.001;
  const FrfSet set = modaltyre_test::synthesise(modaltyre_test::ring_model(), so);
  const EmaResult r = run_ema(set, band(60, 280));  // the 275 Hz mode's half-power band is 6.6 Hz
  EXPECT_TRUE(has(r.warnings, "upper edge (280.0 Hz)")) << all(r.warnings);
  EXPECT_TRUE(has(r.warnings, "mode at 275.0 Hz")) << all(r.warnings);
  const EmaResult inside = run_ema(set, band(60, 330));
  EXPECT_FALSE(has(inside.warnings, "edge")) << all(inside.warnings);
}

// Accelerance data read as mobility: most poles fail the driving-point test, and the warning
// names accelerance, under which they pass.
TEST(EmaUnsure, WrongFrfTypeIsNamedWithTheTypeTheDataFit) {
  SynthOptions so;
  so.noise = 0.01;
  FrfSet set = modaltyre_test::synthesise(modaltyre_test::bundled_model(), so);
  set.type = FrfType::mobility;
  const EmaResult r = run_ema(set, band(80, 350));
  EXPECT_TRUE(has(r.warnings, "fail the driving-point test")) << all(r.warnings);
  EXPECT_TRUE(has(r.warnings, "are the FRFs accelerance?")) << all(r.warnings);
  set.type = FrfType::accelerance;
  const EmaResult right = run_ema(set, band(80, 350));
  EXPECT_FALSE(has(right.warnings, "driving-point")) << all(right.warnings);
}

// --unscaled shapes carry a marker column that the hammer reader reads; a mass-normalised file
// has no marker column. Both carry the standard deviations (issue 35), which the reader reads.
TEST(EmaUnsure, UnscaledShapesAreMarkedForTheHammerReader) {
  SynthOptions so;
  so.noise = 0.001;
  FrfSet set = modaltyre_test::synthesise(modaltyre_test::ring_model(), so);
  EmaOptions o = band(60, 330);
  const std::string scaled = hammer_csv(run_ema(set, o));
  EXPECT_EQ(scaled.rfind("mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential,"
                         "freq_std_hz,damping_std,radial_std,tangential_std\n",
                         0),
            0u);
  o.unscaled = true;
  const std::string unscaled = hammer_csv(run_ema(set, o));
  EXPECT_NE(unscaled.find("radial_std,tangential_std,scaling\n"), std::string::npos);
  EXPECT_NE(unscaled.find(",unscaled\n"), std::string::npos);
  const auto dir = std::filesystem::temp_directory_path();
  const std::string pid = std::to_string(::getpid());
  const auto p1 = dir / ("modaltyre_ema_scaled_" + pid + ".csv");
  const auto p2 = dir / ("modaltyre_ema_unscaled_" + pid + ".csv");
  std::ofstream(p1) << scaled;
  std::ofstream(p2) << unscaled;
  EXPECT_FALSE(modal::read_hammer_csv(p1.string()).unscaled);
  EXPECT_TRUE(modal::read_hammer_csv(p2.string()).unscaled);
  EXPECT_TRUE(modal::read_hammer_csv(p1.string()).has_std);
  EXPECT_TRUE(modal::read_hammer_csv(p2.string()).has_std);
  std::filesystem::remove(p1);
  std::filesystem::remove(p2);
}

}  // namespace
}  // namespace modaltyre::ema
