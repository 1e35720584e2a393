// The tyre driven by its hub (driven_tyre.h, docs/transient.md section 8).
#include "modaltyre/transient/driven_tyre.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/bracketed_root.h"
#include "modaltyre/transient/cell_soil.h"
#include "modaltyre/transient/cell_system.h"
#include "modaltyre/transient/soil_contact.h"
#include "patch_ode.h"

namespace modaltyre::transient {
namespace {

/// Accuracy of the static equilibrium at a deflection: |sinking - deflection| below this [m]
/// (1e-6 of a 10 mm sinking; the transient's own displacement tolerance is 1e-7 m).
constexpr double kDeflectionTolerance_m = 1e-8;
/// Load of the first trial of the bracket search [N], doubled until the sinking exceeds the
/// deflection; at most kMaxBracketDoublings doublings (1000 N x 2^20: beyond any tyre's window).
constexpr double kFirstTrialLoad_N = 1000;
constexpr int kMaxBracketDoublings = 20;
/// Iterations of the Illinois search for the load (each a static footprint).
constexpr int kMaxLoadIterations = 60;
/// Internal steps of one advance() before it is stopped (a bound, never reached in practice:
/// CVODE fails first when its step collapses).
constexpr long kMaxStepsPerAdvance = 1000000;

/// The static state whose sinking is `deflection_m`: load control's footprint searched in the
/// load (the sinking grows monotonically with it). `solve(load)` returns (state, sinking).
template <class State>
State static_at_deflection(double deflection_m,
                           const std::function<std::pair<State, double>(double)>& solve) {
  if (!(deflection_m > 0)) return solve(0.0).first;
  double lo = 0, f_lo = -deflection_m, hi = kFirstTrialLoad_N;
  std::optional<std::pair<State, double>> at_hi;
  for (int k = 0; k <= kMaxBracketDoublings; ++k, hi *= 2) {
    at_hi = solve(hi);
    if (at_hi->second >= deflection_m) break;
    lo = hi, f_lo = at_hi->second - deflection_m;
    at_hi.reset();
  }
  if (!at_hi) {
    std::ostringstream msg;
    msg << "no static footprint reaches the deflection " << deflection_m * 1e3 << " mm";
    throw ComputationError(msg.str());
  }
  const double f_hi = at_hi->second - deflection_m;
  if (f_hi == 0) return at_hi->first;
  std::optional<State> best;
  const solvers::RootResult root = solvers::illinois_root(
      [&](double load) -> std::optional<double> {
        auto [state, sinking] = solve(load);
        best = std::move(state);
        return sinking - deflection_m;
      },
      lo, f_lo, hi, f_hi, {kDeflectionTolerance_m, kMaxLoadIterations});
  if (!root.ok() || !best) {
    std::ostringstream msg;
    msg << "static footprint at the deflection " << deflection_m * 1e3
        << " mm: the load search did not converge (sinking residual " << root.fx << " m)";
    throw ComputationError(msg.str());
  }
  return *best;
}

bool same_hub(const HubState& a, const HubState& b) {
  auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
  return same(a.deflection_m, b.deflection_m) && same(a.speed_m_s, b.speed_m_s) &&
         same(a.spin_rad_s, b.spin_rad_s);
}

bool finite_hub(const HubState& s) {
  return std::isfinite(s.deflection_m) && std::isfinite(s.speed_m_s) &&
         !std::isinf(s.spin_rad_s);  // NaN spin: free rolling
}

/// The static states at a deflection of the 2D units and of the 3D cells.
StaticContact units_at_deflection(const TransientModel& M, double d) {
  return static_at_deflection<StaticContact>(d, [&](double load) {
    StaticContact c = static_contact(M, load);
    const double s = c.sinking_m;
    return std::make_pair(std::move(c), s);
  });
}
StaticCells cells_at_deflection(const CellModel& cm, double d) {
  return static_at_deflection<StaticCells>(d, [&](double load) {
    StaticCells c = static_cells(cm, load);
    const double s = c.sinking_m;
    return std::make_pair(std::move(c), s);
  });
}

}  // namespace

WheelLoad wheel_load(const TransientSample& s) {
  WheelLoad w;
  w.t_s = s.t_s;
  w.fz_N = s.load_N;
  w.fx_N = s.longitudinal_force_N;
  w.my_Nm = -s.pressure_centre_m * s.load_N;
  w.deflection_m = s.hub_displacement_m;
  w.sinking_m = s.sinking_m;
  w.contact_length_m = s.contact_length_m;
  w.width_m = s.width_m;
  w.contact_area_m2 = s.contact_area_m2;
  w.pressure_centre_m = s.pressure_centre_m;
  w.soil_sinkage_m = s.soil_sinkage_m;
  w.compaction_resistance_N = s.soil_resistance_N;
  return w;
}

/// Everything one driven tyre owns: the plan with its hub track, the cell model (3D), the ODE of
/// the patch and its integrator.
struct DrivenTyre::Impl {
  Impl(const TransientModel& model, const DrivenTyreOptions& options)
      : M(model),
        opt(options),
        track(std::make_shared<HubTrack>(model.tyre.config.outer_radius_m)) {
    if (!(opt.max_step_s >= 0) || !std::isfinite(opt.max_step_s))
      throw InputError(InputLocation{"DrivenTyreOptions", 0, "max_step_s"},
                       "the largest step must be finite and >= 0");
    if (!(opt.max_deflection_m >= 0) || !std::isfinite(opt.max_deflection_m))
      throw InputError(InputLocation{"DrivenTyreOptions", 0, "max_deflection_m"},
                       "the largest deflection must be finite and >= 0");
    three_d = model.tyre.config.footprint_3d.has_value() && !opt.force_2d;
    if (three_d) cm.emplace(build_cell_model(model));
    on_soil = model.tyre.config.ground.soil();
    if (on_soil) {
      refuse_on_soil(model, Scenario::load_hold, three_d);
      if (opt.road_profile)
        throw InputError(InputLocation{model.tyre.config.source, 0, "ground.model"},
                         "a road profile under a tyre on a soil is not modelled");
      // Bekker's b at the config's rolling load (soil_for_plan's rule for a scenario's load).
      const double load = model.settings.rolling.load_N;
      if (three_d)
        static_soil_cells(*cm, load, 0.0, &bekker_width_m);
      else
        static_soil_contact(model, load, 0.0, &bekker_width_m);
      if (!(bekker_width_m > 0)) bekker_width_m = model.tyre.config.tread.width_m;
    }
    plan.scenario = Scenario::load_hold;
    plan.duration_s = std::numeric_limits<double>::infinity();
    plan.load = [](double) { return 0.0; };
    plan.radius_m = model.tyre.config.outer_radius_m;
    plan.hub = track;
    plan.road_profile = opt.road_profile;
    plan.road_max_height_m = opt.road_max_height_m;
  }

