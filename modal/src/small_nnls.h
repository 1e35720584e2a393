#pragma once
// Non-negative least squares for a handful of unknowns (the dispersion's three, the ring's
// four): every support set is solved by QR and the best feasible one kept, which is exact for
// this size. Shared by dispersion.cc and ring_model.cc.
#include <Eigen/Dense>
#include <limits>
#include <vector>

namespace modaltyre::modal::detail {

/// min |X x - y| over x >= 0 with at most `max_support` non-zero unknowns; false (x zero) when
/// no support gives a non-negative solution.
inline bool small_nnls(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, int max_support,
                       Eigen::VectorXd& x) {
  const int n = static_cast<int>(X.cols());
  double best = std::numeric_limits<double>::infinity();
  x = Eigen::VectorXd::Zero(n);
  for (int mask = 1; mask < (1 << n); ++mask) {
    std::vector<int> cols;
    for (int c = 0; c < n; ++c)
      if (mask & (1 << c)) cols.push_back(c);
    if (static_cast<int>(cols.size()) > max_support) continue;
    Eigen::MatrixXd Xs(X.rows(), cols.size());
    for (std::size_t j = 0; j < cols.size(); ++j) Xs.col(j) = X.col(cols[j]);
    const Eigen::VectorXd s = Xs.colPivHouseholderQr().solve(y);
    if ((s.array() < 0).any()) continue;
    const double r = (Xs * s - y).squaredNorm();
    if (r < best) {
      best = r;
      x.setZero();
      for (std::size_t j = 0; j < cols.size(); ++j) x(cols[j]) = s(j);
    }
  }
  return best < std::numeric_limits<double>::infinity();
}

}  // namespace modaltyre::modal::detail
