#pragma once
// The probability of each true order of an aliased hammer mode (issue 35, docs/uncertainty.md
// section 6). With N points, orders k and jN +- k look alike at the points; the shapes cannot
// tell them apart, the frequencies can: the ring's dispersion relation (modal/dispersion.h,
// non-negative foundation, tension and bending terms) is refitted to the resolved orders with
// the aliased mode taken as candidate order c, and scored as modal/order_proposal.h scores an
// assignment: every candidate is fitted with the same three coefficients, so
//   chi2_c = sum of squared relative frequency residuals / s^2,
// s^2 = scatter^2 + (freq_std / f)^2, scatter the measured frequencies' relative scatter about
// a ring (0.5 %, as order_proposal.cc), freq_std the hammer CSV's (ema); and
//   P(c) = exp(-chi2_c / 2) / sum over the candidates
// (a uniform prior over the candidates the aliasing leaves).
#include <vector>

#include "modaltyre/modal/mode_identification.h"

namespace modaltyre::uncertainty {

struct OrderChance {
  int order = 0;
  double probability = 0;
  double chi2 = 0;
  double predicted_hz = 0;  ///< the resolved orders' dispersion relation at this order
};

/// The measured frequencies' relative scatter about a ring (modal/order_proposal.cc's).
inline constexpr double kRingFrequencyScatter = 0.005;

/// Probabilities of the candidates of an aliased radial mode `mode` of `id`, best first; empty
/// when the mode is not aliased, has no candidates, or the dispersion fit is invalid.
std::vector<OrderChance> alias_order_probabilities(const modal::ModeIdentification& id,
                                                   const modal::IdentifiedMode& mode);

/// exp(-chi2_i / 2) normalised to a sum of 1 (shifted by the smallest chi2 first, so that large
/// values do not underflow).
std::vector<double> probabilities_from_chi2(const std::vector<double>& chi2);

}  // namespace modaltyre::uncertainty
