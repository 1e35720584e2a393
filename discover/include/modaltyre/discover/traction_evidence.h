#pragma once
// Traction rows (studies/traction_rows.h) as evidence for `discover`: the model's steady rolling
// at slip on the config's soil (contact/traction.h, the path `modaltyre traction` runs) beside
// its footprints, residuals made commensurable with the footprints' relative ones.
//
// Residuals: r = (predicted - measured) / scale,
//   soil_sinkage_mm   scale |measured|: relative, as the footprints' sinking and length;
//   drawbar_pull_N    scale max(|measured|, 0.1 F_z): relative where the pull is a sizable
//                     share of the load, and a share of 0.1 F_z near the self-propelled point,
//                     where the pull crosses zero and a relative residual would grow without
//                     bound (a 2 % noise then reads as at most 2 %, as on a footprint);
//   torque_Nm         scale max(|measured|, 0.1 F_z R0), R0 the outer radius, for the same
//                     reason near the towed point.
// The noise of each observable is its own (model_fit.h profiles one variance per observable),
// so the scales matter for the pooled cross-validated RMS only, where they make a traction row
// count like a footprint row of the same relative precision.
//
// Runs: the traction rows are grouped by load and speed; one steady_traction run per group
// takes every slip of the group in increasing order (each slip warm-starts the next) and as
// many passes as the group's highest pass. The tyre model is rebuilt for each parameter set
// (the baseline scalars act in its kernels and tread; the modes are identified once), on
// discover's evaluation mesh. Each group rolls on one candidate window for the whole run,
// decided once from its measured sinkage (evidence_window.h: the rim's chord at the measured
// sinkage plus the tyre's road deflection, +10 %; the config's where that fits in it or nothing
// was measured). A row whose contact reaches that window's edge fails; `traction` grows its
// window there, discover does not per evaluation (see the .cc).
#include <atomic>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "modaltyre/contact/effects.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/discover/evidence_window.h"
#include "modaltyre/modal/mode_identification.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::discover {

/// The tyre's flexing (hysteresis) loss per load [N] at a speed [m/s] on the model's patch
/// (report/traction_flexing.h, which the command hands over: discover sits below report).
using FlexingLoss = std::function<std::map<double, double>(
    const contact::TyreModel&, const std::vector<double>& loads_N, double speed_m_s)>;

/// The share of the load (of load x R0 for the torque) below which drawbar pull and torque
/// residuals are taken against it rather than against the measured value.
inline constexpr double kTractionFloor = 0.1;

/// The scale a residual of `observable` in `row` is divided by (see above; |measured| for the
/// footprint observables).
double residual_scale(const studies::MeasuredRow& row, const std::string& observable,
                      double measured, double outer_radius_m);

/// Whether an effect acts on soil runs (traction): it switches or fits a key of the config's
/// ground: section (ground.*), the soil the traction rows roll on.
bool acts_on_soil_runs(const contact::EffectInfo& info);

/// The model's value of a traction observable (drawbar_pull_N, soil_sinkage_mm, torque_Nm).
double traction_observable(const contact::TractionResult& r, const std::string& name);

/// The window a group of traction rows rolls on (evidence_window.h).
struct TractionWindow {
  double load_N = 0, speed_kmh = 0;
  EvidenceWindow window;
};

class TractionRows {
 public:
  /// `config`: discover's evaluation config (its mesh; its ground must be a soil when the data
  /// have traction rows, else InputError naming ground.model). The flexing loss (null: none)
  /// is taken once per load and speed at this config and kept through the fits (the soil's
  /// effects do not act on it; the re-fitted baseline moves it by the change of its scalars).
  TractionRows(const contact::TyreConfig& config, const studies::MeasurementSet& data,
               const FlexingLoss& flexing);

  /// The model's traction at `config` for the traction rows among `rows` (indices into
  /// data.rows): the result per row index (failed where the case failed). Groups run in
  /// parallel over `threads` when not already inside a parallel region.
  /// `modes`: the modal basis the models are built on (null: the one identified at
  /// construction); the propagation of the model's uncertainty perturbs it.
  std::map<int, contact::TractionResult> predict(
      const contact::TyreConfig& config, const std::vector<int>& rows, int threads,
      const modal::ModeIdentification* modes = nullptr) const;
  /// The window each group (load, speed) rolls on and why, in the data's order.
  std::vector<TractionWindow> windows() const;
  /// Slip cases run so far (one per slip, pass and predict()).
  long cases() const { return cases_.load(std::memory_order_relaxed); }

 private:
  struct Group {
    double load_N = 0, speed_kmh = 0;
    std::vector<int> rows;
    EvidenceWindow window;  ///< decided once, at construction
  };
  void decide_windows(const contact::TyreConfig& config);
  const studies::MeasurementSet& data_;
  modal::ModeIdentification modes_;
  std::vector<Group> groups_;
  std::vector<int> group_of_;                         ///< per data row (-1: a footprint row)
  std::map<std::pair<double, double>, double> flex_;  ///< (speed, load) -> flexing loss [N]
  mutable std::atomic<long> cases_{0};
};

}  // namespace modaltyre::discover
