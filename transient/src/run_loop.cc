// The scenario runner of both patches (patch_ode.h): one internal CVODE step at a time, output
// samples interpolated inside each step, restarts at the plan's breakpoints, contact switches
// counted between accepted steps (or located by root functions on the 2D patch).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "modaltyre/transient/output_grid.h"
#include "patch_ode.h"
#include "sample_reuse.h"
#include "step_extremes.h"

namespace modaltyre::transient::detail {
namespace {

/// Root returns in a row within kZenoWindow_s of each other before the run is stopped as
/// chattering (never a hang): a located switch is normally followed by a step.
constexpr int kZenoRootReturns = 1000;
constexpr double kZenoWindow_s = 1e-12;
/// Steps with at least this many output samples bound their interpolant's rate (emit_until):
/// the bound costs two interpolations and a pass over the states.
constexpr int kBoundedStepSamples = 4;
/// Fraction of the proven time a sample is repeated over (rounding of the interpolant).
constexpr double kSlackSafety = 0.5;
/// The rolling resistance is the mean of -F_x over the samples from this share of the run.
constexpr double kResistanceFrom = 0.9;

}  // namespace

solvers::OdeOptions ode_options(const PatchOde& ode, const TransientModel& M) {
  solvers::OdeOptions opt;
  // CVODE's error test and Newton's convergence test take an RMS over the states. The tread
  // states the range leaves out are those of units that never touch: zero for good, or
  // advected behind the patch, either way without influence on any force. Scaling the
  // tolerances by sqrt(all states / states) keeps the error test of the full state (the same
  // sum of squares over the same number of states), so that the range changes the cost of a
  // step and not the steps (docs/transient.md section 2).
  const std::vector<double> atol = ode.absolute_tolerances();
  const double norm_scale =
      std::sqrt(static_cast<double>(ode.full_size()) / static_cast<double>(ode.size()));
  opt.relative_tolerance = M.settings.relative_tolerance * norm_scale;
  opt.absolute_tolerance = atol;
  for (double& a : opt.absolute_tolerance) a *= norm_scale;
  // BDF2 at most: orders 3-5 are not A-stable, and the lightly damped carcass modes (eigenvalues
  // near the imaginary axis, up to omega_K) made CVODE's stability-limit detection hold the order
  // at 2-3 anyway, with many more steps (measured: 5500 steps/s of free vibration at order <= 5
  // with detection, 1700 at order <= 2; docs/transient.md section 6).
  opt.max_order = 2;
  opt.stability_limit_detection = false;
  opt.lsetup_frequency = 50;
  opt.delta_gamma_max = 0.6;
  // Contact switches perturb Newton's matrix by a few springs: allow more (cheap) iterations
  // before a convergence failure forces a new Jacobian and factorisation (measured: 6 halves
  // the factorisations of a 0.5 mm load ramp against CVODE's 3).
  opt.max_nonlinear_iterations = 6;
  opt.nonlinear_convergence_coefficient = ode.newton_convergence_coefficient();
  return opt;
}

TransientResult run_plan(PatchOde& sys, const TransientModel& M, const ScenarioPlan& plan,
                         const TransientRunOptions& options, bool& escaped) {
  TransientResult res;
  res.scenario = plan.scenario;
  sys.describe(res);
  solvers::OdeProblem prob;
  sys.configure(prob, options);
  const bool restart_at_switches = options.restart_at_switches;
  const bool locate_switches = prob.roots > 0;
  const solvers::OdeOptions opt = ode_options(sys, M);
  std::vector<double> y = sys.initial_state();
  if (sys.escaped()) {
    escaped = true;
    return res;
  }
  solvers::CvodeKlu ode(prob, opt, 0.0, y, sys.nnz_hint());
  ode.set_max_step(plan.step_limit(0.0));

  const double T = plan.duration_s;
  std::vector<double> map_times = options.map_times_s;
  std::sort(map_times.begin(), map_times.end());
  std::size_t next_map = 0;
  // The pressure maps (3D) at their times within [t_from, t_to], from y_at or interpolated.
  // (Called at every step: the state's work vector only when a map is due, not allocated and
  // cleared at each step for none.)
  std::vector<double> ym;
  auto take_maps = [&](double t_from, double t_to, const std::vector<double>* y_at) {
    while (next_map < map_times.size() && map_times[next_map] <= t_to * (1 + 1e-14)) {
      const double tm = map_times[next_map++];
      if (tm < t_from) continue;
      if (y_at) {
        ym = *y_at;
      } else {
        ode.interpolate(std::min(tm, t_to), ym);
      }
      CellMap map;
      sys.observe(tm, ym.data(), &map);
      res.maps.push_back(std::move(map));
    }
  };
  take_maps(0.0, 0.0, &y);
  res.samples.push_back(sys.observe(0.0, y.data()));
  const OutputGrid grid =
      output_grid(M, plan, res.samples.front().load_N, res.samples.front().sinking_m);
  res.output_grid = grid;
  // The extremes over the integrator's steps, and the free vibration's hub trace (dense output).
  const bool bounce = plan.scenario == Scenario::free_vibration && plan.hub_free();
  StepExtremes extremes([&sys](double t, const double* ys) { return sys.step_forces(t, ys); },
                        [&sys](double t, const double* ys) { return sys.observe_forces(t, ys); },
                        bounce ? M.z_index() : -1);
  extremes.start(0.0, y);
  const std::vector<double> atol = sys.absolute_tolerances();
  SampleReuse reuse(M.settings.relative_tolerance, atol, !plan.has_road());
  reuse.remember(y);
  // Samples with the forces only (TransientRunOptions::summary_samples): the final one is made
  // whole after the loop from the last computed sample's state and time (t_remembered), which is
  // what a whole run's final sample repeats or is.
  const bool forces_only = options.summary_samples && !M.tyre.config.ground.soil();
  double t_remembered = 0.0;
  bool remembered_forces = true;  // whether the last computed sample carries its forces
  // A computed sample: whole; or with summary samples the forces in the rolling resistance's
  // window (its start a rounding margin early) and before it the hub alone (as observe(): the
  // plan's hub_z of the state's z), which the decay on the samples reads.
  const double forces_from = kResistanceFrom * T * (1 - 1e-9);
  auto sample_at = [&](double t, const std::vector<double>& ys) {
    if (!forces_only) return sys.observe(t, ys.data());
    if (t >= forces_from) return sys.observe_forces(t, ys.data());
    TransientSample s;
    s.t_s = t;
    s.applied_load_N = plan.load(t);
    s.speed_m_s = plan.speed(t);
    s.hub_displacement_m = plan.hub_z(t, ys[static_cast<std::size_t>(M.z_index())]);
    return s;
  };
  std::vector<double> breaks = plan.breakpoints;
  std::sort(breaks.begin(), breaks.end());
  std::size_t next_break = 0;
  double t_out = grid.next_after(0.0), t_prev = 0;
  bool failed = false, all_out = false;
  int roots_in_place = 0;
  double last_root_t = -1;
  std::vector<double> y_out(sys.size());
  // The output samples up to t_reached, interpolated inside the step just taken (CVodeGetDky):
  // one internal step at a time, so that neither the output step bounds the step size nor does
  // every output time cost an evaluation of the m root functions (advance() to each output
  // time did: 60000 of them in a 120 s hold at 2 ms, a quarter of its run time).
  // A step whose both ends repeat the last computed sample lies in a settled stretch (a long
  // hold): its samples repeat it without interpolating each (the BDF interpolant between two such
  // history points stays within ~1.25 times their distance; 60000 interpolations and reuse
  // checks of all states were most of a 120 s hold after the faster Newton solver).
  //
  // In a long step that is not settled (a hold's creep over seconds, 500 samples a second) the
  // samples are not each interpolated and checked either: the interpolant of a step is a
  // polynomial of degree <= 2 (BDF orders <= 2, ode_options()), so its values at the step's ends
  // and middle give it exactly and bound its rate, |y'| <= D over the step. A sample within
  // (bound - |y - last|) / D of a checked one (SampleReuse::slack_s) then provably repeats the
  // last computed sample, as unchecked; the first outside is interpolated and checked as before.
  // Whether the step's start (the last step's end) repeats the last computed sample: decided at
  // the end of the last emit_until(), after its samples, while the integrator still held that
  // state (the same test as on a copy of it kept for this step).
  bool start_unchanged = reuse.unchanged(y);
  std::vector<double> y_a, y_m;
  Eigen::ArrayXd rate;
  auto emit_until = [&](double t_start, double t_reached) {
    const bool step_settled = start_unchanged && reuse.unchanged(ode.state());
    const double h = t_reached - t_start;
    // (Not with root functions: a return at a located switch ends inside an internal step.)
    const bool bounded =
        !step_settled && !locate_switches && reuse.allowed() && h > 0 &&
        t_out + kBoundedStepSamples * grid.step_at(t_out) <= t_reached * (1 + 1e-14);
    double reuse_until = -1;  // samples up to this time repeat the last computed one
    if (bounded) {
      ode.interpolate(t_start, y_a);
      ode.interpolate(t_start + 0.5 * h, y_m);
      const std::vector<double>& y_b = ode.state();
      rate.resize(static_cast<Eigen::Index>(y_b.size()));
      for (std::size_t i = 0; i < y_b.size(); ++i) {
        // y(s) = b + c1 s + c2 s^2, s = (t - t_reached) / h in [-1, 0]: y'(s) is linear in s,
        // largest at an end: c1 = 3b - 4m + a at s = 0, c1 - 2 c2 = -(3a - 4m + b) at s = -1.
        const double a = y_a[i], m = y_m[i], b = y_b[i];
        rate(static_cast<Eigen::Index>(i)) =
            std::max(std::abs(3 * b - 4 * m + a), std::abs(3 * a - 4 * m + b)) / h;
      }
    }
    while (!all_out && t_out <= t_reached * (1 + 1e-14)) {
      const bool proven = bounded && t_out <= reuse_until;
      if (!step_settled && !proven) ode.interpolate(std::min(t_out, t_reached), y_out);
      if (step_settled || proven || reuse.unchanged(y_out)) {
        if (bounded && !proven) reuse_until = t_out + kSlackSafety * reuse.slack_s(y_out, rate);
        // The state moved less than kReuseFraction of the integration tolerance since the
        // last computed sample (a settled hold, steady rolling on a flat road): the
        // observables are the same to that accuracy; only the time and the scenario's own
        // functions advance.
        TransientSample smp = res.samples.back();
        // (Summary samples: a repeat inside the resistance's window of a sample computed
        // before it takes the forces that sample's state has.)
        if (forces_only && !remembered_forces && t_out >= forces_from) {
          smp = sys.observe_forces(t_remembered, reuse.last_state());
          remembered_forces = true;
        }
        smp.t_s = t_out;
        smp.applied_load_N = plan.load(t_out);
        smp.speed_m_s = plan.speed(t_out);
        res.samples.push_back(smp);
      } else {
        res.samples.push_back(sample_at(t_out, y_out));
        remembered_forces = !forces_only || t_out >= forces_from;
        reuse.remember(y_out);
        t_remembered = t_out;
        if (bounded) reuse_until = t_out + kSlackSafety * reuse.slack_s(y_out, rate);
      }
      if (options.progress && !options.progress(t_out, T)) {
        res.message = "cancelled";
        return false;
      }
      if (t_out >= T) {
        all_out = true;
        break;
      }
      t_out = grid.next_after(t_out);
    }
    start_unchanged = reuse.unchanged(ode.state());
    return true;
  };
  while (!all_out) {
    while (next_break < breaks.size() && breaks[next_break] <= ode.time()) ++next_break;
    // Steps run up to the next breakpoint (a kink of F(t) or V(t)) or the end.
    const double stop = next_break < breaks.size() ? breaks[next_break] : T;
    const solvers::OdeStatus st = ode.step(stop);
    if (sys.escaped()) {
      escaped = true;
      return res;
    }
    if (!st.ok()) {
      std::ostringstream msg;
      msg << "integrator failed at t = " << st.t << " s: " << st.message;
      res.message = msg.str();
      failed = true;
      break;
    }
    if (st.outcome != solvers::OdeOutcome::root) {
      // Without root functions: units that entered or left the road during the step (and, on
      // the 3D patch, the check of the sections beyond each class's range).
      if (!locate_switches) res.contact_events += sys.update_contact_set(st.t, ode.state().data());
      if (sys.escaped()) {
        escaped = true;
        return res;
      }
    }
    take_maps(t_prev, st.t, nullptr);
    extremes.step(st.t, ode.state());
    const double t_step_start = t_prev;
    t_prev = st.t;
    if (!emit_until(t_step_start, st.t)) {
      failed = true;
      break;
    }
    if (st.outcome == solvers::OdeOutcome::root) {
      // Chattering guard: root returns that no longer advance the time would loop for ever.
      roots_in_place = std::abs(st.t - last_root_t) <= kZenoWindow_s ? roots_in_place + 1 : 0;
      last_root_t = st.t;
      if (roots_in_place >= kZenoRootReturns) {
        std::ostringstream msg;
        msg << "contact switches chatter at t = " << st.t << " s (" << kZenoRootReturns
            << " root returns without the time advancing): a tread tip hovers at the road";
        res.message = msg.str();
        failed = true;
        break;
      }
      sys.contact_switched();
      // A unit's tip touched or left the road: f_i = k max(0, g_i) has a kink there, the
      // right-hand side stays continuous. The located root is counted and the integration
      // continues; BDF's error test shortens the step over the kink (a restart would also throw
      // away the history for a kink of one unit among many). Optionally restart as before.
      ++res.contact_events;
      if (restart_at_switches) ode.reinit(st.t, ode.state());
      continue;
    }
    if (next_break < breaks.size() && st.t >= breaks[next_break]) {
      ode.reinit(st.t, ode.state());
      ode.set_max_step(plan.step_limit(st.t));
      ++next_break;
    }
  }
  if (forces_only && res.samples.size() > 1) {
    TransientSample& fin = res.samples.back();
    TransientSample whole = sys.observe(t_remembered, reuse.last_state());
    whole.t_s = fin.t_s;
    whole.applied_load_N = fin.applied_load_N;
    whole.speed_m_s = fin.speed_m_s;
    fin = whole;
  }
  res.simulated_s = ode.time();
  res.stats = ode.stats();
  extremes.finish(res);
  if (options.keep_final_state) res.final_state = sys.full_state(ode.state());
  res.status = failed ? TransientStatus::failed : TransientStatus::completed;
  if (!failed) {
    std::ostringstream msg;
    msg << "completed: " << res.stats.steps << " steps, " << res.contact_events
        << (res.patch_3d ? " cell contact switches" : " contact switches");
    res.message = msg.str();
  }
  // Rolling resistance: mean of -F_x over the last 10 % of the run.
  const double t_from = kResistanceFrom * res.simulated_s;
  double sum = 0;
  int cnt = 0;
  for (const auto& s : res.samples)
    if (s.t_s >= t_from) sum += -s.longitudinal_force_N, ++cnt;
  res.rolling_resistance_N = cnt ? sum / cnt : 0;
  return res;
}

}  // namespace modaltyre::transient::detail
