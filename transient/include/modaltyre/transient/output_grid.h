#pragma once
// The output samples' times of a scenario run (run by driver.h): the config's
// transient.output_step_ms, or, when it is absent or `auto`, a step chosen to resolve what the
// scenario reports (issue 44: a 10 ms default read five samples per hub-bounce period). The run's
// reported extremes, period and decrement come from the integrator's own steps (step_extremes.h,
// decay.h), not from this grid: the grid is what the CSV and the plot show.
#include <string>

#include "modaltyre/transient/model.h"
#include "modaltyre/transient/scenario.h"

namespace modaltyre::transient {

/// The largest step the automatic grid takes (and the driven tyre's step when none is stated).
constexpr double kAutoOutputStepCap_s = contact::TransientSettings::kAutoOutputStepCap_s;
/// Samples per estimated hub-bounce period on the automatic grid.
constexpr double kSamplesPerBounce = 25;
/// Samples over the time a point of the road takes to pass a cleat's length, while the cleat
/// crosses the candidate window.
constexpr double kSamplesPerCleatPassage = 10;

/// Every `step_s` from 0 and, over [fine_from_s, fine_until_s), every `fine_step_s` (0: none);
/// always the scenario's end.
struct OutputGrid {
  double step_s = kAutoOutputStepCap_s;
  double fine_step_s = 0, fine_from_s = 0, fine_until_s = 0;
  double end_s = 0;
  bool chosen = false;        ///< chosen for the scenario (not stated in the config)
  double bounce_hz = 0;       ///< the hub-bounce frequency the choice resolves (0: none estimated)
  bool sample_bound = false;  ///< coarsened to the 1e6 samples a run may write
  /// The first grid time after t (end_s at the end).
  double next_after(double t) const;
  /// The grid's spacing at t.
  double step_at(double t) const;
  /// How the step was chosen, for the text output (e.g. "2 ms (stated)").
  std::string describe() const;
};

/// The grid of a run of `plan`: the model's stated output step, or, when it is 0 (auto), the
/// smallest of kAutoOutputStepCap_s and a 25th of the hub-bounce period estimated from the
/// initial static contact (load F0, sinking d0: f = sqrt(2 F0 / (d0 m)) / 2 pi, the factor 2
/// bounding the tangent over the secant stiffness of a tyre whose load rises as d^p, p <= 2),
/// and a tenth of the cleat's passage L / V while it crosses the window. At most 1e6 samples.
OutputGrid output_grid(const TransientModel& model, const ScenarioPlan& plan, double initial_load_N,
                       double initial_sinking_m);

}  // namespace modaltyre::transient
