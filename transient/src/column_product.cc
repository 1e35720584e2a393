#include "modaltyre/transient/column_product.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define MODALTYRE_COLUMN_PRODUCT_AVX2 1
#endif

namespace modaltyre::transient {
namespace {

using Index = Eigen::Index;

/// Rows [i0, i1) one at a time: the portable path and the tails.
void rows_scalar(Index i0, Index i1, Index cols, const double* A, Index lda, const double* x,
                 double* out, bool accumulate) {
  for (Index i = i0; i < i1; ++i) {
    double s = 0.0;
    for (Index j = 0; j < cols; ++j) s += A[j * lda + i] * x[j];
    // Eigen adds alpha * sum to the destination (cleared first for an assignment).
    out[i] = s + (accumulate ? out[i] : 0.0);
  }
}

#ifdef MODALTYRE_COLUMN_PRODUCT_AVX2
/// 16 rows at a time in four AVX2 registers (multiply, then add: no FMA), then 4 at a time.
__attribute__((target("avx2"))) Index rows_avx2(Index rows, Index cols, const double* A, Index lda,
                                                const double* x, double* out, bool accumulate) {
  Index i = 0;
  for (; i + 16 <= rows; i += 16) {
    __m256d c0 = _mm256_setzero_pd(), c1 = c0, c2 = c0, c3 = c0;
    for (Index j = 0; j < cols; ++j) {
      const double* a = A + j * lda + i;
      const __m256d b = _mm256_broadcast_sd(x + j);
      c0 = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(a), b), c0);
      c1 = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(a + 4), b), c1);
      c2 = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(a + 8), b), c2);
      c3 = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(a + 12), b), c3);
    }
    double* o = out + i;
    const __m256d z = _mm256_setzero_pd();
    _mm256_storeu_pd(o, _mm256_add_pd(c0, accumulate ? _mm256_loadu_pd(o) : z));
    _mm256_storeu_pd(o + 4, _mm256_add_pd(c1, accumulate ? _mm256_loadu_pd(o + 4) : z));
    _mm256_storeu_pd(o + 8, _mm256_add_pd(c2, accumulate ? _mm256_loadu_pd(o + 8) : z));
    _mm256_storeu_pd(o + 12, _mm256_add_pd(c3, accumulate ? _mm256_loadu_pd(o + 12) : z));
  }
  for (; i + 4 <= rows; i += 4) {
    __m256d c = _mm256_setzero_pd();
    for (Index j = 0; j < cols; ++j)
      c = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(A + j * lda + i), _mm256_broadcast_sd(x + j)),
                        c);
    _mm256_storeu_pd(out + i,
                     _mm256_add_pd(c, accumulate ? _mm256_loadu_pd(out + i) : _mm256_setzero_pd()));
  }
  return i;
}
#endif

}  // namespace

void column_product(Index rows, Index cols, const double* A, Index lda, const double* x,
                    double* out, bool accumulate) {
  Index done = 0;
#ifdef MODALTYRE_COLUMN_PRODUCT_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) done = rows_avx2(rows, cols, A, lda, x, out, accumulate);
#endif
  rows_scalar(done, rows, cols, A, lda, x, out, accumulate);
}

}  // namespace modaltyre::transient
