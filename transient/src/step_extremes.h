#pragma once
// The run's extremes of the contact load and the longitudinal force, and the hub's trace for the
// free vibration's peaks, taken at the integrator's own steps and inside them (CVODE's dense
// output) instead of at the output grid (issue 44): a 10 ms grid read five samples per bounce
// period (log decrement 0.098 against 0.0914), and over a 20 mm cleat at 30 km/h the longitudinal
// force's minimum as -285 N against -780 N. Internal to the transient library (run_loop.cc).
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "modaltyre/transient/driver.h"

namespace modaltyre::transient::detail {

/// The forces of a state (PatchOde::observe_forces).
using ForceObserver = std::function<TransientSample(double t, const double* y)>;

/// Every accepted step's end is observed (from the forces the contact-set update computed there:
/// PatchOde::step_forces). A signal's extreme lies at a step's end or inside one of the two
/// steps around a local extreme of the step ends. The kKept largest local extremes of each
/// signal keep the three states at those steps' ends; at the end of the run each is searched at
/// its steps' quarter points on the quadratic through the three (BDF orders <= 2,
/// ode_options(): CVODE's own interpolant is a quadratic of the same history, equal to it within
/// the local error) and refined at the vertex of the parabola through the best of them and its
/// neighbours. The cost: a copy of the state a step, and a few force passes per kept extreme
/// at the end.
class StepExtremes {
 public:
  /// hub_z_index >= 0: also keep the hub's displacement y[hub_z_index] at every step's end
  /// (TransientResult::hub_steps; the free vibration's peaks, decay.h).
  /// `at_steps` observes an accepted step's end (PatchOde::step_forces), `anywhere` any state
  /// (PatchOde::observe_forces).
  StepExtremes(ForceObserver at_steps, ForceObserver anywhere, int hub_z_index);
  /// The initial state (t = 0).
  void start(double t0, const std::vector<double>& y0);
  /// After an accepted step to t1 with the end state y1.
  void step(double t1, const std::vector<double>& y1);
  /// Searches the kept extremes; the extremes and the hub's trace into the result.
  void finish(TransientResult& r);

  /// Local extremes kept per signal and sense.
  static constexpr int kKept = 3;

 private:
  /// Two consecutive steps around a local extreme at their shared end t[1]: the three ends.
  struct Pair {
    double value = 0;  ///< the signed value at t[1]
    std::array<double, 3> t{};
    std::array<TransientSample, 3> s{};  ///< the samples at t
    /// The states at t, shared with the ring of the last ends (no copy when a pair is kept).
    std::array<std::shared_ptr<const std::vector<double>>, 3> y;
  };
  /// One extreme: sign * quantity is maximised (quantity 0 load, 1 longitudinal force).
  struct Tracker {
    int quantity = 0;
    double sign = 1;
    double best = 0, t_best = 0;
    std::vector<Pair> kept;  ///< at most kKept, the largest values
  };
  static double value(const Tracker& k, const TransientSample& s);
  void offer(const TransientSample& s);
  /// The state at t on the quadratic through a pair's three states.
  void on_quadratic(const Pair& p, double t, std::vector<double>& y) const;
  void keep(Tracker& k, double v);
  void search(Tracker& k, const Pair& p);

  ForceObserver at_steps_, observe_;
  int hub_z_index_;
  std::array<Tracker, 4> trackers_;
  bool started_ = false;
  /// The last three step ends (oldest first).
  int ends_seen_ = 0;
  std::array<double, 3> t_{};
  /// Their states; a buffer that a kept pair still holds is not written again (step()).
  std::array<std::shared_ptr<std::vector<double>>, 3> y_;
  std::array<TransientSample, 3> s_{};
  std::vector<double> work_;
  std::vector<HubStep> hub_;
  long searches_ = 0;
};

}  // namespace modaltyre::transient::detail
