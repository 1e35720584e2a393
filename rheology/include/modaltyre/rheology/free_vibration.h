#pragma once
// Free damped vertical vibration of a tyre on a rigid support (seed 000 Fig. 3b): the period T,
// the logarithmic decrement ln(a_i / a_(i+1)) and the equilibrium deflection h_Z0 taken from
// the measured decay h_Z(t), for the viscosity factor of eq. (22).
//
// File format: t_s,deflection_mm (time strictly increasing; deflection of the tyre, so that
// the equilibrium value is the static deflection h_Z0 that sets the contact length).
#include <string>
#include <vector>

namespace modaltyre::rheology {

struct DecaySignal {
  std::string path = "<data>";
  std::vector<double> t_s;
  std::vector<double> deflection_m;
  std::vector<int> line;
};

DecaySignal read_free_vibration_csv(const std::string& path);

/// h(t) = h0 + exp(-alpha tau) (A cos(omega tau) + B sin(omega tau)), tau = t - t_start.
struct DecayFit {
  double t_start_s = 0.0;
  double equilibrium_m = 0.0, equilibrium_se_m = 0.0;  ///< h_Z0
  double A_m = 0.0, B_m = 0.0;
  double alpha_per_s = 0.0, omega_rad_s = 0.0;
  double period_s = 0.0, period_se_s = 0.0;            ///< damped period T = 2 pi / omega
  double log_decrement = 0.0, log_decrement_se = 0.0;  ///< delta = alpha T
  double log_decrement_peaks = 0.0;  ///< mean ln(a_i/a_(i+1)) over measured peaks, a cross-check
  std::vector<double> extremum_t_s;  ///< measured extrema (alternating sides)
  std::vector<double> amplitude_m;   ///< |h(extremum) - h0|: the a_i of eq. (22)
  double residual_rms_m = 0.0;
  int samples = 0;
};

/// Value of the fitted decay at time t.
double decay_value(const DecayFit& fit, double t_s);

/// Finds extrema above the noise, guesses period and decrement from them and refines all five
/// constants by Levenberg-Marquardt. InputError for fewer than two cycles or a signal whose
/// oscillation does not decay (log decrement < 0.01); ComputationError if the fit fails.
DecayFit fit_free_decay(const DecaySignal& signal);

}  // namespace modaltyre::rheology
