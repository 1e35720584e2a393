#include "modaltyre/transient/ode_system.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/transient/column_product.h"
#include "modaltyre/transient/soil_contact.h"

namespace modaltyre::transient {
namespace {

/// Absolute tolerance of displacement-like states [m] (0.1 um, ~1e-5 of a sinking).
constexpr double kDisplacementTolerance = 1e-7;
/// Offset of the contact root functions [m]: a switch is located where the tip penetration
/// crosses this, 1e4 times the rounding noise of g (~1e-16 m) and 1e5 times below
/// kDisplacementTolerance. A unit grazing the road with zero force (g = 0 to rounding, e.g. the
/// centre of a ladder-like static patch) otherwise makes CVODE return a root at every rounding
/// flip of g without advancing in time. The kink of f = k max(0, g) is located to eta / |g'|.
constexpr double kRootOffset_m = 1e-12;

/// Movement of the state (|dz| + max|T_i| |d xi|) after which update_contact_set() recomputes the
/// reach reference over the whole window: 0.1 mm widens the reach by a unit or two at each end
/// of the default patch (the gap grows by ~0.06 mm per 0.5 mm unit there).
constexpr double kReachRefresh_m = 1e-4;

}  // namespace

ModalRow modal_row(const TransientModel& M, int j, double Omega, double dOmega) {
  ModalRow d;
  const double w = M.omega[j], ze = M.zeta[j];
  d.dq = -w * w;
  d.dv = -2 * ze * w;
  if (M.partner[j] >= 0 && Omega != 0) {
    // Ground-frame pair (docs/transient.md section 1): b = k Omega, a = k Omega'.
    const double b = M.order[j] * Omega, al = M.order[j] * dOmega, s = M.pair_sign[j];
    d.dq += b * b;
    d.dq_p = s * (2 * ze * w * b + al);
    d.dv_p = s * 2 * b;
  }
  return d;
}

TransientSystem::TransientSystem(const TransientModel& model, const ScenarioPlan& plan,
                                 UnitRange units)
    : model_(model), plan_(plan), units_(units.size() > 0 ? units : UnitRange{0, model.m - 1}) {
  MODALTYRE_CHECK(units_.lo >= 0 && units_.hi < model.m, "TransientSystem: units out of range");
  const int lo = units_.lo, hi = units_.hi, n = units_.size(), m = model.m;
  ne_ = model.settings.relaxation ? n : 0;
  has_outside_ = n < m;
  if (model.rank > 0) {
    basis_row_norm_max_ = model.T.middleRows(lo, n).rowwise().norm().maxCoeff();
    if (lo > 0) out_row_norm_max_ = model.T.topRows(lo).rowwise().norm().maxCoeff();
    if (hi + 1 < m)
      out_row_norm_max_ =
          std::max(out_row_norm_max_, model.T.bottomRows(m - 1 - hi).rowwise().norm().maxCoeff());
  }
  if (model.settings.relaxation) {
    inv_c_kv_ = model.c_kv.segment(lo, n).cwiseInverse();
    k_over_c_kv_ = model.k_kv.segment(lo, n).cwiseProduct(inv_c_kv_);
  }
  model.tyre.sag.minCoeff(&centre_);
  CqT_ = model.Cq.transpose();
  CrT_ = model.Cr.transpose();
}

double TransientSystem::spin(double t) const { return plan_.spin(t); }

double TransientSystem::spin_rate(double t) const { return plan_.spin_rate(t); }

void TransientSystem::contact_coordinates(const double* y) const {
  const auto& M = model_;
  const Eigen::Map<const Eigen::VectorXd> q(y, M.nq), r(y + 2 * M.nq, M.nr);
  scratch_xi_.resize(M.rank);
  // Cq q as rank dot products of Cq's rows (contiguous in Cq^T) with q: few long sums instead of
  // many short ones (column_product.h).
  column_dots(CqT_, q, scratch_xi_);
  if (M.nr > 0) column_dots(CrT_, r, scratch_xi_, 1.0, /*accumulate=*/true);
}

void TransientSystem::check_outside(double t, const double* y) const {
  const auto& M = model_;
  const double z = hub_z(t, y);
  const double H = plan_.road_height_bound();
  double p_max = -std::numeric_limits<double>::infinity();
  bool touches = false;
  auto scan = [&](int from, int to) {
    for (int i = from; i <= to; ++i) {
      const double p = z - M.tyre.sag(i) - M.T_by_unit.col(i).dot(scratch_xi_);
      if (p > p_max || std::isnan(p)) p_max = p;
      // Without a tread state the tip is the surface: e = 0 ahead of the patch, and behind it
      // advected e >= 0 only lowers g (so p > 0 is the conservative test).
      if (p + H > 0 && p + road(t, i) > 0) touches = true;
    }
  };
  scan(0, units_.lo - 1);
  scan(units_.hi + 1, M.m - 1);
  p_out_ref_ = p_max;
  xi_out_ref_ = scratch_xi_;
  z_out_ref_ = z;
  if (touches) escaped_ = true;
}

void TransientSystem::reach(double t, const double* y, int& lo, int& hi) const {
  const auto& M = model_;
  const double H = plan_.road_height_bound();
  if (has_outside_) {
    // Units outside units_: p_i <= p_out_ref + (z - z_out_ref) + max|T_i| |xi - xi_out_ref| + h
    // as below; only when this bound does not exclude them is their penetration computed.
    const double bound = xi_out_ref_.size() == 0
                             ? std::numeric_limits<double>::infinity()
                             : p_out_ref_ + (hub_z(t, y) - z_out_ref_) +
                                   out_row_norm_max_ * (scratch_xi_ - xi_out_ref_).norm() + H;
    if (!(bound <= 0)) check_outside(t, y);
  }
  // g_i = z + h_i - s_i - T_i xi - e_i <= z + max h - s_i + max_i |T_i| |xi| - min(0, min e)
  // (Cauchy-Schwarz on the contact basis; xi from contact_coordinates()).
  double lift = H;
  if (ne_ > 0)
    lift -= std::min(0.0, Eigen::Map<const Eigen::VectorXd>(y + M.e_index(), ne_).minCoeff());
  const int u0 = units_.lo, u1 = units_.hi;
  if (p_ref_.size() == units_.size()) {
    // Against the penetration p_ref = z_ref - s - T xi_ref of an accepted state:
    // g_i <= p_ref_i + (z - z_ref) + max |T_i| |xi - xi_ref| + max h - min(0, min e), a band
    // a few units wider than the patch where the bound from rest spans twice as many units.
    const double delta =
        hub_z(t, y) - z_ref_ + basis_row_norm_max_ * (scratch_xi_ - xi_ref_).norm() + lift;
    lo = u0, hi = u1;
    if (!std::isfinite(delta)) return;
    int a = u0, b = u1;  // locals: the loops then keep them in registers
    const double* p = p_ref_.data();
    while (a <= b && !(p[a - u0] + delta > 0)) ++a;
    while (b >= a && !(p[b - u0] + delta > 0)) --b;
    lo = a, hi = b;
    return;
  }
  // Before an accepted state: the sag grows on both sides of centre_, so the units with
  // sag < bound form a range (NaN bound: every unit).
  const double bound = hub_z(t, y) + basis_row_norm_max_ * scratch_xi_.norm() + lift;
  const Eigen::VectorXd& sag = M.tyre.sag;
  lo = u0, hi = u1;
  if (std::isnan(bound)) return;
  while (lo <= hi && !(sag(lo) < bound)) ++lo;
  while (hi >= lo && !(sag(hi) < bound)) --hi;
}

void TransientSystem::add_road(double t, int lo, int hi, Eigen::VectorXd& g) const {
  if (plan_.road_profile) {
    for (int i = lo; i <= hi; ++i) g(i) += road(t, i);
    return;
  }
  if (!plan_.cleat) return;
  // The cleat covers |x - centre| < L/2 only: its units by bisection of the increasing x_i.
  const double centre = plan_.cleat_start_m - plan_.distance(t), half = 0.5 * plan_.cleat_length_m;
  const double* x = model_.x_road.data();
  const int from = std::max<int>(lo, std::lower_bound(x, x + model_.m, centre - half) - x);
  const int to = std::min<int>(hi, std::upper_bound(x, x + model_.m, centre + half) - x - 1);
  for (int i = from; i <= to; ++i) g(i) += road(t, i);
}

void TransientSystem::tip_penetration_in_reach(double t, const double* y,
                                               Eigen::VectorXd& g) const {
  int lo = 0, hi = -1;
  g.setConstant(model_.m, -1.0);
  penetration_band(t, y, g, lo, hi);
}

void TransientSystem::penetration_band(double t, const double* y, Eigen::VectorXd& g, int& lo,
                                       int& hi, bool xi_ready, bool forces) const {
  const auto& M = model_;
  if (forces && soil_) {
    // On a soil: the penetrations, then the unit's spring in series with the soil (phi_i).
    penetration_band(t, y, g, lo, hi, xi_ready, /*forces=*/false);
    if (hi >= lo) soil_->forces(t, lo, hi - lo + 1, g.data() + lo);
    return;
  }
  if (!xi_ready) contact_coordinates(y);
  lo = 0, hi = -1;
  reach(t, y, lo, hi);
  if (hi < lo) return;
  const int n = hi - lo + 1;
  // u = T xi (model.h's contact basis: rank columns instead of nq + nr).
  auto seg = g.segment(lo, n);
  column_product(M.T.middleRows(lo, n), scratch_xi_, seg);
  const double z = hub_z(t, y);
  const double* sag = M.tyre.sag.data() + lo;
  double* u = seg.data();
  if (plan_.has_road()) {
    for (int k = 0; k < n; ++k) u[k] = (z - sag[k]) - u[k];
    add_road(t, lo, hi, g);
    if (ne_ > 0) seg -= Eigen::Map<const Eigen::VectorXd>(y + M.e_index() + (lo - units_.lo), n);
  } else if (ne_ > 0) {
    // One pass: ((z - s) - u) - e, the order of the passes above (and with `forces` the force
    // k max(0, g) in the same pass).
    const double* e = y + M.e_index() + (lo - units_.lo);
    if (forces) {
      const double* kc = M.k_contact.data() + lo;
      for (int k = 0; k < n; ++k) {
        const double gk = ((z - sag[k]) - u[k]) - e[k];
        u[k] = gk > 0 ? kc[k] * gk : 0.0;
      }
      return;
    }
    for (int k = 0; k < n; ++k) u[k] = ((z - sag[k]) - u[k]) - e[k];
  } else {
    for (int k = 0; k < n; ++k) u[k] = (z - sag[k]) - u[k];
  }
  if (forces) seg = (seg.array() > 0).select(M.k_contact.segment(lo, n).array() * seg.array(), 0.0);
}

double TransientSystem::tip_penetration_at(double t, const double* y, int i, bool xi_of_y) const {
  const auto& M = model_;
  if (!xi_of_y) contact_coordinates(y);
  double g = hub_z(t, y) + road(t, i) - M.tyre.sag(i) - M.T_by_unit.col(i).dot(scratch_xi_);
  if (ne_ > 0 && units_.contains(i)) g -= y[M.e_index() + (i - units_.lo)];
  return g;
}

double TransientSystem::road(double t, int i, double* slope) const {
  if (slope) *slope = 0;
  if (plan_.road_profile) return plan_.road_profile(t, model_.x_road(i), slope);
  if (!plan_.cleat) return 0;
  const double L = plan_.cleat_length_m, H = plan_.cleat_height_m;
  const double xi = model_.x_road(i) - (plan_.cleat_start_m - plan_.distance(t));
  const double a = 0.25 * L;  // cosine edges, a quarter of the length each
  const double ax = std::abs(xi);
  if (ax >= 0.5 * L) return 0;
  if (ax <= 0.5 * L - a) return H;
  const double u = M_PI * (ax - (0.5 * L - a)) / a;
  if (slope) *slope = -0.5 * H * std::sin(u) * M_PI / a * (xi > 0 ? 1.0 : -1.0);
  return 0.5 * H * (1 + std::cos(u));
}

void TransientSystem::tip_penetration(double t, const double* y, Eigen::VectorXd& g) const {
  const auto& M = model_;
  const double z = hub_z(t, y);
  contact_coordinates(y);
  // g = z + h - s - u (- e), u = T xi.
  g.noalias() = -(M.T * scratch_xi_);
  g.array() += z;
  g -= M.tyre.sag;
  add_road(t, 0, M.m - 1, g);
  if (ne_ > 0) g.segment(units_.lo, ne_) -= Eigen::Map<const Eigen::VectorXd>(y + M.e_index(), ne_);
}

void TransientSystem::forces_into(double t, const double* y, Eigen::VectorXd& f) const {
  int lo = 0, hi = -1;
  forces_band(t, y, f, lo, hi);
}

void TransientSystem::forces_band(double t, const double* y, Eigen::VectorXd& f, int& lo,
                                  int& hi) const {
  // f = 0 outside the reach [lo, hi] (g < 0 there for certain), k max(0, g) inside. Nothing
  // writes f outside units_, so only that range is cleared when f is reused.
  if (f.size() != model_.m)
    f.setZero(model_.m);
  else
    f.segment(units_.lo, units_.size()).setZero();
  penetration_band(t, y, f, lo, hi, /*xi_ready=*/false, /*forces=*/true);
}

bool TransientSystem::accepted_forces(double t, Eigen::VectorXd& f) const {
  if (t != accepted_t_) return false;
  const auto& M = model_;
  if (f.size() != M.m)
    f.setZero(M.m);
  else
    f.segment(units_.lo, units_.size()).setZero();
  const int lo = accepted_lo_, n = accepted_hi_ - accepted_lo_ + 1;
  if (n <= 0) return true;
  if (soil_) {
    f.segment(lo, n) = scratch_f_.segment(lo, n);
  } else {  // k max(0, g), as penetration_band() with forces
    const auto g = scratch_g_.segment(lo, n).array();
    f.segment(lo, n) = (g > 0).select(M.k_contact.segment(lo, n).array() * g, 0.0);
  }
  return true;
}

Eigen::VectorXd TransientSystem::forces(double t, const double* y) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model_.m);
  forces_into(t, y, f);
  return f;
}

