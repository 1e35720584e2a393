#pragma once
// The uncertain inputs of a tyre model (issue 35, docs/uncertainty.md): what the data say of
// their own precision (the hammer shapes' residual noise per mode) and what a config states
// where no data give it (modal.frequency_std_percent, tread.modulus_std_percent,
// modal.belt_width_std_percent, tread.contact_width_std_percent, a Bekker soil's
// ground.bekker.uncertainty). Each input is a relative
// perturbation x of one quantity with a standard deviation; apply() sets it on a copy of the config
// and of the identified modes.
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/modal/mode_identification.h"

namespace modaltyre::uncertainty {

enum class InputKind {
  mode_amplitude,  ///< a mode's modal amplitude |c|^2 (all its shape products scale by 1 + x)
  mode_frequency,  ///< a mode's natural frequency (multiplied by 1 + x)
  tread_modulus,   ///< the tread compound's modulus (1 + x)
  belt_width,      ///< the belt width of the ring's tension, i.e. the modal mass (1 + x)
  tread_width,     ///< the tread width, 2D contact width and 3D tread width together (1 + x)
  /// A Bekker soil's parameter (ground.bekker.uncertainty, ground::SoilScatter): its value times
  /// (1 + x); n and the friction angle, stated as absolute deviations, enter as relative ones.
  soil_k_c,
  soil_k_phi,
  soil_n,
  soil_cohesion,
  soil_friction_angle,
  soil_shear_modulus,
  /// One principal direction of calibrated scalars' covariance (validate): every key's value
  /// times exp(x direction_k), x with std sqrt(eigenvalue) of Cov(ln value).
  calibration,
};

struct UncertainInput {
  InputKind kind = InputKind::mode_amplitude;
  int mode = -1;                  ///< index into ModeIdentification::modes (mode kinds), else -1
  std::string name;               ///< e.g. "mode 4 amplitude", "tread modulus"
  double rel_std = 0;             ///< standard deviation of x
  std::string source;             ///< e.g. "hammer shapes' residual", "modal.frequency_std_percent"
  std::vector<std::string> keys;  ///< calibration: the config keys (contact/parameter_spec.h)
  std::vector<double> direction;  ///< calibration: a unit eigenvector of Cov(ln value), per key
};

/// The inputs with a standard deviation > 0: one amplitude per mode the carcass uses when its
/// shapes are mass-normalised (their residual noise; ring-normalised shapes carry no amplitude
/// of their own), one frequency per mode when the config states modal.frequency_std_percent, the
/// tread modulus, the belt width and the tread width when stated, and a Bekker soil's parameters
/// whose scatter its ground file states (ground.bekker.uncertainty).
std::vector<UncertainInput> collect_inputs(const contact::TyreConfig& config,
                                           const modal::ModeIdentification& modes);

/// The calibrated scalars' uncertainty (studies::Calibration: standard errors and correlation,
/// from the Levenberg-Marquardt Jacobian) as independent inputs: the principal directions of
/// Cov(ln x)_ij = (se_i / x_i)(se_j / x_j) corr_ij, so that the propagation, which takes its
/// inputs independent, carries the correlation. Directions with zero variance are left out.
std::vector<UncertainInput> calibration_inputs(const std::vector<std::string>& keys,
                                               const std::vector<double>& values,
                                               const std::vector<double>& std_errors,
                                               const std::vector<std::vector<double>>& correlation);

/// Applies x to the input's quantity on `config` / `modes` (copies the caller made).
void apply(const UncertainInput& input, double x, contact::TyreConfig& config,
           modal::ModeIdentification& modes);

}  // namespace modaltyre::uncertainty
