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

/// out_k (=, or += with accumulate) alpha sum_i A(i, k) v_i for k < cols, i < rows: the
/// transposed product A^T v (T^T f over the reach, Cq^T phi, T~^T w). Each sum is that of
/// Eigen 3.4's row-major GEMV on SSE2, kept on AVX2 by two outputs per 256-bit register: the
/// even and odd terms in two partial sums (pairs in order), added, then the odd last term;
/// the destination gets alpha times it added (0 for an assignment).
void transposed_product(Eigen::Index rows, Eigen::Index cols, const double* A, Eigen::Index lda,
                        const double* v, double* out, double alpha = 1.0, bool accumulate = false);

/// The same for an Eigen block A (the product A.transpose() * v).
template <typename Block, typename Out>
void transposed_product(const Block& A, const Eigen::Ref<const Eigen::VectorXd>& v, Out&& out,
                        double alpha = 1.0, bool accumulate = false) {
  transposed_product(A.rows(), A.cols(), A.data(), A.outerStride(), v.data(), out.data(), alpha,
                     accumulate);
}

/// out_k (=, or += with accumulate) alpha sum_i A(i, k) v_i like transposed_product(), for many
/// rows (the units over the reach or in contact): vectorised along the rows, each sum as four
/// partial sums over the rows i mod 4, (s0 + s1) + (s2 + s3), then the last rows % 4 in order,
/// the same on the AVX2 and the portable path. Not Eigen's order (~2x fewer instructions than
/// transposed_product() for a few hundred rows).
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
