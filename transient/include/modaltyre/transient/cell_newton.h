#pragma once
// Newton's linear systems M = I - gamma J of the 3D transient (cell_system.h) through the low
// rank of the contact, as contact_newton.h for the 2D model (docs/transient.md sections 2, 7).
// Every cell of section i reaches the carcass through the same row T~_i = [-T_i, 1] of the
// contact basis, so with Y = M_EE^-1 diag(kd / c') T~ (M_EE: per class an upper band along its
// sections, the advection) the Schur complement on X is S = D - gamma Q K P with
//   K = sum_i T~_i^T R_i,   R_i = sum_c mu_c kd_ic (T~_i - gamma Y_ic)   (rank + 1 square),
// solved by Woodbury's identity with the capacitance matrix I - gamma (P D^-1 Q) K.
#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "modaltyre/transient/cell_system.h"

namespace modaltyre::transient {

class CellNewton {
 public:
  CellNewton(const CellModel& cm, const CellSystem& system);
  bool setup(double t, const double* y, double gamma, bool jacobian_ok);
  void solve(double* x);
  /// Whether the current factorisation is the symmetric form at rest (cell_newton_rest.cc).
  bool symmetric_at_rest() const { return rest_; }

 private:
  void factor(double gamma);
  /// D^-1 Q (DQ_) and H = P D^-1 Q (H_) at gamma and the current spin.
  void factor_dq(double gamma);
  /// The capacitance matrix I - gamma H K and its LU (cap_product(): the matrix by vectorised
  /// column products, update_active_set() then changes it by low-rank products; lu_cap(): its
  /// unblocked LU, false at a zero or non-finite pivot; factor_cap(): Eigen's product order and
  /// LU, a flat crown's).
  void cap_product(double gamma);
  bool lu_cap();
  void factor_cap();
  /// Semismooth Newton: the contact stiffness of the cells whose side of the kink of
  /// k_g max(0, g) differs at the current iterate (the last rhs()) from the matrix's, updated
  /// before the solve (at rest by rank-one changes of K per section, rolling by a new factor()).
  void update_active_set();
  /// Whether solve() runs update_active_set() at the current factorisation (and factor_dq()
  /// keeps HT_ for it).
  bool updates_active_set() const;
  /// solve()'s per-slot factors mu_c kd and gamma kd / c' (0 where kd = 0), all or slot k.
  void slot_coefficients();
  void slot_coefficient(int k);
  /// At rest (no spin, more than one class) H = -A with A symmetric positive definite (the
  /// modes' and residual orders' blocks uncoupled): with A = L L^T the capacitance matrix is
  /// similar to the symmetric positive definite M = L^T (I - gamma H K) L^-T = I + gamma L^T K L
  /// (K = sum_i w_i T~_i^T T~_i, w_i >= 0), factored by Cholesky's n^3 / 6 without pivoting
  /// instead of the LU's n^3 / 3 (cell_newton_rest.cc). rest_basis(): L and Z = L^T T~^T over
  /// the span (factor_dq()), false where A is not positive definite; cap_rest(): M and its
  /// factor; update_rest(): M's change by the switched sections; solve_cap_rest(): x = L M^-1
  /// L^-1 b.
  bool rest_basis();
  bool cap_rest(double gamma);
  void update_rest(double gamma);
  void solve_cap_rest(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// gamma K w after solve_cap_rest()'s w = L t, t = M^-1 s, s = L^-1 b: gamma L^T K L t =
  /// (M - I) t = s - t, so gamma K w = L^-T (s - t), one product with L^-T, and the semismooth
  /// update need not change K (update_active_set()).
  const Eigen::VectorXd& rest_gamma_kw() const;
  void solve_d(double* x) const;
  void solve_cap(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// y <- M_EE^-1 y over the tread states (per class, back substitution along its band).
  /// span_only: rolling, each class's slots from its end down to the first in the sections
  /// [s0_, s0_ + ns_) only (the rest of y left as it was).
  void solve_ee(double* y, bool span_only = false) const;

  const CellModel& cm_;
  const TransientModel& M_;
  const CellSystem& sys_;
  int nx_ = 0, ne_ = 0, np_ = 0;
  bool jacobian_ready_ = false;
  Eigen::VectorXd kd_;  ///< per slot
  double Omega_ = 0, dOmega_ = 0;
  double gamma_ = 0;
  struct Block {
    int n = 0;
    int idx[4] = {0, 0, 0, 0};
    Eigen::Matrix4d inv = Eigen::Matrix4d::Zero();
  };
  std::vector<Block> blocks_;
  double d_r_inv_ = 1, d_zw_ = 0;
  double ee_s1_ = 0, ee_s2_ = 0, adv_ = 0;
  Eigen::VectorXd ee_d_inv_;  ///< per slot
  /// solve_ee(): classes with tread states, longest range first, run kLanes at a time.
  static constexpr int kLanes = 8;
  std::vector<int> lane_order_;
  mutable std::vector<double> pad_;  ///< solve_ee()'s idle lanes (zeros, as long as a class)
  int s0_ = 0, ns_ = 0;              ///< sections with an active cell: [s0_, s0_ + ns_)
  Eigen::MatrixXd Tt_;               ///< T~ rows of those sections (ns x np)
  Eigen::VectorXd w_sec_;            ///< sum_c mu_c kd_ic per section (ns)
  Eigen::MatrixXd K_, cap_mat_;      ///< K: at rest (rest_) the setup's, M carries the updates
  bool dq_ready_ = false;
  bool semismooth_ = false;
  Eigen::VectorXd kc_slot_;      ///< per slot: contact spring
  std::vector<int> slot_class_;  ///< per slot: its class
  Eigen::MatrixXd TT_;           ///< T^T (rank x m)
  /// update_active_set(): T~ rows of the changed sections as columns (Tc_) and scaled by their
  /// change of weight (W_ = diag(dw) Tc_^T).
  Eigen::MatrixXd Tc_, W_, HTc_;
  /// T~ of the span's sections as columns, and H times it (factor_dq(), when updates_active_set()).
  Eigen::MatrixXd TspanT_, HT_;
  Eigen::VectorXd trow_, zero_row_, mukd_, gkc_;
  std::vector<int> changed_, rowperm_, kf_, kl_;
  std::vector<std::pair<int, double>> dw_;
  double dq_gamma_ = 0, dq_Omega_ = 0, dq_dOmega_ = 0;
  bool rest_ok_ = false;  ///< factor_dq() made la_ and z_span_ (rest_basis())
  bool rest_ = false;     ///< the current capacitance factor is M's Cholesky factor
  /// A's Cholesky factor L, its transpose, L^-1 and L^-T, Z = L^T T~^T over the span, M's factor,
  /// and update_rest()'s columns of the switched sections (Zc, gamma diag(dw) Zc^T).
  Eigen::MatrixXd la_, la_t_, la_inv_, la_inv_t_, z_span_, cap_chol_, rest_work_, zc_, wz_;
  mutable Eigen::VectorXd rest_s_, rest_t_, rest_kw_;
  Eigen::PartialPivLU<Eigen::MatrixXd> cap_;
  Eigen::MatrixXd CqT_, CrT_, DQ_, H_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> cap_lu_, Y_, TtR_, RR_;
  Eigen::VectorXi cap_perm_;
  mutable Eigen::VectorXd eta_, eta0_, phi_, w_, work_e_, work_s_, prod_;
};

}  // namespace modaltyre::transient
