#pragma once
// `modaltyre tir export`: the model's vertical and contact-patch behaviour as an MF-Tyre 6.2
// property file (FITTYP 62, SI units).
//
// Fits (least squares on relative residuals, so that light and heavy loads weigh alike), to the
// model's footprints at `loads` (default 12 loads over 0.25-2 x FNOMIN):
//   (A3.3)  F/F_z0 = q_Fz1 x + q_Fz2 x^2,  x = rho/R0      -> Q_FZ2; VERTICAL_STIFFNESS from
//           (A3.4) inverted, C_z0 = F_z0/R0 sqrt(q_Fz1^2 + 4 q_Fz2), so that a simulator's
//           q_Fz1 (derived from C_z0 by A3.4) is the fitted one
//   (A3.7)  a/R0 = Q_RA2 x' + Q_RA1 sqrt(x'),   x' = F/(C_z0 R0)
//   (A3.8)  b/W  = Q_RB2 x' + Q_RB1 x'^(1/3)    only when the predictions carry a width
//   (A3.5)  PFZ1 = (C_z(1.1 p) - C_z(0.9 p)) / (0.2 C_z(p)), tangent stiffnesses at F_z0, when
//           the pressure moves the model (the ring's pressure terms, or the inflation_pressure
//           effect); else PFZ1 is left out (0 in any MF evaluator) and the header says why
// [STRUCTURAL] and [INERTIA] are left out, and the header says why: the hammer test's modes are
// those of the tested tyre's boundary condition, not MF-Swift's rigid ring on a fixed rim.
// With TirExportOptions::slip enabled the file also holds the longitudinal pure-slip force, the
// rolling resistance and the effective rolling radius fitted to the model's own steady runs on
// a prescribed wheel (slip_fit.h, slip_text.h); lateral, aligning, overturning, combined and
// turn-slip sections stay out (the model is in-plane), and the header says so.
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/tir/model_curve.h"
#include "modaltyre/tir/slip_fit.h"

namespace modaltyre::tir {

struct TirExportOptions {
  std::optional<double> fnomin_N;  ///< default: the middle of the config's loads
  std::vector<double> loads_N;     ///< default: load_grid(FNOMIN, 0.25, 2, 12)
  std::string config_label;        ///< the config path as the user gave it (for the header)
  /// Lines added to the header's comments (e.g. the coefficients' uncertainty); printable text.
  std::vector<std::string> comments;
  /// The longitudinal, rolling-resistance and effective-radius laws (slip_fit.h); off by
  /// default here (the command turns it on): the file is then the vertical one of before.
  SlipExportOptions slip;
};

/// One fitted law and how well it follows the model (relative residuals).
struct FitQuality {
  double rms_rel = 0;
  double max_abs_rel = 0;
};

struct TirFit {
  double fnomin_N = 0;
  double unloaded_radius_m = 0;
  double width_m = 0;                         ///< WIDTH of [DIMENSION]
  std::string width_source;                   ///< which config key gave WIDTH
  double rim_radius_m = 0, aspect_ratio = 0;  ///< 0 = not stated by the config
  double pressure_Pa = 0;                     ///< INFLPRES = NOMPRES: the config's pressure

  double q_fz1 = 0, q_fz2 = 0, vertical_stiffness_N_m = 0;
  double model_tangent_stiffness_N_m = 0;  ///< at FNOMIN, for the header's check
  std::optional<double> pfz1;
  std::string pfz1_reason;  ///< why PFZ1 is left out
  double q_ra1 = 0, q_ra2 = 0;
  std::optional<double> q_rb1, q_rb2;
  FitQuality load, sinking, length;
  std::optional<FitQuality> width;
  ModelCurve curve;                ///< the footprints fitted
  std::optional<TirSlipFit> slip;  ///< when TirExportOptions::slip is enabled
};

/// Samples the model and fits the laws; ComputationError when a fit is degenerate.
TirFit fit_tir(const contact::TyreModel& model, const TirExportOptions& options);

/// The .tir text of a fit.
std::string tir_text(const TirFit& fit, const contact::TyreConfig& config,
                     const TirExportOptions& options);

}  // namespace modaltyre::tir
