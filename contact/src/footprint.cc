#include "modaltyre/contact/footprint.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/unilateral_contact.h"
#include "patch_result.h"

namespace modaltyre::contact {

namespace {

PatchOperator static_operator_without_compliance(const TyreModel& model, double ratio) {
  PatchOperator op;
  op.kernels = &model.kernels;
  op.tread_radial_lag = {1.0 / model.k_radial_N_m};
  op.tread_tangential_compliance = 1.0 / model.k_tangential_N_m;
  op.width_m = model.config.tread.width_m;
  op.horizontal_ratio = ratio;
  return op;
}

/// Radial (returned) and tangential (`ut`) displacement of every candidate unit under the unit
/// forces fr, ft: carcass u = H f (seed 001 eq. 1) over the loaded units, plus the tread's own
/// (eq. 6). The carcass part is a 2 x 2 lag convolution of the loaded span: by FFT when large.
std::vector<double> radial_displacements(const PatchOperator& op, const std::vector<char>& active,
                                         const std::vector<double>& fr,
                                         const std::vector<double>& ft, std::vector<double>& ut) {
  const int m = static_cast<int>(fr.size());
  std::vector<double> ur(m);
  const auto& K = *op.kernels;
  const int first = static_cast<int>(std::find(active.begin(), active.end(), 1) - active.begin());
  const int last =
      m - 1 - static_cast<int>(std::find(active.rbegin(), active.rend(), 1) - active.rbegin());
  if (first <= last) {
    const double cs = op.carcass_scale;
    const int span = last - first + 1;
    std::vector<double> vr(span), vt(span);
    for (int j = first; j <= last; ++j) {
      // Only loaded units push (the converged forces of free units are 0 anyway).
      vr[j - first] = active[j] ? cs * fr[j] : 0.0;
      vt[j - first] = active[j] ? cs * ft[j] : 0.0;
    }
    const solvers::LagConvolution2x2 H({K.r_from_r, K.r_from_t, K.t_from_r, K.t_from_t}, K.lags);
    H.apply(0, m, first, span, vr.data(), vt.data(), ur.data(), ut.data());
  } else {
    std::fill(ut.begin(), ut.end(), 0.0);
  }
  const int tread_lags = std::min<int>(static_cast<int>(op.tread_radial_lag.size()), m);
  for (int i = 0; i < m; ++i) {
    ut[i] += ft[i] * op.tread_tangential_compliance;
    for (int l = 1 - tread_lags; l < tread_lags; ++l) {
      const int j = i + l;
      if (j >= 0 && j < m) ur[i] += op.tread_radial_lag[std::abs(l)] * fr[j];
    }
  }
  return ur;
}

}  // namespace

PatchOperator static_matrix_free_operator(const TyreModel& model) {
  PatchOperator op = static_operator_without_compliance(model, 0.0);
  op.compliance_operator =
      std::make_shared<solvers::WeightedToeplitzCompliance>(vertical_compliance_operator(model));
  return op;
}

PatchOperator static_operator(const TyreModel& model, double ratio) {
  PatchOperator op = static_operator_without_compliance(model, ratio);
  if (ratio == 0.0) {
    op.compliance = model.vertical_compliance;
  } else {
    op.compliance = model.vertical_compliance + ratio * vertical_from_horizontal(model);
    op.symmetric = false;
  }
  return op;
}

FootprintResult solve_footprint(const TyreModel& model, const LoadCase& load,
                                std::span<const char> warm_active) {
  MODALTYRE_CHECK(load.load_N > 0, "load must be positive");
  // Without a horizontal force the problem is symmetric and solved matrix-free; with one, C
  // gains the non-symmetric horizontal coupling and is assembled (LU on the contact set).
  const double ratio = load.horizontal_force_N / load.load_N;
  return solve_patch(
      model, ratio == 0.0 ? static_matrix_free_operator(model) : static_operator(model, ratio),
      load, warm_active);
}

FootprintResult solve_patch(const TyreModel& model, PatchOperator op, const LoadCase& load,
                            std::span<const char> warm_active) {
  MODALTYRE_CHECK(load.load_N > 0, "load must be positive");
  MODALTYRE_CHECK(op.kernels != nullptr && !op.tread_radial_lag.empty(), "incomplete operator");
  solvers::ContactProblem p;
  p.compliance = std::move(op.compliance);
  p.compliance_operator = op.compliance_operator.get();
  p.symmetric = op.symmetric;
  p.initial_gap = model.sag;
  p.load_N = load.load_N;
  solvers::ContactOptions opt;
  opt.max_iterations = model.config.solver.max_iterations;
  opt.gap_tolerance = model.config.solver.gap_tolerance;
  const solvers::ContactSolution s = solvers::solve_unilateral_contact(p, opt, warm_active);
  op.compliance = std::move(p.compliance);
  return detail::patch_result(model, op, load, s, {});
}

double max_window_m(const TyreConfig& c) {
  return std::min(M_PI * c.outer_radius_m, 20000 * c.mesh.unit_length_m);
}

double suggested_window_mm(const TyreConfig& c) {
  const double next_mm = std::ceil(1.5 * c.mesh.window_m * 1e2) * 10;
  return std::min(next_mm, std::floor(max_window_m(c) * 1e3));
}

namespace detail {

FootprintResult patch_result(const TyreModel& model, const PatchOperator& op, const LoadCase& load,
                             const solvers::ContactSolution& s,
                             std::span<const double> extra_diagonal) {
  FootprintResult r;
  r.load = load;
  const double ratio = op.horizontal_ratio;
  r.iterations = s.iterations;
  r.message = s.message;
  if (!s.ok()) {
    r.status = s.status;
    return r;
  }
  const int m = model.candidates();
  if (s.active.front() || s.active.back()) {
    std::ostringstream msg;
    msg << "contact reached the edge of the candidate window (+-"
        << 0.5e3 * model.config.mesh.window_m << " mm): increase contact.window_mm (e.g. to "
        << suggested_window_mm(model.config) << ")";
    r.message = msg.str();
    r.status = SolveStatus::failed;
    r.window_exceeded = true;
    return r;
  }
  r.status = SolveStatus::converged;
  r.sinking_m = s.approach_m;
  r.equilibrium_residual = s.equilibrium_residual;
  r.complementarity_residual = s.complementarity_residual;
  r.active = s.active;

  // Radial and tangential displacement of every candidate unit (carcass + tread), eq. (1), (6).
  const Eigen::VectorXd& f = s.force;
  std::vector<double> fr(m), ft(m), ut(m);
  for (int j = 0; j < m; ++j) {
    const double c = std::cos(model.theta[j]), sn = std::sin(model.theta[j]);
    const double fx = ratio * f(j);
    fr[j] = f(j) * c - fx * sn;  // seed 001 eq. (12), f_x positive forward
    ft[j] = f(j) * sn + fx * c;
  }
  const double R0 = model.config.outer_radius_m;
  const double width = op.width_m;
  r.contour_x_m.resize(m);
  r.contour_height_m.resize(m);
  const std::vector<double> ur = radial_displacements(op, s.active, fr, ft, ut);
  for (int i = 0; i < m; ++i) {
    const double th = model.theta[i];
    r.contour_x_m[i] = (R0 - ur[i]) * std::sin(th) + ut[i] * std::cos(th);
    const double depth = (R0 - ur[i]) * std::cos(th) - ut[i] * std::sin(th);
    r.contour_height_m[i] = s.active[i] ? 0.0 : std::max((R0 - r.sinking_m) - depth, 0.0);
  }
  int first = -1, last = -1;
  for (int i = 0; i < m; ++i) {
    if (!s.active[i]) continue;
    if (first < 0) first = i;
    last = i;
    PatchUnit u;
    u.x_m = r.contour_x_m[i];
    u.dx_m = model.unit_length_m * std::cos(model.theta[i]);
    u.fz_N = f(i);
    u.fx_N = ratio * f(i);
    u.pressure_Pa = u.fz_N / (u.dx_m * width);
    r.units.push_back(u);
  }
  // Patch edges between units: the level function phi = f C_ii (force as the unit's own
  // displacement) inside and -g (gap) outside is interpolated linearly to its zero. For a rigid
  // ring on a Winkler layer phi = delta - sag exactly, so the chord is recovered to O(ds^2).
  auto edge = [&](int inside, int outside) {
    double cii = op.compliance_operator ? op.compliance_operator->entry(inside, inside)
                                        : op.compliance(inside, inside);
    if (!extra_diagonal.empty()) cii += extra_diagonal[inside];
    const double phi_in = f(inside) * cii;
    const double phi_out = -s.gap(outside);
    const double t = phi_in / (phi_in - phi_out);
    return r.contour_x_m[inside] + t * (r.contour_x_m[outside] - r.contour_x_m[inside]);
  };
  r.rear_edge_x_m = edge(first, first - 1);
  r.front_edge_x_m = edge(last, last + 1);
  r.contact_length_m = r.front_edge_x_m - r.rear_edge_x_m;
  std::ostringstream msg;
  msg << "converged in " << s.iterations << " active-set iterations";
  r.message = msg.str();
  return r;
}

}  // namespace detail

std::vector<FootprintResult> solve_footprints(const TyreModel& model,
                                              const std::vector<LoadCase>& loads) {
  std::vector<FootprintResult> out;
  std::vector<char> warm;
  for (const auto& lc : loads) {
    out.push_back(solve_footprint(model, lc, warm));
    if (out.back().ok()) warm = out.back().active;
  }
  return out;
}

}  // namespace modaltyre::contact
