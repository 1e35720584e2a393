// Discrete order alternatives mixed into a band (docs/uncertainty.md section 2): the mixture's
// moments and percentiles in closed form, and end to end: init writes the near-ties of an
// ambiguous frequency list, and --uncertainty's band spans their predictions.
#include "modaltyre/uncertainty/order_mixture.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::uncertainty {
namespace {

namespace fs = std::filesystem;

TEST(OrderMixture, TwoPointsWithoutNoiseAreAWeightedQuantile) {
  // 70 % at 10, 30 % at 14: the 2.5 % point is 10, the 97.5 % point 14; std sqrt(.7 .3) 4.
  const Band b{10, 0, 10, 10};
  const Band m = mix_band(b, nullptr, {{0.7, 0}, {0.3, 4}});
  EXPECT_DOUBLE_EQ(m.value, 10);
  EXPECT_NEAR(m.std, 4 * std::sqrt(0.7 * 0.3), 1e-12);
  EXPECT_EQ(m.p025, 10);
  EXPECT_EQ(m.p975, 14);
}

TEST(OrderMixture, NormalComponentsGiveTheMixturesMomentsAndSymmetry) {
  // Equal weights at -d and +d about 0 with sigma: std^2 = sigma^2 + d^2, symmetric percentiles,
  // and for d = 0 the normal's own 1.96 sigma.
  const double sigma = 1.5, d = 3;
  const Band b{0, sigma, -1.96 * sigma, 1.96 * sigma};
  const Band m = mix_band(b, nullptr, {{0.5, -d}, {0.5, d}});
  EXPECT_NEAR(m.std, std::sqrt(sigma * sigma + d * d), 1e-12);
  EXPECT_NEAR(m.p025, -m.p975, 1e-9);
  EXPECT_GT(m.p975, d);  // beyond the upper component's centre
  const Band one = mix_band(b, nullptr, {{1.0, 0}});
  EXPECT_NEAR(one.p975, 1.959964 * sigma, 1e-5);
}

TEST(OrderMixture, SamplesAreShiftedAndPooled) {
  const std::vector<double> s = {-1, 0, 1};  // mean 0, sample variance 1
  const Band b{0, 1, -1, 1};
  const Band m = mix_band(b, &s, {{0.5, 0}, {0.5, 10}});
  // The samples' variance 1 plus the shifts' spread 25; pooled percentiles over the six points
  // (three at 0 +- 1, three at 10 +- 1, each weight 1/6).
  EXPECT_NEAR(m.std, std::sqrt(1.0 + 25.0), 1e-9);
  EXPECT_EQ(m.p025, -1);
  EXPECT_EQ(m.p975, 11);
}

class OrderAlternatives : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("modaltyre_alt_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A ring-normalised frequency list (Vervoort 2007's six free-tyre frequencies, orders 1-6)
  // with the given extra modal: lines.
  std::string config(const std::string& extra) {
    const fs::path p = dir_ / "tyre.yaml";
    std::ofstream(p) << "tyre:\n  outer_radius_mm: 313.5\n  inflation_pressure_kPa: 160\n"
                        "modal:\n  frequencies_hz: [114, 137, 165, 196, 228, 260]\n"
                        "  orders: [1, 2, 3, 4, 5, 6]\n  belt_width_mm: 158\n"
                        "  test_pressure_kPa: 160\n"
                     << extra
                     << "tread:\n  modulus_MPa: 3\n  thickness_mm: 8\n  contact_width_mm: 158\n"
                        "contact:\n  unit_length_mm: 2\n  window_mm: 382\n";
    return p.string();
  }
  fs::path dir_;
};

TEST_F(OrderAlternatives, BadKeysAreRefusedNamingThem) {
  for (const std::string& bad :
       {std::string(
            "  order_alternatives: [[2, 3, 4]]\n  order_alternative_probabilities: [0.3]\n"),
        std::string("  order_alternatives: [[2, 3, 4, 5, 6, 7]]\n"),
        std::string("  order_alternatives: [[2, 3, 4, 5, 6, 7]]\n"
                    "  order_alternative_probabilities: [1.0]\n")}) {
    try {
      (void)contact::load_tyre_config(config(bad));
      ADD_FAILURE() << "accepted:\n" << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("modal.order_alternative"), std::string::npos)
          << e.what();
    }
  }
}

TEST_F(OrderAlternatives, TheBandSpansTheAlternativesPredictions) {
  const auto with =
      contact::load_tyre_config(config("  order_alternatives: [[2, 3, 4, 5, 6, 7]]\n"
                                       "  order_alternative_probabilities: [0.4]\n"));
  const auto cases = std::vector<contact::OperatingConditions>{with.default_conditions(4000)};
  const PropagationResult r = propagate(with, contact::config_modes(with), cases);
  ASSERT_EQ(r.order_alternatives.size(), 2u);
  EXPECT_NEAR(r.order_alternatives[0].probability, 0.6, 1e-12);
  // The alternative's own prediction, as a config that states its orders.
  auto alt = with;
  alt.carcass.orders = {2, 3, 4, 5, 6, 7};
  alt.carcass.order_alternatives.clear();
  alt.carcass.order_alternative_probabilities.clear();
  const PropagationResult a = propagate(alt, contact::config_modes(alt), cases);
  const Band& s = r.cases[0].bands[0];
  const double f0 = s.value, f1 = a.cases[0].bands[0].value;
  ASSERT_GT(std::abs(f1 - f0), 0.01 * f0) << "the orders must move the sinking to be a test";
  // No continuous input: two points, 60/40 -> std sqrt(.6 .4) |f1 - f0|, band [min, max].
  EXPECT_NEAR(s.std, std::sqrt(0.24) * std::abs(f1 - f0), 1e-9 * f0);
  EXPECT_NEAR(s.p025, std::min(f0, f1), 1e-9 * f0);
  EXPECT_NEAR(s.p975, std::max(f0, f1), 1e-9 * f0);
  EXPECT_NE(r.check.find("alternative order"), std::string::npos) << r.check;
}

}  // namespace
}  // namespace modaltyre::uncertainty
