// The 3D transient's driver (cell_model.h, cell_system.h, docs/transient.md section 7): the 2D
// driver's one-step loop (driver.cc) on CellSystem with CellNewton, its output samples with the
// width and the contact area, and the pressure maps at chosen times.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/transient/cell_newton.h"
#include "modaltyre/transient/cell_system.h"
#include "modaltyre/transient/driver.h"
#include "sample_reuse.h"

namespace modaltyre::transient {
namespace {

/// Observables of one state: the 2D sample's (driver.h) plus width and area, and on request the
/// pressure map. Work vectors are the caller's (reused across samples).
class CellObserver {
 public:
  CellObserver(const CellSystem& sys) : sys_(sys), cm_(sys.cell_model()), M_(cm_.M()) {
    sag_min_ = M_.tyre.sag.minCoeff();
    // Columns ordered from the centre outwards on each side: the lateral edge search.
    const CellClasses& C = cm_.classes;
    for (int j = 0; j < C.columns; ++j) slot_class_.push_back(C.column_class[j]);
  }

  TransientSample observe(double t, const double* y, CellMap* map = nullptr) {
    const ScenarioPlan& plan = sys_.plan();
    const CellClasses& C = cm_.classes;
    TransientSample s;
    s.t_s = t;
    sys_.forces(t, y, f_, F_);
    sys_.penetration(t, y, g_, P_);  // P: the undeformed tread's penetration at the crown line
    const double z = y[M_.z_index()];
    const double R0 = M_.tyre.config.outer_radius_m;
    s.applied_load_N = plan.load(t);
    s.hub_displacement_m = z;
    s.speed_m_s = plan.speed(t);
    const UnitRange span = sys_.sections();
    double load = 0, moment = 0, slope_force = 0, sink = z - sag_min_;
    int sections = 0, first = -1, last = -1;
    for (int i = span.lo; i <= span.hi; ++i) {
      if (!(F_(i) > 0)) continue;
      load += F_(i);
      moment += F_(i) * M_.x_road(i);
      ++sections;
      first = first < 0 ? i : first;
      last = i;
    }
    for (int c = 0; c < C.size() && plan.cleat; ++c) {
      const UnitRange& r = sys_.ranges()[c];
      for (int k = 0; k < r.size(); ++k) {
        double slope = 0;
        const double h = sys_.road(t, r.lo + k, c, &slope);
        if (h > 0) sink = std::max(sink, z + h - M_.tyre.sag(r.lo + k) - C.drop_m[c]);
        slope_force += C.multiplicity[c] * f_(sys_.offset(c) + k) * slope;
      }
    }
    s.load_N = load;
    s.contact_units = sections;
    s.sinking_m = sink;
    s.pressure_centre_m = load > 0 ? moment / load : 0;
    s.longitudinal_force_N = -moment / (R0 - z) - slope_force;
    if (first < 0) return s;
    // Deformed belt positions of the sections in and around the patch (as the 2D driver: the
    // dynamic modes from the state, the residual orders quasi-statically from the forces).
    const int x0 = std::max(0, first - 3), x1 = std::min(M_.m - 1, last + 3);
    xb_.assign(M_.m, 0.0);
    ur_.assign(M_.m, 0.0);
    ut_.assign(M_.m, 0.0);
    const Eigen::Map<const Eigen::VectorXd> q(y, M_.nq);
    for (int i = x0; i <= x1; ++i) {
      double ur = M_.phi_r.row(i).dot(q), ut = M_.phi_t.row(i).dot(q);
      if (M_.nr > 0) {
        for (int j = first; j <= last; ++j) {
          if (!(F_(j) > 0)) continue;
          const modal::Transfer2x2 h = M_.residual_kernels.at(i - j);
          const double fr = F_(j) * std::cos(M_.tyre.theta[j]),
                       ft = F_(j) * std::sin(M_.tyre.theta[j]);
          ur += h.r_from_r * fr + h.r_from_t * ft;
          ut += h.t_from_r * fr + h.t_from_t * ft;
        }
      }
      ur_[i] = ur, ut_[i] = ut;
      const double th = M_.tyre.theta[i];
      xb_[i] = (R0 - ur) * std::sin(th) + ut * std::cos(th);
    }
    auto cell_x = [&](int i, double f) {
      const double th = M_.tyre.theta[i], c = std::cos(th), sn = std::sin(th);
      return (R0 - ur_[i] - f * c / cm_.k_radial_cell_N_m) * sn +
             (ut_[i] + f * sn / cm_.k_tangential_cell_N_m) * c;
    };
    // The level function of a cell: the undeformed tread's penetration P_i + h - drop_c (> 0
    // inside, the gap < 0 outside; at rest the 3D patch's d_i - z_j), linear to its zero.
    auto level = [&](int i, int c) { return P_(i) + sys_.road(t, i, c) - C.drop_m[c]; };
    auto force = [&](int i, int c) {
      const UnitRange& r = sys_.ranges()[c];
      return r.contains(i) ? f_(sys_.offset(c) + i - r.lo) : 0.0;
    };
    // Longitudinal extent per class (= per column of it).
    double length = 0, area = 0;
    for (int c = 0; c < C.size(); ++c) {
      const UnitRange& r = sys_.ranges()[c];
      int a = -1, b = -1;
      for (int k = 0; k < r.size(); ++k)
        if (f_(sys_.offset(c) + k) > 0) b = r.lo + k, a = a < 0 ? r.lo + k : a;
      if (a < 0) continue;
      // As the 2D driver and the 3D patch: the level function is the cell's tread compression
      // f / k_i inside (at rest d_i - z_c, patch3d.cc) and its tip penetration g < 0 outside
      // (at rest the gap d_i - z_c; behind a rolling patch the relaxed rubber's lift).
      auto edge = [&](int in, int out) {
        const double xin = cell_x(in, force(in, c));
        const UnitRange& r = sys_.ranges()[c];
        if (out < x0 || out > x1) return xin;
        const double pin = force(in, c) / cm_.k_relaxed(in);
        const double pout = r.contains(out) ? g_(sys_.offset(c) + out - r.lo) : level(out, c);
        if (!(pout < 0)) return xin;
        return xin + pin / (pin - pout) * (cell_x(out, 0.0) - xin);
      };
      const double extent = edge(b, b + 1) - edge(a, a - 1);
      length = std::max(length, extent);
      area += C.multiplicity[c] * C.dy_m * extent;
    }
    s.contact_length_m = length;
    s.contact_area_m2 = area;
    // Lateral extent per section: the outermost column in contact on each side, its zero of the
    // level function towards the next column out (the tread edge if it is the last).
    const double half = 0.5 * C.tread_width_m;
    double width = 0;
    for (int i = first; i <= last; ++i) {
      if (!(F_(i) > 0)) continue;
      int lo = 0, hi = C.columns - 1;
      while (lo < C.columns && !(force(i, C.column_class[lo]) > 0)) ++lo;
      while (hi >= 0 && !(force(i, C.column_class[hi]) > 0)) --hi;
      if (lo > hi) continue;
      auto side = [&](int in, int out) {
        const double ein = level(i, C.column_class[in]), eout = level(i, C.column_class[out]);
        if (!(ein > 0 && eout < 0)) return C.column_y_m[in];
        return C.column_y_m[in] + ein / (ein - eout) * (C.column_y_m[out] - C.column_y_m[in]);
      };
      const double right = hi == C.columns - 1 ? half : side(hi, hi + 1);
      const double left = lo == 0 ? -half : side(lo, lo - 1);
      width = std::max(width, right - left);
    }
    s.width_m = width;
    if (map) {
      map->t_s = t;
      const int m0 = std::max(0, first - 2), m1 = std::min(M_.m - 1, last + 2);
      for (int i = m0; i <= m1; ++i) {
        const double dx = M_.tyre.unit_length_m * std::cos(M_.tyre.theta[i]);
        for (int j = 0; j < C.columns; ++j) {
          map->x_mm.push_back(xb_[i] * 1e3);
          map->y_mm.push_back(C.column_y_m[j] * 1e3);
          map->pressure_kPa.push_back(force(i, C.column_class[j]) / (dx * C.dy_m) * 1e-3);
        }
      }
    }
    return s;
  }

