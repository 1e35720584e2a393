#pragma once
// Transient (time-domain) tyre on a rigid road: modal carcass, Kelvin-Voigt tread, hub DOF,
// unilateral contact; integrated with CVODE (BDF) + KLU. Derivations in docs/transient.md.
//
// State y = [q (nq) | v = q' (nq) | r (nr) | z, w = z' | e (m, tread relaxation on only)].
//
// Carcass, dynamic part (orders <= transient.dynamic_max_order). Every modal term (order k,
// weight w, 2x2 Hermitian shape matrix P = [P_rr P_rt; P_rt* P_tt]) is split into rank-one
// pieces P = sum a a^H (Cholesky of the 2x2); a piece of order k >= 1 gives two real
// coordinates with shapes sqrt(w) Re(a e^{ik theta}) and sqrt(w) Im(a e^{ik theta}) (order 0:
// the real one only), so that sum phi(theta_i) phi(theta_j) / omega^2 is exactly the term's
// contribution to the static kernel (modal_basis.h). Unit modal mass:
//   q'' + 2 zeta omega q' + omega^2 q = psi^T f      (seed 001 eq. 2, one mode)
// psi = phi_r cos theta + phi_t sin theta is the vertical shape at the candidate units and f
// the vertical contact forces (upward on the tyre, seed 001 eq. 12). Rolling at Omega(t) = V/R0
// is written in the ground (hub) frame: a pair (c, s) of order k obeys, with b = k Omega and
// a = k Omega',
//   q_c'' = G_c - 2 zeta omega q_c' + 2 b q_s' - (omega^2 - b^2) q_c + (2 zeta omega b + a) q_s
//   q_s'' = G_s - 2 zeta omega q_s' - 2 b q_c' - (omega^2 - b^2) q_s - (2 zeta omega b + a) q_c
// whose steady state is the rolling receptance 1/(omega^2 - b^2 - 2i zeta omega b) of
// carcass_kernel.h (gyroscopic terms neglected there and here).
//
// Carcass, residual part (orders above the dynamic truncation): quasi-static. Their vertical
// static compliance on the candidates, R = V diag(lambda) V^T (eigen-decomposition), is carried
// by first-order coordinates tau r' + r = diag(lambda) V^T f, tau = 2 zeta / omega_(K+1)
// (the residual modes without their inertia, keeping their damping). Only the eigenpairs with
// lambda >= 0.3 lambda_max are integrated; the others' diagonal (residual_lumped) acts in series
// with the tread spring and their off-diagonal coupling is dropped, so the model's at-rest
// compliance has the static kernel's diagonal exactly and moves the static footprint by
// truncation_error() (0.01 % at the default mesh; docs/transient.md section 1).
//
// Tread, per unit, vertical: relaxed stiffness k_i = 1 / (cos^2/k_r + sin^2/k_t) (the static
// footprint's tread, tyre_model.h). Relaxation off (seed 001 eq. 6): f_i = k_i max(0, p_i).
// Relaxation on (eq. 9-10): a Kelvin-Voigt element (k', c' = k' tan(delta)/Omega_ref) in series
// with an instantaneous spring k_g = ratio k_i (k' = k_i ratio/(ratio-1), so 1/k_g + 1/k' =
// 1/k_i: the static limit is again k_i); e_i is the Kelvin-Voigt deformation:
//   f_i = k_g max(0, p_i - e_i),   c' De_i/Dt + k' e_i = f_i,
//   De/Dt = de/dt - Omega de/dtheta (material flows backward through the ground-fixed units;
//   second-order upwind difference, undeformed rubber enters at the front of the window).
// Penetration of the undeformed tread surface: p_i = z + h(x_i, t) - s_i - u_i, z the hub's
// downward displacement, s_i the sag R0 (1 - cos theta_i), h the road profile (cleat), u_i =
// psi_i q + V_i r the carcass's upward displacement.
//
// Hub: m z'' = F(t) - sum f_i (load control; the scenario gives F and Omega).
#include <Eigen/Dense>
#include <vector>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"