  /// A static state at a deflection, of the patch in use (on the soil at Bekker's b).
  StaticContact units_at(double d) const {
    if (!on_soil) return units_at_deflection(M, d);
    return static_at_deflection<StaticContact>(d, [&](double load) {
      StaticContact c = static_soil_contact(M, load, bekker_width_m);
      const double s = c.sinking_m;
      return std::make_pair(std::move(c), s);
    });
  }
  StaticCells cells_at(double d) const {
    if (!on_soil) return cells_at_deflection(*cm, d);
    return static_at_deflection<StaticCells>(d, [&](double load) {
      StaticCells c = static_soil_cells(*cm, load, bekker_width_m);
      const double s = c.sinking_m;
      return std::make_pair(std::move(c), s);
    });
  }

  /// A virgin soil whose memory is the initial state's depths at t0.
  void new_soil(double t0) {
    if (!on_soil) return;
    const ground::GroundSettings& ground = M.tyre.config.ground;
    if (three_d) {
      soil3d = std::make_unique<CellSoil>(*cm, ground, bekker_width_m, opt.distance_m);
      soil3d->set_memory(initial_cells.soil_depth_m, t0);
    } else {
      soil2d = std::make_unique<SoilContact>(M, ground, M.tyre.config.tread.width_m, bekker_width_m,
                                             opt.distance_m);
      soil2d->set_memory(initial_units.soil_depth_m, t0);
    }
  }
  /// The soil's memory kept at the start of an advance, put back when it is redone.
  void save_soil() {
    saved_soil.clear();
    if (soil2d) saved_soil.push_back(*soil2d);
    if (soil3d)
      for (int c = 0; c < soil3d->classes(); ++c) saved_soil.push_back(soil3d->row(c));
  }
  void restore_soil() {
    if (soil2d) *soil2d = saved_soil.at(0);
    if (soil3d)
      for (int c = 0; c < soil3d->classes(); ++c) soil3d->row(c) = saved_soil.at(c);
  }

