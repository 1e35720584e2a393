#include "order_alternatives.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace modaltyre::init {
namespace {

/// Score differences (Akaike's Delta) up to which an assignment is carried: exp(-6/2) = 5 % of
/// the best's weight. Burnham and Anderson (Model Selection and Multimodel Inference, 2nd ed.,
/// 2002, section 2.6) read Delta 4-7 as "considerably less support", not none: the band weighs
/// such readings rather than dropping them (the near-tie margin 2 says what cannot be decided,
/// not what can be ignored).
constexpr double kPlausibleScore = 6.0;
/// The consecutive readings are carried up to exp(-13.8/2) = 0.1 % of the best's weight: the
/// reading a user expects stays in the set, at the weight the frequencies give it (above Delta
/// 10 Burnham and Anderson see "essentially no support"; a weight of 0.1 % cannot move a 2.5 %
/// point, so carrying it changes no band it should not).
constexpr double kConsecutiveScore = 13.8;
/// modal.order_alternatives takes at most 10 lists (contact/carcass_source.cc).
constexpr std::size_t kMaxCarried = 9;

}  // namespace

bool consecutive_from(const std::vector<int>& orders, const std::vector<double>& freq_hz,
                      int start) {
  if (orders.size() != freq_hz.size()) return false;
  std::vector<std::size_t> idx(orders.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(),
                   [&](std::size_t a, std::size_t b) { return freq_hz[a] < freq_hz[b]; });
  for (std::size_t k = 0; k < idx.size(); ++k) {
    if (orders[idx[k]] != start + static_cast<int>(k)) return false;
  }
  return true;
}

CarriedOrders carried_orders(const std::vector<modal::OrderProposal>& proposals,
                             const std::vector<double>& freq_hz) {
  CarriedOrders c;
  if (proposals.empty()) return c;
  const double best = proposals.front().score;
  std::vector<std::size_t> consecutive, plausible;
  for (std::size_t k = 1; k < proposals.size(); ++k) {
    const double delta = proposals[k].score - best;
    const bool usual = consecutive_from(proposals[k].orders, freq_hz, 1) ||
                       consecutive_from(proposals[k].orders, freq_hz, 2);
    if (usual && delta <= kConsecutiveScore) {
      consecutive.push_back(k);
    } else if (delta <= kPlausibleScore) {
      plausible.push_back(k);
    }
  }
  c.index = {0};
  for (std::size_t k : consecutive) c.index.push_back(k);
  for (std::size_t k : plausible) {
    if (c.index.size() > kMaxCarried) break;
    c.index.push_back(k);
  }
  std::sort(c.index.begin() + 1, c.index.end());  // score order (the proposals' own)
  double total = 0;
  for (std::size_t k : c.index) total += std::exp(-(proposals[k].score - best) / 2);
  for (std::size_t k : c.index) {
    c.probability.push_back(std::exp(-(proposals[k].score - best) / 2) / total);
  }
  return c;
}

}  // namespace modaltyre::init
