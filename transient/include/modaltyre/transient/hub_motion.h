#pragma once
// A prescribed hub (driven_tyre.h, docs/transient.md section 8): the hub's vertical position,
// forward speed and wheel spin as functions of time, in place of the scenarios' load control
// (m z'' = F(t) - sum f) and speed ramp. The hub's displacement z is then an input of the ODE,
// not a state: the penetrations read z(t), the hub's own equations are dropped, and the hub's
// mass plays no part (the host model carries the wheel's mass).
#include <functional>
#include <limits>

namespace modaltyre::transient {

/// The hub at one time.
struct HubState {
  /// The tyre's free radius R0 minus the hub's height above a flat road [m]: the model's hub
  /// displacement z (downward). 0: the undeformed tread touches the road; > 0 pressed into it
  /// (on a flat road this is the sinking); < 0 lifted off.
  double deflection_m = 0;
  double speed_m_s = 0;  ///< forward speed of the hub over the road
  /// Spin of the wheel about its axis [rad/s], forward rolling > 0; NaN: free rolling, the
  /// model's kinematic spin speed / R0.
  double spin_rad_s = std::numeric_limits<double>::quiet_NaN();
};

/// How the hub moves over one step of a step-by-step drive (DrivenTyre::advance).
enum class HubInterpolation {
  hold,   ///< the new state from the start of the step to its end (zero-order hold)
  linear  ///< linear from the state at the start of the step to the new one at its end
};

/// The hub's motion: a function of time, or the two ends of the current step of a
/// step-by-step drive. Rates: exact for the step's linear interpolation (0 for a hold), central
/// differences for a function (kRateStep_s).
class HubTrack {
 public:
  /// Step of the central differences of a function's rates [s]: its truncation error
  /// (h^2 / 6 times the third derivative) and rounding (1e-16 |value| / h) stay below 1e-9 of
  /// the rates of motions on the time scale of the tyre's modes (ms and up).
  static constexpr double kRateStep_s = 1e-6;

  explicit HubTrack(double radius_m) : radius_m_(radius_m) {}
  /// The hub follows f(t) at every t.
  void set_function(std::function<HubState(double)> f);
  /// The current step [t0, t1]: from s0 to s1 (linear) or s1 throughout (hold); before t0 the
  /// start, after t1 the end.
  void set_step(double t0, const HubState& s0, double t1, const HubState& s1, HubInterpolation how);

  double deflection(double t) const;
  double deflection_rate(double t) const;
  double speed(double t) const;
  double acceleration(double t) const;
  /// Spin [rad/s] (free rolling resolved) and its rate.
  double spin(double t) const;
  double spin_rate(double t) const;
  /// The state at t with the spin resolved (never NaN).
  HubState at(double t) const;

 private:
  HubState raw(double t) const;
  double spin_of(const HubState& s) const;
  double radius_m_ = 0;
  std::function<HubState(double)> function_;
  double t0_ = 0, t1_ = 0;
  HubState s0_, s1_;
  bool linear_ = false;
};

}  // namespace modaltyre::transient
