#include "traction3d.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/soil_rate_term.h"
#include "modaltyre/ground/rigid_wheel.h"
#include "modaltyre/solvers/toeplitz_compliance.h"
#include "modaltyre/solvers/unilateral_contact.h"
#include "patch3d_operators.h"
#include "patch3d_soil.h"
#include "traction_anderson.h"
#include "traction_cycle.h"
#include "traction_kinematics.h"

namespace modaltyre::contact::detail {
namespace {

constexpr int kAndersonDepth = 4;  ///< as the 2D fixed point (traction.cc)

// Columns whose drops agree to this (relative to the largest drop, or 1 nm) share a class: the
// crown's mirrored columns differ by rounding only.
constexpr double kSameDrop_m = 1e-12;

// The consistency of a section's linear model with its own law: 1 nm at least
// (SoilSections::consistent: the energies come from root solves), and within a rolling step a
// hundredth of the rolling fixed point's depth tolerance, which is all the rolling steps
// resolve (the normal solve's error then stays 1 % of what the steps settle on).
constexpr double kConsistentFloor_m = 1e-9;
constexpr double kInnerShare = 0.01;

Eigen::VectorXd carcass_product(const solvers::ComplianceOperator& C, const Eigen::VectorXd& F) {
  const int S = C.size();
  Eigen::MatrixXd out(S, 1);
  C.apply(0, S, 0, S, F, out);
  return out.col(0);
}

struct NormalSolution {
  SolveStatus status = SolveStatus::failed;
  std::string message;
  Eigen::VectorXd force;           ///< per section
  double delta_m = 0;              ///< the axle's approach
  std::vector<double> approach_m;  ///< per section: delta - gap0 - C F (+ the soil's floor)
  std::vector<char> active;
  int steps = 0;
};

// The reduction's normal contact (patch3d.h): minimise J(F) = 1/2 F^T C F + gap0^T F +
// sum_i Psi_i(F_i), F >= 0, sum F = load, by linearising each section's law at its approach
// (SoilSections::reduced), solving the linear contact problem exactly (the active-set solver),
// and stepping towards its forces with a backtracking line search on J, until the linear model
// is consistent with the sections' own laws.
NormalSolution solve_normal(const solvers::ComplianceOperator& carcass, const Eigen::VectorXd& gap0,
                            SoilSections& laws, double load_N, const solvers::ContactOptions& opt,
                            std::vector<char> active, int max_steps, double floor_m) {
  const int S = carcass.size();
  NormalSolution out;
  // J at F, and each section's approach there (the sections' own laws).
  std::vector<double> trial_d(S);
  auto objective = [&](const Eigen::VectorXd& F) {
    double e = 0;
    for (int i = 0; i < S; ++i) e += laws.energy_at(i, F(i), trial_d[i]);
    return 0.5 * F.dot(carcass_product(carcass, F)) + gap0.dot(F) + e;
  };
  auto commit = [&] {
    for (int i = 0; i < S; ++i) laws.set_approach(i, trial_d[i]);
  };
  Eigen::VectorXd F;
  double JF = 0;  // J(F)
  for (int it = 1; it <= max_steps; ++it) {
    out.steps = it;
    std::vector<double> diag(S);
    Eigen::VectorXd g(S);
    for (int i = 0; i < S; ++i) {
      double o = 0;
      laws.reduced(i, diag[i], o);
      g(i) = gap0(i) + o;
    }
    const DiagonalShifted op(carcass, std::move(diag));
    solvers::ContactProblem p;
    p.compliance_operator = &op;
    p.initial_gap = g;
    p.load_N = load_N;
    const solvers::ContactSolution s = solvers::solve_unilateral_contact(p, opt, active);
    if (!s.ok()) {
      out.status = s.status;
      out.message = s.message;
      return out;
    }
    active = s.active;
    const Eigen::VectorXd CF = carcass_product(carcass, s.force);
    std::vector<double> d(S);
    for (int i = 0; i < S; ++i) d[i] = s.approach_m - gap0(i) - CF(i);
    // The sections' own approaches at the step's forces (and J there, the full step's trial):
    // consistent when the linear model's approaches are theirs (within the gap tolerance or
    // floor_m).
    const double J1 = objective(s.force);
    const double tol =
        std::max(opt.gap_tolerance * std::max(std::abs(s.approach_m), 1e-12), floor_m);
    bool consistent = true;
    for (int i = 0; i < S && consistent; ++i)
      consistent =
          s.force(i) > 0 ? std::abs(trial_d[i] - d[i]) <= tol : d[i] <= laws.floor(i) + tol;
    if (consistent) {
      out.status = SolveStatus::converged;
      out.force = s.force;
      out.delta_m = s.approach_m;
      out.approach_m = std::move(d);
      out.active = std::move(active);
      return out;
    }
    // A step towards the linear problem's forces, backtracked while J does not decrease.
    if (F.size() == 0 || J1 <= JF) {
      F = s.force;
      JF = J1;
    } else {
      const Eigen::VectorXd dF = s.force - F;
      double alpha = 0.5, J = objective(F + alpha * dF);
      for (int k = 0; k < 40 && J > JF; ++k) J = objective(F + (alpha *= 0.5) * dF);
      F += alpha * dF;
      JF = J;
    }
    commit();
  }
  out.status = SolveStatus::max_iterations;
  out.message = "3D rolling: the soil's section laws did not settle in " +
                std::to_string(max_steps) + " steps";
  return out;
}

}  // namespace

TractionResult case_result(const TractionCase& c, int pass, std::string message,
                           SolveStatus status) {
  TractionResult r;
  r.load_N = c.load_N;
  r.slip = c.slip;
  r.pass = pass;
  r.status = status;
  r.message = std::move(message);
  return r;
}

Rolling3d::Rolling3d(const TyreModel& model, const ground::GroundSettings& ground)
    : model_(model),
      ground_(ground),
      patch_(model, model.config.footprint_3d ? *model.config.footprint_3d : Patch3dSettings{}) {
  if (!model.config.footprint_3d)
    throw std::invalid_argument("3D rolling needs a footprint_3d: section");
  const Patch3dSettings& s = *model.config.footprint_3d;
  if (s.lateral_belt.enabled)
    throw std::invalid_argument("traction on the 3D patch with a lateral belt is not built");
  if (s.sidewall.enabled)
    throw std::invalid_argument("traction on the 3D patch with sidewall softening is not built");
  if (!ground.soil()) throw std::invalid_argument("traction needs a soil");
  V_ = vertical_from_horizontal(model);
  // Column classes: equal drops (to rounding) see the same history and carry the same forces.
  const std::vector<double>& z = patch_.column_drop_m();
  const double zmax = *std::max_element(z.begin(), z.end());
  const double same = std::max(kSameDrop_m * zmax, 1e-9 * kSameDrop_m);
  column_class_.assign(z.size(), -1);
  for (std::size_t j = 0; j < z.size(); ++j) {
    for (std::size_t k = 0; k < class_drop_m_.size(); ++k) {
      if (std::abs(class_drop_m_[k] - z[j]) <= same) {
        column_class_[j] = static_cast<int>(k);
        class_weight_[k] += 1;
        break;
      }
    }
    if (column_class_[j] < 0) {
      column_class_[j] = static_cast<int>(class_drop_m_.size());
      class_drop_m_.push_back(z[j]);
      class_weight_.push_back(1);
    }
  }
  const double dy = s.tread_width_m / patch_.columns(), ds = model.unit_length_m;
  for (double th : model.theta) area_m2_.push_back(dy * ds * std::cos(th));
  const TreadSprings k = tread_springs(model.config.tread, dy, ds);
  k_radial_cell_ = k.radial_N_m;
  k_tangential_cell_ = k.tangential_N_m;
}

TractionResult Rolling3d::pass(const TractionCase& c, int pass, const std::vector<double>& prior_m,
                               const TractionOptions& o, Rolling3dState& st) const {
  const TyreModel& m = model_;
  const int S = m.candidates(), K = static_cast<int>(class_drop_m_.size());
  const int ny = patch_.columns();
  const double R0 = m.config.outer_radius_m;
  const double width = patch_.settings().tread_width_m, dy = width / ny;
  const TreadSprings unit = tread_springs(m.config.tread, 1.0, 1.0);
  const std::unique_ptr<ground::ShearLaw> shear = ground_.shear_law(unit.tangential_N_m);
  const double rho = speed_ratio_over_R0(c, R0);
  std::vector<double> prior(K, 0.0);
  if (!prior_m.empty())
    for (int j = 0; j < ny; ++j)
      prior[column_class_[j]] = std::max(prior[column_class_[j]], prior_m[j]);
  const std::size_t cells = std::size_t(S) * K;
  if (st.depth_m.size() != cells) st.depth_m.assign(cells, 0.0);
  if (st.fx_N.size() != std::size_t(S)) st.fx_N.assign(S, 0.0);
  std::vector<double> t(S), cos_th(S), sin_th(S);
  for (int i = 0; i < S; ++i) {
    t[i] = patch_.cell_tread_compliance(i);
    cos_th[i] = std::cos(m.theta[i]), sin_th[i] = std::sin(m.theta[i]);
  }
  const solvers::WeightedToeplitzCompliance carcass = carcass_compliance_operator(m);
  solvers::ContactOptions copt;
  copt.max_iterations = m.config.solver.max_iterations;
  copt.gap_tolerance = m.config.solver.gap_tolerance;
  const modal::LagKernels& HK = m.kernels;
  const solvers::LagConvolution2x2 H({HK.r_from_r, HK.r_from_t, HK.t_from_r, HK.t_from_t}, HK.lags);
  AndersonMixer mixer(kAndersonDepth);
  CycleGuard cycle;
  bool plain = false;  // Anderson's mixing left for plain steps (traction_cycle.h)
  WongReeceRear wong_reece(ground_.wong_reece, rolling_radius_slip(c, R0), R0, S, K,
                           o.wong_reece_exit_reach);
  wong_reece.prepare(st.rear);
  double last_dp = 0;
  int normal_steps = 0;
  double sinking = st.sinking_m;  // the last rolling step's (0: none yet)  // the section laws'
                                  // linearisations over the rolling steps
  std::vector<double> zmax(cells), f(cells), depth(cells), surface(cells), x(cells);
  std::vector<double> fr(S), ft(S), ur(S), ut(S);
  // A viscous soil's rate term (soil_rate_term.h): its surface per cell carried from step to step.
  const double rate_tau_s = soil_rate_time_s(ground_, o.speed_m_per_s);  // 0: no rate term
  const SoilRateBudget budget = rate_tau_s > 0
                                    ? soil_rate_budget(o.max_iterations, o.depth_tolerance,
                                                       rate_tau_s, o.speed_m_per_s, m.unit_length_m)
                                    : SoilRateBudget{o.max_iterations, o.depth_tolerance};
  std::vector<double> incoming(K, 0.0), rolled(rate_tau_s > 0 ? cells : 0);
  if (rate_tau_s > 0) {
    const auto kv = ground_.normal_law(width, rolling_radius_slip(c, R0));  // b, slip: Bekker's
    for (int k = 0; k < K; ++k) incoming[k] = kv->sinkage_m(0.0, prior[k]);
    if (st.surface_m.size() != cells) {
      st.surface_m.resize(cells);
      for (std::size_t a = 0; a < cells; ++a) st.surface_m[a] = incoming[a % K];
    }
  }
  for (int it = 1; it <= budget.max_iterations; ++it) {
    // 1. The memory of the cells ahead in each column (front = the highest section index).
    for (int k = 0; k < K; ++k) {
      double ahead = prior[k];
      for (int i = S - 1; i >= 0; --i) {
        zmax[std::size_t(i) * K + k] = ahead;
        ahead = std::max(ahead, st.depth_m[std::size_t(i) * K + k]);
      }
    }
    const double normal_load = c.load_N - st.shear_vertical_N;
    if (!(normal_load > 0))
      return case_result(c, pass, "the shear's vertical component exceeds the load");
    const double b_used = st.bekker_width_m > 0 ? st.bekker_width_m : width;
    const std::unique_ptr<ground::PressureSinkage> law =
        ground_.normal_law(b_used, rolling_radius_slip(c, R0));
    SoilRate rate;
    if (rate_tau_s > 0) {
      rate.weight.resize(cells), rate.start_m.resize(cells);
      for (int k = 0; k < K; ++k)
        soil_rate_column(rate, m.theta, R0, rate_tau_s, o.speed_m_per_s, incoming[k], k, K,
                         st.surface_m);
    }
    std::vector<double> z_law;
    std::vector<const ground::PressureSinkage*> cell_law;
    if (wong_reece.on()) {
      wong_reece.set_exit_depths(st.rear, st.depth_m);
      z_law = zmax, cell_law = wong_reece.laws(st.rear, *law, area_m2_, z_law);
    }
    SoilSections laws(t, class_drop_m_, class_weight_, *law, area_m2_,
                      wong_reece.on() ? z_law : zmax, rate, cell_law);
    if (st.approach_m.size() == std::size_t(S))
      for (int i = 0; i < S; ++i) laws.set_approach(i, std::max(st.approach_m[i], laws.floor(i)));
    const Eigen::Map<const Eigen::VectorXd> fx(st.fx_N.data(), S);
    const Eigen::VectorXd gap0 = m.sag + V_ * fx;
    const double floor_m = std::max(kConsistentFloor_m, kInnerShare * o.depth_tolerance * sinking);
    const NormalSolution n = solve_normal(carcass, gap0, laws, normal_load, copt, st.active,
                                          patch_.settings().max_pattern_iterations, floor_m);
    if (!ok(n.status)) return case_result(c, pass, n.message, n.status);
    normal_steps += n.steps;
    sinking = n.delta_m;
    st.active = n.active;
    st.approach_m = n.approach_m;
    // Cell forces, the soil under them, and the cells' deformed positions (patch3d.h).
    double soil_sinkage = 0;
    for (int i = 0; i < S; ++i) {
      laws.cell_forces(i, n.approach_m[i], &f[std::size_t(i) * K]);
      for (int k = 0; k < K; ++k) {
        const std::size_t a = std::size_t(i) * K + k;
        surface[a] = laws.depth(i, k, f[a]);
        depth[a] = f[a] > 0 ? surface[a] : 0.0;
        soil_sinkage = std::max(soil_sinkage, depth[a]);
      }
      fr[i] = n.force(i) * cos_th[i], ft[i] = n.force(i) * sin_th[i];
    }
    wong_reece.fill_track(st.rear, *law, prior, depth);
    H.apply(0, S, 0, S, fr.data(), ft.data(), ur.data(), ut.data());
    for (int i = 0; i < S; ++i) {
      const double cs = cos_th[i], sn = sin_th[i];
      for (int k = 0; k < K; ++k) {
        const std::size_t a = std::size_t(i) * K + k;
        x[a] = (R0 - ur[i] - f[a] * cs / k_radial_cell_) * sn +
               (ut[i] + f[a] * sn / k_tangential_cell_) * cs;
      }
    }
    // 2. Per column class: its edges, slopes and shear from its own front edge.
    const double axle_height = R0 - n.delta_m;
    std::vector<double> fx_new(S, 0.0);
    double H_N = 0, Rc = 0, shear_v = 0, T = 0, length = 0, front_max = -1e300, rear_min = 1e300;
    double rear_depth = 0, columns_in_contact = 0;
    std::vector<double> front_x(K, std::nan(""));  // per class (Wong and Reece's entry)
    for (int k = 0; k < K; ++k) {
      auto at = [&](int i) { return std::size_t(i) * K + k; };
      int first = -1, last = -1;
      for (int i = 0; i < S; ++i)
        if (f[at(i)] > 0) {
          if (first < 0) first = i;
          last = i;
        }
      if (first < 0) continue;
      if (first == 0 || last == S - 1) {
        TractionResult r =
            case_result(c, pass,
                        "contact reached the edge of the candidate window (+-" +
                            std::to_string(int(0.5e3 * m.config.mesh.window_m)) +
                            " mm): increase contact.window_mm (e.g. to " +
                            std::to_string(int(suggested_window_mm(m.config))) + ")");
        r.window_exceeded = true;
        return r;
      }
      columns_in_contact += class_weight_[k];
      // The level e - rut (the compression beyond the surface inside, minus the gap outside),
      // linear to its zero between the last cell in contact and the next.
      auto level = [&](int i) {
        return n.approach_m[i] - class_drop_m_[k] - laws.rest_depth(i, k);
      };
      auto edge_fraction = [&](int in, int out) {
        const double a = level(in), b = level(out);
        return a > b ? a / (a - b) : 0.0;
      };
      const double tf = edge_fraction(last, last + 1), tr = edge_fraction(first, first - 1);
      const double x_front = x[at(last)] + tf * (x[at(last + 1)] - x[at(last)]);
      const double x_rear = x[at(first)] + tr * (x[at(first - 1)] - x[at(first)]);
      const double theta_front = m.theta[last] + tf * (m.theta[last + 1] - m.theta[last]);
      length = std::max(length, x_front - x_rear);
      front_max = std::max(front_max, x_front);
      front_x[k] = x_front;
      if (x_rear < rear_min) rear_min = x_rear, rear_depth = depth[at(first)];
      ground::ShearPoint point;
      double j_prev = 0;
      const double w = class_weight_[k];
      // The shear along the column's deformed contour from its front edge
      // (traction_kinematics.h).
      ContourSlip path(R0, rho, x_front,
                       surface[at(last)] + tf * (surface[at(last + 1)] - surface[at(last)]),
                       theta_front);
      for (int i = last; i >= first; --i) {
        const std::size_t a = at(i);
        const double j = path.advance(x[a], surface[a], m.theta[i]);
        if (!(f[a] > 0)) continue;
        const double slope =
            (surface[at(i - 1)] - surface[at(i + 1)]) / (x[at(i + 1)] - x[at(i - 1)]);
        const double area = area_m2_[i];
        const double sigma = f[a] / area;
        const double tau = shear->advance(point, sigma, j - j_prev);
        j_prev = j;
        const double fs = tau * area;
        const double fxa = fs - f[a] * slope;
        H_N += w * fs;
        Rc += w * f[a] * slope;
        shear_v += w * fs * slope;
        fx_new[i] += w * fxa;
        T += w * (fxa * (axle_height + depth[a]) + (f[a] + fs * slope) * x[a]);
      }
    }
    const double dp = H_N - Rc;
    const RearState rear = wong_reece.image(x, f, depth, area_m2_, front_x);
    st.sinking_m = n.delta_m;
    const double b_new = std::min(columns_in_contact * dy, length);
    const double b_change = std::abs(b_new - b_used);
    st.bekker_width_m = b_new;
    // 3. The fixed point's state: cell depths [mm], section horizontal forces [N], load share.
    for (int k = 0; k < K && rate_tau_s > 0; ++k)
      soil_rate_surface(rolled, rate, *law, incoming[k], k, K, S, depth, zmax);
    const Eigen::Index nstate = Eigen::Index(cells) + S + 1 + wong_reece.size();
    Eigen::VectorXd state(nstate), image(nstate);
    double change = 0, fx_change = 0;
    for (std::size_t a = 0; a < cells; ++a) {
      state(a) = st.depth_m[a] * 1e3, image(a) = depth[a] * 1e3;
      change = std::max(change, std::abs(depth[a] - st.depth_m[a]));
    }
    for (int i = 0; i < S; ++i) {
      state(cells + i) = st.fx_N[i], image(cells + i) = fx_new[i];
      fx_change = std::max(fx_change, std::abs(fx_new[i] - st.fx_N[i]));
    }
    state(Eigen::Index(cells) + S) = st.shear_vertical_N, image(Eigen::Index(cells) + S) = shear_v;
    wong_reece.pack(st.rear, rear, state, image, Eigen::Index(cells) + S + 1);
    const double deepest = std::max(soil_sinkage, 1e-12);
    const SettleTolerances tol{budget.depth_tolerance * std::max(deepest, n.delta_m),
                               o.tolerance * c.load_N, o.tolerance * width};
    const StepChanges changes{change,
                              std::abs(dp - last_dp),
                              fx_change,
                              b_change,
                              std::abs(shear_v - st.shear_vertical_N),
                              wong_reece.change(st.rear, rear)};
    const bool settled = it > 1 && within(changes, tol);
    const double worst = worst_ratio(changes, tol);  // the cycle guard's (traction_cycle.h)
    last_dp = dp;
    const Eigen::VectorXd next = plain ? image : mixer.next(state, image);
    for (std::size_t a = 0; a < cells; ++a) st.depth_m[a] = std::max(next(a) * 1e-3, 0.0);
    for (int i = 0; i < S; ++i) st.fx_N[i] = next(cells + i);
    st.shear_vertical_N = next(Eigen::Index(cells) + S);
    if (rate_tau_s > 0) st.surface_m = rolled;  // plain, not mixed (soil_rate_term.h)
    wong_reece.unpack(next, Eigen::Index(cells) + S + 1, rear, st.rear);
    if (!settled) {
      // A run orbiting a limit cycle (traction_cycle.h) fails now, or, with
      // plain_steps_on_cycle, goes on with plain steps, which settle where the mixing cycles.
      const int period = cycle_period(cycle, next, Eigen::Index(cells), st.bekker_width_m,
                                      st.surface_m, st.active, tol, worst);
      if (period > 0 && (plain || !o.plain_steps_on_cycle))
        return case_result(c, pass, cycle_message(it, period), SolveStatus::max_iterations);
      if (period > 0) plain = true, cycle = {};
      continue;
    }
    TractionResult r = case_result(c, pass, {}, SolveStatus::converged);
    r.iterations = it;
    r.sinking_m = n.delta_m;
    r.soil_sinkage_m = soil_sinkage;
    r.tyre_deflection_m = n.delta_m - soil_sinkage;
    r.column_z_max_m.assign(ny, 0.0);
    for (int j = 0; j < ny; ++j) {
      const int k = column_class_[j];
      double z = prior[k];
      for (int i = 0; i < S; ++i) z = std::max(z, depth[std::size_t(i) * K + k]);
      r.column_z_max_m[j] = z;
      r.z_max_m = std::max(r.z_max_m, z);
    }
    r.rut_depth_m = law->rebound_depth_m(r.z_max_m);
    r.thrust_N = H_N;
    r.motion_resistance_N = Rc;
    r.drawbar_pull_N = dp;
    r.torque_Nm = T;
    r.entry_angle_rad = std::atan2(front_max, axle_height);
    r.exit_angle_rad = std::atan2(rear_min, axle_height + rear_depth);
    r.contact_length_m = length;
    r.bekker_width_m = b_used;
    std::ostringstream msg;
    msg << "converged in " << it << " rolling steps (3D patch, " << K << " column classes, "
        << normal_steps << " section-law linearisations)";
    r.message = msg.str();
    return r;
  }
  std::ostringstream msg;
  msg << "steady rolling on the 3D patch did not settle in " << budget.max_iterations << " steps";
  return case_result(c, pass, msg.str(), SolveStatus::max_iterations);
}

}  // namespace modaltyre::contact::detail
