#include "modaltyre/transient/driver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/arrow_lu.h"
#include "modaltyre/transient/contact_newton.h"
#include "modaltyre/transient/ode_system.h"
#include "modaltyre/transient/tread_window.h"
#include "sample_reuse.h"

namespace modaltyre::transient {
namespace {

/// Root returns in a row within kZenoWindow_s of each other before the run is stopped as
/// chattering (never a hang): a located switch is normally followed by a step.
constexpr int kZenoRootReturns = 1000;
constexpr double kZenoWindow_s = 1e-12;

/// One output sample at (t, y). `f` is the caller's work vector for the forces (reused across
/// samples: no allocation and no clearing of all m units per sample); sag_min: min_i s_i.
TransientSample observe(const TransientModel& M, const TransientSystem& sys,
                        const ScenarioPlan& plan, double t, const double* y, Eigen::VectorXd& f,
                        double sag_min) {
  TransientSample s;
  s.t_s = t;
  // The forces k max(0, g) where units can touch (on the system's units only: tread_window.h);
  // the edge interpolation below needs g also at the first unit outside each end, computed there
  // from the contact coordinates of y that forces_into() left.
  sys.forces_into(t, y, f);
  const int u0 = sys.units().lo, u1 = sys.units().hi;
  const double z = y[M.z_index()];
  const double R0 = M.tyre.config.outer_radius_m;
  s.applied_load_N = plan.load(t);
  s.hub_displacement_m = z;
  s.speed_m_s = plan.speed(t);
  s.load_N = f.segment(u0, u1 - u0 + 1).sum();
  // Sinking max_i (z + h_i - s_i): the least sag on a flat road, over the cleat's units too.
  double sink = z - sag_min, moment = 0, slope_force = 0;
  if (plan.cleat) {
    Eigen::VectorXd h = Eigen::VectorXd::Zero(M.m);
    sys.add_road(t, 0, M.m - 1, h);
    sink = std::max(sink, (z + h.array() - M.tyre.sag.array()).maxCoeff());
  }
  int first = -1, last = -1, units = 0;
  const double* fp = f.data();
  const double* x = M.x_road.data();
  for (int i = u0; i <= u1; ++i) {
    if (fp[i] > 0) {
      first = first < 0 ? i : first;
      last = i;
      ++units;
      moment += fp[i] * x[i];
      if (plan.cleat) {  // on a flat road the slope force stays 0
        double slope = 0;
        sys.road(t, i, &slope);
        slope_force += fp[i] * slope;
      }
    }
  }
  s.contact_units = units;
  s.sinking_m = sink;
  s.pressure_centre_m = s.load_N > 0 ? moment / s.load_N : 0;
  s.longitudinal_force_N = -moment / (R0 - z) - slope_force;
  if (first >= 0) {
    // Deformed positions of the end units (as footprint.cc): dynamic modes from the state,
    // residual orders and tread quasi-statically from the current forces.
    const Eigen::Map<const Eigen::VectorXd> q(y, M.nq);
    auto deformed_x = [&](int i) {
      double ur = M.phi_r.row(i).dot(q), ut = M.phi_t.row(i).dot(q);
      const double th = M.tyre.theta[i];
      if (M.nr > 0) {
        for (int j = first; j <= last; ++j) {
          if (f(j) <= 0) continue;
          const modal::Transfer2x2 h = M.residual_kernels.at(i - j);
          const double fr = f(j) * std::cos(M.tyre.theta[j]), ft = f(j) * std::sin(M.tyre.theta[j]);
          ur += h.r_from_r * fr + h.r_from_t * ft;
          ut += h.t_from_r * fr + h.t_from_t * ft;
        }
      }
      ur += f(i) * std::cos(th) / M.tyre.k_radial_N_m;
      ut += f(i) * std::sin(th) / M.tyre.k_tangential_N_m;
      return (R0 - ur) * std::sin(th) + ut * std::cos(th);
    };
    // Patch edges as in footprint.cc: the level function phi = f C_ii inside and -gap outside,
    // interpolated linearly to its zero between the end unit and its outside neighbour.
    auto edge = [&](int inside, int outside) {
      const double x_in = deformed_x(inside);
      if (outside < 0 || outside >= M.m) return x_in;
      const double phi_in = f(inside) * M.tyre.vertical_compliance(inside, inside);
      const double phi_out = sys.tip_penetration_at(t, y, outside, /*xi_of_y=*/true);
      const double w = phi_in / (phi_in - phi_out);
      return x_in + w * (deformed_x(outside) - x_in);
    };
    s.contact_length_m = edge(last, last + 1) - edge(first, first - 1);
  }
  return s;
}

/// One run on the units `units` (tread_window.h); sets `escaped` (and stops) if a unit outside
/// them reached the road.
TransientResult run_on_units(const TransientModel& M, Scenario scenario,
                             const TransientRunOptions& options, const ScenarioPlan& plan,
                             const StaticContact& initial, UnitRange units, bool& escaped) {
  TransientSystem sys(M, plan, units);
  TransientResult res;
  res.scenario = scenario;
  res.units_lo = sys.units().lo;
  res.units_hi = sys.units().hi;
  res.states = sys.size();

  solvers::OdeProblem prob;
  prob.size = sys.size();
  prob.rhs = [&sys](double t, const double* y, double* yd) {
    sys.rhs(t, y, yd);
    return 0;
  };
  prob.jacobian = [&sys](double t, const double* y, const double*, solvers::CscMatrix& J) {
    sys.jacobian(t, y, J);
    return 0;
  };
  const bool restart_at_switches = options.restart_at_switches;
  const bool locate_switches = restart_at_switches || options.locate_switches;
  prob.roots = locate_switches ? M.m : 0;
  // Newton's matrix I - gamma J has the arrow structure of solvers::ArrowLu: the carcass, residual
  // and hub states (the first e_index()) are densely coupled through the units in contact; each
  // tread state couples to its two upwind neighbours and, in contact, to that dense block.
  using NewtonSolver = TransientRunOptions::NewtonSolver;
  const NewtonSolver newton = options.newton_solver;
  ContactNewton contact_newton(M, sys);
  solvers::ArrowLu arrow;
  solvers::CscMatrix jac;
  if (newton == NewtonSolver::schur) {
    prob.linear_setup = [&](double t, const double* y, double gamma, bool jacobian_ok) {
      // 1: CVODE retries with a smaller step.
      return contact_newton.setup(t, y, gamma, jacobian_ok) ? 0 : 1;
    };
    prob.linear_solve = [&contact_newton](double* x) {
      contact_newton.solve(x);
      return 0;
    };
  } else if (newton == NewtonSolver::arrow) {
    prob.linear_setup = [&](double t, const double* y, double gamma, bool jacobian_ok) {
      if (!jacobian_ok || jac.n == 0) sys.jacobian(t, y, jac);
      return arrow.factor(jac, gamma, M.e_index()) ? 0 : 1;
    };
    prob.linear_solve = [&arrow](double* x) {
      arrow.solve(x);
      return 0;
    };
  }
  prob.root_functions = [&sys](double t, const double* y, double* g) {
    sys.roots(t, y, g);
    return 0;
  };
  solvers::OdeOptions opt;
  // CVODE's error test and Newton's convergence test take an RMS over the states. The tread
  // states the range leaves out are those of units that never touch: zero for good, or
  // advected behind the patch, either way without influence on any force. Scaling the
  // tolerances by sqrt(all states / states) keeps the error test of the full state (the same
  // sum of squares over the same number of states), so that the range changes the cost of a
  // step and not the steps (docs/transient.md section 2).
  const std::vector<double> atol = sys.absolute_tolerances();
  const double norm_scale =
      std::sqrt(static_cast<double>(M.state_size()) / static_cast<double>(sys.size()));
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

  std::vector<double> y = sys.state_from(initial);
  solvers::CvodeKlu ode(prob, opt, 0.0, y, sys.nnz());
  ode.set_max_step(plan.step_limit(0.0));

  const double T = plan.duration_s, dt = M.settings.output_step_s;
  Eigen::VectorXd f_sample;  // observe()'s work vector
  const double sag_min = M.tyre.sag.minCoeff();
  res.samples.push_back(observe(M, sys, plan, 0.0, y.data(), f_sample, sag_min));
  detail::SampleReuse reuse(M.settings.relative_tolerance, atol, !plan.cleat);
  reuse.remember(y);
  std::vector<double> breaks = plan.breakpoints;
  std::sort(breaks.begin(), breaks.end());
  std::size_t next_break = 0;
  long out_index = 1;
  double t_out = std::min(dt, T);
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
  std::vector<double> y_step_start = y;
  auto emit_until = [&](double t_reached) {
    const bool step_settled = reuse.unchanged(y_step_start) && reuse.unchanged(ode.state());
    y_step_start = ode.state();
    while (!all_out && t_out <= t_reached * (1 + 1e-14)) {
      if (!step_settled) ode.interpolate(std::min(t_out, t_reached), y_out);
      if (step_settled || reuse.unchanged(y_out)) {
        // The state moved less than kReuseFraction of the integration tolerance since the
        // last computed sample (a settled hold, steady rolling on a flat road): the
        // observables are the same to that accuracy; only the time and the scenario's own
        // functions advance.
        TransientSample smp = res.samples.back();
        smp.t_s = t_out;
        smp.applied_load_N = plan.load(t_out);
        smp.speed_m_s = plan.speed(t_out);
        res.samples.push_back(smp);
      } else {
        res.samples.push_back(observe(M, sys, plan, t_out, y_out.data(), f_sample, sag_min));
        reuse.remember(y_out);
      }
      if (options.progress && !options.progress(t_out, T)) {
        res.message = "cancelled";
        return false;
      }
      if (t_out >= T) {
        all_out = true;
        break;
      }
      ++out_index;
      t_out = std::min(out_index * dt, T);
      if (T - t_out < 1e-9 * T) t_out = T;
    }
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
    if (!emit_until(st.t)) {
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
    // Without root functions: units that entered or left the road during the step.
    if (!locate_switches) res.contact_events += sys.update_contact_set(st.t, ode.state().data());
    if (next_break < breaks.size() && st.t >= breaks[next_break]) {
      ode.reinit(st.t, ode.state());
      ode.set_max_step(plan.step_limit(st.t));
      ++next_break;
    }
  }
  res.simulated_s = ode.time();
  res.stats = ode.stats();
  if (options.keep_final_state) {
    // In the layout of all units (TransientSystem(M, plan)): e = 0 for the units without a
    // tread state (they never touched).
    res.final_state.assign(M.state_size(), 0.0);
    const std::vector<double>& y_end = ode.state();
    std::copy(y_end.begin(), y_end.begin() + M.e_index(), res.final_state.begin());
    std::copy(y_end.begin() + M.e_index(), y_end.end(),
              res.final_state.begin() + M.e_index() + (M.settings.relaxation ? res.units_lo : 0));
  }
  res.status = failed ? TransientStatus::failed : TransientStatus::completed;
  if (!failed) {
    std::ostringstream msg;
    msg << "completed: " << res.stats.steps << " steps, " << res.contact_events
        << " contact switches";
    res.message = msg.str();
  }
  // Rolling resistance: mean of -F_x over the last 10 % of the run.
  const double t_from = 0.9 * res.simulated_s;
  double sum = 0;
  int cnt = 0;
  for (const auto& s : res.samples)
    if (s.t_s >= t_from) sum += -s.longitudinal_force_N, ++cnt;
  res.rolling_resistance_N = cnt ? sum / cnt : 0;
  return res;
}

}  // namespace

TransientResult run_transient(const TransientModel& M, Scenario scenario,
                              const TransientRunOptions& options) {
  const auto wall0 = std::chrono::steady_clock::now();
  const ScenarioPlan plan = plan_scenario(M, scenario);
  if (scenario == Scenario::cleat && M.settings.cleat.width_m > 0) {
    throw InputError(InputLocation{M.tyre.config.source, 0, "transient.cleat.width_mm"},
                     "the 2D patch's road is uniform across the tread: a cleat narrower than the "
                     "tread needs the 3D patch (a config with footprint_3d:)");
  }
  const StaticContact initial = static_contact(M, plan.initial_load_N);
  const UnitRange all{0, M.m - 1};
  UnitRange units = all;
  if (!options.all_tread_states) {
    const std::optional<StaticContact> bound = bounding_contact(M, plan, initial);
    if (bound) units = touchable_units(M, plan, *bound);
  }
  bool escaped = false;
  TransientResult res = run_on_units(M, scenario, options, plan, initial, units, escaped);
  if (escaped) {
    // A unit outside the range reached the road: the bound did not hold (section 2 of
    // docs/transient.md); the run is repeated with every unit.
    escaped = false;
    res = run_on_units(M, scenario, options, plan, initial, all, escaped);
    res.units_escaped = true;
  }
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace modaltyre::transient
