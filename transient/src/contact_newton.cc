#include "modaltyre/transient/contact_newton.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/transient/column_product.h"
#include "row_lu_solve.h"

namespace modaltyre::transient {

ContactNewton::ContactNewton(const TransientModel& model, const TransientSystem& system)
    : M_(model), sys_(system) {
  nx_ = model.e_index();
  ne_ = system.tread_states();  // tread states of the units system.units(), first unit u0_
  u0_ = system.units().lo;
  np_ = model.rank + 1;
  const int nq = model.nq;
  for (int j = 0; j < nq; ++j) {
    const int p = model.partner[j];
    if (p >= 0 && p < j) continue;  // the pair's block is the first member's
    Block b;
    if (p < 0) {
      b.n = 2;
      b.idx[0] = j, b.idx[1] = nq + j;
    } else {
      b.n = 4;
      b.idx[0] = j, b.idx[1] = p, b.idx[2] = nq + j, b.idx[3] = nq + p;
    }
    blocks_.push_back(b);
  }
  CqT_ = model.Cq.transpose();
  CrT_ = model.Cr.transpose();
  eta_.resize(np_);
  eta0_.resize(np_);
  phi_.resize(np_);
  w_.resize(np_);
  work_x_.resize(nx_);
  work_e_.resize(ne_);
}

void ContactNewton::set_active_span(int first, int last) {
  active_.clear();
  for (int i = first; first >= 0 && i <= last; ++i) active_.push_back(i);
  Tt_active_.resize(static_cast<Eigen::Index>(active_.size()), np_);
  // d g / d z: 1, or 0 under a prescribed hub (z an input, scenario.h).
  const double hub = sys_.plan().hub_free() ? 1.0 : 0.0;
  for (std::size_t a = 0; a < active_.size(); ++a) {
    Tt_active_.row(a).head(M_.rank) = -M_.T.row(active_[a]);
    Tt_active_(a, M_.rank) = hub;
  }
}

double ContactNewton::ee_diagonal(int i, double kd) const {
  const double adv = Omega_ / M_.tyre.dtheta_rad;
  return 1.0 - gamma_ * (kUpwind[0] * adv - (kd + M_.k_kv(i)) / M_.c_kv(i));
}

double ContactNewton::rest_weight(int i, double kd, double d) const {
  return kd * (1.0 - gamma_ * (kd / M_.c_kv(i) / d));
}

bool ContactNewton::setup(double t, const double* y, double gamma, bool jacobian_ok) {
  if (!jacobian_ok || !jacobian_ready_) {
    sys_.jacobian_stiffness(t, y, kd_);
    // The active units: the span from the first to the last unit with a spring (a unit of a
    // gap in it has kd = 0 and adds nothing), so that their tread states are contiguous.
    int first = -1, last = -1;
    for (int i = sys_.units().lo; i <= sys_.units().hi; ++i)
      if (kd_(i) > 0) last = i, first = first < 0 ? i : first;
    set_active_span(first, last);
    kd_active_ = first >= 0 ? kd_.segment(first, last - first + 1) : Eigen::VectorXd();
    Omega_ = sys_.spin(t);
    dOmega_ = sys_.spin_rate(t);
    jacobian_ready_ = true;
  }
  factor(gamma);
  const Eigen::MatrixXd& lu = cap_.matrixLU();
  return lu.allFinite() && (lu.diagonal().array() != 0).all() && ee_d_.allFinite() &&
         (ee_d_.array() != 0).all();
}

void ContactNewton::factor(double gamma) {
  const auto& M = M_;
  const int nq = M.nq, nr = M.nr, Z = M.z_index(), rank = M.rank;
  gamma_ = gamma;
  // D = I - gamma A, block by block (A: q' = v and the modal rows).
  for (Block& b : blocks_) {
    Eigen::Matrix4d d = Eigen::Matrix4d::Identity();
    const int h = b.n / 2;  // q entries first, then v
    for (int a = 0; a < h; ++a) {
      d(a, h + a) = -gamma;  // q' = v
      const ModalRow r = modal_row(M, b.idx[a], Omega_, dOmega_);
      const int o = h == 2 ? 1 - a : a;  // the partner's local index (itself without one)
      d(h + a, a) -= gamma * r.dq;
      d(h + a, h + a) -= gamma * r.dv;
      if (h == 2) {
        d(h + a, o) -= gamma * r.dq_p;
        d(h + a, h + o) -= gamma * r.dv_p;
      }
    }
    b.inv = d.inverse();
  }
  d_r_inv_ = nr > 0 ? 1.0 / (1.0 + gamma / M.tau_residual_s) : 1.0;
  const bool hub_free = sys_.plan().hub_free();
  d_zw_ = hub_free ? gamma : 0.0;  // a prescribed hub: z' = w' = 0, D = I on (z, w)
  // M_EE and Y = M_EE^-1 diag(kd / c') T~ over the active range (zero beyond its last unit);
  // Ty_ = diag(kd) (T~ - gamma Y) on the active rows.
  const int na = static_cast<int>(active_.size());
  Ty_.resize(na, np_);
  bool at_rest = true;  // M_EE diagonal (no advection band): Y row by row, no back substitution
  if (ne_ > 0) {
    const double adv = Omega_ / M.tyre.dtheta_rad;
    ee_s1_ = -gamma * kUpwind[1] * adv;
    ee_s2_ = -gamma * kUpwind[2] * adv;
    at_rest = ee_s1_ == 0 && ee_s2_ == 0;
    ee_d_.resize(ne_);
    for (int k = 0; k < ne_; ++k) ee_d_(k) = ee_diagonal(u0_ + k, kd_(u0_ + k));
    ee_d_inv_ = ee_d_.cwiseInverse();
  } else {
    ee_d_.resize(0);
    ee_d_inv_.resize(0);
  }
  if (ne_ > 0 && na > 0 && !at_rest) {
    // Back substitution up the band, a row per unit (row-major: rows contiguous).
    const int lo = active_.front(), hi = active_.back();
    Y_.setZero(hi - lo + 1, np_);
    for (int a = na - 1, i = hi; i >= lo; --i) {
      const int k = i - lo;
      if (a >= 0 && active_[a] == i) Y_.row(k) = kd_(i) / M.c_kv(i) * Tt_active_.row(a--);
      if (k + 1 < Y_.rows()) Y_.row(k) -= ee_s1_ * Y_.row(k + 1);
      if (k + 2 < Y_.rows()) Y_.row(k) -= ee_s2_ * Y_.row(k + 2);
      Y_.row(k) /= ee_d_(i - u0_);
    }
    for (int a = 0; a < na; ++a)
      Ty_.row(a) = (Tt_active_.row(a) - gamma * Y_.row(active_[a] - lo)) * kd_(active_[a]);
  } else if (ne_ > 0 && na > 0) {
    // At rest M_EE is diagonal and Y_a = (kd_a / c'_a) T~_a / d_a, so diag(kd)(T~ - gamma Y) =
    // diag(w) T~ with w_a = kd_a (1 - gamma (kd_a / c'_a) / d_a) = kd_a (1 + gamma k'_a / c'_a)
    // / (1 + gamma (kd_a + k'_a) / c'_a): the contact spring in series with the tread's
    // Kelvin-Voigt element at the step's time scale gamma. K = T~^T diag(w) T~ is symmetric:
    // its upper triangle only, each coefficient a dot product of two contiguous columns.
    work_s_.resize(na);
    for (int a = 0; a < na; ++a) {
      const int i = active_[a];
      work_s_(a) = rest_weight(i, kd_(i), ee_d_(i - u0_));
    }
    for (int j = 0; j < np_; ++j) Ty_.col(j) = Tt_active_.col(j).cwiseProduct(work_s_);
    K_.resize(np_, np_);
    for (int j = 0; j < np_; ++j) {
      column_dots(Tt_active_.leftCols(j + 1), Ty_.col(j), K_.col(j));  // K_ij, i <= j
      for (int i = 0; i < j; ++i) K_(j, i) = K_(i, j);
    }
  } else {
    for (int a = 0; a < na; ++a) Ty_.row(a) = Tt_active_.row(a) * kd_(active_[a]);
  }
  if (at_rest && ne_ > 0 && na > 0) {
    // K from the symmetric update above.
  } else if (na > 0) {
    // K = T~^T Ty_, coefficient-based (Eigen's GEMM would start OpenMP threads for a product
    // this small; the library is built with OpenMP for sweeps).
    K_.noalias() = Tt_active_.transpose().lazyProduct(Ty_);
  } else {
    K_.setZero(np_, np_);
  }
  // D^-1 Q, column k the response of X to a unit force on eta_k: the force on xi_k enters the
  // v rows as -Cq^T e_k (the r rows as -(lambda / tau) Cr^T e_k), and D^-1 maps it through its
  // blocks (the (q, v) and (v, v) entries of each block inverse); the unit force on z (the hub)
  // enters w as -1 / m_hub, and z as gamma times that. Then H = P D^-1 Q (np x np) and the
  // capacitance I - gamma H K of Woodbury's identity.
  DQ_.setZero(nx_, np_);
  for (const Block& b : blocks_) {
    const int h = b.n / 2;
    for (int r = 0; r < b.n; ++r)
      for (int c = 0; c < h; ++c)
        DQ_.row(b.idx[r]).head(rank) -= b.inv(r, h + c) * M.Cq.col(b.idx[c]).transpose();
  }
  for (int l = 0; l < nr; ++l)
    DQ_.row(2 * nq + l).head(rank) =
        -(d_r_inv_ * M.lambda(l) / M.tau_residual_s) * M.Cr.col(l).transpose();
  DQ_(Z + 1, rank) = hub_free ? -1.0 / M.settings.hub_mass_kg : 0.0;
  DQ_(Z, rank) = d_zw_ * DQ_(Z + 1, rank);
  Eigen::MatrixXd& H = H_;
  H.setZero(np_, np_);
  for (int k = 0; k < np_; ++k) {
    column_product(M.Cq, DQ_.col(k).head(nq), H.col(k));  // first rank rows
    if (nr > 0) column_product(M.Cr, DQ_.col(k).segment(2 * nq, nr), H.col(k), true);
  }
  H.row(rank) = DQ_.row(Z);
  // gamma kd / c' of the active units, for M_EX in solve() (no division per solve).
  gamma_kd_c_.resize(ne_ > 0 ? na : 0);
  for (int a = 0; a < gamma_kd_c_.size(); ++a)
    gamma_kd_c_(a) = gamma * kd_(active_[a]) / M.c_kv(active_[a]);
  Eigen::MatrixXd& cap = cap_mat_;
  cap = Eigen::MatrixXd::Identity(np_, np_);
  for (int k = 0; k < np_; ++k) {
    work_x_.head(np_) = -gamma * K_.col(k);
    column_product(H, work_x_.head(np_), cap.col(k), /*accumulate=*/true);  // cap -= gamma H K
  }
  cap_.compute(cap);
  cap_lu_ = cap_.matrixLU();  // row-major: the triangular solves run along rows
  cap_perm_ = cap_.permutationP().indices();
}

bool ContactNewton::lu_cap() { return row_lu_factor(cap_mat_, cap_lu_, cap_perm_, rowperm_); }

void ContactNewton::update_active_set() {
  // As CellNewton's (cell_newton_update.cc): CVODE's modified Newton keeps the matrix of the
  // last setup, whose contact stiffness is that of the setup's state; a unit that crossed the
  // kink of k max(0, g) since converges linearly (or makes Newton fail) until the next setup.
  // At rest the change is exact: each unit enters K through its weight w_i = kd_i (1 - gamma
  // kd_i / c'_i / d_i) (factor()), so K changes by dw_i T~_i^T T~_i and the capacitance matrix
  // by (-gamma H T~_i^T) dw_i T~_i. Only at rest (no spin): rolling, a unit's stiffness also
  // reaches the units in front of it through Y, and the 3D patch's inexact update (the unit's
  // own diagonal term) measured worse here (rolling at 60 km/h: 197 -> 255 Newton iterations,
  // 23 -> 38 setups). Off on a soil (its kinks inside the contact, cell_newton_update.cc).
  if (sys_.soil() || !(ee_s1_ == 0 && ee_s2_ == 0)) return;
  const Eigen::VectorXd& f = sys_.last_forces();
  const auto& M = M_;
  const int u0 = sys_.units().lo, u1 = sys_.units().hi;
  if (f.size() != M.m || kd_.size() != M.m) return;
  dw_.clear();
  const double gamma = gamma_;
  for (int i = u0; i <= u1; ++i) {
    const bool on = f(i) > 0;
    if (on == (kd_(i) > 0)) continue;
    const double kd_new = on ? M.k_contact(i) : 0.0;
    if (ne_ > 0) {
      const int k = i - u0_;
      const double w_old = rest_weight(i, kd_(i), ee_d_(k));
      ee_d_(k) = ee_diagonal(i, kd_new);
      ee_d_inv_(k) = 1.0 / ee_d_(k);
      dw_.emplace_back(i, rest_weight(i, kd_new, ee_d_(k)) - w_old);
    } else {
      dw_.emplace_back(i, kd_new - kd_(i));
    }
    kd_(i) = kd_new;
  }
  if (dw_.empty()) return;
  // The active span (solve() reads kd, gamma kd / c' and T~ over it) grows to the new units.
  int first = active_.empty() ? M.m : active_.front(), last = active_.empty() ? -1 : active_.back();
  for (const auto& [i, dw] : dw_)
    if (kd_(i) > 0) first = std::min(first, i), last = std::max(last, i);
  if (last >= first && (active_.empty() || first != active_.front() || last != active_.back()))
    set_active_span(first, last);
  const int na = static_cast<int>(active_.size());
  if (na > 0) {
    kd_active_ = kd_.segment(active_.front(), na);
    gamma_kd_c_.resize(ne_ > 0 ? na : 0);
    for (int a = 0; a < gamma_kd_c_.size(); ++a)
      gamma_kd_c_(a) = gamma * kd_(active_[a]) / M.c_kv(active_[a]);
  }
  t_col_.resize(np_);
  const double hub = sys_.plan().hub_free() ? 1.0 : 0.0;
  for (const auto& [i, dw] : dw_) {
    if (dw == 0) continue;
    t_col_.head(M.rank) = -M.T.row(i).transpose();
    t_col_(M.rank) = hub;
    K_.noalias() += dw * t_col_ * t_col_.transpose();
    ht_col_.noalias() = (-gamma * dw) * (H_ * t_col_);
    cap_mat_.noalias() += ht_col_ * t_col_.transpose();
  }
  if (!lu_cap()) factor(gamma);  // the whole factorisation at the current contact set
}

void ContactNewton::solve_cap(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  row_lu_solve(cap_lu_, cap_perm_, b, x);
}

void ContactNewton::solve_d(double* x) const {
  for (const Block& b : blocks_) {
    Eigen::Vector4d v = Eigen::Vector4d::Zero();
    for (int a = 0; a < b.n; ++a) v(a) = x[b.idx[a]];
    const Eigen::Vector4d r = b.inv * v;
    for (int a = 0; a < b.n; ++a) x[b.idx[a]] = r(a);
  }
  const int nq = M_.nq, Z = M_.z_index();
  for (int l = 0; l < M_.nr; ++l) x[2 * nq + l] *= d_r_inv_;
  x[Z] += d_zw_ * x[Z + 1];
}

void ContactNewton::solve_ee(double* y) const {
  if (ee_s1_ == 0 && ee_s2_ == 0) {  // at rest: diagonal
    Eigen::Map<Eigen::VectorXd>(y, ne_).array() *= ee_d_inv_.array();
    return;
  }
  for (int i = ne_ - 1; i >= 0; --i) {
    double v = y[i];
    if (i + 1 < ne_) v -= ee_s1_ * y[i + 1];
    if (i + 2 < ne_) v -= ee_s2_ * y[i + 2];
    y[i] = v * ee_d_inv_(i);
  }
}

void ContactNewton::solve(double* x) {
  update_active_set();
  const auto& M = M_;
  const int nq = M.nq, nr = M.nr, Z = M.z_index(), rank = M.rank;
  const int na = static_cast<int>(active_.size());
  Eigen::Map<Eigen::VectorXd> xx(x, nx_);
  double* xe = x + nx_;
  // phi1: the forces on eta of eliminating E, -gamma T~^T diag(kd) M_EE^-1 b_E; b_X + Q phi1 is
  // then the right-hand side of the Schur complement S = D - gamma Q K P.
  phi_.setZero(np_);
  if (ne_ > 0 && na > 0) {
    work_a_.resize(na);
    const int k0 = active_.front() - u0_;  // the active units' tread states are contiguous
    if (ee_s1_ == 0 && ee_s2_ == 0) {      // at rest M_EE is diagonal: only the active rows
      work_a_ = kd_active_.cwiseProduct(
          Eigen::Map<const Eigen::VectorXd>(xe + k0, na).cwiseProduct(ee_d_inv_.segment(k0, na)));
    } else {
      work_e_ = Eigen::Map<Eigen::VectorXd>(xe, ne_);
      solve_ee(work_e_.data());
      work_a_ = kd_active_.cwiseProduct(work_e_.segment(k0, na));
    }
    column_dots(Tt_active_, work_a_, phi_, -gamma_);  // -gamma T~^T w (column_product.h)
  }
  // S^-1 by Woodbury: with x0 = D^-1 b_X and eta0 = P x0,
  //   x_X = x0 + D^-1 Q phi,  phi = phi1 + gamma K cap^-1 (eta0 + H phi1),
  // and P x_X = eta0 + H phi (H = P D^-1 Q): one application of D^-1 and of P per solve, the
  // forces entering X through the precomputed columns D^-1 Q.
  solve_d(x);
  column_dots(CqT_, xx.head(nq), eta0_);  // P x0 (= Cq q + Cr r, z)
  if (nr > 0) column_dots(CrT_, xx.segment(2 * nq, nr), eta0_, 1.0, /*accumulate=*/true);
  eta0_(rank) = xx(Z);
  eta_ = eta0_;
  eta_.noalias() += H_ * phi_;
  solve_cap(eta_, w_);
  phi_.noalias() += gamma_ * (K_ * w_);
  column_product(DQ_, phi_, xx, /*accumulate=*/true);
  if (ne_ > 0) {
    // x_E = M_EE^-1 (b_E - M_EX x_X), M_EX = -gamma diag(kd / c') T~ P.
    if (na > 0) {
      eta_ = eta0_;
      eta_.noalias() += H_ * phi_;                // P x_X
      column_product(Tt_active_, eta_, work_a_);  // work_a_ has na entries
      Eigen::Map<Eigen::VectorXd>(xe + (active_.front() - u0_), na) +=
          gamma_kd_c_.cwiseProduct(work_a_);
    }
    solve_ee(xe);
  }
}

}  // namespace modaltyre::transient
