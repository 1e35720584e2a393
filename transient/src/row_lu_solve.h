#pragma once
// x = U^-1 L^-1 P b for a small dense P A = L U (partial pivoting, row-major factors, unit L):
// plain loops, which for the Newton solves' capacitance matrices (n ~ 10-40) cost several times
// less than Eigen's dynamic-size triangular solver. Shared by ContactNewton and CellNewton.
#include <Eigen/Dense>

namespace modaltyre::transient {

inline void row_lu_solve(
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& lu_matrix,
    const Eigen::VectorXi& perm, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const int n = static_cast<int>(perm.size());
  x.resize(n);
  for (int i = 0; i < n; ++i) x(perm(i)) = b(i);
  const double* lu = lu_matrix.data();
  for (int i = 1; i < n; ++i) {
    double s = x(i);
    for (int j = 0; j < i; ++j) s -= lu[i * n + j] * x(j);
    x(i) = s;
  }
  for (int i = n - 1; i >= 0; --i) {
    double s = x(i);
    for (int j = i + 1; j < n; ++j) s -= lu[i * n + j] * x(j);
    x(i) = s / lu[i * n + i];
  }
}

}  // namespace modaltyre::transient