namespace modaltyre::transient {

using contact::TransientSettings;
using contact::TyreModel;

struct TransientModel {
  TyreModel tyre;
  TransientSettings settings;
  int m = 0;   ///< candidate units
  int nq = 0;  ///< dynamic modal coordinates
  int nr = 0;  ///< residual (quasi-static) coordinates
  // Dynamic coordinates.
  std::vector<double> omega, zeta;
  std::vector<int> order;
  std::vector<int> partner;       ///< the other member of a (cos, sin) pair, -1 if none
  std::vector<double> pair_sign;  ///< +1 for the cos member, -1 for the sin member, 0 if none
  Eigen::MatrixXd psi;            ///< m x nq vertical shapes
  Eigen::MatrixXd phi_r, phi_t;   ///< m x nq radial and tangential shapes
  // Residual.
  Eigen::MatrixXd V;                       ///< m x nr
  Eigen::MatrixXd psi_by_unit, V_by_unit;  ///< psi^T (nq x m) and V^T (nr x m): a unit per column
  Eigen::VectorXd lambda;                  ///< nr, [m/N]
  /// Diagonal of the residual eigenpairs not integrated (lambda below the truncation), lumped
  /// in series with the tread spring [m/N]; m entries.
  Eigen::VectorXd residual_lumped;
  double tau_residual_s = 0;
  modal::LagKernels residual_kernels;  ///< radial/tangential kernels of the residual orders
  int residual_min_order = 0;
  double residual_min_omega = 0;
  // Contact basis: the carcass's vertical displacement at the units lies in a space of small
  // rank (the default carcass's 44 shapes are trigonometric of orders 0-6 in theta: rank 13).
  // [psi V] = T [Cq Cr] to settings.contact_basis_cutoff of its norm (SVD, smaller singular
  // values dropped: 1e-9 of the largest, ~1e-11 m of displacement; the default carcass's
  // singular values fall by ~5 per index beyond the 26th), so u = T xi with xi = Cq q + Cr r,
  // and the generalised forces are
  // psi^T f = Cq^T (T^T f), V^T f = Cr^T (T^T f): every product over the units costs rank
  // instead of nq + nr per unit, and the contact's coupling in Newton's matrix has that rank.
  int rank = 0;
  Eigen::MatrixXd T;          ///< m x rank
  Eigen::MatrixXd T_by_unit;  ///< T^T (rank x m): a unit per column
  Eigen::MatrixXd Cq, Cr;     ///< rank x nq, rank x nr
  // Tread.
  Eigen::VectorXd k_relaxed;         ///< k_i [N/m]
  Eigen::VectorXd k_contact;         ///< spring between penetration and force: k_i (off) or k_g
  Eigen::VectorXd k_kv, c_kv;        ///< Kelvin-Voigt element (relaxation on)
  double tread_time_constant_s = 0;  ///< c'/k' = tan(delta) / Omega_ref
  Eigen::VectorXd x_road;            ///< R0 sin theta_i

  int state_size() const { return 2 * nq + nr + 2 + (settings.relaxation ? m : 0); }
  int z_index() const { return 2 * nq + nr; }
  int e_index() const { return 2 * nq + nr + 2; }
  /// Vertical compliance of the model at rest (carcass dynamic + residual + tread) [m/N].
  Eigen::MatrixXd at_rest_compliance() const;
};

/// How far the truncated residual moves the model from the static kernel at rest: the static
/// footprint under `load_N` solved with at_rest_compliance() against the one solved with
/// TyreModel::vertical_compliance (relative differences of sinking and length), and the largest
/// entry of the compliance difference relative to the largest compliance.
struct TruncationError {
  double sinking_rel = 0, length_rel = 0, compliance_rel = 0;
};
TruncationError truncation_error(const TransientModel& model, double load_N);

/// Builds the transient model (settings from tyre.config.transient).
TransientModel build_transient_model(const TyreModel& tyre);

/// The carcass at rest under unit forces f (m): q = psi^T f / omega^2 (nq) and the residual
/// coordinates r = diag(lambda) V^T f (nr), the steady state of the equations above.
struct StaticCarcass {
  Eigen::VectorXd q, r;
};
StaticCarcass static_carcass(const TransientModel& model, const Eigen::VectorXd& f);

}  // namespace modaltyre::transient