void TransientSystem::roots(double t, const double* y, double* g) const {
  Eigen::Map<Eigen::VectorXd> gm(g, model_.m);
  scratch_g_.resize(model_.m);
  tip_penetration(t, y, scratch_g_);
  scratch_g_.array() -= kRootOffset_m;
  // CVODE treats an exact 0 as a root; when its root finder lands on one, the function is still
  // 0.0 a rounding step later, which cvRcheck2 rejects as "root found at and very near t"
  // (CV_ILL_INPUT). An exact 0 is reported as just below (the side of no force).
  gm = (scratch_g_.array() == 0.0).select(-std::numeric_limits<double>::min(), scratch_g_);
}

int TransientSystem::update_contact_set(double t, const double* y) const {
  // The penetration p = z - s - T xi over the whole window at an accepted state is the reach
  // reference of the evaluations that follow (reach(): a bound of g from it). Any accepted state
  // gives a valid bound; refreshing it only when the state has moved by kReachRefresh_m in the
  // bound's measure saves the m x rank product at most steps (it was 9 % of a free vibration).
  // The contact set is the sign of g over the reach (g < 0 outside for certain).
  const auto& M = model_;
  if (soil_) {
    // The soil remembers the depths of this accepted state (soil_contact.h).
    int a = 0, b = -1;
    forces_band(t, y, scratch_f_, a, b);
    soil_->accept(t, a, b);
    accepted_lo_ = a, accepted_hi_ = b;
  }
  contact_coordinates(y);
  const bool refresh =
      p_ref_.size() != units_.size() ||
      !(std::abs(hub_z(t, y) - z_ref_) + basis_row_norm_max_ * (scratch_xi_ - xi_ref_).norm() <
        kReachRefresh_m);
  const int u0 = units_.lo, nu = units_.size();
  if (refresh) {
    p_ref_.resize(nu);
    column_product(M.T.middleRows(u0, nu), scratch_xi_, p_ref_);
    p_ref_ = (hub_z(t, y) - M.tyre.sag.segment(u0, nu).array() - p_ref_.array()).matrix();
    xi_ref_ = scratch_xi_;
    z_ref_ = hub_z(t, y);
  }
  int lo = 0, hi = -1;
  scratch_g_.resize(M.m);
  if (refresh) {
    // The reference is this state: g = p_ref + h - e over the reach, without a second product.
    reach(t, y, lo, hi);
    if (hi >= lo) {
      const int n = hi - lo + 1;
      scratch_g_.segment(lo, n) = p_ref_.segment(lo - u0, n);
      add_road(t, lo, hi, scratch_g_);
      if (ne_ > 0)
        scratch_g_.segment(lo, n) -=
            Eigen::Map<const Eigen::VectorXd>(y + M.e_index() + (lo - u0), n);
    }
  } else {
    penetration_band(t, y, scratch_g_, lo, hi, /*xi_ready=*/true);  // xi of y from above
  }
  if (!soil_) accepted_lo_ = lo, accepted_hi_ = hi;
  accepted_t_ = t;
  const bool first = in_contact_.size() == 0;
  if (first) in_contact_.setZero(M.m);
  // Units that can have changed: the reach now and the contact set before.
  const int from = std::min(lo, contact_first_), to = std::max(hi, contact_last_);
  const int a = std::max(from, u0), b = std::min(to, units_.hi);
  const int r0 = std::max(a, lo), r1 = std::min(b, hi);  // [a, b] within the reach
  // Whole-segment passes on in_contact_ (0.0 or 1.0): the units of [a, b] outside the reach
  // are out of contact now, those in it in contact where g > 0; the switches are the count of
  // changed entries.
  double changed_units = 0;
  auto leave = [&](int i0, int i1) {
    if (i1 < i0) return;
    changed_units += in_contact_.segment(i0, i1 - i0 + 1).sum();
    in_contact_.segment(i0, i1 - i0 + 1) = 0.0;
  };
  contact_first_ = M.m, contact_last_ = -1;
  if (r1 < r0) {
    leave(a, b);
  } else {
    leave(a, r0 - 1);
    leave(r1 + 1, b);
    const int n = r1 - r0 + 1;
    auto old = in_contact_.segment(r0, n);
    const auto now = (scratch_g_.segment(r0, n).array() > 0).select(1.0, Eigen::ArrayXd::Zero(n));
    changed_units += (now - old).abs().sum();
    old = now;
    int i = r0;
    while (i <= r1 && in_contact_(i) == 0) ++i;
    if (i <= r1) {
      contact_first_ = i;
      contact_last_ = r1;
      while (in_contact_(contact_last_) == 0) --contact_last_;
    }
  }
  const int changed = static_cast<int>(changed_units);
  if (first) return 0;
  if (changed > 0) contact_switched();
  return changed;
}

