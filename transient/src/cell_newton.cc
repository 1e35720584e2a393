#include "modaltyre/transient/cell_newton.h"

#include <algorithm>
#include <cmath>

#include "cell_kernels.h"
#include "modaltyre/solvers/dense_product.h"
#include "modaltyre/transient/column_product.h"
#include "modaltyre/transient/ode_system.h"
#include "row_lu_solve.h"
#include "slot_kernels.h"

namespace modaltyre::transient {

using detail::band_row;

CellNewton::CellNewton(const CellModel& cm, const CellSystem& system)
    : cm_(cm), M_(cm.M()), sys_(system) {
  const TransientModel& M = M_;
  nx_ = M.e_index();
  ne_ = system.tread_states();
  np_ = M.rank + 1;
  const int nq = M.nq;
  for (int j = 0; j < nq; ++j) {
    const int p = M.partner[j];
    if (p >= 0 && p < j) continue;
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
  CqT_ = M.Cq.transpose();
  CrT_ = M.Cr.transpose();
  // The semismooth update (update_active_set()): per slot its class and contact spring, and
  // the contact basis transposed (a section's row contiguous).
  semismooth_ = cm.classes.size() > 1;
  kc_slot_.resize(system.cells());
  slot_class_.resize(system.cells());
  for (int c = 0; c < cm.classes.size(); ++c) {
    const UnitRange& r = system.ranges()[c];
    for (int k = 0; k < r.size(); ++k) {
      kc_slot_(system.offset(c) + k) = cm.k_contact(r.lo + k);
      slot_class_[system.offset(c) + k] = c;
    }
  }
  TT_ = M.T.transpose();
  // T~ of every section of the span as columns (update_active_set() takes H T~_i^T from HT_).
  const UnitRange span = system.sections();
  TspanT_.resize(np_, span.size());
  for (int s = 0; s < span.size(); ++s) {
    TspanT_.col(s).head(M.rank) = -TT_.col(span.lo + s);
    TspanT_(M.rank, s) = system.plan().hub_free() ? 1.0 : 0.0;
  }
  trow_.resize(np_);
  // solve_ee()'s lanes: the classes with tread states, by the length of their range.
  for (int c = 0; c < cm.classes.size(); ++c)
    if (ne_ > 0 && system.ranges()[c].size() > 0) lane_order_.push_back(c);
  std::stable_sort(lane_order_.begin(), lane_order_.end(), [&](int a, int b) {
    return system.ranges()[a].size() > system.ranges()[b].size();
  });
  int longest = 0;
  for (int c : lane_order_) longest = std::max(longest, system.ranges()[c].size());
  pad_.assign(longest + 2, 0.0);
  eta_.resize(np_);
  eta0_.resize(np_);
  phi_.resize(np_);
  w_.resize(np_);
}

bool CellNewton::setup(double t, const double* y, double gamma, bool jacobian_ok) {
  if (!jacobian_ok || !jacobian_ready_) {
    sys_.jacobian_stiffness(t, y, kd_);
    Omega_ = sys_.spin(t);
    dOmega_ = sys_.spin_rate(t);
    jacobian_ready_ = true;
  } else if (semismooth_) {
    Omega_ = sys_.spin(t);
    dOmega_ = sys_.spin_rate(t);
  }
  factor(gamma);
  const bool cap_ok = rest_ ? cap_chol_.diagonal().allFinite()
                            : cap_lu_.allFinite() && (cap_lu_.diagonal().array() != 0).all();
  return cap_ok && ee_d_inv_.allFinite();
}

void CellNewton::factor(double gamma) {
  const TransientModel& M = M_;
  const CellClasses& C = cm_.classes;
  const int nr = M.nr, rank = M.rank, nc = C.size();
  gamma_ = gamma;
  d_r_inv_ = nr > 0 ? 1.0 / (1.0 + gamma / M.tau_residual_s) : 1.0;
  const bool hub_free = sys_.plan().hub_free();
  d_zw_ = hub_free ? gamma : 0.0;  // a prescribed hub: z' = w' = 0, D = I on (z, w)
  // Sections with an active cell.
  // Per class its first and last active slot (kf_, kl_; kf_ = the range's size if none).
  int s_first = M.m, s_last = -1;
  kf_.resize(nc);
  kl_.resize(nc);
  for (int c = 0; c < nc; ++c) {
    const UnitRange& r = sys_.ranges()[c];
    const double* kd = kd_.data() + sys_.offset(c);
    kf_[c] = detail::first_positive(kd, r.size());
    kl_[c] = detail::last_positive(kd, r.size());
    if (kf_[c] < r.size())
      s_first = std::min(s_first, r.lo + kf_[c]), s_last = std::max(s_last, r.lo + kl_[c]);
  }
  s0_ = s_first;
  ns_ = s_last >= s_first ? s_last - s_first + 1 : 0;
  Tt_.resize(ns_, np_);
  // T~ = [-T, d g / d z] over the sections, column by column (contiguous in both).
  if (ns_ > 0) Tt_.leftCols(rank) = -M.T.middleRows(s0_, ns_);
  Tt_.col(rank).setConstant(hub_free ? 1.0 : 0.0);  // d g / d z (0: z an input)
  // M_EE's diagonal per slot, its (uniform) super-diagonals along each class.
  const double adv = Omega_ / M.tyre.dtheta_rad;
  adv_ = adv;
  ee_s1_ = -gamma * kUpwind[1] * adv;
  ee_s2_ = -gamma * kUpwind[2] * adv;
  ee_d_inv_.resize(ne_);
  for (int c = 0; c < nc && ne_ > 0; ++c) {
    const UnitRange& r = sys_.ranges()[c];
    const int o = sys_.offset(c);
    for (int k = 0; k < r.size(); ++k) {
      const int i = r.lo + k;
      ee_d_inv_(o + k) =
          1.0 / (1.0 - gamma * (kUpwind[0] * adv - (kd_(o + k) + cm_.k_kv(i)) / cm_.c_kv(i)));
    }
  }
  // R_i = sum_c mu_c kd_ic (T~_i - gamma Y_ic); at rest Y_ic = (kd_ic / c'_i) T~_i d_ic^-1, so
  // R_i = w_i T~_i with w_i = sum_c mu_c kd_ic (1 - gamma kd_ic / c'_i / d_ic).
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(ns_, np_);
  // Rolling: Y and R are built row by row; rows of row-major copies are contiguous (the same
  // values, so the same K).
  const bool rows_needed = !(ee_s1_ == 0 && ee_s2_ == 0) && ne_ > 0 && ns_ > 0;
  if (rows_needed) {
    TtR_ = Tt_;
    RR_.setZero(ns_, np_);
  }
  const bool at_rest = ee_s1_ == 0 && ee_s2_ == 0;
  w_sec_.setZero(ns_);
  if (ns_ > 0) {
    for (int c = 0; c < nc; ++c) {
      const UnitRange& r = sys_.ranges()[c];
      const int o = sys_.offset(c), mu = C.multiplicity[c];
      const int kf = kf_[c], kl = kl_[c];
      if (kf == r.size()) continue;
      if (ne_ == 0) {
        for (int k = kf; k <= kl; ++k) w_sec_(r.lo + k - s0_) += mu * kd_(o + k);
        continue;
      }
      if (at_rest) {
        for (int k = kf; k <= kl; ++k) {
          const int i = r.lo + k;
          const double kd = kd_(o + k);
          if (kd > 0)
            w_sec_(i - s0_) += mu * kd * (1.0 - gamma * kd / cm_.c_kv(i) * ee_d_inv_(o + k));
        }
        continue;
      }
      // Back substitution up the class's band from its last active cell.
      // One pass per row, (a T~_i - s1 Y_row+1 - s2 Y_row+2) d^-1 (rows beyond the band: zero).
      const int rows = kl - kf + 1;
      Y_.resize(rows, np_);
      zero_row_.setZero(np_);
      // With this row's term of R in the same pass (per section, the classes' terms are added in
      // the classes' order, as before).
      for (int k = kl; k >= kf; --k) {
        const int i = r.lo + k, row = k - kf;
        const double kd = kd_(o + k), a = kd > 0 ? kd / cm_.c_kv(i) : 0.0;
        const double* t = TtR_.row(i - s0_).data();
        const double* y1 = row + 1 < rows ? Y_.row(row + 1).data() : zero_row_.data();
        const double* y2 = row + 2 < rows ? Y_.row(row + 2).data() : zero_row_.data();
        band_row(np_, kd > 0, a, t, y1, y2, ee_s1_, ee_s2_, ee_d_inv_(o + k), Y_.row(row).data(),
                 kd > 0 ? RR_.row(i - s0_).data() : nullptr, mu * kd, gamma);
      }
    }
  }
  if (rows_needed) R = RR_;
  if (at_rest || ne_ == 0) {
    for (int s = 0; s < ns_; ++s) R.row(s) = w_sec_(s) * Tt_.row(s);
  }
  if (ns_ == 0) {
    K_.setZero(np_, np_);
  } else if (semismooth_) {
    // More than one class: K by the vectorised column products (a flat crown keeps the 2D
    // solver's order of operations below).
    K_.resize(np_, np_);
    for (int k = 0; k < np_; ++k) column_dots(Tt_, R.col(k), K_.col(k));
  } else {
    K_.noalias() = Tt_.transpose().lazyProduct(R);
  }
  // D^-1 Q and H = P D^-1 Q depend on gamma and the spin only, not on the contact: kept from
  // the last factorisation when those are the same.
  if (!(dq_ready_ && gamma == dq_gamma_ && Omega_ == dq_Omega_ && dOmega_ == dq_dOmega_)) {
    dq_ready_ = true, dq_gamma_ = gamma, dq_Omega_ = Omega_, dq_dOmega_ = dOmega_;
    factor_dq(gamma);
  }
  slot_coefficients();
  // At rest with more than one class: the symmetric form's Cholesky factor (cell_newton_rest.cc;
  // cap_rest() false, M's eigenvalues being >= 1, is not seen: the LU below then).
  rest_ = semismooth_ && rest_ok_ && at_rest && cap_rest(gamma);
  if (rest_) return;
  // The capacitance matrix in the 2D solver's order of operations (contact_newton.cc): a flat
  // crown's one class then repeats the 2D transient's arithmetic (FlatCrown test; a
  // rounding-level change here moved its 0.3 s hold's end load by 0.9 %).
  if (semismooth_) {
    // More than one class: the vectorised product and the unblocked LU (Eigen's LU where a
    // pivot vanishes, so that setup() reports the singular matrix as before).
    cap_product(gamma);
    if (!lu_cap()) factor_cap();
  } else {
    cap_mat_ = Eigen::MatrixXd::Identity(np_, np_) - gamma * H_.lazyProduct(K_);
    factor_cap();
  }
}

void CellNewton::factor_cap() {
  cap_.compute(cap_mat_);
  cap_lu_ = cap_.matrixLU();
  cap_perm_ = cap_.permutationP().indices();
}

void CellNewton::factor_dq(double gamma) {
  const TransientModel& M = M_;
  const int nq = M.nq, nr = M.nr, Z = M.z_index(), rank = M.rank;
  const bool hub_free = sys_.plan().hub_free();
  // D's 2 x 2 / 4 x 4 blocks per mode (pair) and their inverses.
  for (Block& b : blocks_) {
    Eigen::Matrix4d d = Eigen::Matrix4d::Identity();
    const int h = b.n / 2;
    for (int a = 0; a < h; ++a) {
      d(a, h + a) = -gamma;
      const ModalRow r = modal_row(M, b.idx[a], Omega_, dOmega_);
      const int o = h == 2 ? 1 - a : a;
      d(h + a, a) -= gamma * r.dq;
      d(h + a, h + a) -= gamma * r.dv;
      if (h == 2) {
        d(h + a, o) -= gamma * r.dq_p;
        d(h + a, h + o) -= gamma * r.dv_p;
      }
    }
    b.inv = d.inverse();
  }
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
  H_.setZero(np_, np_);
  // Cq (D^-1 Q)_q + Cr (D^-1 Q)_r (the bits of a column_product() per column, register-blocked).
  const int ld = static_cast<int>(DQ_.rows());
  detail::small_gemm(rank, np_, nq, M.Cq.data(), static_cast<int>(M.Cq.rows()), DQ_.data(), ld,
                     H_.data(), np_);
  if (nr > 0)
    detail::small_gemm(rank, np_, nr, M.Cr.data(), static_cast<int>(M.Cr.rows()),
                       DQ_.data() + 2 * nq, ld, H_.data(), np_, true);
  H_.row(rank) = DQ_.row(Z);
  if (updates_active_set() && TspanT_.cols() > 0) {
    HT_.resize(np_, TspanT_.cols());
    detail::small_gemm(np_, static_cast<int>(TspanT_.cols()), np_, H_.data(), np_, TspanT_.data(),
                       np_, HT_.data(), np_);
  }
  // At rest (no spin: uncoupled modal blocks, H symmetric) the symmetric form's basis.
  rest_ok_ = semismooth_ && Omega_ == 0 && dOmega_ == 0 && rest_basis();
}

void CellNewton::solve_cap(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  if (rest_) return solve_cap_rest(b, x);
  row_lu_solve(cap_lu_, cap_perm_, b, x);
}

void CellNewton::solve_d(double* x) const {
  for (const Block& b : blocks_) {
    Eigen::Vector4d v = Eigen::Vector4d::Zero();
    for (int a = 0; a < b.n; ++a) v(a) = x[b.idx[a]];
    const Eigen::Vector4d r = b.inv * v;
    for (int a = 0; a < b.n; ++a) x[b.idx[a]] = r(a);
  }
  for (int l = 0; l < M_.nr; ++l) x[2 * M_.nq + l] *= d_r_inv_;
  x[M_.z_index()] += d_zw_ * x[M_.z_index() + 1];
}

void CellNewton::solve_ee(double* y, bool span_only) const {
  if (ee_s1_ == 0 && ee_s2_ == 0) {
    Eigen::Map<Eigen::VectorXd>(y, ne_).array() *= ee_d_inv_.array();
    return;
  }
  // Each class's back substitution is a serial recurrence (its latency, not its arithmetic, is
  // the cost): kLanes classes of similar length run in lockstep, aligned at their ends, so that
  // their chains overlap. The same operations per element as one class at a time.
  const double s1 = ee_s1_, s2 = ee_s2_;
  const double* dinv = ee_d_inv_.data();
  auto one = [&](double* yc, const double* dc, int n, int k) {
    double v = yc[k];
    if (k + 1 < n) v -= s1 * yc[k + 1];
    if (k + 2 < n) v -= s2 * yc[k + 2];
    yc[k] = v * dc[k];
  };
  for (std::size_t g = 0; g < lane_order_.size(); g += kLanes) {
    const int lanes = static_cast<int>(std::min<std::size_t>(kLanes, lane_order_.size() - g));
    double* yc[kLanes];
    const double* dc[kLanes];
    int n[kLanes], m[kLanes];  // the class's slots, and how many from its end are computed
    int nmin = 1 << 30;
    for (int l = 0; l < lanes; ++l) {
      const int c = lane_order_[g + l];
      const UnitRange& r = sys_.ranges()[c];
      n[l] = r.size();
      yc[l] = y + sys_.offset(c);
      dc[l] = dinv + sys_.offset(c);
      // Span only: down to the class's first slot in the sections [s0, s0 + ns) (the slots
      // below are not computed; the upwind band carries nothing from them upwards).
      m[l] = span_only ? std::max(0, std::min(r.size(), r.hi + 1 - s0_)) : n[l];
      nmin = std::min(nmin, m[l]);
    }

    // Steps t = 0, 1 from each end (the band's boundary), then t = 2 .. nmin - 1 in lockstep,
    // then each lane's remaining front.
    const int head = std::min(2, nmin);
    for (int l = 0; l < lanes; ++l)
      for (int t = 0; t < head; ++t) one(yc[l], dc[l], n[l], n[l] - 1 - t);
    double* ye[kLanes];
    const double* de[kLanes];
    for (int l = 0; l < lanes; ++l) ye[l] = yc[l] + n[l] - 1, de[l] = dc[l] + n[l] - 1;
    // A last group of fewer classes runs with idle lanes on zeros (pad_: zeros stay zeros).
    static_assert(kLanes == 8, "band_lockstep8() runs eight lanes");
    for (int l = lanes; l < kLanes; ++l) ye[l] = pad_.data() + pad_.size() - 1, de[l] = ye[l];
    detail::band_lockstep8(head, nmin, ye, de, s1, s2);  // cell_kernels.h
    for (int l = 0; l < lanes; ++l)
      for (int t = nmin; t < m[l]; ++t) one(yc[l], dc[l], n[l], n[l] - 1 - t);
  }
}

bool CellNewton::updates_active_set() const {
  // One class (a flat crown) takes the update where the 2D patch's ContactNewton takes it, at
  // rest off a soil, so that it keeps repeating the 2D transient (test FlatCrown); more classes
  // rolling and on a soil too (measured: docs/transient.md section 7, third round).
  return semismooth_ || (ee_s1_ == 0 && ee_s2_ == 0 && !sys_.soil());
}

void CellNewton::solve(double* x) {
  if (updates_active_set()) update_active_set();
  const TransientModel& M = M_;
  const int nq = M.nq, nr = M.nr, Z = M.z_index(), rank = M.rank, nc = cm_.classes.size();
  Eigen::Map<Eigen::VectorXd> xx(x, nx_);
  double* xe = x + nx_;
  // phi1 = -gamma sum_i T~_i^T s_i, s_i = sum_c mu_c kd_ic (M_EE^-1 b_E)_ic.
  phi_.setZero(np_);
  // At rest M_EE is diagonal: its solves are products with d^-1 inside the passes below (the
  // same operations, without a copy and a pass of their own).
  const bool at_rest = ee_s1_ == 0 && ee_s2_ == 0;
  if (ne_ > 0 && ns_ > 0) {
    if (!at_rest) {
      work_e_ = Eigen::Map<Eigen::VectorXd>(xe, ne_);
      solve_ee(work_e_.data(), /*span_only=*/true);  // read by the gather below only
    }
    work_s_.setZero(ns_);
    // Over each class's slots within the sections [s0, s0 + ns) (mu kd = 0 where not active).
    for (int c = 0; c < nc; ++c) {
      const UnitRange& r = sys_.ranges()[c];
      const int o = sys_.offset(c), k0 = std::max(0, s0_ - r.lo),
                k1 = std::min(r.size(), s0_ + ns_ - r.lo);
      if (k1 <= k0) continue;
      // ws += mu kd (b d) at rest, ws += mu kd (M_EE^-1 b) rolling (slot_kernels.h).
      const int ok = o + k0;
      detail::slot_gather(k1 - k0, mukd_.data() + ok, at_rest ? xe + ok : work_e_.data() + ok,
                          at_rest ? ee_d_inv_.data() + ok : nullptr,
                          work_s_.data() + (r.lo + k0 - s0_));
    }
    column_dots(Tt_, work_s_, phi_, -gamma_);
  }
  solve_d(x);
  column_dots(CqT_, xx.head(nq), eta0_);
  if (nr > 0) column_dots(CrT_, xx.segment(2 * nq, nr), eta0_, 1.0, true);
  eta0_(rank) = xx(Z);
  // H phi and K w with Eigen's matrix-vector bits (solvers/dense_product.h: its AVX2 path where
  // the CPU runs it), each added as Eigen's += adds its sums (alpha c + r, c = the product).
  prod_.resize(np_);
  solvers::detail::dense_product(np_, np_, H_.data(), np_, phi_, prod_);
  eta_ = eta0_ + prod_;
  solve_cap(eta_, w_);
  if (rest_) {
    phi_ += rest_gamma_kw();  // gamma K w from the capacitance solve (cell_newton_rest.cc)
  } else {
    solvers::detail::dense_product(np_, np_, K_.data(), np_, w_, prod_);
    phi_ += gamma_ * prod_;
  }
  column_product(DQ_, phi_, xx, true);
  if (ne_ > 0) {
    if (ns_ > 0) {
      // x_E = M_EE^-1 (b_E - M_EX x_X), M_EX = -gamma diag(kd / c') T~ P.
      // P x_X = eta0 + H phi, which is the capacitance solve's w (w = eta0 + H phi1 + gamma H K
      // w): at rest taken as such, otherwise recomputed (the bits of the 2D solver's order).
      if (!rest_) {
        solvers::detail::dense_product(np_, np_, H_.data(), np_, phi_, prod_);
        eta_ = eta0_ + prod_;
      }
      work_s_.resize(ns_);
      column_product(Tt_, rest_ ? w_ : eta_, work_s_);  // T~_i P x_X per section
      for (int c = 0; c < nc; ++c) {
        const UnitRange& r = sys_.ranges()[c];
        const int o = sys_.offset(c), k0 = std::max(0, s0_ - r.lo),
                  k1 = std::min(r.size(), s0_ + ns_ - r.lo);
        // x = (x + g ws) d at rest (x d alone outside the active sections), x += g ws rolling.
        const double* d = ee_d_inv_.data() + o;
        double* xc = xe + o;
        if (at_rest) detail::slot_scale(std::min(k0, r.size()), d, xc);
        if (k1 > k0)
          detail::slot_scatter(k1 - k0, gkc_.data() + o + k0, work_s_.data() + (r.lo + k0 - s0_),
                               at_rest ? d + k0 : nullptr, xc + k0);
        if (at_rest) {
          const int k2 = std::max(k0, k1);
          detail::slot_scale(r.size() - k2, d + k2, xc + k2);
        }
      }
      if (at_rest) return;
    }
    solve_ee(xe);
  }
}

}  // namespace modaltyre::transient
