// The model's steady slip curve on a prescribed wheel (model_slip.h).
#include "modaltyre/tir/model_slip.h"

#include <cmath>
#include <string>

#include "modaltyre/core/errors.h"
#include "modaltyre/fmu/tyre_wheel.h"

namespace modaltyre::tir {
namespace {

/// Secant holds for the free-rolling spin beyond the first two (the settled start and one at
/// +kSecantSlip): M_y is linear in the spin near free rolling (the brush's stick region), so
/// one or two more land on it.
constexpr int kMaxSecantHolds = 4;
/// The second spin of the secant, relative to the first: a slip of 0.2 % stays linear.
constexpr double kSecantSlip = 0.002;
/// Converged when the hub moment is below this share of r F_z (a free-rolling F_x off by 1e-4
/// F_z) or the next spin is within kSpinTolerance of this one: a slip of 1e-4, which moves F_x
/// by at most 0.2 % of F_z for C_kappa / F_z <= 20. The held moment rattles by up to ~1 % of
/// its braking value at slip (the tread's units passing; sf350_fig5.yaml: 5 N m at kappa 1e-4),
/// so a tighter spin bound would chase that noise.
constexpr double kMomentTolerance = 1e-4;
/// A hold is steady when two successive windows' mean F_x differ by at most this share of F_z.
constexpr double kSteadyFx = 1e-3;
constexpr double kSpinTolerance = 1e-4;

double smoothstep(double s) {
  s = std::clamp(s, 0.0, 1.0);
  return s * s * (3 - 2 * s);
}

void need(bool ok, const char* option, const std::string& what) {
  if (!ok) throw InputError({option, 0, ""}, what);
}

/// The wheel and its time: steps of step_s at constant speed and spin, averaging the end.
class Run {
 public:
  Run(std::shared_ptr<const transient::TransientModel> model, double deflection_m,
      const SlipSettings& s)
      : s_(s), wheel_(model, fmu::WheelSettings{s.step_s, nullptr}) {
    radius_m_ = model->tyre.config.outer_radius_m;
    in_.plane.z_m = radius_m_ - deflection_m;
    in_.mu = s.mu;
    wheel_.start(0, in_);
  }

  /// From rest to V over ramp_s, the spin at V / base_radius throughout.
  void ramp(double base_radius_m) {
    const int n = steps(s_.ramp_s);
    for (int k = 0; k < n; ++k) {
      const double v = s_.speed_m_s * smoothstep((k + 0.5) / n);
      step(v, v / base_radius_m);
    }
  }

  /// Holds the spin at V for `duration_s`, then in windows of average_m for at least hold_m
  /// until two successive windows' mean F_x agree within kSteadyFx of F_z (at most
  /// max_hold_m): the last window's means. The relaxation length C_kappa C_x of the tread and
  /// the carcass sets how long a hold must be, from decimetres (the default) to metres (a
  /// stiff tread on a soft carcass, sf350_fig5.yaml).
  SlipPoint hold(double spin_rad_s, double duration_s = 0) {
    const double v = s_.speed_m_s;
    for (int k = steps(duration_s); k > 0; --k) step(v, spin_rad_s);
    const int window = std::max(1, steps(s_.average_m / v));
    const int least = steps(s_.hold_m / v), most = steps(s_.max_hold_m / v);
    SlipPoint p, previous;
    double hub_moment = 0;
    for (int done = 0, windows = 0;; ++windows) {
      previous = p;
      p = SlipPoint{};
      hub_moment = 0;
      for (int k = 0; k < window; ++k, ++done) {
        step(v, spin_rad_s);
        const fmu::WheelOutput& o = wheel_.output();
        p.fx_N += o.load.fx_N / window;
        p.fz_N += o.load.fz_N / window;
        hub_moment += o.load.my_Nm / window;
      }
      const bool steady = windows > 0 && std::abs(p.fx_N - previous.fx_N) <= kSteadyFx * p.fz_N;
      if ((done >= least && steady) || done >= most) break;
    }
    p.loaded_radius_m = in_.plane.z_m;  // the road is flat at 0: the hub's height
    // The FMU's hub moment is M_r - r F_x (tyre_wheel.cc): the contact's own moment back.
    p.rolling_moment_Nm = hub_moment + p.loaded_radius_m * p.fx_N;
    last_hub_moment_ = hub_moment;
    return p;
  }
  double last_hub_moment() const { return last_hub_moment_; }

 private:
  int steps(double duration_s) const {
    return std::max(1, static_cast<int>(std::lround(duration_s / s_.step_s)));
  }
  void step(double v, double spin) {
    in_.plane.speed_m_s = v;
    in_.plane.spin_rad_s = spin;
    wheel_.step(t_, s_.step_s, in_);
    t_ += s_.step_s;
    in_.plane.x_m += v * s_.step_s;
  }

