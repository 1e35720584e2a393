#pragma once
// A rolling fixed point caught in a limit cycle (traction.cc, traction3d.cc), internal to the
// contact library. On a stiff tyre the rear unit on the rut's rigid floor can leave and re-enter
// contact step after step: with it the tyre rides on the floor and the depths ahead creep until
// it lets go; without it the tyre drops and they creep back (docs/soil.md section 10, "Runs that
// do not settle"). The orbit closes on that cycle (its return after p steps shrinks to the
// solver's rounding, or stays within a per cent of its swing) and the settle test fails at each
// of its steps, so more steps do not help; the plain step x <- G(x) settles on such runs (the
// fixed point exists; the mixing's secants, spanning a contact switch, miss it). A run found
// orbiting fails there, with the status of a run that used its whole budget, or (the option
// TractionOptions::plain_steps_on_cycle) goes on with plain steps, failing if found cycling again.
#include <Eigen/Dense>
#include <algorithm>
#include <string>
#include <vector>

namespace modaltyre::contact::detail {

/// A rolling step's changes from its state to its image (the largest per kind) and the settle
/// test's tolerances on them (traction.h: TractionOptions).
struct StepChanges {
  double depth_m = 0, pull_N = 0, fx_N = 0, width_m = 0, shear_N = 0, rear_N = 0;
};
struct SettleTolerances {
  double depth_m = 0, force_N = 0, width_m = 0;
};
/// Every change within its tolerance.
inline bool within(const StepChanges& d, const SettleTolerances& t) {
  return d.depth_m <= t.depth_m && d.pull_N <= t.force_N && d.fx_N <= t.force_N &&
         d.width_m <= t.width_m && d.shear_N <= t.force_N && d.rear_N <= t.force_N;
}
/// The largest change over its tolerance (> 1: not settled).
inline double worst_ratio(const StepChanges& d, const SettleTolerances& t) {
  return std::max({d.depth_m / t.depth_m, d.pull_N / t.force_N, d.fx_N / t.force_N,
                   d.width_m / t.width_m, d.shear_N / t.force_N, d.rear_N / t.force_N});
}

/// The last steps' carried states; a run orbiting a cycle is found by its returns.
class CycleGuard {
 public:
  /// Records this step's carried state and returns the period p of the cycle it orbits, 0 if
  /// none. state: the next step's iterate (and whatever else it carries), unscaled; scale: each
  /// entry's settle tolerance now (depths: depth_tolerance x the sinkage; forces: tolerance x the
  /// load); active: its contact set; worst: the settle test's largest ratio (> 1: not settled).
  /// A cycle of p >= 2 steps: for max(p, kHold) steps in a row the state came back, in the same
  /// contact set, to the state p steps before within kReturn of the period's largest step (its
  /// swing), the settle test failing by kMargin or more, and the swing is kAmplitude tolerances or
  /// more. A run creeping to its fixed point is never taken for one: its return is the sum of its
  /// steps, not less than its largest. A damped oscillation returning within 1 % of its swing
  /// loses at most 2 % of it per period, and from kAmplitude tolerances needs ln(10) / 0.02 = 115
  /// periods (230 steps or more) to settle: more than the run's 200 steps.
  int repeat(const Eigen::VectorXd& state, const Eigen::VectorXd& scale,
             const std::vector<char>& active, double worst) {
    const int n = static_cast<int>(states_.size());
    held_.resize(kWindow + 1, 0);
    steps_.push_back(n > 0 ? distance(state, states_[n - 1], scale) : 0.0);
    int found = 0;
    double swing = 0;  // the largest step of the last p (this one included)
    for (int p = 1; p <= kWindow; ++p) {
      if (p <= static_cast<int>(steps_.size())) swing = std::max(swing, steps_[steps_.size() - p]);
      if (p < 2) continue;
      const bool back = p <= n && worst >= kMargin && active_[n - p] == active &&
                        distance(state, states_[n - p], scale) <= kReturn * swing;
      held_[p] = back ? held_[p] + 1 : 0;
      if (!found && held_[p] >= std::max(p, kHold) && swing >= kAmplitude) found = p;
    }
    states_.push_back(state), active_.push_back(active);
    if (static_cast<int>(states_.size()) > kWindow) {
      states_.erase(states_.begin()), active_.erase(active_.begin());
      steps_.erase(steps_.begin());
    }
    return found;
  }

 private:
  static double distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                         const Eigen::VectorXd& scale) {
    if (a.size() != b.size()) return 1e300;
    return ((a - b).cwiseAbs().array() / scale.array()).maxCoeff();
  }
  static constexpr int kWindow = 64;          ///< the longest cycle looked for [steps]
  static constexpr int kHold = 8;             ///< the fewest returns in a row [steps]
  static constexpr double kMargin = 2.0;      ///< the settle test's least failing ratio
  static constexpr double kAmplitude = 10.0;  ///< the cycle's least swing [tolerances]
  static constexpr double kReturn = 0.01;     ///< the return's largest share of the swing
  std::vector<Eigen::VectorXd> states_;
  std::vector<std::vector<char>> active_;
  std::vector<double> steps_;  ///< each step's move [tolerances]
  std::vector<int> held_;
};

/// The run's cycle period (0: none) from the carried state: the mixed iterate `next` (its first
/// `depths` entries depths in mm, the rest forces in N), Bekker's b and a viscous soil's rolled
/// surface [m], with the settle test's tolerances [m, N, m] and its largest ratio this step.
inline int cycle_period(CycleGuard& guard, const Eigen::VectorXd& next, Eigen::Index depths,
                        double bekker_width_m, const std::vector<double>& surface_m,
                        const std::vector<char>& active, const SettleTolerances& tol,
                        double worst) {
  const double depth_tol_m = tol.depth_m, force_tol_N = tol.force_N, width_tol_m = tol.width_m;
  const Eigen::Index n = next.size(), r = Eigen::Index(surface_m.size());
  Eigen::VectorXd y(n + 1 + r), scale(n + 1 + r);
  y.head(n) = next, y(n) = bekker_width_m;
  scale.head(depths).setConstant(depth_tol_m * 1e3);
  scale.segment(depths, n - depths).setConstant(force_tol_N);
  scale(n) = width_tol_m;
  for (Eigen::Index i = 0; i < r; ++i) y(n + 1 + i) = surface_m[i], scale(n + 1 + i) = depth_tol_m;
  return guard.repeat(y, scale, active, worst);
}

/// The failure of a run caught in a cycle of `period` steps at step `step`.
inline std::string cycle_message(int step, int period) {
  return "steady rolling did not settle: at step " + std::to_string(step) +
         " it orbits a cycle of " + std::to_string(period) +
         " steps (the state returning within 1 % of its swing, the contact switching), which "
         "more steps do not end";
}

}  // namespace modaltyre::contact::detail
