#include "modaltyre/solvers/dense_product.h"

#include <algorithm>

#include "modaltyre/solvers/instruction_set.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define MODALTYRE_DENSE_PRODUCT_AVX2
#endif

namespace modaltyre::solvers::detail {
namespace {

/// Eigen 3.4's column blocking of a column-major matrix-vector product
/// (GeneralMatrixVector.h: block_cols).
int eigen_block_columns(int nc, int lda) {
  return nc < 128 ? nc
                  : (static_cast<long>(lda) * static_cast<long>(sizeof(double)) < 32000 ? 16 : 4);
}

#ifdef MODALTYRE_DENSE_PRODUCT_AVX2
/// Rows [i, i + 8) of two right-hand sides (x0, x1; y0, y1), columns [j0, j1): the sums in
/// registers, then added to the entries.
__attribute__((target("avx2"))) inline void two_rows8(int i, int j0, int j1, const double* a,
                                                      int lda, const double* x0, const double* x1,
                                                      double* y0, double* y1) {
  __m256d c00 = _mm256_setzero_pd(), c01 = c00, c10 = c00, c11 = c00;
  for (int j = j0; j < j1; ++j) {
    const double* col = a + static_cast<long>(j) * lda + i;
    const __m256d p = _mm256_loadu_pd(col), q = _mm256_loadu_pd(col + 4);
    const __m256d b0 = _mm256_broadcast_sd(x0 + j), b1 = _mm256_broadcast_sd(x1 + j);
    c00 = _mm256_add_pd(_mm256_mul_pd(p, b0), c00);
    c01 = _mm256_add_pd(_mm256_mul_pd(q, b0), c01);
    c10 = _mm256_add_pd(_mm256_mul_pd(p, b1), c10);
    c11 = _mm256_add_pd(_mm256_mul_pd(q, b1), c11);
  }
  _mm256_storeu_pd(y0 + i, _mm256_add_pd(c00, _mm256_loadu_pd(y0 + i)));
  _mm256_storeu_pd(y0 + i + 4, _mm256_add_pd(c01, _mm256_loadu_pd(y0 + i + 4)));
  _mm256_storeu_pd(y1 + i, _mm256_add_pd(c10, _mm256_loadu_pd(y1 + i)));
  _mm256_storeu_pd(y1 + i + 4, _mm256_add_pd(c11, _mm256_loadu_pd(y1 + i + 4)));
}

/// One right-hand side, rows [i, i + 8).
__attribute__((target("avx2"))) inline void one_rows8(int i, int j0, int j1, const double* a,
                                                      int lda, const double* x, double* y) {
  __m256d c0 = _mm256_setzero_pd(), c1 = c0;
  for (int j = j0; j < j1; ++j) {
    const double* col = a + static_cast<long>(j) * lda + i;
    const __m256d b = _mm256_broadcast_sd(x + j);
    c0 = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(col), b), c0);
    c1 = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(col + 4), b), c1);
  }
  _mm256_storeu_pd(y + i, _mm256_add_pd(c0, _mm256_loadu_pd(y + i)));
  _mm256_storeu_pd(y + i + 4, _mm256_add_pd(c1, _mm256_loadu_pd(y + i + 4)));
}

/// Rows [i, i + 4) of one or two right-hand sides (x1, y1 null for one): the rows 8 at a time
/// leave (the per-entry sums are the same, in the same order, for any grouping of the rows).
__attribute__((target("avx2"))) inline void rows4(int i, int j0, int j1, const double* a, int lda,
                                                  const double* x0, const double* x1, double* y0,
                                                  double* y1) {
  __m256d c0 = _mm256_setzero_pd(), c1 = c0;
  for (int j = j0; j < j1; ++j) {
    const __m256d p = _mm256_loadu_pd(a + static_cast<long>(j) * lda + i);
    c0 = _mm256_add_pd(_mm256_mul_pd(p, _mm256_broadcast_sd(x0 + j)), c0);
    if (x1) c1 = _mm256_add_pd(_mm256_mul_pd(p, _mm256_broadcast_sd(x1 + j)), c1);
  }
  _mm256_storeu_pd(y0 + i, _mm256_add_pd(c0, _mm256_loadu_pd(y0 + i)));
  if (y1) _mm256_storeu_pd(y1 + i, _mm256_add_pd(c1, _mm256_loadu_pd(y1 + i)));
}

/// The AVX2 path (no FMA: the target has none, so nothing is contracted). Y starts at zero, as
/// Eigen's product sets it before adding each column block's sums.
__attribute__((target("avx2"))) void dense_product_avx2(int nr, int nc, const double* a, int lda,
                                                        const Eigen::Ref<const Eigen::MatrixXd>& X,
                                                        Eigen::Ref<Eigen::MatrixXd> Y) {
  const int nrhs = static_cast<int>(X.cols()), block = eigen_block_columns(nc, lda);
  Y.setZero();
  for (int c = 0; c < nrhs; c += 2) {
    const bool pair = c + 1 < nrhs;
    const double *x0 = X.col(c).data(), *x1 = pair ? X.col(c + 1).data() : nullptr;
    double *y0 = Y.col(c).data(), *y1 = pair ? Y.col(c + 1).data() : nullptr;
    for (int j0 = 0; j0 < nc; j0 += block) {
      const int j1 = std::min(nc, j0 + block);
      int i = 0;
      for (; i + 8 <= nr; i += 8) {
        if (pair)
          two_rows8(i, j0, j1, a, lda, x0, x1, y0, y1);
        else
          one_rows8(i, j0, j1, a, lda, x0, y0);
      }
      if (i + 4 <= nr) {
        rows4(i, j0, j1, a, lda, x0, x1, y0, y1);
        i += 4;
      }
      for (; i < nr; ++i) {  // the last nr % 4 rows
        double s0 = 0, s1 = 0;
        for (int j = j0; j < j1; ++j) {
          const double aij = a[static_cast<long>(j) * lda + i];
          s0 = aij * x0[j] + s0;
          if (pair) s1 = aij * x1[j] + s1;
        }
        y0[i] = s0 + y0[i];
        if (pair) y1[i] = s1 + y1[i];
      }
    }
  }
}
#endif

}  // namespace

void dense_product(int nr, int nc, const double* a, int lda,
                   const Eigen::Ref<const Eigen::MatrixXd>& X, Eigen::Ref<Eigen::MatrixXd> Y) {
#ifdef MODALTYRE_DENSE_PRODUCT_AVX2
  // (One row: Eigen takes a dot product there, in its own order.)
  if (instruction_set() == InstructionSet::avx2_fma && nr > 1 && nc > 0)
    return dense_product_avx2(nr, nc, a, lda, X, Y);
#endif
  // The portable path: Eigen's product column by column (a matrix-matrix product with two
  // columns would first copy (pack) the whole block).
  const Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> A(a, nr, nc,
                                                                     Eigen::OuterStride<>(lda));
  for (Eigen::Index c = 0; c < X.cols(); ++c) Y.col(c).noalias() = A * X.col(c);
}

}  // namespace modaltyre::solvers::detail
