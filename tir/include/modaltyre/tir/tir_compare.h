#pragma once
// `modaltyre tir compare`: a .tir file's vertical and contact-patch laws against the model's own
// footprints over the model's deflection range (its loads 0.25-2 x FNOMIN).
//
// Same tyre size (UNLOADED_RADIUS within 3 % of the config's outer radius and, when both state
// it, WIDTH within 5 % of tyre.section_width_mm): absolute units, the .tir's load, length and
// width at the model's deflection rho. Otherwise dimensionless: at the same rho/R0 the .tir's
// load/FNOMIN, 2a/R0 and 2b/W against the model's (the model's FNOMIN: --fnomin or the middle of
// its loads); the rows' absolute columns then carry the .tir's law scaled to the model's size
// (load ratio x the model's FNOMIN, 2a/R0 x the model's R0, 2b/W x its section width).
// With CompareOptions::slip, the longitudinal force, rolling resistance and effective radius too
// (slip_compare.h), on the same basis.
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/tir/mf_tyre.h"
#include "modaltyre/tir/model_curve.h"
#include "modaltyre/tir/slip_compare.h"

namespace modaltyre::tir {

struct CompareOptions {
  std::optional<double> fnomin_N;  ///< the model's nominal load
  int points = 12;                 ///< model footprints over 0.25-2 x FNOMIN (3..200)
  /// The longitudinal laws too (slip_compare.h): off by default (it runs the transient).
  SlipExportOptions slip;
};

struct CompareRow {
  double rho_m = 0;   ///< the model's deflection
  double load_N = 0;  ///< the model's load
  std::optional<double> tir_load_N;
  double model_length_m = 0;
  std::optional<double> tir_length_m;
  std::optional<double> model_width_m, tir_width_m;
};

struct TirComparison {
  MfTyre tir;
  bool dimensionless = false;
  std::string basis;  ///< the sentence saying why absolute or dimensionless
  double model_fnomin_N = 0, model_radius_m = 0, model_section_width_m = 0;
  std::vector<CompareRow> rows;
  /// RMS of (tir - model) / model over the rows where both exist; absent with a reason.
  std::optional<double> rms_load, rms_length, rms_width;
  std::string load_reason, length_reason, width_reason;
  std::optional<SlipComparison> slip;  ///< when CompareOptions::slip is enabled
};

TirComparison compare_tir(const contact::TyreModel& model, const MfTyre& tir,
                          const CompareOptions& options = {});

}  // namespace modaltyre::tir
