#pragma once
// out = A x for a column-major A with few columns (the contact basis T: m x rank, rank ~ 13;
// Cq: rank x nq; ContactNewton's T~: units x (rank + 1)), vectorised over the rows.
//
// Why: these products are the largest single item of a transient step (callgrind, free
// vibration: Eigen's column-major GEMV ~19 % of the run), and the library is compiled for
// SSE2. This kernel has an AVX2 + FMA path chosen at run time. Each out_i is
// fma(A_i,n-1, x_n-1, ... fma(A_i1, x_1, fma(A_i0, x_0, 0))) over the columns in order (+ out_i
// when accumulating); the portable path computes the same with std::fma, so every CPU gives the
// same bits. (Until issue 21's sixth round this was Eigen's order without FMA, to keep the
// trajectories to the bit; docs/transient.md section 6.)
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

/// out_k (=, or += with accumulate) alpha sum_i A(i, k) v_i: the transposed product A^T v
/// (T^T f over the reach, T~^T w over the units in contact, Cq q as Cq^T's columns with q),
/// vectorised along the rows. Each sum is four partial sums of fused multiply-adds over the rows
/// i mod 4, (s0 + s1) + (s2 + s3), then the last rows % 4 in order, the same on the AVX2 + FMA
/// and the portable (std::fma) path. Not Eigen's order (~2-3x fewer instructions than Eigen's
/// row-major GEMV for a few hundred rows).
void column_dots(Eigen::Index rows, Eigen::Index cols, const double* A, Eigen::Index lda,
                 const double* v, double* out, double alpha = 1.0, bool accumulate = false);

/// The same for an Eigen block A (A^T v).
template <typename Block, typename Out>
void column_dots(const Block& A, const Eigen::Ref<const Eigen::VectorXd>& v, Out&& out,
                 double alpha = 1.0, bool accumulate = false) {
  column_dots(A.rows(), A.cols(), A.data(), A.outerStride(), v.data(), out.data(), alpha,
              accumulate);
}

}  // namespace modaltyre::transient