void TransientSystem::rhs(double t, const double* y, double* ydot) const {
  const auto& M = model_;
  const int nq = M.nq, nr = M.nr;
  Eigen::VectorXd& f = scratch_f_;
  Eigen::VectorXd& G = scratch_G_;
  int lo = 0, hi = -1;
  forces_band(t, y, f, lo, hi);
  // G = psi^T f = Cq^T phi and Vf = V^T f = Cr^T phi with phi = T^T f over the reach only
  // (f = 0 elsewhere; about the patch).
  Eigen::VectorXd& phi = scratch_phi_;
  phi.setZero(M.rank);
  double load = 0;
  if (hi >= lo) {
    const int n = hi - lo + 1;
    // Dot products of the contact basis' columns with f (13 x n with n contiguous per column).
    column_dots(M.T.middleRows(lo, n), f.segment(lo, n), phi);  // T^T f (column_product.h)
    load = f.segment(lo, n).sum();
  }
  G.resize(nq);
  column_product(CqT_, phi, G);  // Cq^T phi (Cq^T stored: a product over its nq rows)
  Eigen::VectorXd& Vf = scratch_Vf_;
  if (nr > 0) {
    Vf.resize(nr);
    column_product(CrT_, phi, Vf);
  }
  const double Omega = spin(t), dOmega = spin_rate(t);
  // The modal rows depend on the spin only: kept while it does not change (at rest, on a hold
  // or at a steady speed).
  if (modal_rows_.size() != static_cast<std::size_t>(nq) || Omega != rows_Omega_ ||
      dOmega != rows_dOmega_) {
    modal_rows_.resize(nq);
    for (int j = 0; j < nq; ++j) modal_rows_[j] = modal_row(M, j, Omega, dOmega);
    rows_Omega_ = Omega, rows_dOmega_ = dOmega;
  }
  for (int j = 0; j < nq; ++j) {
    const ModalRow& d = modal_rows_[j];
    const int p = std::max(M.partner[j], 0);  // d.dq_p = d.dv_p = 0 without a partner
    ydot[j] = y[nq + j];
    ydot[nq + j] = G(j) + d.dq * y[j] + d.dv * y[nq + j] + d.dq_p * y[p] + d.dv_p * y[nq + p];
  }
  if (nr > 0) {
    for (int l = 0; l < nr; ++l)
      ydot[2 * nq + l] = (M.lambda(l) * Vf(l) - y[2 * nq + l]) / M.tau_residual_s;
  }
  const int Z = M.z_index();
  plan_.hub_rates(t, y + Z, load, M.settings.hub_mass_kg, ydot + Z);
  if (M.settings.relaxation) {
    const int E = M.e_index();
    const double adv = Omega / M.tyre.dtheta_rad;
    // de/dtheta by the second-order one-sided (upwind) difference from the front, e = 0
    // entering: (-3 e_i + 4 e_{i+1} - e_{i+2}) / (2 dtheta).
    // c' e' = f - k' e, as whole-vector operations (one pass each, no division).
    // Over units_ only: ahead of it e = 0 enters (no unit there ever touches).
    const int n = ne_;
    const Eigen::Map<const Eigen::VectorXd> e(y + E, n);
    Eigen::Map<Eigen::VectorXd> de(ydot + E, n);
    de = f.segment(units_.lo, n).cwiseProduct(inv_c_kv_) - e.cwiseProduct(k_over_c_kv_);
    if (adv != 0) {
      de += kUpwind[0] * adv * e;
      if (n > 1) de.head(n - 1) += kUpwind[1] * adv * e.tail(n - 1);
      if (n > 2) de.head(n - 2) += kUpwind[2] * adv * e.tail(n - 2);
    }
  }
}

