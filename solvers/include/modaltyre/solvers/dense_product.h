#pragma once
// Dense column-major products with several right-hand sides in one pass over the matrix
// (DenseCompliance::apply(), the lockstep CG of the dense contact solve; the 3D transient's
// Newton solve, CellNewton; issue 47).
#include <Eigen/Dense>

namespace modaltyre::solvers::detail {

/// Y.col(c) = A X.col(c) for every column c of X, A = the nr x nc block at `a` of a column-major
/// matrix with leading dimension lda. Every entry is Eigen 3.4's column-major matrix-vector
/// product's on SSE2 to the bit (a multiply, then an add: no fused multiply-add; the columns in
/// order, in blocks of 16, or of 4 when lda >= 4000, once nc >= 128, each block's sum added to
/// the entry), so the answers do not depend on the path. The AVX2 path (solvers/instruction_set.h)
/// reads each column of A once for all of X's columns instead of once per column: the matrix of
/// m ~ 1000 does not fit in the caches and the product is bound by reading it.
void dense_product(int nr, int nc, const double* a, int lda,
                   const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::MatrixXd> Y);

}  // namespace modaltyre::solvers::detail
