// The tread's cosine modes (patch3d_cosine.h), by folding the columns about the tread's centre:
// phi_m(n - 1 - j) = (-1)^m phi_m(j), so the even modes see only x(j) + x(n - 1 - j) and the odd
// ones only x(j) - x(n - 1 - j) (the middle column, for n odd, only the even modes: phi_m there
// is cos(pi m / 2)). Two half-size products instead of one full: half the multiplications of
// the dense n x n transform, the same sums up to rounding (test: against phi to 1e-12).
#include "patch3d_cosine.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/solvers/instruction_set.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace modaltyre::contact::detail {

CosineModes::CosineModes(int n) : n_(n), half_(n / 2), even_((n + 1) / 2), odd_(n / 2) {
  phi_.resize(n, n);
  for (int m = 0; m < n; ++m) {
    const double norm = std::sqrt((m == 0 ? 1.0 : 2.0) / n);
    for (int j = 0; j < n; ++j) phi_(j, m) = norm * std::cos(M_PI * m * (j + 0.5) / n);
  }
  // Folded rows: j < n / 2, and for n odd the middle column (folded with nothing).
  e_.resize(even_, even_);
  o_.resize(half_, odd_);
  for (int j = 0; j < even_; ++j)
    for (int p = 0; p < even_; ++p) e_(j, p) = phi_(j, 2 * p);
  for (int j = 0; j < half_; ++j)
    for (int p = 0; p < odd_; ++p) o_(j, p) = phi_(j, 2 * p + 1);
  e_t_ = e_.transpose();
  o_t_ = o_.transpose();
}

void CosineModes::forward(const Eigen::MatrixXd& x, Eigen::MatrixXd& c) const {
  const Eigen::Index rows = x.rows();
  Eigen::MatrixXd a, b, ce, co;  // folded inputs, even and odd products
  a.resize(rows, even_);
  b.resize(rows, half_);
  for (int j = 0; j < half_; ++j) {
    a.col(j) = x.col(j) + x.col(n_ - 1 - j);
    b.col(j) = x.col(j) - x.col(n_ - 1 - j);
  }
  if (even_ > half_) a.col(half_) = x.col(half_);
  small_product(a, e_, ce);
  small_product(b, o_, co);
  c.resize(rows, n_);
  for (int k = 0; k < even_; ++k) c.col(2 * k) = ce.col(k);
  for (int k = 0; k < odd_; ++k) c.col(2 * k + 1) = co.col(k);
}

void CosineModes::backward(const Eigen::MatrixXd& c, Eigen::MatrixXd& x) const {
  const Eigen::Index rows = c.rows();
  Eigen::MatrixXd a, b, ce, co;  // folded inputs, even and odd products
  a.resize(rows, even_);
  b.resize(rows, odd_);
  for (int k = 0; k < even_; ++k) a.col(k) = c.col(2 * k);
  for (int k = 0; k < odd_; ++k) b.col(k) = c.col(2 * k + 1);
  small_product(a, e_t_, ce);  // the even modes' part at j < n / 2 (and the middle)
  small_product(b, o_t_, co);  // the odd modes' part at j < n / 2
  x.resize(rows, n_);
  for (int j = 0; j < half_; ++j) {
    x.col(j) = ce.col(j) + co.col(j);
    x.col(n_ - 1 - j) = ce.col(j) - co.col(j);
  }
  if (even_ > half_) x.col(half_) = ce.col(half_);
}

namespace {

// out(s .. s + R, m .. m + M) = A(s .. s + R, :) B(:, m .. m + M), every entry's sum in the
// order l = 0, 1, ... (a multiply, then an add) on every path below: the same bits.
template <int R, int M>
inline void block_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& out,
                          Eigen::Index s, Eigen::Index m) {
  double acc[M][R] = {};
  const Eigen::Index k = A.cols();
  for (Eigen::Index l = 0; l < k; ++l) {
    const double* a = &A.coeffRef(s, l);
    for (int q = 0; q < M; ++q) {
      const double b = B(l, m + q);
      for (int i = 0; i < R; ++i) acc[q][i] += b * a[i];
    }
  }
  for (int q = 0; q < M; ++q)
    for (int i = 0; i < R; ++i) out(s + i, m + q) = acc[q][i];
}

// The loop over blocks of four sections by four outputs (Block(s, m, 4)) or by one output
// (Block(s, m, 1)), and the remaining sections one by one.
template <class Block>
inline void blocked(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& out,
                    Block block) {
  const Eigen::Index rows = A.rows(), cols = B.cols();
  const Eigen::Index r4 = rows - rows % 4, m4 = cols - cols % 4;
  for (Eigen::Index m = 0; m < m4; m += 4) {
    for (Eigen::Index s = 0; s < r4; s += 4) block(s, m, 4);
    for (Eigen::Index s = r4; s < rows; ++s) block_product<1, 4>(A, B, out, s, m);
  }
  for (Eigen::Index m = m4; m < cols; ++m) {
    for (Eigen::Index s = 0; s < r4; s += 4) block(s, m, 1);
    for (Eigen::Index s = r4; s < rows; ++s) block_product<1, 1>(A, B, out, s, m);
  }
}

