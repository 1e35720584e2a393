#pragma once
// Harmonic orders for a list of frequencies without shapes (issue 36 item 3): which assignment
// of orders makes the list one ring family (ring_model.h), which orders are missing, which
// frequencies are doublets of one order, and which alternatives fit nearly as well.
//
// Candidates: the frequencies sorted; the radial family's orders rise with frequency (doublets
// of one order allowed when two frequencies lie within `doublet_tolerance`, at most one order
// skipped between neighbours); the family starts at order 1 or 2 or 3; one frequency may be the
// breathing mode (order 0) instead, anywhere in the list. A free test's order-1 mode lies off
// the rim-held family (docs/ring_model.md section 5): it is scored when it is rim-held
// (order1_in_fit) or when the wheel's mass lets it be moved there, else it joins unscored.
// Score: every assignment is fitted with the same four ring coefficients, so the score is the
// evidence: chi^2 of the relative frequency residuals with a known scatter of 0.5 %, plus 2 per
// discrete choice (each skipped order, each frequency left out of the fit; Akaike), plus a
// prior against lists that lack the family's lowest orders (3 choices per order), plus a large
// penalty for a family of four or fewer scored frequencies (it fits anything) and, when a belt
// width and pressure are given, for a tension mass outside a belt's plausible range. Near-ties
// (within 2) are what the frequencies cannot decide: they are returned, and `init` says so.
// Orders below 0 never occur; at most `max_alternatives` are returned, best first.
#include <string>
#include <vector>

namespace modaltyre::modal {

struct OrderProposalOptions {
  double doublet_tolerance = 0.03;  ///< two frequencies within 3 % may be one order's pair
  int max_skipped = 2;              ///< missing orders in the whole list at most
  int max_alternatives = 5;
  bool order1_in_fit = false;  ///< the order-1 frequency is rim-held (score it with the family)
  /// A free test's wheel mass [kg]: the order-1 frequency is moved to the held wheel with the
  /// belt mass 2 pi R mu of the tension (needs the mass check's inputs) and then scored;
  /// 0 = a free order 1 is not scored.
  double wheel_mass_kg = 0;
  /// For the mass check: pressure [Pa], belt width [m] and ring radius [m]; 0 = no check.
  double pressure_Pa = 0, belt_width_m = 0, radius_m = 0;
  /// A belt's mass per length range [kg/m] (passenger to light truck, docs/ring_model.md).
  double min_mass_kg_m = 1.0, max_mass_kg_m = 8.0;
};

struct OrderProposal {
  std::vector<int> orders;          ///< per frequency, in the caller's order
  double score = 0;                 ///< lower is better
  double rms_rel_error = 0;         ///< of the ring fit over the scored orders
  double mass_per_length_kg_m = 0;  ///< the tension's mu (0 without the check)
  std::vector<int> missing;         ///< orders between the lowest and highest the list skips
  std::string note;
};

/// Proposes assignments, best first; empty when fewer than three frequencies are given (no
/// family can be tested). Frequencies must be positive.
std::vector<OrderProposal> propose_orders(const std::vector<double>& freq_hz,
                                          const OrderProposalOptions& options = {});

}  // namespace modaltyre::modal
