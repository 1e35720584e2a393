#pragma once
// Frequency-order relation of the tyre's radial mode family, used (a) to tell which true order an
// aliased mode most likely has and (b) to extend the carcass compliance beyond the measured
// orders.
//
// Model: a tensioned ring on an elastic foundation (inextensional in-plane ring with bending
// stiffness EI, inflation tension T and sidewall foundation stiffness) has, for order k >= 2,
//   omega_k^2 ~= s0 + s1 k^2 + s2 k^4,  s0, s1, s2 >= 0
// (foundation, membrane tension, bending). The coefficients are fitted to the resolved measured
// orders by non-negative least squares on omega^2. Orders 0 (breathing) and 1 (rigid translation
// on the sidewalls) obey other physics and are not part of the fit.
#include <string>
#include <vector>

namespace modaltyre::modal {

struct DispersionFit {
  bool valid = false;      ///< false when fewer than two distinct orders >= 2 were given
  double s0 = 0, s1 = 0, s2 = 0;  ///< [rad^2/s^2]
  int orders_used = 0;     ///< distinct orders in the fit
  double rms_rel_error = 0;  ///< RMS relative error of the fitted frequencies
  std::string reason;      ///< why it is invalid

  double omega_sq(int k) const { return s0 + s1 * k * k + s2 * double(k) * k * k * k; }
  double freq_hz(int k) const;
};

/// Fits the dispersion relation to (order, frequency) pairs; orders < 2 are ignored.
DispersionFit fit_dispersion(const std::vector<int>& orders, const std::vector<double>& freq_hz);

}  // namespace modaltyre::modal
