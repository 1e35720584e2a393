// Identification on FRFs synthesised from planted modes (issue 19): the ring-like model with
// and without 1 % noise, the bundled SF-350 data (16 modes, close pairs), the three FRF types,
// the roving-hammer layout, and the refusals (no driving point, no shared DOF).
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

#include "ema_match.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/ema/ema.h"
#include "planted_models.h"

namespace modaltyre::ema {
namespace {

using modaltyre_test::match;
using modaltyre_test::PlantedModel;
using modaltyre_test::SynthOptions;

EmaOptions ring_band() {
  EmaOptions o;
  o.band_lo_hz = 60;
  o.band_hi_hz = 330;
  return o;
}

std::vector<const modaltyre_test::PlantedMode*> in_band(const PlantedModel& m, double lo,
                                                        double hi) {
  std::vector<const modaltyre_test::PlantedMode*> out;
  for (const auto& p : m.modes) {
    if (p.freq_hz >= lo && p.freq_hz <= hi) out.push_back(&p);
  }
  return out;
}

struct NoiseCase {
  std::string name;
  double noise;
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const NoiseCase& c, std::ostream* os) { *os << c.name; }

class RingModel : public ::testing::TestWithParam<NoiseCase> {};

// Issue 19 item 5: every planted in-band mode found, frequency within 0.5 %, damping within
// 10 %, MAC >= 0.98, mass-normalised amplitude (overall scale and driving point) within 5 %,
// no spurious mode; the out-of-band modes (25 Hz, 420 Hz) are taken up by the residuals.
TEST_P(RingModel, FindsEveryPlantedModeWithinTolerance) {
  const PlantedModel model = modaltyre_test::ring_model();
  SynthOptions so;
  so.noise = GetParam().noise;
  const EmaResult r = run_ema(modaltyre_test::synthesise(model, so), ring_band());
  const auto planted = in_band(model, 60, 330);
  EXPECT_EQ(r.modes.size(), planted.size()) << "spurious or missing modes";
  for (const auto* p : planted) {
    const auto m = match(*p, r, p->radial[0], 0);
    ASSERT_NE(m.found, nullptr) << p->freq_hz << " Hz not found";
    EXPECT_LT(std::abs(m.freq_err), 0.005) << p->freq_hz;
    EXPECT_LT(std::abs(m.damping_err), 0.10) << p->freq_hz;
    EXPECT_GE(m.mac, 0.98) << p->freq_hz;
    EXPECT_LT(std::abs(m.scale - 1), 0.05) << p->freq_hz;
    EXPECT_LT(std::abs(m.driving_err), 0.05) << p->freq_hz;
    EXPECT_GT(m.found->mpc, 0.99) << p->freq_hz;  // real planted modes come out real
  }
  // The re-synthesis misses the noise and the residual approximation of the 25 Hz mode only.
  EXPECT_LT(r.synthesis_error, 0.02 + GetParam().noise);
  EXPECT_EQ(r.points.size(), 12u);
  EXPECT_DOUBLE_EQ(r.angle_deg[3], 90.0);
}

INSTANTIATE_TEST_SUITE_P(Noise, RingModel,
                         ::testing::Values(NoiseCase{"NoiseFree", 0.0},
                                           NoiseCase{"OnePercent", 0.01}),
                         [](const auto& info) { return info.param.name; });

// The bundled data: 16 modes, five pairs 0.6-1.5 % apart with 3-5 % damping, radial
// reference at point 1. Two modes have the reference near a node (driving-point shares 0.047
// and 0.005 of their largest value): their mass normalisation is unreliable and they are left
// out with that reason; the other 14 come back to rounding without noise.
TEST(BundledData, NoiseFreeRoundTripIsExactForTheScalableModes) {
  const PlantedModel model = modaltyre_test::bundled_model();
  EmaOptions o;
  o.band_lo_hz = 80;
  o.band_hi_hz = 350;
  const EmaResult r = run_ema(modaltyre_test::synthesise(model, SynthOptions{}), o);
  ASSERT_EQ(r.modes.size(), 14u);
  // The two near-node modes are dropped with that reason. On noise-free data the over-modelled
  // LSCF orders fit the rational FRFs exactly, so how many computational poles reach the LSFD
  // step follows the last bits of the arithmetic (it differed between two x86-64 hosts' libm);
  // each must be dropped as one, and none may pass as a mode (the 14 above).
  int near_node = 0;
  for (const auto& d : r.dropped) {
    if (std::abs(d.freq_hz - 210.787) < 0.01 || std::abs(d.freq_hz - 250.064) < 0.01) {
      EXPECT_NE(d.reason.find("near a node"), std::string::npos) << d.freq_hz;
      ++near_node;
    } else {
      EXPECT_NE(d.reason.find("computational pole"), std::string::npos)
          << d.freq_hz << " Hz: " << d.reason;
    }
  }
  EXPECT_EQ(near_node, 2);
  for (const auto& p : model.modes) {
    if (std::abs(p.freq_hz - 210.787) < 0.01 || std::abs(p.freq_hz - 250.064) < 0.01) continue;
    const auto m = match(p, r, p.radial[0], 0, 0.003);
    ASSERT_NE(m.found, nullptr) << p.freq_hz;
    EXPECT_LT(std::abs(m.freq_err), 1e-5) << p.freq_hz;
    EXPECT_LT(std::abs(m.damping_err), 1e-3) << p.freq_hz;
    EXPECT_GT(m.mac, 0.9999) << p.freq_hz;
    EXPECT_LT(std::abs(m.scale - 1), 1e-3) << p.freq_hz;
  }
  EXPECT_LT(r.synthesis_error, 1e-3);
}

// With 1 % noise (seed 19) the close pairs are at the limit of one reference. Tolerances stated
// for this case (docs/ema.md): all 14 scalable modes found, frequency within 0.25 %, damping
// within 5 %, MAC >= 0.99, mass-normalised scale within 10 %, nothing spurious.
TEST(BundledData, OnePercentNoise) {
  const PlantedModel model = modaltyre_test::bundled_model();
  EmaOptions o;
  o.band_lo_hz = 80;
  o.band_hi_hz = 350;
  SynthOptions so;
  so.noise = 0.01;
  const EmaResult r = run_ema(modaltyre_test::synthesise(model, so), o);
  EXPECT_EQ(r.modes.size(), 14u);
  for (const auto& p : model.modes) {
    if (std::abs(p.freq_hz - 210.787) < 0.01 || std::abs(p.freq_hz - 250.064) < 0.01) continue;
    const auto m = match(p, r, p.radial[0], 0, 0.0025);
    ASSERT_NE(m.found, nullptr) << p.freq_hz;
    EXPECT_LT(std::abs(m.freq_err), 0.0025) << p.freq_hz;
    EXPECT_LT(std::abs(m.damping_err), 0.05) << p.freq_hz;
    EXPECT_GE(m.mac, 0.99) << p.freq_hz;
    EXPECT_LT(std::abs(m.scale - 1), 0.10) << p.freq_hz;
  }
}

// Receptance, mobility and accelerance of the same structure identify the same modes; an
// accelerance set converted to receptance (frf_set.h) is the receptance set. With 0.01 % noise:
// on exactly rational noise-free FRFs the over-modelled orders' computational poles follow the
// last bits of the arithmetic, and one host's libm let a 15 %-damped one pass as a mode beside
// the 275 Hz mode of the converted set; a realistic (if tiny) noise floor fixes them.
TEST(FrfTypes, GiveTheSameModes) {
  const PlantedModel model = modaltyre_test::ring_model();
  std::vector<EmaResult> res;
  for (FrfType t : {FrfType::receptance, FrfType::mobility, FrfType::accelerance}) {
    SynthOptions so;
    so.type = t;
    so.f_lo_hz = 0.25;
    so.noise = 1e-4;
    res.push_back(run_ema(modaltyre_test::synthesise(model, so), ring_band()));
  }
  SynthOptions so;
  so.f_lo_hz = 0.25;
  so.noise = 1e-4;
  const FrfSet converted =
      convert_frf_type(modaltyre_test::synthesise(model, so), FrfType::receptance);
  res.push_back(run_ema(converted, ring_band()));
  for (const auto& r : res) {
    ASSERT_EQ(r.modes.size(), res[0].modes.size());
    for (std::size_t k = 0; k < r.modes.size(); ++k) {
      EXPECT_NEAR(r.modes[k].freq_hz, res[0].modes[k].freq_hz, 2e-4 * res[0].modes[k].freq_hz);
      EXPECT_NEAR(r.modes[k].damping_ratio, res[0].modes[k].damping_ratio,
                  0.01 * res[0].modes[k].damping_ratio);
      for (std::size_t i = 0; i < r.points.size(); ++i) {
        EXPECT_NEAR(r.modes[k].radial[i], res[0].modes[k].radial[i], 0.01);
      }
    }
  }
  for (std::size_t k = 0; k < res[0].modes.size(); ++k) {
    EXPECT_NEAR(res[3].modes[k].freq_hz, res[0].modes[k].freq_hz, 1e-4 * res[0].modes[k].freq_hz);
  }
}

// Roving hammer: the response is fixed and the force moves; by reciprocity the same row of
// the FRF matrix, so the same modes.
TEST(Layouts, RovingHammerEqualsRovingAccelerometer) {
  const PlantedModel model = modaltyre_test::ring_model();
  SynthOptions so;
  const EmaResult a = run_ema(modaltyre_test::synthesise(model, so), ring_band());
  so.roving_hammer = true;
  const EmaResult b = run_ema(modaltyre_test::synthesise(model, so), ring_band());
  EXPECT_TRUE(b.roving_hammer);
  ASSERT_EQ(a.modes.size(), b.modes.size());
  for (std::size_t k = 0; k < a.modes.size(); ++k) {
    EXPECT_DOUBLE_EQ(a.modes[k].freq_hz, b.modes[k].freq_hz);
    EXPECT_EQ(a.modes[k].radial, b.modes[k].radial);
    EXPECT_EQ(a.modes[k].tangential, b.modes[k].tangential);
  }
}

// Without a driving point the sign check of the driving-point constant is unavailable; with
// measurement noise (1 %) the size check alone leaves the planted modes only.
TEST(Layouts, NoDrivingPointIsRefusedUnlessUnscaled) {
  const PlantedModel model = modaltyre_test::ring_model();
  SynthOptions so;
  so.noise = 0.01;
  FrfSet set = modaltyre_test::synthesise(model, so);
  set.channels.erase(set.channels.begin());  // point 1 radial: the driving point
  try {
    run_ema(set, ring_band());
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "synthetic");
    EXPECT_NE(std::string(e.what()).find("no driving-point FRF"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("point 1 radial"), std::string::npos) << e.what();
  }
  EmaOptions o = ring_band();
  o.unscaled = true;
  const EmaResult r = run_ema(set, o);
  EXPECT_FALSE(r.scaled);
  ASSERT_EQ(r.modes.size(), 6u);
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    double largest = 0;
    for (double v : r.modes[k].radial) largest = std::max(largest, std::abs(v));
    for (double v : r.modes[k].tangential) largest = std::max(largest, std::abs(v));
    EXPECT_NEAR(largest, 1.0, 1e-12);
    auto measured = *in_band(model, 60, 330)[k];
    measured.radial[0] = 0;  // the DOF left out: compare the measured ones
    const auto m = match(measured, r, 1, 0);
    EXPECT_GE(m.mac, 0.98);
  }
}

TEST(Layouts, TwoReferencesAndTwoResponsesAreRefused) {
  FrfSet set = modaltyre_test::synthesise(modaltyre_test::ring_model(), SynthOptions{});
  set.channels[3].reference = {2, Direction::radial};
  set.channels[3].line = 77;
  try {
    run_ema(set, ring_band());
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 77);
    EXPECT_NE(std::string(e.what()).find("one DOF shared by every FRF"), std::string::npos);
  }
}

TEST(Options, AreValidatedWithTheirNames) {
  const FrfSet set = modaltyre_test::synthesise(modaltyre_test::ring_model(), SynthOptions{});
  EmaOptions o = ring_band();
  o.max_order = 3;
  EXPECT_THROW(run_ema(set, o), InputError);
  o = ring_band();
  o.band_lo_hz = 300;
  o.band_hi_hz = 310;  // 41 lines: too few for order 64
  try {
    run_ema(set, o);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "--band");
  }
  o = ring_band();
  o.band_hi_hz = 50;
  EXPECT_THROW(run_ema(set, o), InputError);
}

}  // namespace
}  // namespace modaltyre::ema
