#pragma once
// The Newton solvers' tests (contact_newton_test.cc, cell_newton_test.cc): a structured solve of
// (I - gamma J) x = b against a dense LU of the same matrix, b a fixed smooth vector.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

namespace modaltyre::transient {

/// b_k = cos(0.7 k) (1 + k mod 5).
inline Eigen::VectorXd smooth_rhs(Eigen::Index n) {
  Eigen::VectorXd b(n);
  for (Eigen::Index k = 0; k < n; ++k) b(k) = std::cos(0.7 * k) * (1.0 + k % 5);
  return b;
}

/// newton.solve() of A x = smooth_rhs() within tol of A's dense LU (relative to its largest
/// entry); returns x.
template <class Newton>
Eigen::VectorXd expect_solve_near_dense_lu(Newton& newton, const Eigen::MatrixXd& A, double tol) {
  const Eigen::VectorXd b = smooth_rhs(A.rows());
  Eigen::VectorXd x = b;
  newton.solve(x.data());
  const Eigen::VectorXd want = A.partialPivLu().solve(b);
  EXPECT_LT((x - want).cwiseAbs().maxCoeff(), tol * want.cwiseAbs().maxCoeff());
  return x;
}

}  // namespace modaltyre::transient
