#pragma once
// Scenarios of the transient simulation: the load F(t), rolling speed V(t), road profile and
// initial condition of load-hold, free-vibration, rolling and cleat (settings: the config's
// transient: section, docs/transient.md).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "modaltyre/modal/critical_speed.h"
#include "modaltyre/transient/hub_motion.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::transient {

enum class Scenario { load_hold, free_vibration, rolling, cleat };
/// "load-hold", "free-vibration", "rolling", "cleat"; anything else is an InputError.
Scenario parse_scenario(const std::string& name);
const char* to_string(Scenario s);

/// Time functions and initial condition of a scenario.
struct ScenarioPlan {
  Scenario scenario = Scenario::load_hold;
  double duration_s = 0;
  double initial_load_N = 0;           ///< 0: start undeformed, touching the road
  std::vector<double> breakpoints;     ///< times where F or Omega change slope (restarts)
  std::function<double(double)> load;  ///< F(t) [N]
  double speed_m_s = 0;                ///< final rolling speed
  double ramp_s = 0;                   ///< speed ramp from 0 (0: at speed from t = 0)
  bool cleat = false;
  double cleat_height_m = 0, cleat_length_m = 0, cleat_start_m = 0;  ///< centre at t = 0
  /// Step-size bound while a cleat crosses the window, in force over [from, until) [s].
  double step_limit_s = 0, step_limit_from_s = 0, step_limit_until_s = 0;
  /// A prescribed hub (hub_motion.h): its deflection, speed and spin replace the load control
  /// and the speed ramp (load, speed_m_s and ramp_s are then unused; the road is flat).
  std::shared_ptr<const HubTrack> hub;
  double radius_m = 0;                    ///< R0: the free-rolling spin V / R0
  double step_limit(double t) const;      ///< the bound in force at t (0 = none)
  double speed(double t) const;           ///< V(t), smoothstep ramp from rest (or the hub's)
  double acceleration(double t) const;    ///< V'(t)
  double distance(double t) const;        ///< integral of V (the speed ramp's; the cleat's road)
  double spin(double t) const;            ///< Omega(t): V / R0, or the prescribed hub's spin
  double spin_rate(double t) const;       ///< Omega'(t)
  bool hub_free() const { return !hub; }  ///< the hub's z a state (load control)
  /// A road under a driven tyre in place of the cleat (the FMU's road_profile, issue 34): its
  /// height above the flat road at ground position x relative to the hub (a unit's x_road) at
  /// time t, and its slope dh/dx into `slope` when not null. Empty: the cleat or a flat road.
  std::function<double(double t, double x_m, double* slope)> road_profile;
  double road_max_height_m = 0;  ///< >= every height road_profile returns (reach bounds)
  bool has_road() const { return cleat || static_cast<bool>(road_profile); }
  /// An upper bound of the road's height over the flat road (>= 0).
  double road_height_bound() const {
    if (road_profile) return road_max_height_m > 0 ? road_max_height_m : 0.0;
    return cleat && cleat_height_m > 0 ? cleat_height_m : 0.0;
  }
  /// The hub's displacement z at t: the state's (load control) or the prescribed one.
  double hub_z(double t, double state_z) const { return hub ? hub->deflection(t) : state_z; }
  /// The hub's rates (z', w') at t from its states (z, w) and the contact load: m z'' = F(t) -
  /// load under load control; 0 and 0 under a prescribed hub (z is the plan's, the states stay).
  void hub_rates(double t, const double* zw, double load_N, double hub_mass_kg,
                 double* zw_dot) const {
    zw_dot[0] = hub ? 0.0 : zw[1];
    zw_dot[1] = hub ? 0.0 : (this->load(t) - load_N) / hub_mass_kg;
  }
};

/// The plan of a scenario from the settings; InputError for an ill-posed one (a rolling or
/// cleat speed at or beyond critical_speed_of() among them).
ScenarioPlan plan_scenario(const TransientModel& model, Scenario s);

/// The critical speed of the model's dynamic orders (modal/critical_speed.h): the rolling and
/// cleat scenarios refuse speeds at or beyond it.
modal::CriticalSpeed critical_speed_of(const TransientModel& model);

/// From this share of the critical speed the standing wave visibly grows (the default tyre's
/// rolling resistance at 240 km/h is 1.8 times that at 200 km/h, at 255 km/h 3 times): the
/// outputs say so.
constexpr double kNearCriticalShare = 0.85;

}  // namespace modaltyre::transient