 private:
  const CellSystem& sys_;
  const CellModel& cm_;
  const TransientModel& M_;
  double sag_min_ = 0;
  std::vector<int> slot_class_;
  Eigen::VectorXd f_, F_, g_, P_;
  std::vector<double> xb_, ur_, ut_;
};

/// The sections each class can touch in the scenario: where the bounding static footprint's
/// undeformed-tread penetration d_i - z_c exceeds -(margin + cleat height) (tread_window.h's
/// bound, per class).
std::vector<UnitRange> touchable_cells(const CellModel& cm, const ScenarioPlan& plan,
                                       const StaticCells& initial) {
  const TransientModel& M = cm.M();
  double F_max = std::max(plan.load(0.0), plan.load(plan.duration_s));
  for (double t : plan.breakpoints) F_max = std::max(F_max, plan.load(t));
  StaticCells bound = initial;
  if (F_max > plan.initial_load_N) {
    try {
      bound = static_cells(cm, 2 * F_max - plan.initial_load_N);
    } catch (const ComputationError&) {
      return {};  // every section for every class
    }
  }
  const double level = -(kTouchMarginFraction * bound.sinking_m +
                         (plan.cleat ? std::max(0.0, plan.cleat_height_m) : 0.0));
  std::vector<UnitRange> ranges;
  for (int c = 0; c < cm.classes.size(); ++c) {
    int lo = 0, hi = M.m - 1;
    auto p = [&](int i) { return bound.d(i) - cm.classes.drop_m[c]; };
    while (lo <= hi && !(p(lo) > level)) ++lo;
    while (hi >= lo && !(p(hi) > level)) --hi;
    ranges.push_back(hi >= lo ? UnitRange{lo, hi} : UnitRange{0, -1});
  }
  return ranges;
}

TransientResult run_cells(const CellModel& cm, Scenario scenario,
                          const TransientRunOptions& options, const ScenarioPlan& plan,
                          const StaticCells& initial, std::vector<UnitRange> ranges,
                          bool& escaped) {
  const TransientModel& M = cm.M();
  CellSystem sys(cm, plan, std::move(ranges));
  TransientResult res;
  res.scenario = scenario;
  res.patch_3d = true;
  res.units_lo = sys.sections().lo;
  res.units_hi = sys.sections().hi;
  res.states = sys.size();
  CellNewton newton(cm, sys);
  solvers::OdeProblem prob;
  prob.size = sys.size();
  prob.rhs = [&sys](double t, const double* y, double* yd) {
    sys.rhs(t, y, yd);
    return 0;
  };
  prob.linear_setup = [&newton](double t, const double* y, double gamma, bool jacobian_ok) {
    return newton.setup(t, y, gamma, jacobian_ok) ? 0 : 1;
  };
  prob.linear_solve = [&newton](double* x) {
    newton.solve(x);
    return 0;
  };
  prob.roots = 0;
  // The 2D driver's integrator settings (driver.cc), its tolerance scaled to the states of the
  // 2D model with a tread state per section (the RMS error test over comparable states).
  solvers::OdeOptions opt;
  const std::vector<double> atol = sys.absolute_tolerances();
  // As the 2D driver: the tolerances scaled by sqrt(states of every section / states), so that
  // the RMS error test is that of the full state (a tread state per class and section).
  const int full = M.e_index() + (M.settings.relaxation ? cm.classes.size() * M.m : 0);
  const double norm_scale = std::sqrt(static_cast<double>(full) / sys.size());
  opt.relative_tolerance = M.settings.relative_tolerance * norm_scale;
  opt.absolute_tolerance = atol;
  for (double& a : opt.absolute_tolerance) a *= norm_scale;
  opt.max_order = 2;
  opt.stability_limit_detection = false;
  opt.lsetup_frequency = 50;
  opt.delta_gamma_max = 0.6;
  opt.max_nonlinear_iterations = 6;
  std::vector<double> y = sys.state_from(initial);
  if (sys.escaped()) {
    escaped = true;
    return res;
  }
  solvers::CvodeKlu ode(prob, opt, 0.0, y, 1);
  ode.set_max_step(plan.step_limit(0.0));
  const double T = plan.duration_s, dt = M.settings.output_step_s;
  CellObserver obs(sys);
  std::vector<double> map_times = options.map_times_s;
  std::sort(map_times.begin(), map_times.end());
  std::size_t next_map = 0;
  auto take_maps = [&](double t_from, double t_to, const std::vector<double>* y_at) {
    std::vector<double> ym(sys.size());
    while (next_map < map_times.size() && map_times[next_map] <= t_to * (1 + 1e-14)) {
      const double tm = map_times[next_map++];
      if (tm < t_from) continue;
      if (y_at) {
        ym = *y_at;
      } else {
        ode.interpolate(std::min(tm, t_to), ym);
      }
      CellMap map;
      obs.observe(tm, ym.data(), &map);
      res.maps.push_back(std::move(map));
    }
  };
  take_maps(0.0, 0.0, &y);
  res.samples.push_back(obs.observe(0.0, y.data()));
  detail::SampleReuse reuse(M.settings.relative_tolerance, atol, !plan.cleat);
  reuse.remember(y);
  std::vector<double> breaks = plan.breakpoints;
  std::sort(breaks.begin(), breaks.end());
  std::size_t next_break = 0;
  long out_index = 1;
  double t_out = std::min(dt, T), t_prev = 0;
  bool failed = false, all_out = false;
  std::vector<double> y_out(sys.size()), y_step_start = y;
  while (!all_out) {
    while (next_break < breaks.size() && breaks[next_break] <= ode.time()) ++next_break;
    const double stop = next_break < breaks.size() ? breaks[next_break] : T;
    const solvers::OdeStatus st = ode.step(stop);
    if (!st.ok()) {
      std::ostringstream msg;
      msg << "integrator failed at t = " << st.t << " s: " << st.message;
      res.message = msg.str();
      failed = true;
      break;
    }
    res.contact_events += sys.update_contact_set(st.t, ode.state().data());
    if (sys.escaped()) {
      escaped = true;
      return res;
    }
    take_maps(t_prev, st.t, nullptr);
    t_prev = st.t;
    const bool step_settled = reuse.unchanged(y_step_start) && reuse.unchanged(ode.state());
    y_step_start = ode.state();
    while (!all_out && t_out <= st.t * (1 + 1e-14)) {
      if (!step_settled) ode.interpolate(std::min(t_out, st.t), y_out);
      if (step_settled || reuse.unchanged(y_out)) {
        TransientSample smp = res.samples.back();
        smp.t_s = t_out;
        smp.applied_load_N = plan.load(t_out);
        smp.speed_m_s = plan.speed(t_out);
        res.samples.push_back(smp);
      } else {
        res.samples.push_back(obs.observe(t_out, y_out.data()));
        reuse.remember(y_out);
      }
      if (options.progress && !options.progress(t_out, T)) {
        res.message = "cancelled";
        failed = true;
        all_out = true;
        break;
      }
      if (t_out >= T) {
        all_out = true;
        break;
      }
      ++out_index;
      t_out = std::min(out_index * dt, T);
      if (T - t_out < 1e-9 * T) t_out = T;
    }
    if (next_break < breaks.size() && st.t >= breaks[next_break]) {
      ode.reinit(st.t, ode.state());
      ode.set_max_step(plan.step_limit(st.t));
      ++next_break;
    }
  }
  res.simulated_s = ode.time();
  res.stats = ode.stats();
  if (options.keep_final_state) res.final_state = ode.state();
  res.status = failed ? TransientStatus::failed : TransientStatus::completed;
  if (!failed) {
    std::ostringstream msg;
    msg << "completed: " << res.stats.steps << " steps, " << res.contact_events
        << " cell contact switches";
    res.message = msg.str();
  }
  const double t_from = 0.9 * res.simulated_s;
  double sum = 0;
  int cnt = 0;
  for (const auto& s : res.samples)
    if (s.t_s >= t_from) sum += -s.longitudinal_force_N, ++cnt;
  res.rolling_resistance_N = cnt ? sum / cnt : 0;
  return res;
}

}  // namespace

TransientResult run_transient_3d(const TransientModel& M, Scenario scenario,
                                 const TransientRunOptions& options) {
  const auto wall0 = std::chrono::steady_clock::now();
  const ScenarioPlan plan = plan_scenario(M, scenario);
  const double cleat_width = scenario == Scenario::cleat ? M.settings.cleat.width_m : 0.0;
  const CellModel cm = build_cell_model(M, cleat_width, !options.per_column_cells);
  for (double t : options.map_times_s) {
    if (!(t >= 0 && t <= plan.duration_s)) {
      std::ostringstream msg;
      msg << "map time " << t << " s outside the scenario's 0 .. " << plan.duration_s << " s";
      throw InputError(InputLocation{"--map-times", 0, ""}, msg.str());
    }
  }
  const StaticCells initial = static_cells(cm, plan.initial_load_N);
  std::vector<UnitRange> ranges;
  if (!options.all_tread_states) ranges = touchable_cells(cm, plan, initial);
  bool escaped = false;
  TransientResult res = run_cells(cm, scenario, options, plan, initial, ranges, escaped);
  if (escaped) {
    escaped = false;
    res = run_cells(cm, scenario, options, plan, initial, {}, escaped);
    res.units_escaped = true;
  }
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace modaltyre::transient
