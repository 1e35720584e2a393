#pragma once
// The model's own steady longitudinal slip curve and rolling resistance, for the .tir bridge:
// the tyre on a prescribed wheel as the FMU runs it (fmu::TyreWheel: the transient of
// transient/driven_tyre.h with the tangential contact of fmu/longitudinal_contact.h, docs/fmu.md
// sections 3-4), the hub held at the static sinking of a load, at constant forward speed V and
// constant wheel spin Omega.
//
// The run at one load: from rest, the speed ramps to V (smoothstep) with the spin at V / R_b
// (R_b the tread base radius), then rolls; the free-rolling spin Omega_free, where the wheel's
// moment about its axis M_y vanishes (no drive or brake torque), is found by the secant on M_y
// over held spins (each held until steady, below). The effective rolling radius is R_e = V /
// Omega_free, and the slip of every later hold is MF's longitudinal slip kappa = -(V - Omega R_e) /
// V with R_e that of free rolling (Pacejka 2012, Tire and Vehicle Dynamics, 3rd ed., ch. 1 and
// sec. 4.3.2): Omega = Omega_free (1 + kappa), each held until steady.
//
// What each point carries: F_x, the road's longitudinal force on the tyre (ISO x), F_z, and the
// rolling-resistance moment of the pressure distribution M_r = -sum f_i x_i about the contact
// point (MF's M_y, < 0 rolling forward): the FMU's hub moment is M_r - r F_x, r = R0 - deflection.
#include <functional>
#include <memory>
#include <vector>

#include "modaltyre/transient/model.h"

namespace modaltyre::tir {

struct SlipSettings {
  double speed_m_s = 60 / 3.6;  ///< V (the file's LONGVL)
  double mu = 0.8;              ///< road friction (the FMU's terrain_mu start value)
  double step_s = 1e-3;         ///< the FMU's step_size (its default)
  double ramp_s = 0.3;          ///< speed ramp from rest
  double settle_s = 0.4;        ///< rolling at V / R_b after the ramp
  /// Each held spin lasts at least this travel (about ten contact lengths: the tread's shear
  /// and the carcass's longitudinal compliance relax over a length, not a time) and until two
  /// successive windows of average_m give the same mean F_x to 0.1 % of F_z, at most max_hold_m;
  /// its forces are the last window's means (whole units of travel rattle F_x by about 0.2 % of
  /// F_z at slip).
  double hold_m = 1.5;
  double average_m = 0.6;
  double max_hold_m = 30;
  std::vector<double> slips;  ///< MF kappa of the holds after free rolling is found
};

/// Validates the settings (InputError naming the option) and returns the number of steps one
/// load costs (bounded: kMaxSlipSteps).
long slip_run_steps(const SlipSettings& s);

inline constexpr long kMaxSlipSteps = 2'000'000;
inline constexpr int kMaxSlips = 200;

struct SlipPoint {
  double kappa = 0;              ///< MF slip from R_e
  double fx_N = 0;               ///< longitudinal force of the road on the tyre
  double fz_N = 0;               ///< vertical load
  double rolling_moment_Nm = 0;  ///< M_r = -sum f x (MF's M_y)
  double loaded_radius_m = 0;    ///< r = R0 - deflection (the hub's)
};

struct SlipCurve {
  double target_load_N = 0;  ///< the static load whose sinking holds the hub
  double deflection_m = 0;   ///< the hub's, held
  double speed_m_s = 0;
  double free_spin_rad_s = 0;
  double effective_radius_m = 0;  ///< R_e = V / Omega_free
  SlipPoint free;                 ///< at kappa = 0 (Omega_free), measured
  std::vector<SlipPoint> points;  ///< in the order of SlipSettings::slips
};

/// One load's run (see above). `tick` (optional) is called after every hold.
/// ComputationError when the integration fails or the secant finds no free-rolling spin.
SlipCurve model_slip_curve(std::shared_ptr<const transient::TransientModel> model,
                           double deflection_m, double target_load_N, const SlipSettings& s,
                           const std::function<void()>& tick = {});

/// Holds in one run: the secant's and the slips'.
int slip_run_holds(const SlipSettings& s);

}  // namespace modaltyre::tir
