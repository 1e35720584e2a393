#include "modaltyre/uncertainty/inputs.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "modaltyre/contact/parameter_spec.h"
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
      const bool from_ema =
          std::max(m.radial_noise_stated, m.tangential_noise_stated) > 0 &&
          (m.kind == modal::ModeKind::rotation ? m.tangential_noise == m.tangential_noise_stated
                                               : m.radial_noise == m.radial_noise_stated);
      out.push_back({InputKind::mode_amplitude,
                     int(i),
                     label + " amplitude",
                     m.amplitude2_rel_std,
                     from_ema ? "hammer CSV radial_std / tangential_std (ema)"
                              : "hammer shapes' residual (one-harmonic fit)",
                     {},
                     {}});
    }
    // The measured frequency's own scatter (ema's freq_std_hz) and a stated one (temperature,
    // preload, test to test) are independent: their variances add.
    const double f_rel = m.freq_hz > 0 ? m.freq_std_hz / m.freq_hz : 0.0;
    const double f_std = std::hypot(f_rel, u.frequency_rel_std);
    if (f_std > 0 && (used || !shapes_scale)) {
      const std::string source =
          f_rel > 0 ? (u.frequency_rel_std > 0
                           ? "hammer CSV freq_std_hz (ema) and modal.frequency_std_percent"
                           : "hammer CSV freq_std_hz (ema)")
                    : "modal.frequency_std_percent";
      out.push_back(
          {InputKind::mode_frequency, int(i), label + " frequency", f_std, source, {}, {}});
    }
  }
  // The config's stated scalars (a ring-normalised belt width only: shapes carry their own mass).
  struct Stated {
    InputKind kind;
    const char* name;
    double rel_std;
    const char* key;
  };
  // A Bekker soil's stated scatter (ground.bekker.uncertainty); n and the friction angle are
  // stated as absolute deviations and enter relative to their values (the reader keeps both below
  // half the value and refuses a percentage of a zero value).
  const bool bekker = config.ground.model == ground::GroundModel::bekker;
  const auto& sc = config.ground.bekker_scatter;
  const auto& b = config.ground.bekker;
  const auto& sh = config.ground.bekker_shear;
  auto soil = [&](double rel_std) { return bekker ? rel_std : 0.0; };
  const Stated stated[] = {
      {InputKind::tread_modulus, "tread modulus", u.tread_modulus_rel_std,
       "tread.modulus_std_percent"},
      {InputKind::tread_width, "tread width", u.tread_width_rel_std,
       "tread.contact_width_std_percent"},
      {InputKind::belt_width, "belt width (modal mass)", shapes_scale ? 0.0 : u.belt_width_rel_std,
       "modal.belt_width_std_percent"},
      {InputKind::soil_k_c, "soil k_c", soil(sc.k_c_rel_std),
       "ground.bekker.uncertainty.k_c_std_percent"},
      {InputKind::soil_k_phi, "soil k_phi", soil(sc.k_phi_rel_std),
       "ground.bekker.uncertainty.k_phi_std_percent"},
      {InputKind::soil_n, "soil n", soil(b.n > 0 ? sc.n_std / b.n : 0.0),
       "ground.bekker.uncertainty.n_std"},
      {InputKind::soil_cohesion, "soil cohesion", soil(sc.cohesion_rel_std),
       "ground.bekker.uncertainty.cohesion_std_percent"},
      {InputKind::soil_friction_angle, "soil friction angle",
       soil(sh.friction_angle_deg > 0 ? sc.friction_angle_std_deg / sh.friction_angle_deg : 0.0),
       "ground.bekker.uncertainty.friction_angle_std_deg"},
      {InputKind::soil_shear_modulus, "soil shear modulus K", soil(sc.shear_modulus_rel_std),
       "ground.bekker.uncertainty.shear_modulus_K_std_percent"}};
  for (const Stated& st : stated) {
    if (st.rel_std > 0) out.push_back({st.kind, -1, st.name, st.rel_std, st.key, {}, {}});
  }
  return out;
}

std::vector<UncertainInput> calibration_inputs(
    const std::vector<std::string>& keys, const std::vector<double>& values,
    const std::vector<double>& std_errors, const std::vector<std::vector<double>>& correlation) {
  const auto n = static_cast<Eigen::Index>(keys.size());
  if (n == 0 || std_errors.size() != keys.size() || values.size() != keys.size()) return {};
  Eigen::MatrixXd cov(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      const double corr = i == j ? 1.0 : correlation.at(i).at(j);
      cov(i, j) = std_errors[i] / values[i] * std_errors[j] / values[j] * corr;
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);
  std::vector<UncertainInput> out;
  for (Eigen::Index d = n - 1; d >= 0; --d) {  // largest variance first
    const double var = eig.eigenvalues()(d);
    if (!(var > 0) || !std::isfinite(var)) continue;
    UncertainInput in;
    in.kind = InputKind::calibration;
    in.rel_std = std::sqrt(var);
    in.keys = keys;
    std::string along;
    for (Eigen::Index k = 0; k < n; ++k) {
      in.direction.push_back(eig.eigenvectors()(k, d));
      char b[96];
      std::snprintf(b, sizeof b, "%s%+.2f %s", k ? " " : "", eig.eigenvectors()(k, d),
                    keys[k].c_str());
      along += b;
    }
    in.name = n == 1 ? keys[0] + " (calibrated)"
                     : "calibration direction " + std::to_string(n - d) + " (" + along + ")";
    in.source = "validate's calibration (Jacobian at the fit, residual variance)";
    out.push_back(std::move(in));
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
    case InputKind::tread_width:
      config.tread.width_m *= 1 + x;
      if (config.footprint_3d) config.footprint_3d->tread_width_m *= 1 + x;
      break;
    case InputKind::soil_k_c:
      config.ground.bekker.k_c *= 1 + x;
      break;
    case InputKind::soil_k_phi:
      config.ground.bekker.k_phi *= 1 + x;
      break;
    case InputKind::soil_n:
      config.ground.bekker.n *= 1 + x;
      break;
    case InputKind::soil_cohesion:
      config.ground.bekker_shear.cohesion_kPa *= 1 + x;
      break;
    case InputKind::soil_friction_angle:
      config.ground.bekker_shear.friction_angle_deg *= 1 + x;
      break;
    case InputKind::soil_shear_modulus:
      config.ground.bekker_shear.shear_modulus_K_mm *= 1 + x;
      break;
    case InputKind::calibration:
      for (std::size_t k = 0; k < input.keys.size(); ++k) {
        const contact::ParameterSpec* p = contact::find_parameter(input.keys[k]);
        MODALTYRE_CHECK(p != nullptr, "calibration input: unknown key " + input.keys[k]);
        p->set(config, p->get(config) * std::exp(x * input.direction.at(k)));
      }
      break;
  }
}

}  // namespace modaltyre::uncertainty
