#include "modaltyre/contact/traction.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "modaltyre/contact/ground_patch.h"
#include "modaltyre/contact/rolling_radius.h"
#include "modaltyre/contact/soil_rate_term.h"
#include "modaltyre/contact/validity.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/ground/rigid_wheel.h"
#include "traction3d.h"
#include "traction_anderson.h"
#include "traction_cycle.h"
#include "traction_kinematics.h"
#include "wong_reece_flexible.h"

namespace modaltyre::contact {
namespace {

constexpr int kAndersonDepth = 4;  ///< the rolling fixed points' mixing depth

// What one slip's fixed point hands to the next (warm start) and what it iterates on.
struct RollingState {
  std::vector<double> depth_m;  ///< ground surface depth under each candidate unit
  std::vector<double> fx_N;     ///< horizontal force on each unit (on the tyre, +x forward)
  double shear_vertical_N = 0;  ///< vertical component of the shear forces
  double bekker_width_m = 0;
  std::vector<char> active;
  std::vector<double> force_N;    ///< vertical force per unit (the soil's linearisation point)
  std::vector<double> surface_m;  ///< a viscous soil's rolled surface per unit (soil_rate_term.h)
  detail::RearState rear;         ///< Wong and Reece's rear region (wong_reece_flexible.h)
};

using detail::case_result;

TractionResult rolling_pass(const TyreModel& model, const Eigen::MatrixXd& V,
                            const ground::GroundSettings& g, const TractionCase& c, int pass,
                            double prior, const TractionOptions& o, RollingState& st) {
  const int m = model.candidates();
  const double R0 = model.config.outer_radius_m, width = model.config.tread.width_m;
  const double ds = model.unit_length_m;
  // The tread's stick stiffness per unit area on a rigid road: G / h (seed 001 eq. 6-9).
  const TreadSprings unit = tread_springs(model.config.tread, 1.0, 1.0);
  const std::unique_ptr<ground::ShearLaw> shear = g.shear_law(unit.tangential_N_m);
  const double rho = speed_ratio_over_R0(c, R0);
  if (st.depth_m.size() != std::size_t(m)) st.depth_m.assign(m, 0.0);
  if (st.fx_N.size() != std::size_t(m)) st.fx_N.assign(m, 0.0);
  std::vector<double> z_max(m), offset(m), slope(m);
  const PatchOperator op = static_matrix_free_operator(model);
  double last_dp = 0;
  detail::AndersonMixer mixer(kAndersonDepth);
  detail::CycleGuard cycle;
  bool plain = false;  // Anderson's mixing left for plain steps (traction_cycle.h)
  // A viscous soil's rate term (soil_rate_term.h): its surface carried from step to step.
  const double rate_tau_s = soil_rate_time_s(g, o.speed_m_per_s);  // 0: no rate term
  SoilRate rate;
  const SoilRateBudget budget =
      rate_tau_s > 0
          ? soil_rate_budget(o.max_iterations, o.depth_tolerance, rate_tau_s, o.speed_m_per_s, ds)
          : SoilRateBudget{o.max_iterations, o.depth_tolerance};
  std::unique_ptr<ground::PressureSinkage> rate_law;
  double incoming = 0;
  if (rate_tau_s > 0) {
    rate_law = g.normal_law(width, rolling_radius_slip(c, R0));  // b, slip: a Bekker soil's
    incoming = rate_law->sinkage_m(0.0, prior);
    rate.weight.resize(m), rate.start_m.resize(m);
    if (st.surface_m.size() != std::size_t(m)) st.surface_m.assign(m, incoming);
  }
  detail::WongReeceRear wong_reece(g.wong_reece, rolling_radius_slip(c, R0), R0, m, 1,
                                   o.wong_reece_exit_reach);
  wong_reece.prepare(st.rear);
  std::vector<double> area(m), z_law;
  for (int i = 0; i < m; ++i) area[i] = width * ds * std::cos(model.theta[i]);
  for (int it = 1; it <= budget.max_iterations; ++it) {
    // 1. The memory of the ground ahead of each unit (front = the highest index).
    double ahead = prior;
    for (int i = m - 1; i >= 0; --i) {
      z_max[i] = ahead;
      ahead = std::max(ahead, st.depth_m[i]);
    }
    const Eigen::Map<const Eigen::VectorXd> fx(st.fx_N.data(), m);
    Eigen::Map<Eigen::VectorXd>(offset.data(), m) = V * fx;
    const double normal_load = c.load_N - st.shear_vertical_N;
    if (!(normal_load > 0))
      return case_result(c, pass, "the shear's vertical component exceeds the load");
    GroundPatchInput in;
    if (g.soil()) in.z_max_m = z_max;
    in.gap_offset_m = offset;
    // Bekker's b = min(width, contact length) iterates with the rolling state (fixed per step).
    in.bekker_width_m = st.bekker_width_m > 0 ? st.bekker_width_m : width;
    in.slip = rolling_radius_slip(c, R0);
    in.fixed_bekker_width = true;
    const double b_used = in.bekker_width_m;
    in.warm_active = st.active;
    in.initial_force_N = st.force_N;
    if (rate_tau_s > 0) {
      soil_rate_column(rate, model.theta, R0, rate_tau_s, o.speed_m_per_s, incoming, 0, 1,
                       st.surface_m);
      in.rate = &rate;
    }
    std::vector<const ground::PressureSinkage*> unit_law;
    std::unique_ptr<ground::PressureSinkage> soil_law;
    if (wong_reece.on()) {
      z_law = z_max;
      soil_law = g.normal_law(b_used, in.slip);
      wong_reece.set_exit_depths(st.rear, st.depth_m);
      unit_law = wong_reece.laws(st.rear, *soil_law, area, z_law);
      in.z_max_m = z_law, in.unit_law = unit_law;
    }
    const FootprintResult f = solve_ground_patch(model, op, {normal_load, 0}, g, in);
    if (!f.ok()) {
      TractionResult r = case_result(c, pass, f.message, f.status);
      r.window_exceeded = f.window_exceeded;
      return r;
    }
    st.active = f.active;
    st.bekker_width_m = std::min(width, f.contact_length_m);
    const double b_change = std::abs(st.bekker_width_m - b_used);
    // The sinkage the tyre presses into the ground: the units in contact's (a free unit's
    // surface depth is the memory it was given, which must not feed the memory back).
    std::vector<double> depth(m, 0.0), surface(m, 0.0);
    if (f.on_soil) {
      surface = f.soil_depth_m;
      for (int i = 0; i < m; ++i) depth[i] = f.active[i] ? f.soil_depth_m[i] : 0.0;
      if (wong_reece.on()) wong_reece.fill_track(st.rear, *soil_law, {prior}, depth);
    }
    const std::vector<double>& x = f.contour_x_m;
    // 2. Slopes of the ground surface, shear from the front edge.
    for (int i = 1; i + 1 < m; ++i)
      slope[i] = (surface[i - 1] - surface[i + 1]) / (x[i + 1] - x[i - 1]);
    int first = -1, last = -1;
    for (int i = 0; i < m; ++i)
      if (f.active[i]) {
        if (first < 0) first = i;
        last = i;
      }
    // The shear along the deformed contour from the front edge (traction_kinematics.h).
    const double t = (f.front_edge_x_m - x[last]) / (x[last + 1] - x[last]);
    const double theta_front = model.theta[last] + t * (model.theta[last + 1] - model.theta[last]);
    detail::ContourSlip path(R0, rho, f.front_edge_x_m,
                             surface[last] + t * (surface[last + 1] - surface[last]), theta_front);
    ground::ShearPoint point;
    double j_prev = 0, H = 0, Rc = 0, shear_v = 0, T = 0;
    const double axle_height = R0 - f.sinking_m;
    std::vector<double> fx_new(m, 0.0), fz_unit(m, 0.0);
    for (std::size_t k = 0, i = 0; i < std::size_t(m); ++i)
      if (f.active[i]) fz_unit[i] = f.units[k++].fz_N;  // units: the active ones, in order
    st.force_N = fz_unit;
    for (int i = last; i >= first; --i) {
      const double j = path.advance(x[i], surface[i], model.theta[i]);
      if (!f.active[i]) continue;
      const double dx = ds * std::cos(model.theta[i]);
      const double area = width * dx;
      const double fz = fz_unit[i];
      const double sigma = fz / area;  // the normal stress (vertical force over road area)
      const double tau = shear->advance(point, sigma, j - j_prev);
      j_prev = j;
      const double fs = tau * area;
      H += fs;
      Rc += fz * slope[i];
      shear_v += fs * slope[i];
      fx_new[i] = fs - fz * slope[i];
      const double h = axle_height + depth[i];
      T += fx_new[i] * h + (fz + fs * slope[i]) * x[i];
    }
    const double dp = H - Rc;
    const detail::RearState rear = wong_reece.image(x, fz_unit, depth, area, {f.front_edge_x_m});
    // Residual of the fixed point x = G(x) on the state (depth profile, horizontal forces, the
    // shear's load share), in mm and N so that the mixing weighs them alike.
    std::vector<double> rolled(rate_tau_s > 0 ? m : 0);
    if (rate_tau_s > 0) soil_rate_surface(rolled, rate, *rate_law, incoming, 0, 1, m, depth, z_max);
    const Eigen::Index n = 2 * m + 1 + wong_reece.size();
    Eigen::VectorXd state(n), image(n);
    for (int i = 0; i < m; ++i) {
      state(i) = st.depth_m[i] * 1e3, image(i) = depth[i] * 1e3;
      state(m + i) = st.fx_N[i], image(m + i) = fx_new[i];
    }
    state(2 * m) = st.shear_vertical_N, image(2 * m) = shear_v;
    wong_reece.pack(st.rear, rear, state, image, 2 * m + 1);
    double change = 0, deepest = 1e-12, fx_change = 0;
    for (int i = 0; i < m; ++i) {
      change = std::max(change, std::abs(depth[i] - st.depth_m[i]));
      deepest = std::max(deepest, std::abs(depth[i]));
      fx_change = std::max(fx_change, std::abs(fx_new[i] - st.fx_N[i]));
    }
    const detail::SettleTolerances tol{budget.depth_tolerance * std::max(deepest, f.sinking_m),
                                       o.tolerance * c.load_N, o.tolerance * width};
    const detail::StepChanges changes{change,
                                      std::abs(dp - last_dp),
                                      fx_change,
                                      b_change,
                                      std::abs(shear_v - st.shear_vertical_N),
                                      wong_reece.change(st.rear, rear)};
    const bool settled = it > 1 && detail::within(changes, tol);
    const double worst = detail::worst_ratio(changes, tol);  // the cycle guard's (traction_cycle.h)
    last_dp = dp;
    // Anderson mixing (traction_anderson.h): the plain step x <- G(x) converges linearly at a
    // ratio of ~0.7 here (the ground's memory follows the sinkage of the units ahead).
    const Eigen::VectorXd next = plain ? image : mixer.next(state, image);
    for (int i = 0; i < m; ++i) {
      st.depth_m[i] = std::max(next(i) * 1e-3, 0.0);
      st.fx_N[i] = next(m + i);
    }
    st.shear_vertical_N = next(2 * m);
    if (rate_tau_s > 0) st.surface_m = rolled;  // plain, not mixed (soil_rate_term.h)
    wong_reece.unpack(next, 2 * m + 1, rear, st.rear);
    if (settled) {
      TractionResult r = case_result(c, pass, {}, SolveStatus::converged);
      r.iterations = it;
      r.sinking_m = f.sinking_m;
      r.soil_sinkage_m = f.soil_sinkage_m;
      r.tyre_deflection_m = f.sinking_m - f.soil_sinkage_m;
      r.z_max_m = std::max(prior, *std::max_element(depth.begin(), depth.end()));
      r.rut_depth_m =
          g.soil()
              ? g.normal_law(std::max(f.bekker_width_m, 1e-6), in.slip)->rebound_depth_m(r.z_max_m)
              : 0.0;
      r.thrust_N = H;
      r.motion_resistance_N = Rc;
      r.drawbar_pull_N = dp;
      r.torque_Nm = T;
      r.entry_angle_rad = std::atan2(f.front_edge_x_m, axle_height);
      r.exit_angle_rad = std::atan2(f.rear_edge_x_m, axle_height + depth[first]);
      r.contact_length_m = f.contact_length_m;
      r.bekker_width_m = f.bekker_width_m;
      std::ostringstream msg;
      msg << "converged in " << it << " rolling steps";
      r.message = msg.str();
      return r;
    }
    // A run orbiting a limit cycle (traction_cycle.h) fails now, or, with plain_steps_on_cycle,
    // goes on with plain steps, which settle where the mixing cycles.
    if (const int period = detail::cycle_period(cycle, next, m, st.bekker_width_m, st.surface_m,
                                                st.active, tol, worst)) {
      if (plain || !o.plain_steps_on_cycle)
        return case_result(c, pass, detail::cycle_message(it, period), SolveStatus::max_iterations);
      plain = true, cycle = {};
    }
  }
  std::ostringstream msg;
  msg << "steady rolling did not settle in " << budget.max_iterations << " steps";
  return case_result(c, pass, msg.str(), SolveStatus::max_iterations);
}

TractionResult rigid_pass(const TyreModel& model, const ground::GroundSettings& g,
                          const TractionCase& c, int pass, double prior, const TractionOptions& o) {
  const ground::RigidWheel wheel{model.config.outer_radius_m, model.config.tread.width_m,
                                 o.speed_m_per_s};
  const ground::RigidWheelResult w = ground::rigid_wheel_rolling(g, wheel, c.load_N, c.slip, prior);
  if (!w.ok()) return case_result(c, pass, w.message, w.status);
  TractionResult r = case_result(c, pass, w.message, w.status);
  r.soil_sinkage_m = w.sinkage_m;
  r.sinking_m = w.sinkage_m;
  r.rut_depth_m = w.rut_depth_m;
  r.z_max_m = w.z_max_m;
  r.drawbar_pull_N = w.drawbar_pull_N;
  r.thrust_N = w.thrust_N;
  r.motion_resistance_N = w.motion_resistance_N;
  r.torque_Nm = w.torque_Nm;
  r.entry_angle_rad = w.entry_angle_rad;
  r.exit_angle_rad = w.exit_angle_rad;
  r.contact_length_m = w.contact_length_m;
  r.bekker_width_m = w.bekker_width_m;
  return r;
}

// What a case's row adds to its pass (docs/soil.md sections 5.1-5.4): the slip's reference, the
// validity, the motion resistance by its parts (compaction from the pass, the tyre's flexing
// loss on the road, the soil's bulldozing ahead of the contact beyond the incoming surface), the
// drawbar pull DP = H - their sum, and the tractive efficiency DP V / (T omega), V / omega = rho
// R0.
void finish_case(TractionResult& r, const TractionCase& c, const TyreModel& model,
                 const ground::GroundSettings& g, const TractionOptions& o, const RollingRadius& re,
                 double incoming_rut_m) {
  const TyreConfig& config = model.config;
  const double R0 = config.outer_radius_m;
  r.rolling_radius_m = re.radius_m;
  r.loaded_radius_m = re.loaded_radius_m;
  r.slip_radius_m = c.slip_radius_m > 0 ? c.slip_radius_m : R0;
  r.window_m = config.mesh.window_m;
  if (!r.ok()) {
    r.valid = false;
    r.validity = "not computed: " + r.message;
    return;
  }
  const Validity v = validity_on_soil(config, r.tyre_deflection_m, r.soil_sinkage_m,
                                      r.entry_angle_rad, r.exit_angle_rad, o.rigid);
  r.valid = v.valid;
  r.validity = v.reason;
  r.compaction_resistance_N = r.motion_resistance_N;
  const auto flex = o.flexing_resistance_N.find(c.load_N);
  r.flexing_resistance_N = o.rigid || flex == o.flexing_resistance_N.end() ? 0.0 : flex->second;
  if (g.model == ground::GroundModel::bekker) {
    const double width =
        !o.rigid && config.footprint_3d ? config.footprint_3d->tread_width_m : config.tread.width_m;
    const ground::JanosiParams& shear = g.soil_shear();
    r.bulldozing_resistance_N =
        ground::bulldozing_resistance_N(g.bulldozing, shear.cohesion_kPa, shear.friction_angle_deg,
                                        width, r.soil_sinkage_m - incoming_rut_m);
  }
  r.motion_resistance_N =
      r.compaction_resistance_N + r.flexing_resistance_N + r.bulldozing_resistance_N;
  r.drawbar_pull_N = r.thrust_N - r.motion_resistance_N;
  if (r.torque_Nm > 0 && r.drawbar_pull_N > 0)
    r.tractive_efficiency = r.drawbar_pull_N * speed_ratio_over_R0(c, R0) * R0 / r.torque_Nm;
}

}  // namespace

double rolling_radius_slip(const TractionCase& c, double R0_m) {
  if (!(c.rolling_radius_m > 0)) return c.slip;
  const double v_over_omega_re = speed_ratio_over_R0(c, R0_m) * R0_m / c.rolling_radius_m;
  return v_over_omega_re <= 1 ? 1 - v_over_omega_re : 1 / v_over_omega_re - 1;
}

double speed_ratio_over_R0(const TractionCase& c, double R0_m) {
  return ground::speed_ratio(c.slip) * (c.slip_radius_m > 0 ? c.slip_radius_m / R0_m : 1.0);
}

namespace {

// A case whose rolling did not settle with Wong and Reece's rut extrapolated towards theta2
// (TractionOptions::wong_reece_exit_reach) is rolled again from the virgin state with the rut
// extrapolated half a unit (to the last rear cell's segment's edge), then at that cell's depth:
// the extrapolated floor moves with the tyre and can leave the first cell behind theta2, or a
// stretch of the tyre's flat bottom, in grazing contact, switching step after step (docs/soil.md
// section 10, "Mesh"). The reach used is kept on the result when it is not the option's.
// Only a case with a rear region is rolled again (WongReeceStress::has_rear_region: the rut
// exists only there); the reset clears the pass's warm state before each new roll.
template <class Run, class Reset>
TractionResult roll_with_a_shorter_reach(TractionResult r, const ground::GroundSettings& g,
                                         const TractionCase& c, double R0_m,
                                         const TractionOptions& o, Run run, Reset reset) {
  TractionOptions shorter = o;
  const bool rear = g.wong_reece.has_rear_region(rolling_radius_slip(c, R0_m));
  while (!r.ok() && r.status == SolveStatus::max_iterations && !o.rigid && rear &&
         shorter.wong_reece_exit_reach > 0) {
    shorter.wong_reece_exit_reach = shorter.wong_reece_exit_reach > 0.5 ? 0.5 : 0.0;
    reset();
    TractionResult again = run(shorter);
    if (!again.ok()) continue;
    again.rut_reach_units = shorter.wong_reece_exit_reach;
    std::ostringstream msg;
    msg << " (Wong-Reece rut extrapolated " << shorter.wong_reece_exit_reach
        << " of a unit behind the last rear cell: with " << o.wong_reece_exit_reach
        << " the rolling did not settle)";
    again.message += msg.str();
    return again;
  }
  return r;
}

}  // namespace

TractionResult traction_pass(const TyreModel& model, const ground::GroundSettings& g,
                             const TractionCase& c, double prior, const TractionOptions& o) {
  const double R0 = model.config.outer_radius_m;
  auto run = [&](const TractionOptions& oo) {
    if (oo.rigid) return rigid_pass(model, g, c, 1, prior, oo);
    if (model.config.footprint_3d) {
      const detail::Rolling3d rolling(model, g);
      detail::Rolling3dState st;
      return rolling.pass(c, 1, std::vector<double>(rolling.columns(), prior), oo, st);
    }
    RollingState st;
    return rolling_pass(model, vertical_from_horizontal(model), g, c, 1, prior, oo, st);
  };
  TractionResult r = roll_with_a_shorter_reach(run(o), g, c, R0, o, run, [] {});
  RollingRadius rigid;  // the rigid cylinder rolls on the road at its radius
  if (o.rigid) rigid.radius_m = rigid.loaded_radius_m = R0;
  finish_case(r, c, model, g, o, rigid, 0.0);
  return r;
}

std::vector<TractionResult> steady_traction(const TyreModel& model, const ground::GroundSettings& g,
                                            const std::vector<TractionCase>& cases,
                                            const TractionOptions& o) {
  std::vector<TractionResult> out;
  if (g.model == ground::GroundModel::profile)
    throw std::invalid_argument(
        "traction on a road profile is not built (a soil or the flat road)");
  const bool three_d = !o.rigid && model.config.footprint_3d.has_value();
  const Eigen::MatrixXd V =
      o.rigid || three_d ? Eigen::MatrixXd() : vertical_from_horizontal(model);
  std::unique_ptr<detail::Rolling3d> rolling3d;
  if (three_d) rolling3d = std::make_unique<detail::Rolling3d>(model, g);
  // Each pass's state warm-starts the same pass of the next case (same load, next slip).
  const std::size_t P = std::max(1, o.passes);
  std::vector<RollingState> states(P);
  std::vector<detail::Rolling3dState> states3d(P);
  // The rolling radius per load (the rigid cylinder's is its radius).
  const double R0 = model.config.outer_radius_m;
  std::map<double, RollingRadius> radii;
  for (const auto& given : cases) {
    TractionCase c = given;
    auto it = radii.find(c.load_N);
    if (it == radii.end()) {
      RollingRadius rr;
      if (o.rigid) {
        rr.status = SolveStatus::converged, rr.radius_m = R0, rr.loaded_radius_m = R0;
      } else {
        rr = rolling_radius(model, c.load_N);
      }
      it = radii.emplace(c.load_N, rr).first;
    }
    const RollingRadius& re = it->second;
    if (o.slip_reference == SlipReference::rolling) {
      if (!re.ok()) {
        for (int p = 1; p <= o.passes; ++p) {
          TractionResult r = detail::case_result(c, p, re.message);
          r.window_exceeded = re.window_exceeded;
          finish_case(r, c, model, g, o, re, 0.0);
          out.push_back(std::move(r));
        }
        continue;
      }
      c.slip_radius_m = re.radius_m;
    }
    if (re.ok()) c.rolling_radius_m = re.radius_m;
    double prior = 0, prior_rut = 0;
    std::vector<double> prior_columns;  // 3D: the track's memory per column
    for (int p = 1; p <= o.passes; ++p) {
      auto run = [&](const TractionOptions& oo) {
        return oo.rigid  ? rigid_pass(model, g, c, p, prior, oo)
               : three_d ? rolling3d->pass(c, p, prior_columns, oo, states3d[p - 1])
                         : rolling_pass(model, V, g, c, p, prior, oo, states[p - 1]);
      };
      const bool warm =
          !o.rigid && (three_d ? !states3d[p - 1].depth_m.empty() : !states[p - 1].depth_m.empty());
      TractionResult r = run(o);
      // A warm start that does not settle is tried once more from the virgin state (the previous
      // slip's state can sit across a change of the contact's edges from this slip's).
      auto reset = [&] { states[p - 1] = {}, states3d[p - 1] = {}; };
      if (!r.ok()) reset();
      if (!r.ok() && warm) r = run(o);
      r = roll_with_a_shorter_reach(std::move(r), g, c, R0, o, run, reset);
      if (!r.ok()) reset();
      finish_case(r, c, model, g, o, re, prior_rut);
      prior = r.z_max_m;
      prior_rut = r.rut_depth_m;
      prior_columns = r.column_z_max_m;
      out.push_back(std::move(r));
      if (!out.back().ok()) break;
    }
  }
  return out;
}

}  // namespace modaltyre::contact
