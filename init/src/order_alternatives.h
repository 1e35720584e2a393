#pragma once
// Which order assignments of a frequency list `init` carries into the bands (issue 44 item 3):
// the proposal's best (modal.orders) and every other reading a modal analyst would weigh, each
// with its Akaike weight exp(-(score - best) / 2) normalised over the set (docs/uncertainty.md
// section 2). Apart from the config writer.
#include <cstddef>
#include <vector>

#include "modaltyre/modal/order_proposal.h"

namespace modaltyre::init {

/// How many assignments the proposal is asked for: enough that the consecutive readings are
/// among them whatever the near-ties.
constexpr int kProposalsAsked = 60;

struct CarriedOrders {
  std::vector<std::size_t> index;   ///< into the proposals, the best (index 0) first
  std::vector<double> probability;  ///< per index, normalised over the set
};

/// The set: every assignment within kPlausibleScore of the best (Akaike weight at least 5 % of
/// the best's), and the list's consecutive readings (orders 1..n and 2..n+1 of the sorted
/// frequencies: the usual readings of "the first n natural frequencies") within
/// kConsecutiveScore (weight at least 0.1 % of the best's); at most kMaxCarried alternatives
/// beside the best (the config's limit less one), the consecutive readings kept first.
/// `proposals` best first (modal::propose_orders), `freq_hz` in the proposals' order.
CarriedOrders carried_orders(const std::vector<modal::OrderProposal>& proposals,
                             const std::vector<double>& freq_hz);

/// Whether `orders`, read in the order of rising frequency, is start, start + 1, ... .
bool consecutive_from(const std::vector<int>& orders, const std::vector<double>& freq_hz,
                      int start);

}  // namespace modaltyre::init
