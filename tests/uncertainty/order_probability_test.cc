// The probability of each true order of an aliased hammer mode (docs/uncertainty.md section 6):
// the analytic form of the normalisation, a planted ring whose aliased mode's order the
// frequencies decide, and a frequency placed where two candidates are equally likely.
#include "modaltyre/uncertainty/order_probability.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "modaltyre/modal/hammer_data.h"

namespace modaltyre::uncertainty {
namespace {

namespace fs = std::filesystem;
constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kSumTolerance = 1e-12;  // rounding of a normalised sum

TEST(OrderProbability, NormalisedGaussianLikelihood) {
  // exp(0) : exp(-ln 3) = 3 : 1.
  const auto p = probabilities_from_chi2({0.0, 2 * std::log(3.0)});
  EXPECT_NEAR(p[0], 0.75, kSumTolerance);
  EXPECT_NEAR(p[1], 0.25, kSumTolerance);
  // Far beyond exp's range: no underflow to 0/0.
  const auto r = probabilities_from_chi2({5000.0, 5002.0});
  EXPECT_NEAR(r[0] + r[1], 1.0, kSumTolerance);
  EXPECT_NEAR(r[0] / r[1], std::exp(1.0), 1e-9);
}

// A ring on 10 points: orders 2, 3, 4 resolved, order 7 shows as order 3 above order 4
// (aliased: candidates 7, 13, 17, ...); frequencies on w^2 = s0 + s1 k^2 + s2 k^4 exactly.
std::string ring_csv(double f7_scale) {
  const double mu = 2.5, R = 0.3;
  const auto f_of = [](int k) {
    return std::sqrt(7.6e5 + 4.3e4 * k * k + 90.0 * std::pow(k, 4)) / kTwoPi;
  };
  std::ostringstream s;
  s.precision(12);
  s << "mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential\n";
  const int orders[] = {2, 3, 4, 7};
  for (int i = 0; i < 4; ++i) {
    const int k = orders[i];
    const double f = f_of(k) * (k == 7 ? f7_scale : 1.0);
    const double a = std::sqrt(1 / (M_PI * mu * R));
    for (int p = 0; p < 10; ++p) {
      const double th = kTwoPi * p / 10;
      s << i + 1 << "," << f << ",0.03," << p + 1 << "," << 36.0 * p << "," << a * std::cos(k * th)
        << "," << a / k * std::sin(k * th) << "\n";
    }
  }
  return s.str();
}

modal::ModeIdentification identify(const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("modaltyre_orders_" + std::to_string(::getpid()));
  std::ofstream(p) << text;
  auto id = modal::identify_modes(modal::read_hammer_csv(p.string()));
  fs::remove(p);
  return id;
}

TEST(OrderProbability, ThePlantedOrderOfAnAliasedModeIsTheLikelyOne) {
  const auto id = identify(ring_csv(1.0));
  const auto& m = id.modes.back();
  ASSERT_TRUE(m.aliased) << m.note;
  const auto p = alias_order_probabilities(id, m);
  ASSERT_GE(p.size(), 2u);
  double sum = 0;
  for (const auto& c : p) sum += c.probability;
  EXPECT_NEAR(sum, 1.0, kSumTolerance);
  EXPECT_EQ(p.front().order, 7);
  EXPECT_EQ(p.front().order, m.likely_order);
  EXPECT_GT(p.front().probability, 0.99);
}

TEST(OrderProbability, AFrequencyBetweenTwoCandidatesSplitsTheProbability) {
  // Where the two best candidates' likelihoods are equal: bisection on the aliased mode's
  // frequency between their predictions (chi2 is continuous in it).
  const auto base = identify(ring_csv(1.0));
  const auto p0 = alias_order_probabilities(base, base.modes.back());
  ASSERT_GE(p0.size(), 2u);
  const auto first = std::min(p0[0], p0[1], [](auto& a, auto& b) { return a.order < b.order; });
  const auto second = std::max(p0[0], p0[1], [](auto& a, auto& b) { return a.order < b.order; });
  const double f7 = base.modes.back().freq_hz;
  double lo = first.predicted_hz / f7, hi = second.predicted_hz / f7;
  std::vector<OrderChance> p;
  for (int it = 0; it < 60; ++it) {
    const double mid = std::sqrt(lo * hi);
    const auto id = identify(ring_csv(mid));
    p = alias_order_probabilities(id, id.modes.back());
    double p_first = 0;
    for (const auto& c : p) p_first += c.order == first.order ? c.probability : 0.0;
    (p_first > 0.5 ? lo : hi) = mid;
  }
  ASSERT_GE(p.size(), 2u);
  EXPECT_NEAR(p[0].probability, 0.5, 1e-3);
  EXPECT_NEAR(p[1].probability, 0.5, 1e-3);
}

}  // namespace
}  // namespace modaltyre::uncertainty