  /// A new ODE (tread states on the touchable range, or everywhere when `all`) and its
  /// integrator at (t, y); y empty: the ODE's own initial (static) state.
  void start(double t, std::vector<double> y, bool all) {
    if (three_d) {
      std::vector<UnitRange> ranges;
      if (!all && bound_cells) ranges = touchable_sections(*cm, plan, *bound_cells);
      ode = detail::make_cells_ode(*cm, plan, initial_cells, ranges, soil3d.get());
    } else {
      UnitRange units{0, M.m - 1};
      if (!all && bound_units) units = touchable_units(M, plan, *bound_units);
      ode = detail::make_units_ode(M, plan, initial_units, units, soil2d.get());
    }
    if (y.empty()) {
      y = ode->initial_state();
      if (ode->escaped() && !all) return start(t, {}, true);
    }
    all_units = all;
    prob = solvers::OdeProblem{};
    ode->configure(prob, TransientRunOptions{});
    cvode = std::make_unique<solvers::CvodeKlu>(prob, detail::ode_options(*ode, M), t, y,
                                                ode->nnz_hint());
    cvode->set_max_step(opt.max_step_s);
  }

  DriveStatus integrate(double t_next) {
    DriveStatus st;
    const double t0 = cvode->time();
    const std::vector<double> y0 = ode->full_state(cvode->state());
    if (on_soil && !all_units) save_soil();
    for (long k = 0; cvode->time() < t_next; ++k) {
      if (k >= kMaxStepsPerAdvance) {
        st.ok = false;
        st.message = "more than 1e6 internal steps in one advance";
        break;
      }
      const solvers::OdeStatus s = cvode->step(t_next);
      if (!s.ok()) {
        st.ok = false;
        std::ostringstream msg;
        msg << "integrator failed at t = " << s.t << " s: " << s.message;
        st.message = msg.str();
        break;
      }
      ode->update_contact_set(s.t, cvode->state().data());
      if (ode->escaped()) {
        // A unit beyond the touchable range reached the road: the step again with every unit,
        // from its start (the tread states of the others are zero: never touched).
        widened_ = true;
        if (on_soil) restore_soil();
        start(t0, y0, true);
        return integrate(t_next);
      }
    }
    st.t_s = cvode->time();
    return st;
  }

