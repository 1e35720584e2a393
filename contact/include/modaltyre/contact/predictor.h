#pragma once
// Footprint predictions: the one entry point behind `footprint`, `validate`, `sweep`, `discover`
// and the carcass-level calibration, for any operating conditions and switchable effects
// (effects.h) on one immutable TyreModel.
//
// predict(model, conditions) predicts with the model's own parameters. With no effect on in the
// model's config it takes the effect-free path, bit for bit: the model's own operator
// (solve_footprint, matrix-free), where only the load and the horizontal force act. With an
// effect on it takes the effects path below with the model's own parameters.
//
// predict(model, parameters, conditions) predicts with other parameters than the model's (what
// a calibration or a fit varies: TyreParameters) and always takes the effects path, one step per
// effect: the applied load shared with dry friction (dry_friction), the carcass compliance level
// (modal.compliance_scale relative to the model's, inflation_pressure, load_stiffening), the
// carcass kernels rebuilt only when an effect changes them (rolling_speed at a speed > 0,
// belt_flattening), the tread (tread.modulus_MPa, tread_relaxation, tread_coupling) and soil
// (soil_compliance) assembled in O(m^2), the horizontal coupling, and the patch width
// iterated with the sinking (contact_width).
//
// A config with a `footprint_3d:` section (TyreParameters::footprint_3d) is predicted on the 3D
// patch (patch3d.h) on both entry points: the width, the contour and the pressure map come from
// it. The effects act on it as on the 2D patch where they compose (carcass level and kernels,
// tread cells, applied load, soil under the cells); tread_coupling, rolling_speed,
// contact_width and a horizontal force are refused (the config reader refuses them; a
// prediction asked for them anyway fails with the reason).
//
// The model is shared read-only by every call and thread; each call's working data (the
// assembled operator, the contact set) are its own.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/patch3d.h"
#include "modaltyre/core/solve_status.h"

namespace modaltyre::contact {

/// What a prediction may vary without rebuilding the model: the carcass level, the tread and the
/// effects. Everything that defines the modal basis and the mesh (hammer data, extension,
/// contact.*) is the model's. SI units, as in TyreConfig.
struct TyreParameters {
  double compliance_scale = 1.0;  ///< modal.compliance_scale, > 0
  TreadParams tread;
  EffectsConfig effects;
  /// The 3D patch's settings (crown, tread width): present = predicted on the 3D patch.
  std::optional<Patch3dSettings> footprint_3d;
  /// modal.pneumatic_share: beta of F_z = F_s + beta p A (pneumatic_share.h), p the row's
  /// inflation pressure; 0 = the modal carcass alone.
  double pneumatic_share = 0;
};

/// The parameters a config states.
TyreParameters parameters_of(const TyreConfig& config);

struct PredictOptions {
  /// Contact flags of the candidate units to start the active set from (empty: cold start).
  std::span<const char> warm_active;
  /// The 3D patch: a previous result's cell forces to start the sections' lateral patterns
  /// from (Patch3d::solve; empty: every cell).
  std::span<const double> warm_cells;
};

struct Prediction {
  /// The footprint's status; failed when the conditions or the effects refuse the prediction.
  SolveStatus status = SolveStatus::failed;
  std::string message;  ///< reason when !ok()
  double sinking_mm = 0;
  double length_mm = 0;
  /// The 3D patch's width; on the 2D patch the config's, or the crown-profile width
  /// (contact_width).
  double width_mm = 0;
  double rolling_resistance_N = 0;  ///< sum f_z x / (R0 - sinking): 0 for a standing tyre
  double elastic_load_N = 0;        ///< load on the elastic tyre (dry_friction moves it)
  /// On a soil (config ground:, ground_patch.h): the deepest point of the soil below its
  /// undisturbed surface, the tyre's own deflection (sinking - soil sinkage), Bekker's b.
  bool on_soil = false;
  double soil_sinkage_mm = 0, tyre_deflection_mm = 0, bekker_width_mm = 0;
  /// The footprint; `footprint.load` is the applied load (the conditions'), whatever part of it
  /// dry friction carries. On the 3D patch: one unit per section in contact (its resultant, the
  /// centre-line pressure), the longest column's edges and the centre line's contour.
  FootprintResult footprint;
  /// The 3D patch's result (cells, contour per x and y; pressure_map()); null on the 2D patch.
  std::shared_ptr<const Patch3dResult> patch3d;

  /// Observable by its measurement-column name (sinking_mm, length_mm, width_mm,
  /// rolling_resistance_N).
  double observable(const std::string& name) const;
  bool ok() const { return modaltyre::ok(status); }
};

/// The observable columns a prediction provides, in CSV order.
const std::vector<std::string>& observable_names();

/// Whether operating conditions beyond the load and the horizontal force act on this config's
/// predictions: they act through effects and, the pressure, through modal.pneumatic_share.
bool conditions_act(const TyreConfig& config);

/// The model's own parameters at `conditions` (see above).
Prediction predict(const TyreModel& model, const OperatingConditions& conditions,
                   const PredictOptions& options = {});

/// Other parameters than the model's at `conditions`: always the effects path.
Prediction predict(const TyreModel& model, const TyreParameters& parameters,
                   const OperatingConditions& conditions, const PredictOptions& options = {});

/// The model's own parameters at several conditions in order. On the effect-free path each case
/// starts from the previous converged contact set (as solve_footprints); with effects each
/// starts cold (as predict).
std::vector<Prediction> predict_all(const TyreModel& model,
                                    const std::vector<OperatingConditions>& conditions);

/// Tread radial compliance between units l apart for a Pasternak (shear-coupled) tread layer
/// discretised with units of length ds: k_r (u_i - a (u_{i-1} - 2 u_i + u_{i+1})) = f_i with
/// a = (coupling_length / ds)^2. On an unbounded line the inverse is g_l = rho^|l| /
/// (k_r sqrt(1 + 4a)), rho = (1 + 2a - sqrt(1 + 4a)) / (2a); sum_l g_l = 1 / k_r (a uniform
/// load compresses it like independent springs). Entries below 1e-12 g_0 are dropped.
std::vector<double> pasternak_tread_lags(double k_radial_N_m, double coupling_length_m,
                                         double unit_length_m, int max_lags);

}  // namespace modaltyre::contact
