#pragma once
// The covariance of the output-error pole estimate (refine_poles) and of the LSFD residues,
// linearised at the fit, with each FRF's noise estimated from its fit residual (issue 35;
// derivation in docs/uncertainty.md, section 5).
//
// Model: y_o = A(x) c_o + e_o per FRF o (stacked real and imaginary parts, lsfd.h), x = (ln f_k,
// ln zeta_k), e_o independent with variance s_o^2 per real component. The poles minimise
// sum_o w_o^2 |P(x) y_o|^2 (P the projector off A's columns; w_o the refinement's weight of FRF
// o), the residues are c_o = A^+ y_o at the poles. To first order (Gauss-Newton, the variable
// projection's Jacobian K_o = P J_o, J_o = d(A c_o)/dx):
//   Cov(x)          = S^-1 (sum_o w_o^4 s_o^2 K_o^T K_o) S^-1,   S = sum_o w_o^2 K_o^T K_o,
//   Cov(c_o, c_p)   = delta_op s_o^2 (A^T A)^-1 + G_o Cov(x) G_p^T,   G_o = A^+ J_o,
// (A^+ e_o is uncorrelated with x's error since A^+ P = 0).
#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "modaltyre/ema/frf_set.h"

namespace modaltyre::ema {

struct LsfdCovariance {
  /// 2m x 2m: (ln f_1 ... ln f_m, ln zeta_1 ... ln zeta_m); relative variances.
  Eigen::MatrixXd pole_cov;
  /// Per FRF: the noise's standard deviation per real component, from the fit residual.
  Eigen::VectorXd noise;
  /// Per mode k: (2 no) x (2 no) covariance of (Re R_0k, Im R_0k, Re R_1k, Im R_1k, ...).
  std::vector<Eigen::MatrixXd> residue_cov;
  double dof = 0;  ///< residual degrees of freedom per FRF
};

/// At the poles `poles` (in the LSFD order), for the lines `freq_hz` and the FRFs `frf` (lines x
/// channels, unweighted) whose poles were estimated with the channel weights `weight`.
/// ComputationError when the lines do not leave degrees of freedom for the noise.
LsfdCovariance lsfd_covariance(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf,
                               FrfType type, const std::vector<std::complex<double>>& poles,
                               const Eigen::VectorXd& weight);

/// Standard deviations of mode k's real shape values phi_o = q_o q_r^-e, where
/// q_o = Re(z R_ok) are the modal constants projected on the real axis (z = 2 j w_d e^{-j theta},
/// with theta the real normalisation's angle), r the scaling channel and e its exponent (1/2:
/// mass normalisation by the driving point; 1: a largest value of 1). Linearised.
Eigen::VectorXd real_shape_std(const LsfdCovariance& cov, int k, std::complex<double> z,
                               const Eigen::VectorXd& q, int r, double e);

}  // namespace modaltyre::ema