  const TransientModel& M;
  DrivenTyreOptions opt;
  bool three_d = false;
  std::optional<CellModel> cm;
  std::shared_ptr<HubTrack> track;
  ScenarioPlan plan;
  StaticContact initial_units;
  StaticCells initial_cells;
  std::optional<StaticContact> bound_units;
  std::optional<StaticCells> bound_cells;
  std::unique_ptr<detail::PatchOde> ode;
  solvers::OdeProblem prob;
  std::unique_ptr<solvers::CvodeKlu> cvode;
  HubState hub_now;
  bool all_units = false, widened_ = false;
  bool on_soil = false;
  double bekker_width_m = 0;
  double bound_deflection_m = -1;  ///< d_max of the bound kept (-1: none)
  std::unique_ptr<SoilContact> soil2d;
  std::unique_ptr<CellSoil> soil3d;
  std::vector<SoilContact> saved_soil;
};

DrivenTyre::DrivenTyre(const TransientModel& model, const DrivenTyreOptions& options)
    : impl_(std::make_unique<Impl>(model, options)) {
  reset(HubState{});
}

DrivenTyre::~DrivenTyre() = default;
DrivenTyre::DrivenTyre(DrivenTyre&&) noexcept = default;
DrivenTyre& DrivenTyre::operator=(DrivenTyre&&) noexcept = default;

void DrivenTyre::reset(const HubState& initial, double t0) {
  Impl& I = *impl_;
  if (!finite_hub(initial) || !std::isfinite(t0))
    throw InputError(InputLocation{"DrivenTyre::reset", 0, "initial"},
                     "the hub's initial state and time must be finite");
  I.hub_now = initial;
  I.track->set_step(t0, initial, t0, initial, HubInterpolation::hold);
  I.widened_ = false;
  const double d = initial.deflection_m, d_max = std::max(I.opt.max_deflection_m, d);
  // The bound depends on d_max only: kept from the last reset at the same d_max (a static
  // footprint search each; on a 3D soil seconds).
  const bool keep_bound = I.opt.max_deflection_m > 0 && d_max == I.bound_deflection_m;
  if (!keep_bound) {
    I.bound_units.reset();
    I.bound_cells.reset();
    I.bound_deflection_m = -1;
  }
  if (I.three_d)
    I.initial_cells = I.cells_at(d);
  else
    I.initial_units = I.units_at(d);
  if (I.opt.max_deflection_m > 0 && !keep_bound) {
    try {
      if (I.three_d)
        I.bound_cells = I.cells_at(d_max);
      else
        I.bound_units = I.units_at(d_max);
    } catch (const ComputationError&) {
      // On a soil the bounding footprint may leave the candidate window (a soft soil wraps a
      // long contact): every unit then, as the soil runs do (bounding_soil_contact).
      if (!I.on_soil) throw;
    }
  }
  if (I.opt.max_deflection_m > 0) I.bound_deflection_m = d_max;
  I.new_soil(t0);
  I.start(t0, {}, false);
}

DriveStatus DrivenTyre::advance(double t_next, const HubState& hub, HubInterpolation how) {
  Impl& I = *impl_;
  const double t = I.cvode->time();
  if (!(t_next > t) || !std::isfinite(t_next) || !finite_hub(hub)) {
    std::ostringstream msg;
    msg << "advance to t = " << t_next << " s from " << t
        << " s: the time must lie ahead and the hub's state be finite";
    return DriveStatus{false, t, msg.str()};
  }
  if (how == HubInterpolation::hold && !same_hub(hub, I.hub_now)) {
    // The hub jumps at t: the right-hand side does, and the BDF history before it no longer
    // belongs to the trajectory.
    I.track->set_step(t, hub, t_next, hub, how);
    I.cvode->reinit(t, I.cvode->state());
  } else {
    I.track->set_step(t, I.hub_now, t_next, hub, how);
  }
  const DriveStatus st = I.integrate(t_next);
  if (st.ok) I.hub_now = hub;
  return st;
}

void DrivenTyre::follow(std::function<HubState(double)> motion) {
  Impl& I = *impl_;
  I.track->set_function(std::move(motion));
  // The motion need not continue the previous one: a fresh BDF history from here.
  I.cvode->reinit(I.cvode->time(), I.cvode->state());
}

DriveStatus DrivenTyre::advance(double t_next) {
  Impl& I = *impl_;
  const double t = I.cvode->time();
  if (!(t_next > t) || !std::isfinite(t_next)) {
    std::ostringstream msg;
    msg << "advance to t = " << t_next << " s from " << t << " s: the time must lie ahead";
    return DriveStatus{false, t, msg.str()};
  }
  const DriveStatus st = I.integrate(t_next);
  if (st.ok) I.hub_now = I.track->at(st.t_s);
  return st;
}

double DrivenTyre::time() const { return impl_->cvode->time(); }
HubState DrivenTyre::hub() const { return impl_->track->at(time()); }
WheelLoad DrivenTyre::load() const {
  Impl& I = *impl_;
  return wheel_load(I.ode->observe(I.cvode->time(), I.cvode->state().data()));
}
void DrivenTyre::vertical_forces(Eigen::VectorXd& F) const {
  Impl& I = *impl_;
  I.ode->vertical_forces(I.cvode->time(), I.cvode->state().data(), F);
}
bool DrivenTyre::patch_3d() const { return impl_->three_d; }
solvers::OdeStats DrivenTyre::stats() const { return impl_->cvode->stats(); }
int DrivenTyre::states() const { return impl_->ode->size(); }
bool DrivenTyre::widened() const { return impl_->widened_; }

TransientResult run_prescribed(const TransientModel& M,
                               const std::function<HubState(double)>& motion, double duration_s,
                               const TransientRunOptions& options, bool force_2d) {
  const auto wall0 = std::chrono::steady_clock::now();
  if (!(duration_s > 0) || !std::isfinite(duration_s))
    throw InputError(InputLocation{"run_prescribed", 0, "duration_s"},
                     "the duration must be finite and positive");
  // The config's output step, or the automatic grid's largest (output_grid.h).
  const double dt = M.settings.output_step_s > 0 ? M.settings.output_step_s : kAutoOutputStepCap_s;
  if (duration_s / dt > 1e6)
    throw InputError(InputLocation{M.tyre.config.source, 0, "transient.output_step_ms"},
                     "more than 1e6 output samples over the prescribed motion");
  auto track = std::make_shared<HubTrack>(M.tyre.config.outer_radius_m);
  track->set_function(motion);
  ScenarioPlan plan;
  plan.scenario = Scenario::load_hold;
  plan.duration_s = duration_s;
  plan.load = [](double) { return 0.0; };
  plan.radius_m = M.tyre.config.outer_radius_m;
  plan.hub = track;
  // The touchable range: the static footprint at the largest deflection on the output grid
  // (the run is repeated with every unit should one beyond it touch).
  double d_max = 0;
  for (double t = 0; t <= duration_s + 0.5 * dt; t += dt)
    d_max = std::max(d_max, track->deflection(std::min(t, duration_s)));
  const double d0 = track->deflection(0.0);
  for (double t : options.map_times_s)
    if (!(t >= 0 && t <= duration_s))
      throw InputError(InputLocation{"--map-times", 0, ""}, "map time outside the motion");
  bool escaped = false;
  TransientResult res;
  const bool three_d = M.tyre.config.footprint_3d.has_value() && !force_2d;
  if (three_d) {
    const CellModel cm = build_cell_model(M, 0.0, !options.per_column_cells);
    auto at = [&](double d) { return cells_at_deflection(cm, d); };
    const StaticCells initial = at(d0);
    std::vector<UnitRange> ranges;
    if (!options.all_tread_states && d_max > 0) ranges = touchable_sections(cm, plan, at(d_max));
    res = detail::run_plan(*detail::make_cells_ode(cm, plan, initial, ranges), M, plan, options,
                           escaped);
    if (escaped) {
      escaped = false;
      res = detail::run_plan(*detail::make_cells_ode(cm, plan, initial, {}), M, plan, options,
                             escaped);
      res.units_escaped = true;
    }
  } else {
    auto at = [&](double d) { return units_at_deflection(M, d); };
    const StaticContact initial = at(d0);
    const UnitRange all{0, M.m - 1};
    UnitRange units = all;
    if (!options.all_tread_states && d_max > 0) units = touchable_units(M, plan, at(d_max));
    res = detail::run_plan(*detail::make_units_ode(M, plan, initial, units), M, plan, options,
                           escaped);
    if (escaped) {
      escaped = false;
      res = detail::run_plan(*detail::make_units_ode(M, plan, initial, all), M, plan, options,
                             escaped);
      res.units_escaped = true;
    }
  }
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace modaltyre::transient
