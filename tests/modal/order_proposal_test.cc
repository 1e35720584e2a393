// Orders from frequencies alone (modal/order_proposal.h): a planted ring's list, with a missing
// order, doublets and a breathing mode, gets its orders back first; a list shifted by one
// order is told apart by the tension's mass; fewer than three frequencies propose nothing.
#include "modaltyre/modal/order_proposal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "modal_test_constants.h"
#include "modaltyre/modal/ring_model.h"

namespace modaltyre::modal {
namespace {

using test::kTwoPi;

// mu 2.8 kg/m, R 0.3 m, T = 200 kPa x 0.15 m x R, EI 1.5 N m^2, k_r 2.2, k_t 0.7 MN/m^2.
RingCoefficients planted() {
  const double mu = 2.8, R = 0.3, T = 200e3 * 0.15 * R;
  return {2.2e6 / mu, T / (mu * R * R), 1.5 / (mu * std::pow(R, 4)), 0.7e6 / mu};
}
double hz(int n) { return std::sqrt(planted().omega_sq(n)) / kTwoPi; }

OrderProposalOptions with_mass_check() {
  OrderProposalOptions o;
  o.pressure_Pa = 200e3;
  o.belt_width_m = 0.15;
  o.radius_m = 0.3;
  return o;
}

TEST(OrderProposal, PlantedFamilyGetsItsOrdersBackFirst) {
  const std::vector<int> orders = {2, 3, 4, 5, 6, 7};
  std::vector<double> f;
  for (int n : orders) f.push_back(hz(n));
  const auto p = propose_orders(f, with_mass_check());
  ASSERT_FALSE(p.empty());
  EXPECT_EQ(p.front().orders, orders);
  EXPECT_TRUE(p.front().missing.empty());
  EXPECT_NEAR(p.front().mass_per_length_kg_m, 2.8, 0.01 * 2.8);
  EXPECT_GT(p.size(), 1u);  // the alternatives are reported
}

// Orders 2, 3, 3 (a split pair), 5 (4 missing), 6, 7, a breathing mode at 145 Hz and a free
// order-1 mode, given out of order. Which of the two low modes is the breathing one the ring
// cannot tell (the 1 % doublet is the evidence's scatter): the planted assignment is among the
// near-ties (within 2 of the best score, Akaike's margin); shifting the whole family by an
// order is clearly worse.
TEST(OrderProposal, MissingOrderDoubletAndBreathingAreAmongTheNearTies) {
  const double mb = 2 * M_PI * 0.3 * 2.8, mw = 7.0;
  const double free1 = hz(1) * std::sqrt((mb + mw) / mw);
  std::vector<double> f = {hz(5), hz(2), 145.0, hz(3), hz(3) * 1.01, hz(6), hz(7), free1};
  const std::vector<int> planted = {5, 2, 0, 3, 3, 6, 7, 1};
  OrderProposalOptions o = with_mass_check();
  o.wheel_mass_kg = mw;
  o.max_alternatives = 8;
  const auto p = propose_orders(f, o);
  ASSERT_FALSE(p.empty());
  bool planted_found = false;
  for (const auto& a : p) {
    if (a.score > p.front().score + 2) break;
    planted_found = planted_found || a.orders == planted;
  }
  EXPECT_TRUE(planted_found);
  std::vector<int> shifted = planted;  // the whole family one order up, the low pair kept
  for (int& k : shifted)
    if (k >= 2) ++k;
  for (const auto& a : p) {
    if (a.orders == shifted) {
      EXPECT_GT(a.score, p.front().score + 2);
    }
  }
}

TEST(OrderProposal, TooFewFrequenciesProposeNothing) {
  EXPECT_TRUE(propose_orders({100, 120}).empty());
}

// A free test's list without an order 1 costs one choice (Akaike: 2 in the score): the planted
// family 2-7 scores exactly 2 worse when the list is a free test's (a wheel mass given) than
// when it is not. On Vervoort 2007's free 205/60 R15 list (114-260 Hz, 1.6 bar) the first six
// are read as orders 1-6, and the shift 2-7 stays a near-tie (docs/ring_model.md section 6).
TEST(OrderProposal, AFreeTestsListWithoutOrderOneCostsOneChoice) {
  std::vector<double> f;
  for (int n = 2; n <= 7; ++n) f.push_back(hz(n));
  OrderProposalOptions plain = with_mass_check(), free_test = with_mass_check();
  plain.max_alternatives = free_test.max_alternatives = 40;
  free_test.wheel_mass_kg = 7.0;
  auto score_of = [&](const OrderProposalOptions& o, const std::vector<int>& orders) {
    for (const auto& a : propose_orders(f, o))
      if (a.orders == orders) return a.score;
    ADD_FAILURE() << "assignment not proposed";
    return 0.0;
  };
  const std::vector<int> truth = {2, 3, 4, 5, 6, 7};
  EXPECT_NEAR(score_of(free_test, truth) - score_of(plain, truth), 2.0, 1e-9);

  OrderProposalOptions vv;
  vv.pressure_Pa = 160e3, vv.belt_width_m = 0.158, vv.radius_m = 0.3135, vv.wheel_mass_kg = 7.7;
  const auto p = propose_orders({114, 137, 165, 196, 228, 260}, vv);
  ASSERT_GT(p.size(), 1u);
  EXPECT_EQ(p.front().orders, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  bool shift_is_a_near_tie = false;
  for (const auto& a : p)
    shift_is_a_near_tie |=
        a.orders == std::vector<int>{2, 3, 4, 5, 6, 7} && a.score < p.front().score + 2;
  EXPECT_TRUE(shift_is_a_near_tie);
}

}  // namespace
}  // namespace modaltyre::modal
