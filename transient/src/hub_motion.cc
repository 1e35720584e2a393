#include "modaltyre/transient/hub_motion.h"

#include <cmath>
#include <utility>

namespace modaltyre::transient {

void HubTrack::set_function(std::function<HubState(double)> f) { function_ = std::move(f); }

void HubTrack::set_step(double t0, const HubState& s0, double t1, const HubState& s1,
                        HubInterpolation how) {
  function_ = nullptr;
  t0_ = t0, t1_ = t1;
  s0_ = s0, s1_ = s1;
  linear_ = how == HubInterpolation::linear && t1 > t0;
  // Both ends with a resolved spin, so that a free-rolling end interpolates V / R0.
  s0_.spin_rad_s = spin_of(s0_);
  s1_.spin_rad_s = spin_of(s1_);
}

double HubTrack::spin_of(const HubState& s) const {
  return std::isnan(s.spin_rad_s) ? s.speed_m_s / radius_m_ : s.spin_rad_s;
}

HubState HubTrack::raw(double t) const {
  if (function_) {
    HubState s = function_(t);
    s.spin_rad_s = spin_of(s);
    return s;
  }
  if (!linear_ || t >= t1_) return s1_;
  if (t <= t0_) return s0_;
  const double a = (t - t0_) / (t1_ - t0_);
  HubState s;
  s.deflection_m = s0_.deflection_m + a * (s1_.deflection_m - s0_.deflection_m);
  s.speed_m_s = s0_.speed_m_s + a * (s1_.speed_m_s - s0_.speed_m_s);
  s.spin_rad_s = s0_.spin_rad_s + a * (s1_.spin_rad_s - s0_.spin_rad_s);
  return s;
}

HubState HubTrack::at(double t) const { return raw(t); }
double HubTrack::deflection(double t) const { return raw(t).deflection_m; }
double HubTrack::speed(double t) const { return raw(t).speed_m_s; }
double HubTrack::spin(double t) const { return raw(t).spin_rad_s; }

namespace {
/// The slope of a linear step inside it (0 outside and for a hold).
double step_rate(bool linear, double t0, double t1, double t, double v0, double v1) {
  return linear && t > t0 && t < t1 ? (v1 - v0) / (t1 - t0) : 0.0;
}
}  // namespace

double HubTrack::deflection_rate(double t) const {
  if (function_) {
    const double h = kRateStep_s;
    return (raw(t + h).deflection_m - raw(t - h).deflection_m) / (2 * h);
  }
  return step_rate(linear_, t0_, t1_, t, s0_.deflection_m, s1_.deflection_m);
}

double HubTrack::acceleration(double t) const {
  if (function_) {
    const double h = kRateStep_s;
    return (raw(t + h).speed_m_s - raw(t - h).speed_m_s) / (2 * h);
  }
  return step_rate(linear_, t0_, t1_, t, s0_.speed_m_s, s1_.speed_m_s);
}

double HubTrack::spin_rate(double t) const {
  if (function_) {
    const double h = kRateStep_s;
    return (raw(t + h).spin_rad_s - raw(t - h).spin_rad_s) / (2 * h);
  }
  return step_rate(linear_, t0_, t1_, t, s0_.spin_rad_s, s1_.spin_rad_s);
}

}  // namespace modaltyre::transient
