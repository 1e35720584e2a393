#pragma once
// Scenarios of the transient simulation: the load F(t), rolling speed V(t), road profile and
// initial condition of load-hold, free-vibration, rolling and cleat (settings: the config's
// transient: section, docs/transient.md).
#include <functional>
#include <string>
#include <vector>

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
  double step_limit(double t) const;    ///< the bound in force at t (0 = none)
  double speed(double t) const;         ///< V(t), smoothstep ramp from rest
  double acceleration(double t) const;  ///< V'(t)
  double distance(double t) const;      ///< integral of V
};

/// The plan of a scenario from the settings; InputError for an ill-posed one.
ScenarioPlan plan_scenario(const TransientModel& model, Scenario s);

}  // namespace modaltyre::transient
