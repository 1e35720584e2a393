#pragma once
// The discrete alternatives mixed into the bands (docs/uncertainty.md section 2), private to
// uncertainty/: a frequency list's other order assignments (modal.order_alternatives, each with
// its probability) and, for a crown taken flat for want of a section drawing, the crowns from
// flat to the circular crown of footprint_3d.crown.round_limit_radius_mm (uniform in the
// curvature). Each alternative's nominal prediction shifts the continuous inputs' distribution
// (order_mixture.h); the two kinds combine with their shifts added (each evaluated alone at the
// nominal inputs, as the continuous inputs' differences are).
#include <string>
#include <vector>

#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::uncertainty {

using Outputs = std::vector<std::vector<double>>;  // [case][output]

/// Every row has one value per output, all finite (propagation.cc).
void check_shape(const Outputs& v, std::size_t rows, std::size_t outputs, const std::string& what);

/// The crowns a flat crown's band spans: curvatures i / (n - 1) of the round limit's, i < n, with
/// the trapezoid rule's weights (1/2, 1, ..., 1, 1/2) / (n - 1): a uniform distribution of the
/// curvature from flat (the nominal, i = 0, not evaluated again) to the limit.
constexpr int kCrownPoints = 5;

/// Mixes the config's alternatives into `r`'s bands (nothing when it states none), adds their
/// evaluations and says so in `r.check`. `nominal` the outputs at the nominal inputs, `samples`
/// the Monte Carlo samples (empty: linear). ComputationError when an alternative's model fails.
void mix_alternatives(PropagationResult& r, const contact::TyreConfig& config,
                      const modal::ModeIdentification& modes, const Evaluator& evaluate,
                      const Outputs& nominal, const std::vector<Outputs>& samples);

}  // namespace modaltyre::uncertainty
