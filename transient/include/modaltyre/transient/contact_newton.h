#pragma once
// Newton's linear systems M = I - gamma J of the transient model (ode_system.h) through the
// low rank of its contact coupling (docs/transient.md section 2).
//
// The contact forces depend on the carcass only through eta = (xi, z), xi = Cq q + Cr r, the
// rank coordinates of the units' displacement (model.h's contact basis), and act on it only
// through T~^T f, T~_i = [-T_i, 1]. With X = (q, v, r, z, w) and E the tread states:
//
//   M_XX = D - gamma Q T~^T diag(kd) T~ P,   D = I - gamma A (modal blocks: 2 x 2 per
//          coordinate, 4 x 4 per rolling pair; r and the hub),
//   M_XE = gamma Q T~^T diag(kd),   M_EX = -gamma diag(kd / c') T~ P,
//   M_EE = I - gamma (advection band - diag((kd + k') / c'))   (upper, width 2),
//
// with P: X -> eta and Q: eta-forces -> X rows (v rows -Cq^T, r rows -(lambda/tau) Cr^T, w row
// -1/m_hub). Eliminating E by back substitution leaves the Schur complement
//
//   S = D - gamma Q K P,   K = T~^T diag(kd) (T~ - gamma M_EE^-1 diag(kd / c') T~),
//
// K of size rank + 1, and S is solved by Woodbury's identity with the capacitance matrix
// I - gamma (P D^-1 Q) K: a factorisation costs O(rank^2 n_contact) and a solve
// O(rank (nq + n_contact) + m), against O((nq + nr)^2 n_contact + (2 nq + nr)^3) for the
// Schur complement on X (solvers::ArrowLu) and more for KLU on the whole matrix.
#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "modaltyre/transient/model.h"
#include "modaltyre/transient/ode_system.h"

namespace modaltyre::transient {

class ContactNewton {
 public:
  ContactNewton(const TransientModel& model, const TransientSystem& system);
  /// Prepares M = I - gamma J at (t, y); the contact set and rolling speed of the previous call
  /// are kept when `jacobian_ok` (CVODE judges the last Jacobian still good). Returns false if
  /// a pivot is not finite or zero (CVODE then retries with a smaller step).
  bool setup(double t, const double* y, double gamma, bool jacobian_ok);
  /// x <- M^-1 x (system.size() entries). First the semismooth update: the units whose side of
  /// the contact's kink differs at the current iterate (the last rhs()) from the matrix's get
  /// the iterate's stiffness (docs/transient.md section 2; off on a soil).
  void solve(double* x);

 private:
  void factor(double gamma);
  /// active_ = [first, last] (empty for first < 0) and their rows T~ in Tt_active_.
  void set_active_span(int first, int last);
  /// M_EE's diagonal of unit i with contact stiffness kd at gamma_ and the spin Omega_.
  double ee_diagonal(int i, double kd) const;
  /// Unit i's weight in K at rest, kd (1 - gamma kd / c' / d) with d = ee_diagonal(i, kd): the
  /// contact spring in series with the tread's Kelvin-Voigt element (factor()).
  double rest_weight(int i, double kd, double d) const;
  void update_active_set();
  /// The capacitance's LU from cap_mat_ into cap_lu_ / cap_perm_ (false at a zero pivot).
  bool lu_cap();
  /// x <- D^-1 x on the X states.
  void solve_d(double* x) const;
  /// x = cap^-1 b from the factors of factor().
  void solve_cap(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// y <- M_EE^-1 y over the tread states.
  void solve_ee(double* y) const;

  const TransientModel& M_;
  const TransientSystem& sys_;
  int nx_ = 0, ne_ = 0, np_ = 0;  ///< X states, tread states, rank + 1
  int u0_ = 0;                    ///< unit of the first tread state
  bool jacobian_ready_ = false;
  // Jacobian data: contact stiffness, units with kd > 0, rolling speed.
  Eigen::VectorXd kd_;
  std::vector<int> active_;    ///< a span of units: first to last with kd > 0
  Eigen::VectorXd kd_active_;  ///< kd over active_
  double Omega_ = 0, dOmega_ = 0;
  // Factorisation.
  double gamma_ = 0;
  /// D's blocks: the states of each (a coordinate's q, v, or a pair's q, q', v, v') and the
  /// inverse of the block; r and the hub separately.
  struct Block {
    int n = 0;
    int idx[4] = {0, 0, 0, 0};
    Eigen::Matrix4d inv = Eigen::Matrix4d::Zero();
  };
  std::vector<Block> blocks_;
  double d_r_inv_ = 1, d_zw_ = 0;    ///< 1 / (1 + gamma / tau); D^-1 of (z, w) is [1 gamma; 0 1]
  double ee_s1_ = 0, ee_s2_ = 0;     ///< M_EE's super-diagonals (uniform)
  Eigen::VectorXd ee_d_, ee_d_inv_;  ///< M_EE's diagonal and its inverse
  Eigen::MatrixXd K_;                ///< np x np
  Eigen::PartialPivLU<Eigen::MatrixXd> cap_;
  Eigen::MatrixXd Tt_active_;   ///< T~ rows of the active units (na x np)
  Eigen::VectorXd gamma_kd_c_;  ///< gamma kd_i / c'_i of the active units (relaxation on)
  /// factor()'s work: diag(kd) (T~ - gamma Y) on the active rows, Y (rolling), per-unit factors.
  Eigen::MatrixXd Ty_;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Y_;
  Eigen::VectorXd work_s_;
  Eigen::MatrixXd CqT_, CrT_;  ///< Cq^T, Cr^T (P's products as column_dots)
  Eigen::MatrixXd DQ_;         ///< D^-1 Q (nx x np): X's response to unit forces on eta
  Eigen::MatrixXd H_;          ///< P D^-1 Q (np x np)
  /// The capacitance's LU factors (row-major) and row permutation, for solve_cap().
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> cap_lu_;
  Eigen::VectorXi cap_perm_;
  /// The capacitance matrix I - gamma H K (the semismooth update changes it by low-rank terms).
  Eigen::MatrixXd cap_mat_;
  std::vector<int> rowperm_;
  std::vector<std::pair<int, double>> dw_;  ///< update_active_set(): (unit, change of weight)
  Eigen::VectorXd t_col_, ht_col_;
  mutable Eigen::VectorXd eta_, eta0_, phi_, w_, work_x_, work_e_, work_a_;
};

}  // namespace modaltyre::transient
