#include "modaltyre/solvers/linear_least_squares.h"

#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::solvers {

LinearFit solve_linear_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  MODALTYRE_CHECK(A.rows() == b.size() && A.rows() >= A.cols() && A.cols() > 0,
                  "least squares: bad dimensions");
  // Scale columns so that the rank decision does not depend on the units of the unknowns.
  Eigen::VectorXd scale = A.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < scale.size(); ++j)
    if (scale(j) == 0) throw ComputationError("least squares: a column of the design is zero");
  const Eigen::MatrixXd As = A * scale.cwiseInverse().asDiagonal();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(As);
  qr.setThreshold(1e-10);
  if (qr.rank() < As.cols())
    throw ComputationError("least squares: the unknowns cannot be separated by these data");
  LinearFit fit;
  const Eigen::VectorXd cs = qr.solve(b);
  fit.coef = cs.cwiseQuotient(scale);
  fit.residuals = A * fit.coef - b;
  const double rss = fit.residuals.squaredNorm();
  const auto n = A.rows(), p = A.cols();
  fit.residual_rms = std::sqrt(rss / static_cast<double>(n));
  fit.std_error = Eigen::VectorXd::Zero(p);
  if (n > p) {
    const double s2 = rss / static_cast<double>(n - p);
    const Eigen::MatrixXd inv =
        (As.transpose() * As).inverse();  // small p: explicit inverse is fine
    for (Eigen::Index j = 0; j < p; ++j)
      fit.std_error(j) = std::sqrt(std::max(0.0, s2 * inv(j, j))) / scale(j);
  }
  return fit;
}

}  // namespace modaltyre::solvers
