#include "modaltyre/transient/scenario.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/modal/critical_speed.h"

namespace modaltyre::transient {
namespace {

/// Output samples of one run (memory and CSV rows): 1e6 is 2000 s at the default 2 ms.
constexpr double kMaxTransientSamples = 1e6;

/// Refuses a rolling speed at or beyond the carcass's critical speed (modal/critical_speed.h):
/// there the run has no steady state (issue 44: at 350 km/h the hub left the road, at 500 and
/// 1000 km/h it ended 13 m and 605 m above it).
void refuse_beyond_critical(const TransientModel& model, double speed_m_s, const char* key) {
  const modal::CriticalSpeed c = critical_speed_of(model);
  if (speed_m_s < c.speed_m_s) return;
  std::ostringstream msg;
  msg.precision(4);
  msg << speed_m_s * 3.6 << " km/h is at or beyond the carcass's critical speed " << c.speed_km_h()
      << " km/h (order " << c.order << ": omega_" << c.order << " R0 / " << c.order
      << ", where its backward wave stands still on the road). Beyond it the contact feeds "
         "energy into that wave and the modal carcass (measured at rest, without the belt's "
         "centrifugal stiffening) has no steady rolling state: a run there is a blow-up, not a "
         "tyre. Below it the standing wave grows as the speed approaches (docs/transient.md "
         "section 3a)";
  throw InputError(InputLocation{model.tyre.config.source, 0, key}, msg.str());
}

}  // namespace

modal::CriticalSpeed critical_speed_of(const TransientModel& model) {
  // The dynamic orders only: the residual ones respond without inertia (model.h).
  return modal::critical_speed(model.tyre.basis, model.tyre.config.outer_radius_m,
                               std::max(model.settings.dynamic_max_order, 1));
}

Scenario parse_scenario(const std::string& name) {
  if (name == "load-hold") return Scenario::load_hold;
  if (name == "free-vibration") return Scenario::free_vibration;
  if (name == "rolling") return Scenario::rolling;
  if (name == "cleat") return Scenario::cleat;
  throw InputError(
      InputLocation{"--scenario", 0, ""},
      "unknown scenario '" + name + "': expected one of load-hold, free-vibration, rolling, cleat");
}

const char* to_string(Scenario s) {
  switch (s) {
    case Scenario::load_hold:
      return "load-hold";
    case Scenario::free_vibration:
      return "free-vibration";
    case Scenario::rolling:
      return "rolling";
    case Scenario::cleat:
      return "cleat";
  }
  return "?";
}

// Speed ramp from rest: smoothstep V (3 s^2 - 2 s^3), s = t / ramp_s. The acceleration rises
// from 0 and returns to 0: a linear ramp's jump of V' at t = 0 (infinite jerk) excited the
// lightly damped carcass modes, and resolving their ringing took ~1000 steps of 0.4 ms in the
// first 0.4 s of the default rolling run (docs/transient.md section 3).
double ScenarioPlan::speed(double t) const {
  if (hub) return hub->speed(t);
  if (speed_m_s == 0) return 0;
  if (ramp_s <= 0 || t >= ramp_s) return speed_m_s;
  const double s = std::max(t, 0.0) / ramp_s;
  return speed_m_s * s * s * (3 - 2 * s);
}
double ScenarioPlan::acceleration(double t) const {
  if (hub) return hub->acceleration(t);
  if (ramp_s <= 0 || t >= ramp_s || t < 0) return 0;
  const double s = t / ramp_s;
  return speed_m_s * 6 * s * (1 - s) / ramp_s;
}
double ScenarioPlan::distance(double t) const {
  if (ramp_s <= 0) return speed_m_s * t;
  if (t <= ramp_s) {
    const double s = std::max(t, 0.0) / ramp_s;
    return speed_m_s * ramp_s * s * s * s * (1 - 0.5 * s);
  }
  return 0.5 * speed_m_s * ramp_s + speed_m_s * (t - ramp_s);
}
double ScenarioPlan::spin(double t) const { return hub ? hub->spin(t) : speed(t) / radius_m; }
double ScenarioPlan::spin_rate(double t) const {
  return hub ? hub->spin_rate(t) : acceleration(t) / radius_m;
}
double ScenarioPlan::step_limit(double t) const {
  return t >= step_limit_from_s && t < step_limit_until_s ? step_limit_s : 0.0;
}

ScenarioPlan plan_scenario(const TransientModel& model, Scenario s) {
  const auto& T = model.settings;
  const std::string src = model.tyre.config.source;
  ScenarioPlan p;
  p.scenario = s;
  p.radius_m = model.tyre.config.outer_radius_m;
  switch (s) {
    case Scenario::load_hold: {
      const auto& L = T.load_hold;
      if (L.hold_s < 0) {
        throw InputError(InputLocation{src, 0, "transient.load_hold.hold_s"},
                         "hold time must not be negative");
      }
      const double t_ramp = L.load_N / L.ramp_rate_N_s;
      p.duration_s = t_ramp + L.hold_s;
      p.breakpoints = {t_ramp};
      const double F = L.load_N, rate = L.ramp_rate_N_s;
      p.load = [F, rate](double t) { return std::min(F, rate * std::max(t, 0.0)); };
      break;
    }
    case Scenario::free_vibration: {
      const auto& V = T.free_vibration;
      if (V.initial_load_N == V.load_N) {
        throw InputError(InputLocation{src, 0, "transient.free_vibration.initial_load_N"},
                         "equals load_N: the tyre would not vibrate");
      }
      p.duration_s = V.duration_s;
      p.initial_load_N = V.initial_load_N;
      const double F = V.load_N;
      p.load = [F](double) { return F; };
      break;
    }
    case Scenario::rolling: {
      const auto& R = T.rolling;
      refuse_beyond_critical(model, R.speed_m_s, "transient.rolling.speed_km_h");
      p.duration_s = R.duration_s;
      p.initial_load_N = R.load_N;
      p.speed_m_s = R.speed_m_s;
      p.ramp_s = R.ramp_s;
      if (R.ramp_s > 0 && R.ramp_s < R.duration_s) p.breakpoints = {R.ramp_s};
      const double F = R.load_N;
      p.load = [F](double) { return F; };
      break;
    }
    case Scenario::cleat: {
      const auto& C = T.cleat;
      refuse_beyond_critical(model, C.speed_m_s, "transient.cleat.speed_km_h");
      p.initial_load_N = C.load_N;
      p.speed_m_s = C.speed_m_s;
      p.ramp_s = C.ramp_s;

      p.cleat = true;
      p.cleat_height_m = C.height_m;
      p.cleat_length_m = C.length_m;
      const double xw = model.x_road.maxCoeff();
      const double settle = 0.1;  // steady rolling before the cleat enters the window
      const double t_arrive = C.ramp_s + settle;
      p.cleat_start_m = xw + 0.5 * C.length_m + p.distance(t_arrive);
      // Until the cleat has left the window at the back, plus the same settling time.
      const double travel = p.cleat_start_m + xw + 0.5 * C.length_m;
      const double t_leave = C.ramp_s + (travel - p.distance(C.ramp_s)) / C.speed_m_s;
      p.duration_s = t_leave + settle;
      // The road moves under the tyre: CVODE cannot see a cleat that enters and leaves a unit
      // between two steps (a settled run stepped 26 ms and jumped onto it: 114 kN). While the
      // cleat is in the window the step is bounded by half the passage time of one of its
      // cosine edges.
      p.step_limit_from_s = t_arrive;
      p.step_limit_until_s = t_leave;
      p.step_limit_s = 0.5 * (0.25 * C.length_m) / C.speed_m_s;
      p.breakpoints = {t_arrive, t_leave};
      if (C.ramp_s > 0) p.breakpoints.push_back(C.ramp_s);
      const double F = C.load_N;
      p.load = [F](double) { return F; };
      if (C.height_m >= model.tyre.sag.maxCoeff()) {
        throw InputError(InputLocation{src, 0, "transient.cleat.height_mm"},
                         "cleat higher than the tyre's sag at the edge of the candidate window; "
                         "increase contact.window_mm");
      }
      break;
    }
  }
  if (!(p.duration_s > 0)) {
    throw InputError(InputLocation{src, 0, "transient"},
                     std::string("scenario ") + to_string(s) + " has zero duration");
  }
  // A stated output step (0: chosen per run, output_grid.h): every output step is a sample held
  // in memory and a CSV row, bounded, so that a tiny step or a long run is refused at once
  // instead of filling the memory.
  const double dt = model.settings.output_step_s;
  if (dt > 0 && dt > p.duration_s) {
    throw InputError(InputLocation{src, 0, "transient.output_step_ms"},
                     "output step longer than the scenario");
  }
  const double samples = dt > 0 ? p.duration_s / dt : 0.0;
  if (!(samples <= kMaxTransientSamples)) {
    std::ostringstream msg;
    msg << "output step " << dt * 1e3 << " ms over the scenario's " << p.duration_s << " s gives "
        << samples << " samples; at most " << kMaxTransientSamples
        << " are written: use an output step of at least "
        << p.duration_s / kMaxTransientSamples * 1e3 << " ms or a shorter scenario";
    throw InputError(InputLocation{src, 0, "transient.output_step_ms"}, msg.str());
  }
  return p;
}

}  // namespace modaltyre::transient
