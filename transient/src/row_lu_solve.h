#pragma once
// x = U^-1 L^-1 P b for a small dense P A = L U (partial pivoting, row-major factors, unit L):
// plain loops, which for the Newton solves' capacitance matrices (n ~ 10-40) cost several times
// less than Eigen's dynamic-size triangular solver; row_lu_factor() makes the factors. Shared by
// ContactNewton and CellNewton.
#include <Eigen/Dense>
#include <vector>

#include "cell_kernels.h"

namespace modaltyre::transient {

/// The row-major LU of a (n x n, partial pivoting, detail::lu_factor) and the permutation
/// row_lu_solve() reads (perm(original row) = its position); rows is work space. False at a
/// zero or non-finite pivot. Eigen's blocked LU would run these 10-42 squares through its
/// matrix-product kernels.
inline bool row_lu_factor(
    const Eigen::MatrixXd& a,
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& lu_matrix,
    Eigen::VectorXi& perm, std::vector<int>& rows) {
  const int n = static_cast<int>(a.rows());
  lu_matrix.resize(n, n);
  rows.resize(n);
  if (!detail::lu_factor(n, a.data(), lu_matrix.data(), rows.data())) return false;
  perm.resize(n);
  for (int pos = 0; pos < n; ++pos) perm(rows[pos]) = pos;
  return true;
}

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
