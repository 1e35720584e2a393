// SampleReuse (transient/src/sample_reuse.h) computes the repeat bounds as its check reaches
// them: its decisions and slack times equal those of the whole-state bounds computed at every
// remembered sample (the previous code, written out here), on states that move in their first,
// middle or last component, or not at all, with checks before and after each slack time.
#include "../../transient/src/sample_reuse.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace {

using modaltyre::transient::detail::SampleReuse;

/// The bounds of every component at remember(), one pass (the code before lazy bounds).
struct WholeStateReuse {
  double rtol;
  Eigen::ArrayXd atol, last, bound;
  void remember(const std::vector<double>& y) {
    last = Eigen::Map<const Eigen::ArrayXd>(y.data(), static_cast<Eigen::Index>(y.size()));
    bound = 1e-3 * (rtol * last.abs() + atol);
  }
  bool unchanged(const std::vector<double>& y) const {
    const Eigen::Map<const Eigen::ArrayXd> v(y.data(), last.size());
    return ((v - last).abs() <= bound).all();
  }
  double slack_s(const std::vector<double>& y, const Eigen::ArrayXd& rate) const {
    const Eigen::Map<const Eigen::ArrayXd> v(y.data(), last.size());
    const double t = ((bound - (v - last).abs()) / rate).minCoeff();
    return t > 0 ? t : 0.0;
  }
};

TEST(SampleReuseLazyBounds, DecisionsAndSlackEqualTheWholeStateBounds) {
  const int n = 403;
  const double rtol = 1e-4;
  std::mt19937 rng(47);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> atol(n);
  for (int i = 0; i < n; ++i) atol[i] = std::pow(10.0, -7 - (i % 4));
  SampleReuse lazy(rtol, atol, true);
  WholeStateReuse whole{rtol, Eigen::Map<const Eigen::ArrayXd>(atol.data(), n), {}, {}};
  std::vector<double> y(n);
  for (int i = 0; i < n; ++i) y[i] = u(rng) * std::pow(10.0, i % 5 - 2);
  Eigen::ArrayXd rate(n);
  for (int i = 0; i < n; ++i) rate[i] = std::abs(u(rng)) + (i % 9 == 0 ? 0.0 : 1e-3);
  int repeats = 0, moves = 0;
  for (int round = 0; round < 40; ++round) {
    lazy.remember(y);
    whole.remember(y);
    EXPECT_EQ(std::memcmp(lazy.last_state(), y.data(), n * sizeof(double)), 0);
    if (round % 2 == 1) {
      // slack_s() right after remember() (the run loop's bounded steps) reads every bound, none
      // of them computed by a check yet.
      const double s = lazy.slack_s(y, rate), w = whole.slack_s(y, rate);
      ASSERT_EQ(std::memcmp(&s, &w, sizeof(double)), 0) << s << " vs " << w;
    }
    // A move of one component by a fraction of its bound or by several bounds, or none.
    for (int trial = 0; trial < 8; ++trial) {
      std::vector<double> z = y;
      const int k = trial % 4 == 0 ? 0 : trial % 4 == 1 ? n / 2 : trial % 4 == 2 ? n - 1 : -1;
      const double size = trial < 4 ? 0.3 : 3.0;
      if (k >= 0) z[k] += size * 1e-3 * (rtol * std::abs(y[k]) + atol[k]) * (round % 2 ? 1 : -1);
      const bool want = whole.unchanged(z);
      ASSERT_EQ(lazy.unchanged(z), want) << "round " << round << ", trial " << trial;
      (want ? repeats : moves) += 1;
      if (want) {
        const double s = lazy.slack_s(z, rate), w = whole.slack_s(z, rate);
        ASSERT_EQ(std::memcmp(&s, &w, sizeof(double)), 0) << s << " vs " << w;
      }
    }
    for (int i = 0; i < n; ++i) y[i] += u(rng) * 1e-3 * std::abs(y[i]);
  }
  EXPECT_GT(repeats, 40);
  EXPECT_GT(moves, 40);
}

}  // namespace
