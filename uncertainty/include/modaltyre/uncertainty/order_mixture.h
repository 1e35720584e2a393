#pragma once
// Discrete alternatives mixed into a band (docs/uncertainty.md section 2): a frequency list's
// other order assignments (modal.order_alternatives) each shift the prediction by
// f_a - f_nominal; the band is that of the mixture of the continuous inputs' distribution
// shifted to each alternative, weighted by the alternatives' probabilities.
#include <vector>

#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::uncertainty {

struct MixtureComponent {
  double weight = 0;  ///< probability; the components' weights sum to 1
  double shift = 0;   ///< f_a - f_nominal
};

/// The band of the mixture. `band` holds the continuous one (value, std; percentiles); with
/// `samples` (the sampled values of the output) the components are the shifted samples, else
/// normal distributions of the band's std about value + shift. The value stays the nominal
/// assignment's; std and the 2.5 / 97.5 % points become the mixture's.
Band mix_band(const Band& band, const std::vector<double>* samples,
              const std::vector<MixtureComponent>& components);

}  // namespace modaltyre::uncertainty
