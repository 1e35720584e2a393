#include "modaltyre/uncertainty/inputs.h"

#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::uncertainty {

std::vector<UncertainInput> collect_inputs(const contact::TyreConfig& config,
                                           const modal::ModeIdentification& modes) {
  std::vector<UncertainInput> out;
  const auto& u = config.uncertainty;
  const bool shapes_scale = config.carcass.normalisation == contact::ModalNormalisation::shapes;
  for (std::size_t i = 0; i < modes.modes.size(); ++i) {
    const auto& m = modes.modes[i];
    const bool used =
        m.kind == modal::ModeKind::rotation || (m.kind == modal::ModeKind::radial && !m.aliased);
    const std::string label = "mode " + std::to_string(m.id);
    if (shapes_scale && used && m.amplitude2_rel_std > 0) {
      out.push_back({InputKind::mode_amplitude, int(i), label + " amplitude", m.amplitude2_rel_std,
                     "hammer shapes' residual (one-harmonic fit)"});
    }
    if (u.frequency_rel_std > 0 && (used || !shapes_scale)) {
      out.push_back({InputKind::mode_frequency, int(i), label + " frequency", u.frequency_rel_std,
                     "modal.frequency_std_percent"});
    }
  }
  if (u.tread_modulus_rel_std > 0) {
    out.push_back({InputKind::tread_modulus, -1, "tread modulus", u.tread_modulus_rel_std,
                   "tread.modulus_std_percent"});
  }
  if (u.belt_width_rel_std > 0 && !shapes_scale) {
    out.push_back({InputKind::belt_width, -1, "belt width (modal mass)", u.belt_width_rel_std,
                   "modal.belt_width_std_percent"});
  }
  return out;
}

void apply(const UncertainInput& input, double x, contact::TyreConfig& config,
           modal::ModeIdentification& modes) {
  MODALTYRE_CHECK(x > -1, "a relative perturbation of -100 % or less");
  switch (input.kind) {
    case InputKind::mode_amplitude: {
      auto& m = modes.modes.at(static_cast<std::size_t>(input.mode));
      const double s = std::sqrt(1 + x);
      m.c_radial *= s;
      m.c_tangential *= s;
      m.radial.A[0] *= s;  // the rotation's products come from the order-0 coefficients
      m.tangential.A[0] *= s;
      break;
    }
    case InputKind::mode_frequency: {
      auto& m = modes.modes.at(static_cast<std::size_t>(input.mode));
      m.freq_hz *= 1 + x;  // the model is built from the modes, not the config's list
      break;
    }
    case InputKind::tread_modulus:
      config.tread.modulus_Pa *= 1 + x;
      break;
    case InputKind::belt_width:
      config.carcass.belt_width_m *= 1 + x;
      break;
  }
}

}  // namespace modaltyre::uncertainty
