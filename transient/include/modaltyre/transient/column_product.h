#pragma once
// out = A x for a column-major A with few columns (the contact basis T: m x rank, rank ~ 13;
// Cq: rank x nq; ContactNewton's T~: units x (rank + 1)), vectorised over the rows.
//
// Why: these products are the largest single item of a transient step (callgrind, free
// vibration: Eigen's column-major GEMV ~19 % of the run), and the library is compiled for
// SSE2. This kernel has an AVX2 path chosen at run time (multiply then add, no FMA). Each out_i is
// 0 + ((A_i0 x_0 + A_i1 x_1) + ...) summed over the columns in order, the order of Eigen 3.4's
// column-major GEMV without FMA, so the results are those of `A * x` to the bit (checked by the
// transient outputs being byte-identical; docs/transient.md section 6).
#include <Eigen/Dense>

namespace modaltyre::transient {

/// out_i (=, or += with accumulate) sum_j A(i, j) x_j for i < rows, j < cols; A column-major
/// with leading dimension lda. out must not overlap A or x.
void column_product(Eigen::Index rows, Eigen::Index cols, const double* A, Eigen::Index lda,
                    const double* x, double* out, bool accumulate = false);

/// The same for an Eigen block (A.data(), A.outerStride()) into a vector segment.
template <typename Block, typename Out>
void column_product(const Block& A, const Eigen::Ref<const Eigen::VectorXd>& x, Out&& out,
                    bool accumulate = false) {
  column_product(A.rows(), A.cols(), A.data(), A.outerStride(), x.data(), out.data(), accumulate);
}

}  // namespace modaltyre::transient
