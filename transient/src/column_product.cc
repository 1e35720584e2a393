#include "modaltyre/transient/column_product.h"

namespace modaltyre::transient {

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
__attribute__((target_clones("avx2", "default")))
#endif
void column_product(Eigen::Index rows, Eigen::Index cols, const double* A, Eigen::Index lda,
                    const double* x, double* out, bool accumulate) {
  // Rows in chunks whose partial sums stay in registers / L1; columns in order within a chunk.
  constexpr Eigen::Index kChunk = 64;
  double acc[kChunk];
  for (Eigen::Index i0 = 0; i0 < rows; i0 += kChunk) {
    const Eigen::Index nr = rows - i0 < kChunk ? rows - i0 : kChunk;
    for (Eigen::Index k = 0; k < nr; ++k) acc[k] = 0.0;
    for (Eigen::Index j = 0; j < cols; ++j) {
      const double* a = A + j * lda + i0;
      const double xj = x[j];
      for (Eigen::Index k = 0; k < nr; ++k) acc[k] += a[k] * xj;
    }
    // Eigen adds alpha * sum to the destination (cleared first for an assignment).
    double* o = out + i0;
    if (accumulate)
      for (Eigen::Index k = 0; k < nr; ++k) o[k] = acc[k] + o[k];
    else
      for (Eigen::Index k = 0; k < nr; ++k) o[k] = acc[k] + 0.0;
  }
}

}  // namespace modaltyre::transient
