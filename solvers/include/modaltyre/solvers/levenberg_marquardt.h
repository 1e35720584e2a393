#pragma once
// Small dense nonlinear least squares (Levenberg-Marquardt with a forward-difference Jacobian),
// for calibrating a handful of scalar model parameters against measurements.
#include <Eigen/Dense>
#include <functional>
#include <string>

#include "modaltyre/core/solve_status.h"

namespace modaltyre::solvers {

struct LeastSquaresOptions {
  int max_iterations = 50;
  double relative_step = 1e-4;       ///< finite-difference step, relative to |x| (or absolute at 0)
  double gradient_tolerance = 1e-10;
  double step_tolerance = 1e-8;      ///< stop when |dx| < tol (|x| + tol)
  double cost_tolerance = 1e-10;     ///< stop when a step lowers the cost by less than tol*cost
};

struct LeastSquaresResult {
  Eigen::VectorXd x;
  Eigen::VectorXd residual;
  double cost = 0;  ///< 1/2 |r|^2
  int iterations = 0;
  int evaluations = 0;
  SolveStatus status = SolveStatus::max_iterations;  ///< or converged
  std::string message;
  bool ok() const { return modaltyre::ok(status); }
};

/// Minimises 1/2 |r(x)|^2. The residual function may throw; that propagates to the caller.
LeastSquaresResult levenberg_marquardt(
    const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& residual,
    const Eigen::VectorXd& x0, const LeastSquaresOptions& options = {});

}  // namespace modaltyre::solvers
