// ema -> hammer CSV -> fit-modes: the CSV ema writes is the file modal::read_hammer_csv reads,
// and the harmonic fits of fit-modes give back the planted orders.
#include <gtest/gtest.h>

#include <map>

#include "ema_test_support.h"
#include "modaltyre/ema/ema.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/mode_identification.h"
#include "planted_models.h"

namespace modaltyre::ema {
namespace {

class Chain : public modaltyre_test::ScratchDir {};

TEST_F(Chain, RingModelGivesThePlantedOrders) {
  modaltyre_test::SynthOptions so;
  so.noise = 0.01;
  EmaOptions o;
  o.band_lo_hz = 60;
  o.band_hi_hz = 330;
  const EmaResult r = run_ema(modaltyre_test::synthesise(modaltyre_test::ring_model(), so), o);
  const auto data = modal::read_hammer_csv(write(hammer_csv(r), "hammer.csv"));
  ASSERT_EQ(data.points, 12);
  const auto id = modal::identify_modes(data);
  const std::vector<int> planted = {0, 2, 3, 4, 5, 1};  // ring_model(), in frequency order
  ASSERT_EQ(id.modes.size(), planted.size());
  for (std::size_t k = 0; k < planted.size(); ++k) {
    EXPECT_EQ(id.modes[k].order(), planted[k]) << id.modes[k].freq_hz << " Hz";
    EXPECT_EQ(id.modes[k].kind, modal::ModeKind::radial);
    EXPECT_FALSE(id.modes[k].aliased);
    EXPECT_GT(id.modes[k].r2, 0.99);
  }
}

// The bundled data through FRFs with 1 % noise and back: fit-modes gives the orders and kinds
// it gives for the bundled file, for the 14 modes the radial reference can scale.
TEST_F(Chain, BundledDataKeepsItsOrders) {
  modaltyre_test::SynthOptions so;
  so.noise = 0.01;
  EmaOptions o;
  o.band_lo_hz = 80;
  o.band_hi_hz = 350;
  const EmaResult r = run_ema(modaltyre_test::synthesise(modaltyre_test::bundled_model(), so), o);
  const auto back = modal::identify_modes(modal::read_hammer_csv(write(hammer_csv(r), "h.csv")));
  const auto orig =
      modal::identify_modes(modal::read_hammer_csv(modaltyre_test::bundled_hammer_path()));
  ASSERT_EQ(back.modes.size(), 14u);
  for (const auto& m : back.modes) {
    const modal::IdentifiedMode* twin = nullptr;
    for (const auto& q : orig.modes) {
      if (!twin || std::abs(q.freq_hz - m.freq_hz) < std::abs(twin->freq_hz - m.freq_hz)) twin = &q;
    }
    EXPECT_EQ(m.apparent_order, twin->apparent_order) << m.freq_hz << " Hz";
    EXPECT_EQ(m.kind, twin->kind) << m.freq_hz << " Hz";
  }
}

}  // namespace
}  // namespace modaltyre::ema
