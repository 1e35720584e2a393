#pragma once
// `tir export`'s longitudinal laws: the MF 6.2 pure-slip longitudinal force, rolling-resistance
// moment and effective rolling radius (mf_longitudinal.h) fitted to the model's own steady slip
// curves and free rolling on a prescribed wheel (model_slip.h, as the FMU runs it).
//
// The runs: at each slip load (default 0.5, 0.75, 1, 1.25, 1.5 x FNOMIN) the hub is held at the
// static sinking of that load and rolls at LONGVL (default 60 km/h) through the slips (default
// +-0.0025 ... +-0.3); at FNOMIN's sinking it also rolls freely at the other speeds of the
// rolling-resistance fit (default 40, 80, 100, 120 km/h). The fits:
//   F_x0: PCX1, PDX1-2, PEX1-4, PKX1-3, PHX1-2, PVX1-2 by Levenberg-Marquardt on
//         (F_x0(kappa, F_z) - F_x) / F_z over every slip point and free rolling (kappa = 0),
//         with E_x <= 1 (4.E14) kept over the fitted loads by a penalty (evaluators that do not
//         clamp E_x then agree with those that do); PDX3 = 0: no camber in the in-plane model
//   M_y:  QSY1, QSY3, QSY4, QSY7 by Levenberg-Marquardt on (M_y - M_r) / M_r over the
//         free-rolling points (load and speed), then QSY2 alone by least squares over the slip
//         points (M_y is linear in it).
//         QSY7, the load exponent, is part of MF 6.1/6.2's law: without it M_y would not grow
//         with the load. QSY4 >= 0 (a negative one turns the moment propulsive at high speed).
//         QSY5-6 (camber) and QSY8 (pressure) are not fitted
//   R_e:  DREFF, FREFF by linear least squares at BREFF on a grid over [0.5, 200], the best
//         kept, on the free-rolling radii at LONGVL; Q_RE0 = 1 (the model's free radius is
//         R0: Q_RE0 also moves the vertical law's deflection origin in MF 6.2) and Q_V1 = 0
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/tir/mf_longitudinal.h"
#include "modaltyre/tir/model_slip.h"

namespace modaltyre::tir {

struct SlipExportOptions {
  bool enabled = false;            ///< off by default (the command turns it on)
  std::vector<double> loads_N;     ///< slip-curve loads; default 0.5 ... 1.5 x FNOMIN (5)
  std::vector<double> speeds_m_s;  ///< free-rolling speeds besides LONGVL; default see above
  SlipSettings run;                ///< speed (LONGVL), mu, slips (default grid), holds
  /// Called with (holds done, holds in all) after every hold; optional.
  std::function<void(int, int)> progress;
};

/// The default slip grid: 0.0025, 0.005, 0.01, 0.02, 0.035, 0.05, 0.075, 0.1, 0.15, 0.2, 0.25,
/// 0.3, braking and driving.
std::vector<double> default_slips();
/// The default free-rolling speeds besides LONGVL [m/s].
std::vector<double> default_rolling_speeds_m_s();

/// A residual measure: RMS and largest magnitude.
struct Residual {
  double rms = 0, max = 0;
};

struct TirSlipFit {
  MfBasis basis;  ///< R0, FNOMIN, LONGVL, pressures, C_z of the vertical fit
  double mu = 0;  ///< the road friction of the runs
  MfLongitudinal longitudinal;
  MfRolling rolling;
  MfEffectiveRadius radius;
  Residual fx_over_fz;        ///< (F_x0 - F_x) / F_z over the slip and free points
  Residual rolling_rel;       ///< (M_y - M_r) / M_r over the free-rolling points
  Residual rolling_slip_rel;  ///< the same over the slip points
  Residual radius_m;          ///< R_e law - model at LONGVL [m]
  double max_curvature = 0;   ///< largest E_x over the fitted loads, both signs
  double kappa_min = 0, kappa_max = 0;
  double fz_min_N = 0, fz_max_N = 0;  ///< of the slip runs
  std::vector<SlipCurve> curves;      ///< at LONGVL, one per slip load
  std::vector<SlipCurve> free_runs;   ///< free rolling at the other speeds (no slips)
};

/// InputError naming the option for loads, speeds, slips or settings out of range.
void check_slip_options(const SlipExportOptions& options);

/// The model's runs of the options: slip curves at LONGVL, free rolling at the other speeds.
struct SlipRuns {
  double speed_m_s = 0, mu = 0;
  std::vector<SlipCurve> curves;     ///< one per slip load
  std::vector<SlipCurve> free_runs;  ///< at FNOMIN's sinking, one per further speed
};
/// Builds a transient model of `model` and runs it (model_slip.h); ComputationError when a run
/// fails.
SlipRuns run_slip(const contact::TyreModel& model, double fnomin_N,
                  const SlipExportOptions& options);

/// run_slip, then the fits. `basis` carries R0, FNOMIN, the pressure and C_z of the vertical
/// fit; its LONGVL is set from the options. InputError for options out of range;
/// ComputationError when a run or a fit fails.
TirSlipFit fit_slip(const contact::TyreModel& model, MfBasis basis,
                    const SlipExportOptions& options);

/// The fits alone, on runs already made (curves at LONGVL with slips, free runs without).
TirSlipFit fit_slip_laws(MfBasis basis, double mu, std::vector<SlipCurve> curves,
                         std::vector<SlipCurve> free_runs);

}  // namespace modaltyre::tir
