#include "modaltyre/report/modes_json.h"

#include <cmath>

#include "modaltyre/core/number_format.h"
#include "modaltyre/uncertainty/order_probability.h"

namespace modaltyre::report {

nlohmann::json modes_json(const modal::ModeIdentification& id) {
  nlohmann::json modes = nlohmann::json::array();
  for (const auto& m : id.modes) {
    nlohmann::json A = nlohmann::json::array(), B = nlohmann::json::array();
    for (double a : m.radial.A) A.push_back(round_sig(a));
    for (double b : m.radial.B) B.push_back(round_sig(b));
    nlohmann::json tA = nlohmann::json::array(), tB = nlohmann::json::array();
    for (double a : m.tangential.A) tA.push_back(round_sig(a));
    for (double b : m.tangential.B) tB.push_back(round_sig(b));
    nlohmann::json j = {
        {"mode", m.id},
        {"freq_hz", m.freq_hz},
        {"damping_ratio", m.damping_ratio},
        {"kind", modal::to_string(m.kind)},
        {"order", m.apparent_order},
        {"aliased", m.aliased},
        {"r2", round_sig(m.r2, 6)},
        {"A", A},
        {"B", B},
        {"A_nyquist", round_sig(m.radial.nyquist)},
        {"tangential_A", tA},
        {"tangential_B", tB},
        {"amplitude", round_sig(std::abs(m.c_radial))},
        {"phase_deg", m.apparent_order > 0
                          ? round_sig(-std::arg(m.c_radial) * 180 / M_PI / m.apparent_order, 6)
                          : 0.0},
        {"note", m.note},
        // The one-harmonic model's residual as noise, and the coefficient's covariance
        // (docs/uncertainty.md section 1): Re c and Im c independent, each with this std.
        {"radial_noise", round_sig(m.radial_noise, 6)},
        {"tangential_noise", round_sig(m.tangential_noise, 6)},
        {"coefficient_std", round_sig(m.c_radial_std, 6)},
        {"tangential_coefficient_std", round_sig(m.c_tangential_std, 6)},
        {"amplitude2_rel_std", round_sig(m.amplitude2_rel_std, 6)}};
    if (m.freq_std_hz > 0 || m.radial_noise_stated > 0) {  // the hammer CSV's (ema)
      j["freq_std_hz"] = round_sig(m.freq_std_hz, 6);
      j["damping_std"] = round_sig(m.damping_std, 6);
      j["radial_noise_stated"] = round_sig(m.radial_noise_stated, 6);
      j["tangential_noise_stated"] = round_sig(m.tangential_noise_stated, 6);
    }
    if (m.aliased) {
      j["alias_candidates"] = m.alias_candidates;
      j["likely_order"] = m.likely_order >= 0 ? nlohmann::json(m.likely_order) : nlohmann::json();
      // docs/uncertainty.md section 6: P(order) from the dispersion fit with each candidate.
      nlohmann::json chances = nlohmann::json::array();
      for (const auto& c : uncertainty::alias_order_probabilities(id, m)) {
        chances.push_back({{"order", c.order},
                           {"probability", round_sig(c.probability, 4)},
                           {"chi2", round_sig(c.chi2, 4)}});
      }
      j["order_probabilities"] = chances;
    }
    modes.push_back(j);
  }
  nlohmann::json disp = {{"valid", id.dispersion.valid}};
  if (id.dispersion.valid) {
    disp["model"] = "omega^2 = s0 + s1 k^2 + s2 k^4 (orders >= 2)";
    disp["s0_rad2_s2"] = round_sig(id.dispersion.s0);
    disp["s1_rad2_s2"] = round_sig(id.dispersion.s1);
    disp["s2_rad2_s2"] = round_sig(id.dispersion.s2);
    disp["orders_used"] = id.dispersion.orders_used;
    disp["rms_rel_error"] = round_sig(id.dispersion.rms_rel_error, 6);
  } else {
    disp["reason"] = id.dispersion.reason;
  }
  return {{"points", id.points}, {"modes", modes}, {"dispersion", disp}};
}

}  // namespace modaltyre::report
