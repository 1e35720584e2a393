// The semismooth part of the 3D patch's Newton solver (cell_newton.h, docs/transient.md section
// 7): the contact stiffness of the cells that switched side of the kink at the current iterate,
// the changes of K and the capacitance matrix's new LU, and solve()'s per-slot factors.
#include <algorithm>
#include <cmath>

#include "cell_kernels.h"
#include "modaltyre/transient/cell_newton.h"
#include "modaltyre/transient/column_product.h"
#include "modaltyre/transient/ode_system.h"
#include "row_lu_solve.h"

namespace modaltyre::transient {
namespace {

/// On a soil: a contact cell whose series stiffness changed by this factor since the Jacobian
/// crossed a kink of the soil's law (virgin curve to memory branch); a smooth change of
/// pressure on one branch moves it by far less within a step. 1.5 and 4 gave the same steps
/// within 10 % (1 mm sections, 5 mm columns, rolling 1.5 s: 1023, 944, 914 steps for 1.5, 2, 4).
constexpr double kSoilKinkRatio = 2.0;

}  // namespace

void CellNewton::slot_coefficients() {
  mukd_.setZero(kd_.size());
  gkc_.setZero(kd_.size());
  if (ne_ == 0) return;
  for (int c = 0; c < cm_.classes.size(); ++c) {
    const UnitRange& r = sys_.ranges()[c];
    for (int k = 0, o = sys_.offset(c); k < r.size(); ++k) slot_coefficient(o + k);
  }
}

void CellNewton::slot_coefficient(int k) {
  const int c = slot_class_[k], i = sys_.ranges()[c].lo + (k - sys_.offset(c));
  const double kd = kd_(k);
  mukd_(k) = kd > 0 ? cm_.classes.multiplicity[c] * kd : 0.0;
  gkc_(k) = kd > 0 ? gamma_ * kd / cm_.c_kv(i) : 0.0;
}

void CellNewton::cap_product(double gamma) {
  // I - gamma H K by columns (the vectorised product: Eigen's blocked one would hand these sizes
  // to OpenMP threads, which only wait on the shared cores).
  cap_mat_.resize(np_, np_);
  // H K (the bits of a column_product() per column of K, register-blocked).
  detail::small_gemm(np_, np_, np_, H_.data(), np_, K_.data(), np_, cap_mat_.data(), np_);
  cap_mat_ *= -gamma;
  cap_mat_.diagonal().array() += 1.0;
}

bool CellNewton::lu_cap() { return row_lu_factor(cap_mat_, cap_lu_, cap_perm_, rowperm_); }

void CellNewton::update_active_set() {
  const Eigen::VectorXd& f = sys_.last_forces();
  const int n = sys_.cells();
  if (f.size() != n || kd_.size() != n) return;
  changed_.clear();
  detail::sign_mismatches(n, f.data(), kd_.data(), changed_);
  if (sys_.soil()) {
    // On a soil a cell in contact also changes side of a kink: between the virgin curve and
    // its memory's branch (cell_soil.h) its series stiffness jumps (to k on a rigid-plastic
    // branch). Rolling, the memory moves under the cells and many cross it at every step; left
    // to the next Jacobian, CVODE's Newton failed on them (default mesh, 3 kN at 10 km/h,
    // 1.5 s: 5.3 iterations and 0.7 Jacobians per step, 3948 steps; with this update 2.7,
    // 0.26 and 1146 steps, CPU 53 -> 11 s).
    for (int k = 0; k < n; ++k) {
      if (!(f(k) > 0 && kd_(k) > 0)) continue;
      const double s = sys_.slot_stiffness(k);
      if (s > kSoilKinkRatio * kd_(k) || kd_(k) > kSoilKinkRatio * s) changed_.push_back(k);
    }
  }
  if (changed_.empty()) return;
  const TransientModel& M = M_;
  const CellClasses& C = cm_.classes;
  // Each cell enters K through its section's weight: at rest (M_EE diagonal) exactly w_i =
  // sum_c mu_c kd_ic (1 - gamma kd_ic / c'_i / d_ic) (factor()), so K changes by
  // (w_i,new - w_i,old) T~_i^T T~_i for the sections of the switched cells. Rolling, a cell's
  // stiffness also reaches the cells in front of it along the class's band (Y, factor()): that
  // part is left to the next setup, i.e. the switched cell's own diagonal term only (an inexact
  // Jacobian, as the whole matrix is between setups; a new factor() per switch cost a cleat run
  // 1.6 times its time for 2 % fewer steps).
  const double gamma = gamma_;
  dw_.clear();
  for (int k : changed_) {
    const int c = slot_class_[k], i = sys_.ranges()[c].lo + (k - sys_.offset(c));
    const double mu = C.multiplicity[c], c_kv = ne_ > 0 ? cm_.c_kv(i) : 0.0;
    auto weight = [&](double kd) {
      return ne_ > 0 ? mu * kd * (1.0 - gamma * kd / c_kv * ee_d_inv_(k)) : mu * kd;
    };
    const double w_old = weight(kd_(k));
    kd_(k) = f(k) > 0 ? sys_.slot_stiffness(k) : 0.0;
    if (ne_ > 0)
      ee_d_inv_(k) = 1.0 / (1.0 - gamma * (kUpwind[0] * adv_ - (kd_(k) + cm_.k_kv(i)) / c_kv));
    dw_.emplace_back(i, weight(kd_(k)) - w_old);
    if (ne_ > 0) slot_coefficient(k);
  }
  // Per section one change of weight (a section's cells share its row T~_i): dK = Tc^T diag(dw)
  // Tc over the changed sections, and the capacitance matrix changes by -gamma H dK = (-gamma H
  // Tc) W, with H T~_i^T taken from HT_ (factor_dq()): two register-blocked products of rank
  // nchg, ~2 np^2 nchg instead of the np^3 of a new product H K (the matrix then differs from
  // I - gamma H K by rounding only, until the next factor()). Measured on the free vibration at
  // 1 mm / 5 mm (~11 sections a Newton iteration): CPU real-time factor 19.2 -> 20.8x.
  std::sort(dw_.begin(), dw_.end());
  int nchg = 0;
  for (const auto& [i, dw] : dw_) {
    if (nchg > 0 && dw_[nchg - 1].first == i)
      dw_[nchg - 1].second += dw;
    else
      dw_[nchg++] = {i, dw};
  }
  dw_.resize(nchg);
  const int span_lo = sys_.sections().lo;
  if (rest_) {
    // M, the symmetric form's matrix, which also gives solve() its K w (cell_newton_rest.cc):
    // K itself is left at the setup's.
    update_rest(gamma);
  } else {
    // T~_i^T of the changed sections from the span's columns (constructor).
    Tc_.resize(np_, nchg);
    W_.resize(nchg, np_);
    for (int a = 0; a < nchg; ++a) Tc_.col(a) = TspanT_.col(dw_[a].first - span_lo);
    for (int b = 0; b < np_; ++b)
      for (int a = 0; a < nchg; ++a) W_(a, b) = dw_[a].second * Tc_(b, a);
    detail::small_gemm(np_, np_, nchg, Tc_.data(), np_, W_.data(), nchg, K_.data(), np_, true);
    HTc_.resize(np_, nchg);
    for (int a = 0; a < nchg; ++a) HTc_.col(a) = -gamma * HT_.col(dw_[a].first - span_lo);
    detail::small_gemm(np_, np_, nchg, HTc_.data(), np_, W_.data(), nchg, cap_mat_.data(), np_,
                       true);
  }
  // The span of sections with an active cell (solve() reads T~ over it) only grows here.
  int lo = ns_ > 0 ? s0_ : M.m, hi = ns_ > 0 ? s0_ + ns_ - 1 : -1;
  for (const auto& [i, dw] : dw_) lo = std::min(lo, i), hi = std::max(hi, i);
  if (lo != s0_ || hi - lo + 1 != ns_) {
    s0_ = lo;
    ns_ = hi - lo + 1;
    Tt_ = TspanT_.middleCols(s0_ - span_lo, ns_).transpose();
  }
  const bool factored =
      rest_ ? detail::cholesky_factor(np_, cap_mat_.data(), cap_chol_.data()) : lu_cap();
  if (!factored) factor(gamma);  // the whole factorisation at the current contact set
}

}  // namespace modaltyre::transient
