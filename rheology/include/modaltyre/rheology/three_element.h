#pragma once
// Three-element (Hooke-Newton-Saint-Venant) tyre model, seed 000 eq. (13)-(22).
//   sigma1 = E1 eps1 + eta1 deps1/dt + chi E1 sgn(deps1/dt),  eps1 = Delta_P / H      eq. (13)
// Integrated over the patch (arc measure as eq. 8):
//   P_Z = 2 B_tr r0^2 (E1/H) f(phi1) + B_tr r0 eta1 (dh/dt / H) cos phi1 ln((1+sin)/(1-sin))
//         + 2 B_tr chi E1 r0 phi1 cos phi1 sgn(dh/dt),
//   f(phi1) = cos phi1 (phi1 - cos phi1 atanh(sin phi1)), lambda = 2 f              eq. (14)-(15)
// A static loop (loading and unloading branches, dh/dt ~ 0) gives E1 (eq. 17) and chi (eq. 18);
// a free damped vibration gives eta1 = 2 m ln(a_i/a_(i+1)) / (T L_C)               eq. (22).
//
// Static file format: load_N,deflection_mm,branch with branch "loading" or "unloading" (or
// "load", "unload": the words of core/conditions.h), optional pressure_kPa.
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/rheology/free_vibration.h"
#include "modaltyre/rheology/report.h"

namespace modaltyre::rheology {

struct StaticLoopRow {
  double load_N = 0.0;
  double deflection_m = 0.0;
  bool loading = true;
  int line = 0;
};

struct StaticLoop {
  std::string path = "<data>";
  std::vector<StaticLoopRow> rows;
};

StaticLoop read_static_loop_csv(const std::string& path);

struct ThreeElementOptions {
  double r0_m = 0.0;              ///< free radius (static fit; contact length from the decay)
  double tread_width_m = 0.0;     ///< B_tr (static fit)
  double section_height_m = 0.0;  ///< H, the height eps1 = Delta_P / H refers to (static fit)
  double mass_kg = 0.0;           ///< reduced mass m = tyre + rim (+ fixture), eq. (22)
  double contact_length_m = 0.0;  ///< L_C at h_Z0; 0: from the decay's h_Z0 and r0
};

/// Static load of the model on a loading (true) or unloading branch, eq. (14) at dh/dt -> 0.
double static_loop_load(double E1_Pa, double chi, double deflection_m, bool loading,
                        const ThreeElementOptions& o);
/// eta1 = 2 m delta / (T L_C), seed 000 eq. (22) [Pa s].
double eta1_eq22(double mass_kg, double log_decrement, double period_s, double contact_length_m);

struct StaticLoopFit {
  double E1_Pa = 0.0, E1_se = 0.0, chi = 0.0, chi_se = 0.0;
  double residual_rms_N = 0.0;
  int rows = 0;
};

/// Least squares of eq. (14) at dh/dt = 0 over both branches, linear in (E1, chi E1).
/// InputError when a branch is missing or geometry is missing.
StaticLoopFit identify_static_loop(const StaticLoop& loop, const ThreeElementOptions& o);

struct FreeVibrationResult {
  DecayFit decay;
  double contact_length_m = 0.0;
  double eta1_Pa_s = 0.0, eta1_se = 0.0;
  std::optional<StaticLoopFit> static_fit;
  FitReport report;
};

/// eta1 from the decay (eq. 22); E1 and chi as well when a static loop is given.
FreeVibrationResult identify_free_vibration(const DecaySignal& signal, const StaticLoop* loop,
                                            const ThreeElementOptions& o);

}  // namespace modaltyre::rheology
