#include "modaltyre/solvers/levenberg_marquardt.h"

#include <cmath>

namespace modaltyre::solvers {

LeastSquaresResult levenberg_marquardt(
    const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& residual,
    const Eigen::VectorXd& x0, const LeastSquaresOptions& opt) {
  LeastSquaresResult res;
  Eigen::VectorXd x = x0;
  Eigen::VectorXd r = residual(x);
  ++res.evaluations;
  double cost = 0.5 * r.squaredNorm();
  double lambda = 1e-3;
  const int n = static_cast<int>(x.size());
  for (int it = 1; it <= opt.max_iterations; ++it) {
    res.iterations = it;
    Eigen::MatrixXd J(r.size(), n);
    for (int j = 0; j < n; ++j) {
      const double h = opt.relative_step * std::max(std::abs(x(j)), 1.0);
      Eigen::VectorXd xp = x;
      xp(j) += h;
      J.col(j) = (residual(xp) - r) / h;
      ++res.evaluations;
    }
    const Eigen::VectorXd g = J.transpose() * r;
    if (g.lpNorm<Eigen::Infinity>() < opt.gradient_tolerance) {
      res.status = SolveStatus::converged;
      res.message = "gradient below tolerance";
      break;
    }
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    bool improved = false;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal() += lambda * JtJ.diagonal().cwiseMax(1e-12);
      const Eigen::VectorXd dx = A.ldlt().solve(-g);
      const Eigen::VectorXd xn = x + dx;
      const Eigen::VectorXd rn = residual(xn);
      ++res.evaluations;
      const double cn = 0.5 * rn.squaredNorm();
      if (std::isfinite(cn) && cn < cost) {
        const bool small = dx.norm() < opt.step_tolerance * (x.norm() + opt.step_tolerance) ||
                           cost - cn < opt.cost_tolerance * cost;
        x = xn;
        r = rn;
        cost = cn;
        lambda = std::max(lambda / 3, 1e-12);
        improved = true;
        if (small) {
          res.status = SolveStatus::converged;
          res.message = "step below tolerance";
        }
      } else {
        lambda *= 4;
      }
    }
    if (!improved) {
      // No descent direction left at finite-difference precision.
      res.status = SolveStatus::converged;
      res.message = "no further decrease";
    }
    if (res.ok()) break;
  }
  if (!res.ok()) res.message = "iteration limit reached";
  res.x = x;
  res.residual = r;
  res.cost = cost;
  return res;
}

}  // namespace modaltyre::solvers
