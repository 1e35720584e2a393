#pragma once
// The largest eigenpairs of a dense symmetric matrix, without the full eigenvector matrix.
//
// Householder tridiagonalisation A = Q T Q^T (Eigen), all eigenvalues of T (implicit QL, no
// vectors), then for each eigenvalue kept an eigenvector of T by inverse iteration on T - lambda I
// (tridiagonal LU with partial pivoting, as LAPACK's dgttrf/dgtts2), re-orthogonalised within
// clusters of close eigenvalues (|lambda_a - lambda_b| <= 1e-3 |T|, as LAPACK's dstein), and back
// to A's basis by Q. Cost: the tridiagonalisation (4/3 n^3) plus O(n^2) per vector, against the
// accumulation of all n eigenvectors (~3 n^3 more) of a full SelfAdjointEigenSolver. Used for the
// truncated residual compliance of the transient model, which keeps ~16 of ~700 pairs.
#include <Eigen/Dense>

namespace modaltyre::solvers {

struct EigenPairs {
  Eigen::VectorXd values;   ///< kept eigenvalues, descending
  Eigen::MatrixXd vectors;  ///< n x kept, orthonormal columns
  double largest_abs = 0;   ///< max |eigenvalue| of the whole matrix
};

/// Eigenpairs of the symmetric matrix `a` (lower triangle used) with eigenvalue >=
/// `fraction` * max |eigenvalue|, fraction in (0, 1]. ComputationError if inverse iteration
/// does not converge.
EigenPairs leading_eigenpairs(const Eigen::MatrixXd& a, double fraction);

}  // namespace modaltyre::solvers
