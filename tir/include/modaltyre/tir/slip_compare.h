#pragma once
// `tir compare --slip`: a .tir's longitudinal pure-slip force, rolling-resistance moment and
// effective rolling radius (mf_longitudinal.h) against the model's own runs on a prescribed
// wheel (slip_fit.h's run_slip: slip curves at LONGVL, free rolling at other speeds).
//
// Same tyre size: at each run point the file's F_x0(kappa, F_z), M_y(F_x, F_z, V) and
// R_e(F_z, Omega) at the model's F_z (the model's F_x in M_y, as MF takes its own). Another size
// (tir_compare.h): dimensionless, at the same F_z / FNOMIN, the file's F_x / F_z, M_y / (F_z R0)
// and R_e / R0 against the model's; the rows' absolute columns carry the file's values scaled
// to the model's size. Each law compares at its own slip: kappa from its own R_e.
//
// Measures: RMS of (file - model) / F_z for the force (the 5 %-of-F_z measure), of
// (file - model) / model for the moment, and of (file - model) / R0 for the radius.
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/tir/mf_tyre.h"
#include "modaltyre/tir/slip_fit.h"

namespace modaltyre::tir {

struct SlipForceRow {
  double target_load_N = 0, fz_N = 0, kappa = 0, model_fx_N = 0;
  std::optional<double> tir_fx_N;
};

struct RollingRow {
  double speed_m_s = 0, fz_N = 0, model_moment_Nm = 0;
  std::optional<double> tir_moment_Nm;
};

struct RadiusRow {
  double fz_N = 0, model_radius_m = 0;
  std::optional<double> tir_radius_m;
};

struct SlipComparison {
  double speed_m_s = 0, mu = 0;
  std::vector<SlipForceRow> force;  ///< every slip point and free rolling of each load
  std::vector<RollingRow> rolling;  ///< free rolling at each load and speed
  std::vector<RadiusRow> radius;    ///< free rolling at each load at LONGVL
  std::optional<double> rms_fx_over_fz, max_fx_over_fz;
  std::optional<double> rms_rolling, max_rolling;
  std::optional<double> rms_radius_over_r0;
  std::string force_reason, rolling_reason, radius_reason;
};

/// The comparison on runs already made. `model_fnomin_N` and `model_radius_m` scale the file's
/// laws to the model's size when `dimensionless`.
SlipComparison compare_slip_runs(const MfTyre& tir, const SlipRuns& runs, bool dimensionless,
                                 double model_fnomin_N, double model_radius_m);

}  // namespace modaltyre::tir