  const SlipSettings& s_;
  fmu::TyreWheel wheel_;
  fmu::WheelInput in_;
  double radius_m_ = 0, t_ = 0, last_hub_moment_ = 0;
};

}  // namespace

int slip_run_holds(const SlipSettings& s) {
  return 2 + kMaxSecantHolds + 1 + static_cast<int>(s.slips.size());
}

long slip_run_steps(const SlipSettings& s) {
  need(s.speed_m_s >= 1 && s.speed_m_s <= 100, "--speed-kmh",
       "the speed must be in [3.6, 360] km/h");
  need(s.mu > 0 && s.mu <= 10, "--mu", "the friction coefficient must be in (0, 10]");
  need(s.step_s >= 1e-5 && s.step_s <= 1e-2, "step_s", "the step must be in [1e-5, 1e-2] s");
  need(s.ramp_s >= 0 && s.ramp_s <= 10 && s.settle_s >= 0 && s.settle_s <= 10, "ramp_s",
       "the ramp and the settling must be in [0, 10] s");
  need(s.hold_m > 0 && s.max_hold_m >= s.hold_m && s.max_hold_m <= 100 && s.average_m > 0 &&
           s.average_m <= s.hold_m,
       "hold_m", "the holds must be 0 < average <= hold <= max_hold <= 100 m");
  need(s.slips.size() <= static_cast<std::size_t>(kMaxSlips), "--slips",
       "give at most " + std::to_string(kMaxSlips) + " slips");
  for (double k : s.slips)
    need(std::isfinite(k) && k > -0.9 && k < 1.5, "--slips", "every slip must be in (-0.9, 1.5)");
  const double t =
      s.ramp_s + s.settle_s + slip_run_holds(s) * (s.max_hold_m + s.average_m) / s.speed_m_s;
  const double n = t / s.step_s;
  need(n <= static_cast<double>(kMaxSlipSteps), "--slips",
       "the run would take " + std::to_string(static_cast<long>(n)) + " steps (at most " +
           std::to_string(kMaxSlipSteps) + ")");
  return static_cast<long>(n);
}

SlipCurve model_slip_curve(std::shared_ptr<const transient::TransientModel> model,
                           double deflection_m, double target_load_N, const SlipSettings& s,
                           const std::function<void()>& tick) {
  slip_run_steps(s);
  const auto& config = model->tyre.config;
  // The tread base's radius: the tangential contact carries the base at Omega R_b
  // (fmu/longitudinal_contact.h), so V / R_b is free rolling up to the rolling resistance's slip.
  const double base_radius_m = config.outer_radius_m - config.tread.thickness_m;
  const auto done = [&] {
    if (tick) tick();
  };
  Run run(std::move(model), deflection_m, s);
  run.ramp(base_radius_m);
  double spin0 = s.speed_m_s / base_radius_m;
  run.hold(spin0, s.settle_s);
  double moment0 = run.last_hub_moment();
  done();
  // Secant on the hub moment M_y(Omega) for M_y = 0 (no drive or brake torque).
  double spin1 = spin0 * (1 + kSecantSlip);
  bool converged = false;
  for (int k = 0; k < 1 + kMaxSecantHolds && !converged; ++k) {
    const SlipPoint p = run.hold(spin1);
    const double moment1 = run.last_hub_moment();
    done();
    if (moment1 == moment0) break;
    const double next = spin1 - moment1 * (spin1 - spin0) / (moment1 - moment0);
    converged = std::abs(moment1) <= kMomentTolerance * p.loaded_radius_m * p.fz_N ||
                std::abs(next - spin1) <= kSpinTolerance * std::abs(spin1);
    spin0 = spin1, moment0 = moment1, spin1 = next;
  }
  if (!converged || !(spin1 > 0)) {
    throw ComputationError("no free-rolling spin found at " + std::to_string(target_load_N) +
                           " N (the hub moment's secant did not settle; last moment " +
                           std::to_string(moment0) + " N m)");
  }
  SlipCurve c;
  c.target_load_N = target_load_N;
  c.deflection_m = deflection_m;
  c.speed_m_s = s.speed_m_s;
  c.free_spin_rad_s = spin1;
  c.effective_radius_m = s.speed_m_s / spin1;
  c.free = run.hold(spin1);
  done();
  for (double kappa : s.slips) {
    SlipPoint p = run.hold(spin1 * (1 + kappa));
    p.kappa = kappa;
    c.points.push_back(p);
    done();
  }
  return c;
}

}  // namespace modaltyre::tir
