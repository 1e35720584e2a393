#include "modaltyre/uncertainty/order_probability.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/modal/dispersion.h"

namespace modaltyre::uncertainty {

std::vector<double> probabilities_from_chi2(const std::vector<double>& chi2) {
  if (chi2.empty()) return {};
  const double lo = *std::min_element(chi2.begin(), chi2.end());
  std::vector<double> p(chi2.size());
  double sum = 0;
  for (std::size_t i = 0; i < chi2.size(); ++i) {
    p[i] = std::exp(-(chi2[i] - lo) / 2);
    sum += p[i];
  }
  for (auto& v : p) v /= sum;
  return p;
}

std::vector<OrderChance> alias_order_probabilities(const modal::ModeIdentification& id,
                                                   const modal::IdentifiedMode& mode) {
  if (!mode.aliased || mode.alias_candidates.empty() || !id.dispersion.valid) return {};
  // The resolved radial orders the dispersion relation was fitted to (mode_identification.cc).
  std::vector<int> orders;
  std::vector<double> freqs;
  for (const auto& m : id.modes) {
    if (m.kind == modal::ModeKind::radial && !m.aliased) {
      orders.push_back(m.apparent_order);
      freqs.push_back(m.freq_hz);
    }
  }
  const double rows =
      1.0 + double(std::count_if(orders.begin(), orders.end(), [](int k) { return k >= 2; }));
  const double measured_rel = mode.freq_hz > 0 ? mode.freq_std_hz / mode.freq_hz : 0.0;
  const double s2 = kRingFrequencyScatter * kRingFrequencyScatter + measured_rel * measured_rel;
  orders.push_back(0);
  freqs.push_back(mode.freq_hz);
  std::vector<OrderChance> out;
  std::vector<double> chi2;
  for (int c : mode.alias_candidates) {
    orders.back() = c;
    const modal::DispersionFit fit = modal::fit_dispersion(orders, freqs);
    if (!fit.valid) continue;  // no non-negative ring fits this assignment
    OrderChance o;
    o.order = c;
    o.predicted_hz = id.dispersion.freq_hz(c);
    o.chi2 = fit.rms_rel_error * fit.rms_rel_error * rows / s2;
    chi2.push_back(o.chi2);
    out.push_back(o);
  }
  const auto p = probabilities_from_chi2(chi2);
  for (std::size_t i = 0; i < out.size(); ++i) out[i].probability = p[i];
  std::stable_sort(out.begin(), out.end(), [](const OrderChance& a, const OrderChance& b) {
    return a.probability > b.probability;
  });
  return out;
}

}  // namespace modaltyre::uncertainty
