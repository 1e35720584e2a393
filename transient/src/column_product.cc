#include "modaltyre/transient/column_product.h"

#include <cmath>

#include "modaltyre/solvers/instruction_set.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define MODALTYRE_COLUMN_PRODUCT_AVX2 1
#endif

namespace modaltyre::transient {
namespace {

using Index = Eigen::Index;

/// Rows [i0, i1) one at a time: the portable path and the tails. s = fma(A_ij, x_j, s) over the
/// columns in order (std::fma: one rounding, as the AVX2 path's fused multiply-add).
void rows_scalar(Index i0, Index i1, Index cols, const double* A, Index lda, const double* x,
                 double* out, bool accumulate) {
  for (Index i = i0; i < i1; ++i) {
    double s = 0.0;
    for (Index j = 0; j < cols; ++j) s = std::fma(A[j * lda + i], x[j], s);
    out[i] = s + (accumulate ? out[i] : 0.0);
  }
}

#ifdef MODALTYRE_COLUMN_PRODUCT_AVX2
/// Rows [i, i + 4 V) in V registers, each a chain of fused multiply-adds over the columns.
template <int V>
__attribute__((target("avx2,fma"))) inline void rows_block(Index i, Index cols, const double* A,
                                                           Index lda, const double* x, double* out,
                                                           bool accumulate) {
  __m256d c[V];
  for (int v = 0; v < V; ++v) c[v] = _mm256_setzero_pd();
  for (Index j = 0; j < cols; ++j) {
    const double* a = A + j * lda + i;
    const __m256d b = _mm256_broadcast_sd(x + j);
    for (int v = 0; v < V; ++v) c[v] = _mm256_fmadd_pd(_mm256_loadu_pd(a + 4 * v), b, c[v]);
  }
  double* o = out + i;
  for (int v = 0; v < V; ++v)
    _mm256_storeu_pd(o + 4 * v, _mm256_add_pd(c[v], accumulate ? _mm256_loadu_pd(o + 4 * v)
                                                               : _mm256_setzero_pd()));
}

/// 32 rows at a time in eight AVX2 registers (fused multiply-add; eight independent chains, so
/// that the multiply-adds' latency overlaps: four had left the loop latency-bound), then 16, 4.
__attribute__((target("avx2,fma"))) Index rows_avx2(Index rows, Index cols, const double* A,
                                                    Index lda, const double* x, double* out,
                                                    bool accumulate) {
  Index i = 0;
  for (; i + 32 <= rows; i += 32) rows_block<8>(i, cols, A, lda, x, out, accumulate);
  for (; i + 16 <= rows; i += 16) rows_block<4>(i, cols, A, lda, x, out, accumulate);
  for (; i + 4 <= rows; i += 4) rows_block<1>(i, cols, A, lda, x, out, accumulate);
  for (; i < rows; ++i) {  // the last rows % 4, as rows_scalar() (std::fma: vfmadd here)
    double c = 0.0;
    for (Index j = 0; j < cols; ++j) c = std::fma(A[j * lda + i], x[j], c);
    out[i] = c + (accumulate ? out[i] : 0.0);
  }
  return i;
}
#endif

/// Outputs [k0, k1) of column_dots() one at a time: four partial sums over the rows i = 0, 1, 2,
/// 3 mod 4 (the AVX2 lanes), added as (s0 + s1) + (s2 + s3), then the last rows % 4 in order;
/// every product fused with its addition (std::fma, as the AVX2 path).
void dots_scalar(Index k0, Index k1, Index rows, const double* A, Index lda, const double* v,
                 double* out, double alpha, bool accumulate) {
  for (Index k = k0; k < k1; ++k) {
    const double* a = A + k * lda;
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    Index i = 0;
    for (; i + 4 <= rows; i += 4) {
      s0 = std::fma(a[i], v[i], s0), s1 = std::fma(a[i + 1], v[i + 1], s1);
      s2 = std::fma(a[i + 2], v[i + 2], s2), s3 = std::fma(a[i + 3], v[i + 3], s3);
    }
    double s = (s0 + s1) + (s2 + s3);
    for (; i < rows; ++i) s = std::fma(a[i], v[i], s);
    out[k] = (accumulate ? out[k] : 0.0) + alpha * s;
  }
}

#ifdef MODALTYRE_COLUMN_PRODUCT_AVX2
/// out_k from the four lanes of c and the last rows % 4.
__attribute__((target("avx2,fma"))) void dots_finish(__m256d c, Index k, Index r4, Index rows,
                                                     const double* A, Index lda, const double* v,
                                                     double* out, double alpha, bool accumulate) {
  alignas(32) double l[4];
  _mm256_store_pd(l, c);
  double s = (l[0] + l[1]) + (l[2] + l[3]);
  const double* a = A + k * lda;
  for (Index i = r4; i < rows; ++i) s = std::fma(a[i], v[i], s);
  out[k] = (accumulate ? out[k] : 0.0) + alpha * s;
}

/// Outputs [k, k + W), each a register of four partial sums along the rows (one load of v per
/// four rows for all W), in dots_scalar()'s order.
template <int W>
__attribute__((target("avx2,fma"))) inline void dots_block(Index k, Index r4, Index rows,
                                                           const double* A, Index lda,
                                                           const double* v, double* out,
                                                           double alpha, bool accumulate) {
  __m256d c[W];
  for (int w = 0; w < W; ++w) c[w] = _mm256_setzero_pd();
  const double* a = A + k * lda;
  for (Index i = 0; i < r4; i += 4) {
    const __m256d b = _mm256_loadu_pd(v + i);
    for (int w = 0; w < W; ++w) c[w] = _mm256_fmadd_pd(_mm256_loadu_pd(a + w * lda + i), b, c[w]);
  }
  for (int w = 0; w < W; ++w) dots_finish(c[w], k + w, r4, rows, A, lda, v, out, alpha, accumulate);
}

/// Eight outputs at a time (eight independent chains: four had left the loop latency-bound),
/// then four, then one.
__attribute__((target("avx2,fma"))) Index dots_avx2(Index rows, Index cols, const double* A,
                                                    Index lda, const double* v, double* out,
                                                    double alpha, bool accumulate) {
  Index k = 0;
  const Index r4 = rows / 4 * 4;
  for (; k + 8 <= cols; k += 8) dots_block<8>(k, r4, rows, A, lda, v, out, alpha, accumulate);
  for (; k + 4 <= cols; k += 4) dots_block<4>(k, r4, rows, A, lda, v, out, alpha, accumulate);
  for (; k < cols; ++k) dots_block<1>(k, r4, rows, A, lda, v, out, alpha, accumulate);
  return k;
}
#endif

}  // namespace

void column_dots(Index rows, Index cols, const double* A, Index lda, const double* v, double* out,
                 double alpha, bool accumulate) {
  Index done = 0;
#ifdef MODALTYRE_COLUMN_PRODUCT_AVX2
  static const bool avx2 = solvers::instruction_set() == solvers::InstructionSet::avx2_fma;
  if (avx2) done = dots_avx2(rows, cols, A, lda, v, out, alpha, accumulate);
#endif
  dots_scalar(done, cols, rows, A, lda, v, out, alpha, accumulate);
}

void column_product(Index rows, Index cols, const double* A, Index lda, const double* x,
                    double* out, bool accumulate) {
  Index done = 0;
#ifdef MODALTYRE_COLUMN_PRODUCT_AVX2
  static const bool avx2 = solvers::instruction_set() == solvers::InstructionSet::avx2_fma;
  if (avx2) done = rows_avx2(rows, cols, A, lda, x, out, accumulate);
#endif
  rows_scalar(done, rows, cols, A, lda, x, out, accumulate);
}

}  // namespace modaltyre::transient