#if defined(__x86_64__) && defined(__GNUC__)
#define MODALTYRE_COSINE_SIMD
// The compilers vectorise block_product<4, 4> across the outputs (gathering A's rows), so the
// blocks are written out on raw pointers: SSE2 (the baseline) holds four sections by four outputs
// in eight registers, AVX2 in four (no FMA: the target has none, so nothing is contracted).
void blocked_sse2(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& out) {
  const Eigen::Index k = A.cols(), lda = A.rows(), ldb = B.rows(), ldo = out.rows();
  blocked(A, B, out, [&](Eigen::Index s, Eigen::Index m, int outputs) {
    const double* a = A.data() + s;
    const double* b = B.data() + m * ldb;
    double* o = out.data() + m * ldo + s;
    if (outputs == 1) {
      __m128d c0 = _mm_setzero_pd(), c1 = _mm_setzero_pd();
      for (Eigen::Index l = 0; l < k; ++l, a += lda) {
        const __m128d bl = _mm_set1_pd(b[l]);
        c0 = _mm_add_pd(c0, _mm_mul_pd(bl, _mm_loadu_pd(a)));
        c1 = _mm_add_pd(c1, _mm_mul_pd(bl, _mm_loadu_pd(a + 2)));
      }
      _mm_storeu_pd(o, c0), _mm_storeu_pd(o + 2, c1);
      return;
    }
    __m128d c00 = _mm_setzero_pd(), c01 = c00, c10 = c00, c11 = c00, c20 = c00, c21 = c00,
            c30 = c00, c31 = c00;
    for (Eigen::Index l = 0; l < k; ++l, a += lda) {
      const __m128d a0 = _mm_loadu_pd(a), a1 = _mm_loadu_pd(a + 2);
      __m128d bl = _mm_set1_pd(b[l]);
      c00 = _mm_add_pd(c00, _mm_mul_pd(bl, a0)), c01 = _mm_add_pd(c01, _mm_mul_pd(bl, a1));
      bl = _mm_set1_pd(b[l + ldb]);
      c10 = _mm_add_pd(c10, _mm_mul_pd(bl, a0)), c11 = _mm_add_pd(c11, _mm_mul_pd(bl, a1));
      bl = _mm_set1_pd(b[l + 2 * ldb]);
      c20 = _mm_add_pd(c20, _mm_mul_pd(bl, a0)), c21 = _mm_add_pd(c21, _mm_mul_pd(bl, a1));
      bl = _mm_set1_pd(b[l + 3 * ldb]);
      c30 = _mm_add_pd(c30, _mm_mul_pd(bl, a0)), c31 = _mm_add_pd(c31, _mm_mul_pd(bl, a1));
    }
    _mm_storeu_pd(o, c00), _mm_storeu_pd(o + 2, c01);
    _mm_storeu_pd(o + ldo, c10), _mm_storeu_pd(o + ldo + 2, c11);
    _mm_storeu_pd(o + 2 * ldo, c20), _mm_storeu_pd(o + 2 * ldo + 2, c21);
    _mm_storeu_pd(o + 3 * ldo, c30), _mm_storeu_pd(o + 3 * ldo + 2, c31);
  });
}

__attribute__((target("avx2"))) void blocked_avx2(const Eigen::MatrixXd& A,
                                                  const Eigen::MatrixXd& B, Eigen::MatrixXd& out) {
  const Eigen::Index k = A.cols(), lda = A.rows(), ldb = B.rows(), ldo = out.rows();
  blocked(
      A, B, out, [&](Eigen::Index s, Eigen::Index m, int outputs) __attribute__((target("avx2"))) {
        const double* a = A.data() + s;
        const double* b = B.data() + m * ldb;
        double* o = out.data() + m * ldo + s;
        if (outputs == 1) {
          __m256d c0 = _mm256_setzero_pd();
          for (Eigen::Index l = 0; l < k; ++l, a += lda)
            c0 = _mm256_add_pd(c0, _mm256_mul_pd(_mm256_broadcast_sd(b + l), _mm256_loadu_pd(a)));
          _mm256_storeu_pd(o, c0);
          return;
        }
        __m256d c0 = _mm256_setzero_pd(), c1 = c0, c2 = c0, c3 = c0;
        for (Eigen::Index l = 0; l < k; ++l, a += lda) {
          const __m256d al = _mm256_loadu_pd(a);
          c0 = _mm256_add_pd(c0, _mm256_mul_pd(_mm256_broadcast_sd(b + l), al));
          c1 = _mm256_add_pd(c1, _mm256_mul_pd(_mm256_broadcast_sd(b + l + ldb), al));
          c2 = _mm256_add_pd(c2, _mm256_mul_pd(_mm256_broadcast_sd(b + l + 2 * ldb), al));
          c3 = _mm256_add_pd(c3, _mm256_mul_pd(_mm256_broadcast_sd(b + l + 3 * ldb), al));
        }
        _mm256_storeu_pd(o, c0), _mm256_storeu_pd(o + ldo, c1);
        _mm256_storeu_pd(o + 2 * ldo, c2), _mm256_storeu_pd(o + 3 * ldo, c3);
      });
}
#endif

}  // namespace

void small_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& out) {
  out.resize(A.rows(), B.cols());
#ifdef MODALTYRE_COSINE_SIMD
  if (solvers::instruction_set() == solvers::InstructionSet::avx2_fma)
    return blocked_avx2(A, B, out);
  blocked_sse2(A, B, out);
#else
  blocked(A, B, out, [&](Eigen::Index s, Eigen::Index m, int outputs) {
    outputs == 4 ? block_product<4, 4>(A, B, out, s, m) : block_product<4, 1>(A, B, out, s, m);
  });
#endif
}

}  // namespace modaltyre::contact::detail