std::vector<double> TransientSystem::absolute_tolerances() const {
  const auto& M = model_;
  std::vector<double> a(size(), kDisplacementTolerance);
  for (int j = 0; j < M.nq; ++j) {
    const double s = std::max(M.psi.col(j).cwiseAbs().maxCoeff(), 1e-300);
    a[j] = kDisplacementTolerance / s;
    a[M.nq + j] = a[j] * M.omega[j];
  }
  // Tread states (relaxation on): their own tolerance (TransientSettings::tread_tolerance_m).
  std::fill(a.begin() + M.e_index(), a.begin() + M.e_index() + ne_, M.settings.tread_tolerance_m);
  // Hub velocity: displacement tolerance over a 10 ms time scale.
  a[M.z_index() + 1] = kDisplacementTolerance * 100;
  return a;
}

std::vector<double> TransientSystem::static_state(double load_N) const {
  return state_from(static_contact(model_, load_N));
}

std::vector<double> TransientSystem::state_from(const StaticContact& c) const {
  const auto& M = model_;
  std::vector<double> y(size(), 0.0);
  if (!(c.sinking_m != 0 || c.f.any())) return y;
  const Eigen::VectorXd& f = c.f;
  for (int i = 0; i < M.m; ++i)
    if (f(i) > 0 && !units_.contains(i)) escaped_ = true;
  const StaticCarcass s = static_carcass(M, f);
  for (int j = 0; j < M.nq; ++j) y[j] = s.q(j);
  for (int l = 0; l < M.nr; ++l) y[2 * M.nq + l] = s.r(l);
  y[M.z_index()] = c.sinking_m;
  // The tread state that gives each unit its static force through the contact spring at the
  // model's own penetration (e = p - f / k_g; cell_system.cc's state_from() says why).
  if (ne_ > 0) contact_coordinates(y.data());
  for (int k = 0; k < ne_; ++k) {
    const int i = units_.lo + k;
    double p = c.sinking_m - M.tyre.sag(i) - M.T_by_unit.col(i).dot(scratch_xi_) + road(0.0, i);
    if (c.soil_depth_m.size() == M.m) p -= c.soil_depth_m(i);  // on a soil: above its surface
    y[M.e_index() + k] = f(i) > 0 ? p - f(i) / M.k_contact(i) : std::max(0.0, p);
  }
  return y;
}

double TransientSystem::energy(double t, const double* y) const {
  const auto& M = model_;
  double e = 0;
  for (int j = 0; j < M.nq; ++j)
    e += 0.5 * (y[M.nq + j] * y[M.nq + j] + M.omega[j] * M.omega[j] * y[j] * y[j]);
  const double w = y[M.z_index() + 1];
  e += 0.5 * M.settings.hub_mass_kg * w * w;
  const Eigen::VectorXd f = forces(t, y);
  for (int i = 0; i < M.m; ++i) e += 0.5 * f(i) * f(i) / M.k_contact(i);
  return e;
}

}  // namespace modaltyre::transient
