// Which readings of a frequency list init carries into the bands (init/src/order_alternatives.h,
// issue 44 item 3), on planted scores: the best first, every reading within 6 of it, the
// consecutive readings within 13.8 even when others crowd the set, the Akaike weights normalised.
#include "../../init/src/order_alternatives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace modaltyre::init {
namespace {

modal::OrderProposal proposal(std::vector<int> orders, double score) {
  modal::OrderProposal p;
  p.orders = std::move(orders);
  p.score = score;
  return p;
}

TEST(OrderAlternatives, ConsecutiveReadingsFollowTheFrequenciesNotTheListOrder) {
  const std::vector<double> f = {137, 114, 165};  // given unsorted
  EXPECT_TRUE(consecutive_from({2, 1, 3}, f, 1));
  EXPECT_FALSE(consecutive_from({1, 2, 3}, f, 1));
  EXPECT_TRUE(consecutive_from({3, 2, 4}, f, 2));
  EXPECT_FALSE(consecutive_from({3, 2, 5}, f, 2));
}

TEST(OrderAlternatives, TheUsualReadingsStayInACrowdedSetWithTheirWeights) {
  const std::vector<double> f = {114, 137, 165, 196};
  std::vector<modal::OrderProposal> p = {proposal({2, 3, 4, 5}, 1.0)};
  // Eleven readings within 6 of the best (more than the config's ten lists take) ...
  for (int k = 0; k < 11; ++k) p.push_back(proposal({2, 3, 4, 6 + k}, 1.5 + 0.4 * k));
  // ... one far off, and the usual reading 1-4 at Delta 12 (weight exp(-6) of the best's).
  p.push_back(proposal({0, 2, 3, 4}, 9.0));
  p.push_back(proposal({1, 2, 3, 4}, 13.0));
  p.push_back(proposal({2, 4, 5, 6}, 20.0));  // beyond every margin
  const CarriedOrders c = carried_orders(p, f);
  ASSERT_EQ(c.index.size(), 10u);  // the best and nine alternatives
  EXPECT_EQ(c.index.front(), 0u);
  EXPECT_NE(std::find(c.index.begin(), c.index.end(), 13u), c.index.end()) << "1-4 kept";
  EXPECT_EQ(std::find(c.index.begin(), c.index.end(), 12u), c.index.end()) << "Delta 8 dropped";
  EXPECT_EQ(std::find(c.index.begin(), c.index.end(), 14u), c.index.end());
  double total = 0, sum = 0;
  for (std::size_t k : c.index) total += std::exp(-(p[k].score - 1.0) / 2);
  for (std::size_t i = 0; i < c.index.size(); ++i) {
    EXPECT_NEAR(c.probability[i], std::exp(-(p[c.index[i]].score - 1.0) / 2) / total, 1e-15);
    sum += c.probability[i];
    if (i > 1) {
      EXPECT_LT(c.index[i - 1], c.index[i]) << "score order";
    }
  }
  EXPECT_NEAR(sum, 1.0, 1e-15);
  // Alone, the best carries everything.
  const CarriedOrders one = carried_orders({p.front()}, f);
  ASSERT_EQ(one.index.size(), 1u);
  EXPECT_DOUBLE_EQ(one.probability.front(), 1.0);
}

}  // namespace
}  // namespace modaltyre::init
