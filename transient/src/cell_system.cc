#include "modaltyre/transient/cell_system.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/core/errors.h"
#include "modaltyre/transient/cell_soil.h"
#include "modaltyre/transient/column_product.h"
#include "modaltyre/transient/ode_system.h"
#include "slot_kernels.h"

namespace modaltyre::transient {
namespace {

/// Absolute tolerance of displacement-like states [m], as the 2D system (ode_system.cc).
constexpr double kDisplacementTolerance = 1e-7;
/// Length beyond each class's contact ends whose cells enter Newton's matrix while cells are
/// switching (the 2D system's kJacobianEdgeMargin_m, ode_jacobian.cc).
constexpr double kJacobianEdgeMargin_m = 2e-3;
/// Sections checked beyond each end of a class's range at every accepted step (escaped()).
constexpr int kEscapeCheckSections = 3;

}  // namespace

StaticCells static_cells(const CellModel& cm, double load_N) {
  const TransientModel& M = cm.M();
  const int nc = cm.classes.size();
  StaticCells s;
  s.F = Eigen::VectorXd::Zero(M.m);
  s.f = Eigen::MatrixXd::Zero(M.m, nc);
  s.d = -M.tyre.sag;
  if (load_N <= 0) return s;
  const contact::Patch3d patch = static_patch(cm);
  const contact::Patch3dResult r = patch.solve(load_N);
  if (!r.ok()) throw ComputationError("static 3D initial state: " + r.message);
  for (int i = 0; i < M.m; ++i) {
    s.F(i) = r.section_force_N[i];
    s.d(i) = r.section_approach_m[i];
    for (int j = 0; j < r.columns; ++j) s.f(i, cm.classes.column_class[j]) = r.cell_force(i, j);
  }
  s.sinking_m = r.sinking_m;
  return s;
}

std::vector<UnitRange> touchable_sections(const CellModel& cm, const ScenarioPlan& plan,
                                          const StaticCells& bound) {
  const TransientModel& M = cm.M();
  const double level = -(kTouchMarginFraction * bound.sinking_m + plan.road_height_bound());
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

CellSystem::CellSystem(const CellModel& cm, const ScenarioPlan& plan, std::vector<UnitRange> ranges,
                       CellSoil* soil)
    : cm_(cm),
      plan_(plan),
      relax_(cm.M().settings.relaxation),
      ranges_(std::move(ranges)),
      soil_(soil) {
  const TransientModel& M = cm.M();
  const int nc = cm.classes.size();
  if (ranges_.empty()) ranges_.assign(nc, UnitRange{0, M.m - 1});
  MODALTYRE_CHECK(static_cast<int>(ranges_.size()) == nc, "CellSystem: one range per class");
  span_ = UnitRange{M.m, -1};
  for (int c = 0; c < nc; ++c) {
    const UnitRange& r = ranges_[c];
    MODALTYRE_CHECK(r.size() == 0 || (r.lo >= 0 && r.hi < M.m), "CellSystem: range out of window");
    offset_.push_back(ncells_);
    ncells_ += r.size();
    if (r.size() > 0) span_.lo = std::min(span_.lo, r.lo), span_.hi = std::max(span_.hi, r.hi);
  }
  if (span_.hi < span_.lo) span_ = UnitRange{0, -1};
  inv_c_.setZero(ncells_);
  k_over_c_.setZero(ncells_);
  kc_slot_.resize(ncells_);
  drop_slot_.resize(ncells_);
  for (int c = 0; c < nc; ++c) {
    for (int i = ranges_[c].lo, k = offset_[c]; i <= ranges_[c].hi; ++i, ++k) {
      kc_slot_(k) = cm.k_contact(i);
      drop_slot_(k) = cm.classes.drop_m[c];
      if (relax_) {
        inv_c_(k) = 1.0 / cm.c_kv(i);
        k_over_c_(k) = cm.k_kv(i) / cm.c_kv(i);
      }
    }
  }
  CqT_ = M.Cq.transpose();
  CrT_ = M.Cr.transpose();
  TT_ = M.T.transpose();
  in_contact_.assign(ncells_, 0);
  if (soil_) kd_soil_.setZero(ncells_);
}

double CellSystem::spin(double t) const { return plan_.spin(t); }
double CellSystem::spin_rate(double t) const { return plan_.spin_rate(t); }

double CellSystem::road(double t, int i, int c, double* slope) const {
  if (slope) *slope = 0;
  // A road profile is uniform across the tread (every column class); the cleat may be narrower.
  if (plan_.road_profile) return plan_.road_profile(t, cm_.M().x_road(i), slope);
  if (!plan_.cleat || !cm_.classes.on_cleat[c]) return 0;
  // The 2D model's cleat profile (ode_system.cc): flat top, raised-cosine edges of L/4.
  const double L = plan_.cleat_length_m, H = plan_.cleat_height_m;
  const double xi = cm_.M().x_road(i) - (plan_.cleat_start_m - plan_.distance(t));
  const double a = 0.25 * L, ax = std::abs(xi);
  if (ax >= 0.5 * L) return 0;
  if (ax <= 0.5 * L - a) return H;
  const double u = M_PI * (ax - (0.5 * L - a)) / a;
  if (slope) *slope = -0.5 * H * std::sin(u) * M_PI / a * (xi > 0 ? 1.0 : -1.0);
  return 0.5 * H * (1 + std::cos(u));
}

void CellSystem::road_heights(double t, int lo, int n, int c, double* h, double* slope) const {
  if (plan_.road_profile || !plan_.cleat || !cm_.classes.on_cleat[c]) {
    for (int k = 0; k < n; ++k) h[k] = road(t, lo + k, c, slope ? slope + k : nullptr);
    return;
  }
  // road()'s cleat with the rolled distance taken once (the same operations per section).
  const double L = plan_.cleat_length_m, H = plan_.cleat_height_m;
  const double shift = plan_.cleat_start_m - plan_.distance(t);
  const double a = 0.25 * L;
  const Eigen::VectorXd& x = cm_.M().x_road;
  for (int k = 0; k < n; ++k) {
    const double xi = x(lo + k) - shift, ax = std::abs(xi);
    if (slope) slope[k] = 0;
    if (ax >= 0.5 * L) {
      h[k] = 0;
    } else if (ax <= 0.5 * L - a) {
      h[k] = H;
    } else {
      const double u = M_PI * (ax - (0.5 * L - a)) / a;
      if (slope) slope[k] = -0.5 * H * std::sin(u) * M_PI / a * (xi > 0 ? 1.0 : -1.0);
      h[k] = 0.5 * H * (1 + std::cos(u));
    }
  }
}

void CellSystem::contact_coordinates(const double* y) const {
  const TransientModel& M = cm_.M();
  xi_.resize(M.rank);
  column_dots(CqT_, Eigen::Map<const Eigen::VectorXd>(y, M.nq), xi_);
  if (M.nr > 0)
    column_dots(CrT_, Eigen::Map<const Eigen::VectorXd>(y + 2 * M.nq, M.nr), xi_, 1.0, true);
}

void CellSystem::penetration(double t, const double* y, Eigen::VectorXd& g,
                             Eigen::VectorXd& P) const {
  slots(t, y, g, P, nullptr, nullptr);
}

void CellSystem::slots(double t, const double* y, Eigen::VectorXd& g, Eigen::VectorXd& P,
                       Eigen::VectorXd* f, Eigen::VectorXd* F) const {
  const TransientModel& M = cm_.M();
  contact_coordinates(y);
  if (P.size() != M.m) P.setZero(M.m);
  g.resize(ncells_);
  if (span_.size() == 0) return;
  const int lo = span_.lo, n = span_.size();
  auto seg = P.segment(lo, n);
  column_product(M.T.middleRows(lo, n), xi_, seg);  // u = T xi
  const double z = hub_z(t, y);
  for (int k = 0; k < n; ++k) seg(k) = (z - M.tyre.sag(lo + k)) - seg(k);
  const double* e = y + M.e_index();
  const int nc = cm_.classes.size();
  // The road's height per section, once: the same for every class it covers (road()).
  int road_class = -1;
  for (int c = 0; c < nc && road_class < 0; ++c)
    if (plan_.road_profile || (plan_.cleat && cm_.classes.on_cleat[c])) road_class = c;
  if (road_class >= 0) {
    road_.resize(n);
    road_heights(t, lo, n, road_class, road_.data());
  }
  for (int c = 0; c < nc; ++c) {
    const UnitRange& r = ranges_[c];
    if (r.size() == 0) continue;
    const int o = offset_[c];
    // g = ((P - drop) + h) - e and, with f, the class's forces k max(0, g) and its share of the
    // section forces in the same pass (slot_kernels.h: the same operations in the same order
    // as a pass per term).
    const bool on_road = plan_.road_profile || (plan_.cleat && cm_.classes.on_cleat[c]);
    detail::slot_pass(r.size(), P.data() + r.lo, cm_.classes.drop_m[c],
                      on_road ? road_.data() + (r.lo - lo) : nullptr, relax_ ? e + o : nullptr,
                      kc_slot_.data() + o, cm_.classes.multiplicity[c], g.data() + o,
                      f ? f->data() + o : nullptr, f ? F->data() + r.lo : nullptr);
  }
}

void CellSystem::forces(double t, const double* y, Eigen::VectorXd& f, Eigen::VectorXd& F,
                        Eigen::VectorXd* g, Eigen::VectorXd* P) const {
  const TransientModel& M = cm_.M();
  if (soil_) {
    // On a soil: each cell's spring in series with the soil under it (cell_soil.h).
    if (g) {
      penetration(t, y, *g, P ? *P : P_);
      f = *g;
    } else {
      penetration(t, y, f, P ? *P : P_);
    }
    soil_->forces(t, ranges_, offset_, f.data(), kd_soil_.data());
  } else {
    // The rigid road: f = k max(0, g) and F = sum_c mu_c f_c in penetration's pass (slots()).
    if (F.size() != M.m) F.resize(M.m);
    F.setZero();
    f.resize(ncells_);
    slots(t, y, g ? *g : g_work_, P ? *P : P_, &f, &F);
    return;
  }
  if (F.size() != M.m) F.resize(M.m);
  F.setZero();
  const int nc = cm_.classes.size();
  for (int c = 0; c < nc; ++c) {
    const UnitRange& r = ranges_[c];
    if (r.size() == 0) continue;
    F.segment(r.lo, r.size()) += cm_.classes.multiplicity[c] * f.segment(offset_[c], r.size());
  }
}

bool CellSystem::accepted_forces(double t, const Eigen::VectorXd*& f,
                                 const Eigen::VectorXd*& F) const {
  if (t != t_step_) return false;
  f = &f_step_, F = &F_step_;
  return true;
}

void CellSystem::rhs(double t, const double* y, double* ydot) const {
  const TransientModel& M = cm_.M();
  const int nq = M.nq, nr = M.nr;
  forces(t, y, f_, F_);
  phi_.setZero(M.rank);
  double load = 0;
  if (span_.size() > 0) {
    column_dots(M.T.middleRows(span_.lo, span_.size()), F_.segment(span_.lo, span_.size()), phi_);
    load = F_.segment(span_.lo, span_.size()).sum();
  }
  G_.resize(nq);
  column_product(CqT_, phi_, G_);
  if (nr > 0) {
    Vf_.resize(nr);
    column_product(CrT_, phi_, Vf_);
  }
  const double Omega = spin(t), dOmega = spin_rate(t);
  // The modal rows at this spin, kept while it holds (as the 2D system: the same values).
  if (modal_rows_.size() != static_cast<std::size_t>(nq) || Omega != rows_Omega_ ||
      dOmega != rows_dOmega_) {
    modal_rows_.resize(nq);
    for (int j = 0; j < nq; ++j) modal_rows_[j] = modal_row(M, j, Omega, dOmega);
    rows_Omega_ = Omega, rows_dOmega_ = dOmega;
  }
  for (int j = 0; j < nq; ++j) {
    const ModalRow& d = modal_rows_[j];
    const int p = std::max(M.partner[j], 0);
    ydot[j] = y[nq + j];
    ydot[nq + j] = G_(j) + d.dq * y[j] + d.dv * y[nq + j] + d.dq_p * y[p] + d.dv_p * y[nq + p];
  }
  for (int l = 0; l < nr; ++l)
    ydot[2 * nq + l] = (M.lambda(l) * Vf_(l) - y[2 * nq + l]) / M.tau_residual_s;
  const int Z = M.z_index();
  plan_.hub_rates(t, y + Z, load, M.settings.hub_mass_kg, ydot + Z);
  if (!relax_) return;
  // c' De/Dt + k' e = f per slot; De/Dt = de/dt - Omega de/dtheta along each class's sections
  // (second-order upwind from the front of its range, e = 0 entering: ode_system.h).
  const int E = M.e_index();
  const Eigen::Map<const Eigen::VectorXd> e(y + E, ncells_);
  Eigen::Map<Eigen::VectorXd> de(ydot + E, ncells_);
  const double adv = Omega / M.tyre.dtheta_rad;
  if (adv == 0) {  // de = f / c' - e k' / c'
    detail::tread_rates(ncells_, f_.data(), inv_c_.data(), k_over_c_.data(), e.data(), 0, 0, 0,
                        /*at_rest=*/true, de.data());
    return;
  }
  // Per class in one pass: (((f / c' - e k' / c') + a0 e_k) + a1 e_k+1) + a2 e_k+2, the upwind
  // terms that reach beyond the range left out (the same operations in the same order as a pass
  // per term).
  const double a0 = kUpwind[0] * adv, a1 = kUpwind[1] * adv, a2 = kUpwind[2] * adv;
  const double *fv = f_.data(), *ic = inv_c_.data(), *kc = k_over_c_.data(), *ev = y + E;
  double* dv = ydot + E;
  const int nc = cm_.classes.size();
  for (int c = 0; c < nc; ++c) {
    const int n = ranges_[c].size(), o = offset_[c];
    detail::tread_rates(n, fv + o, ic + o, kc + o, ev + o, a0, a1, a2, /*at_rest=*/false, dv + o);
  }
}

void CellSystem::jacobian_stiffness(double t, const double* y, Eigen::VectorXd& kd) const {
  const TransientModel& M = cm_.M();
  if (soil_) {
    forces(t, y, kd, F_);
    kd = (kd.array() > 0).select(kd_soil_.array(), 0.0);
  } else {
    penetration(t, y, kd, P_);
    kd = (kd.array() > 0).select(kc_slot_.array(), 0.0);
  }
  const bool moving = switches_since_jacobian_ > 0;
  switches_since_jacobian_ = 0;
  if (!moving) return;
  const int margin =
      std::max(1, static_cast<int>(std::lround(kJacobianEdgeMargin_m / M.tyre.unit_length_m)));
  for (int c = 0; c < cm_.classes.size(); ++c) {
    const int n = ranges_[c].size(), o = offset_[c];
    int first = -1, last = -1;
    for (int k = 0; k < n; ++k)
      if (kd(o + k) > 0) last = k, first = first < 0 ? k : first;
    if (first < 0) continue;
    for (int k = std::max(0, first - margin); k < first; ++k) kd(o + k) = kc_slot_(o + k);
    for (int k = last + 1; k <= std::min(n - 1, last + margin); ++k) kd(o + k) = kc_slot_(o + k);
  }
}

int CellSystem::update_contact_set(double t, const double* y) const {
  const TransientModel& M = cm_.M();
  if (soil_) {
    // On a soil: the contact set is where cells carry a force (g beyond the rut), and the soil
    // remembers the depths of this accepted state (cell_soil.h).
    forces(t, y, f_acc_, F_, &g_, &P_);
    soil_->accept(t, ranges_);
    g_ = f_acc_;
    f_step_ = f_acc_;
    F_step_ = F_;
  } else {
    // The penetration, and in the same pass the forces at this state (accepted_forces()).
    F_step_.setZero(M.m);
    f_step_.resize(ncells_);
    slots(t, y, g_, P_, &f_step_, &F_step_);
  }
  t_step_ = t;
  long changed = 0;
  const int nc = cm_.classes.size();
  const double z = hub_z(t, y);
  for (int c = 0; c < nc; ++c) {
    const UnitRange& r = ranges_[c];
    const int o = offset_[c], mu = cm_.classes.multiplicity[c];
    const double* gc = g_.data() + o;
    const int flips = detail::contact_flips(r.size(), gc, in_contact_.data() + o);
    changed += static_cast<long>(mu) * flips;
    // Sections just outside the range (e = 0 there): a positive penetration means the range
    // did not hold the scenario's contact. The undeformed tread's penetration z - s_i - u_i is
    // penetration()'s P over the span, and from a contiguous row of T^T beyond it.
    if (r.size() == 0) continue;
    // The road's height from penetration()'s per-section heights where it has them (the same
    // values; a cleat's cosine per check before).
    const bool on_road = plan_.road_profile || (plan_.cleat && cm_.classes.on_cleat[c]);
    auto outside = [&](int i) {
      const bool in_span = span_.contains(i);
      const double p = in_span ? P_(i) : (z - M.tyre.sag(i)) - TT_.col(i).dot(xi_);
      const double h = !on_road ? 0.0 : in_span ? road_(i - span_.lo) : road(t, i, c);
      const double rut = soil_ ? soil_->rut_m(c, i, t) : 0.0;
      return p - cm_.classes.drop_m[c] + h - rut > 0;
    };
    for (int k = 1; k <= kEscapeCheckSections; ++k) {
      if (r.lo - k >= 0 && outside(r.lo - k)) escaped_ = true;
      if (r.hi + k < M.m && outside(r.hi + k)) escaped_ = true;
    }
  }
  if (changed > 0) ++switches_since_jacobian_;
  return static_cast<int>(changed);
}

std::vector<double> CellSystem::state_from(const StaticCells& s) const {
  const TransientModel& M = cm_.M();
  std::vector<double> y(size(), 0.0);
  if (!(s.sinking_m != 0 || s.F.any())) return y;
  const StaticCarcass sc = static_carcass(M, s.F);
  for (int j = 0; j < M.nq; ++j) y[j] = sc.q(j);
  for (int l = 0; l < M.nr; ++l) y[2 * M.nq + l] = sc.r(l);
  y[M.z_index()] = s.sinking_m;
  if (relax_) {
    // The tread state that gives each cell its static force through the contact spring at the
    // model's own penetration p (e = p - f / k_g), not f / k': the model's carcass differs from
    // the static kernel by the truncated residual's off-diagonal coupling (a micrometre at the
    // patch centre), which the glassy spring k_g = 20 k would turn into force errors of 20 times
    // the truncation's (-1.4 % of the load at 2 mm sections, -0.3 % at 0.5 mm). The Kelvin-Voigt
    // element then starts within the truncation error of its rest length f / k'.
    contact_coordinates(y.data());
    const double z = y[M.z_index()];
    for (int c = 0; c < cm_.classes.size(); ++c) {
      for (int i = ranges_[c].lo, k = offset_[c]; i <= ranges_[c].hi; ++i, ++k) {
        const double p =
            z - M.tyre.sag(i) - M.T.row(i).dot(xi_) - cm_.classes.drop_m[c] + road(0.0, i, c);
        const double f = s.f(i, c);
        // On a soil the tip sits on the soil's surface, its depth below the undisturbed one.
        const double below = s.soil_depth_m.size() > 0 ? s.soil_depth_m(i, c) : 0.0;
        y[M.e_index() + k] = f > 0 ? p - below - f / cm_.k_contact(i) : std::max(0.0, p - below);
        if (f > 0) in_contact_[k] = 1;
      }
    }
  }
  // Forces outside the ranges: the ranges do not hold the initial patch.
  for (int c = 0; c < cm_.classes.size(); ++c)
    for (int i = 0; i < M.m; ++i)
      if (s.f(i, c) > 0 && !ranges_[c].contains(i)) escaped_ = true;
  return y;
}

std::vector<double> CellSystem::absolute_tolerances() const {
  const TransientModel& M = cm_.M();
  std::vector<double> a(size(), kDisplacementTolerance);
  for (int j = 0; j < M.nq; ++j) {
    const double s = std::max(M.psi.col(j).cwiseAbs().maxCoeff(), 1e-300);
    a[j] = kDisplacementTolerance / s;
    a[M.nq + j] = a[j] * M.omega[j];
  }
  std::fill(a.begin() + M.e_index(), a.end(), M.settings.tread_tolerance_m);
  a[M.z_index() + 1] = kDisplacementTolerance * 100;
  return a;
}

}  // namespace modaltyre::transient
