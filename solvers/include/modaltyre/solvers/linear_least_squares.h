#pragma once
// Linear least squares with standard errors (Eigen, column-pivoted QR on scaled columns).
// The nonlinear counterpart is levenberg_marquardt.h.
#include <Eigen/Dense>

namespace modaltyre::solvers {

struct LinearFit {
  Eigen::VectorXd coef;       ///< minimiser of |A c - b|
  Eigen::VectorXd std_error;  ///< sqrt(diag(s^2 (A^T A)^-1)), s^2 = RSS / (n - p); 0 if n == p
  Eigen::VectorXd residuals;  ///< A c - b
  double residual_rms = 0.0;  ///< sqrt(RSS / n)
};

/// Solves A c ~ b. Throws ComputationError if A is rank deficient (callers reject degenerate
/// inputs first, with an InputError that names the cause).
LinearFit solve_linear_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace modaltyre::solvers
