#include "cell_kernels.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/solvers/instruction_set.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define MODALTYRE_CELL_KERNELS_AVX2 1
#endif

namespace modaltyre::transient::detail {
namespace {

/// lu_factor()'s step k up to the row updates: the first row i >= k with the largest |a_ik|
/// swapped into row k; false at a zero or non-finite pivot.
inline bool lu_pivot(int n, double* a, int* rows, int k) {
  int p = k;
  for (int i = k + 1; i < n; ++i)
    if (std::abs(a[i * n + k]) > std::abs(a[p * n + k])) p = i;
  if (p != k) {
    std::swap_ranges(a + k * n, a + (k + 1) * n, a + p * n);
    std::swap(rows[k], rows[p]);
  }
  const double pivot = a[k * n + k];
  return std::isfinite(pivot) && pivot != 0;
}

#ifdef MODALTYRE_CELL_KERNELS_AVX2
/// Whether the AVX2 (and FMA) paths run: the CPU has them and MODALTYRE_ISA allows them
/// (solvers/instruction_set.h; decided once).
bool avx2_fma() {
  static const bool yes = solvers::instruction_set() == solvers::InstructionSet::avx2_fma;
  return yes;
}
bool avx2() { return avx2_fma(); }
#endif

/// Rows [k, n) of one output in order onto its combined partial sums s.
double tail(int k, int n, const double* a, const double* x, const double* c, const double* y,
            double s) {
  for (; k < n; ++k) {
    s = std::fma(a[k], x[k], s);
    if (y) s = std::fma(c[k], y[k], s);
  }
  return s;
}

/// band_row()'s entries [j0, n).
void band_row_scalar(int j0, int n, bool with_t, double a, const double* t, const double* y1,
                     const double* y2, double s1, double s2, double d, double* y, double* r,
                     double w, double gamma) {
  for (int j = j0; j < n; ++j) {
    y[j] =
        with_t ? ((a * t[j] - s1 * y1[j]) - s2 * y2[j]) * d : ((0.0 - s1 * y1[j]) - s2 * y2[j]) * d;
    if (r) r[j] += w * (t[j] - gamma * y[j]);
  }
}

void pair_dots_scalar(int n, const double* a, const double* b, const double* x, const double* c,
                      const double* d, const double* y, double out[2]) {
  double sa[8] = {0, 0, 0, 0, 0, 0, 0, 0}, sb[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  const int n8 = n / 8 * 8;
  for (int k = 0; k < n8; k += 8) {
    for (int l = 0; l < 8; ++l) {
      sa[l] = std::fma(a[k + l], x[k + l], sa[l]);
      sb[l] = std::fma(b[k + l], x[k + l], sb[l]);
      if (y) {
        sa[l] = std::fma(c[k + l], y[k + l], sa[l]);
        sb[l] = std::fma(d[k + l], y[k + l], sb[l]);
      }
    }
  }
  auto combine = [](const double* s) {
    const double l0 = s[0] + s[4], l1 = s[1] + s[5], l2 = s[2] + s[6], l3 = s[3] + s[7];
    return (l0 + l1) + (l2 + l3);
  };
  out[0] = tail(n8, n, a, x, c, y, combine(sa));
  out[1] = tail(n8, n, b, x, d, y, combine(sb));
}

/// sum_k a[k] b[k], k < n: four partial sums (k mod 4) by fused multiply-adds, added as
/// (s0 + s1) + (s2 + s3), then the last n % 4 terms in order (lower_transpose_solve()).
double lane_dot_scalar(int n, const double* a, const double* b) {
  double s[4] = {0, 0, 0, 0};
  const int n4 = n / 4 * 4;
  for (int k = 0; k < n4; k += 4)
    for (int l = 0; l < 4; ++l) s[l] = std::fma(a[k + l], b[k + l], s[l]);
  double r = (s[0] + s[1]) + (s[2] + s[3]);
  for (int k = n4; k < n; ++k) r = std::fma(a[k], b[k], r);
  return r;
}

#ifdef MODALTYRE_CELL_KERNELS_AVX2
__attribute__((target("avx2,fma"))) double combine_avx2(__m256d lo, __m256d hi) {
  alignas(32) double l[4];
  _mm256_store_pd(l, _mm256_add_pd(lo, hi));
  return (l[0] + l[1]) + (l[2] + l[3]);
}

__attribute__((target("avx2,fma"))) void pair_dots_avx2(int n, const double* a, const double* b,
                                                        const double* x, const double* c,
                                                        const double* d, const double* y,
                                                        double out[2]) {
  __m256d a0 = _mm256_setzero_pd(), a1 = a0, b0 = a0, b1 = a0;
  const int n8 = n / 8 * 8;
  for (int k = 0; k < n8; k += 8) {
    const __m256d x0 = _mm256_loadu_pd(x + k), x1 = _mm256_loadu_pd(x + k + 4);
    a0 = _mm256_fmadd_pd(_mm256_loadu_pd(a + k), x0, a0);
    a1 = _mm256_fmadd_pd(_mm256_loadu_pd(a + k + 4), x1, a1);
    b0 = _mm256_fmadd_pd(_mm256_loadu_pd(b + k), x0, b0);
    b1 = _mm256_fmadd_pd(_mm256_loadu_pd(b + k + 4), x1, b1);
    if (y) {
      const __m256d y0 = _mm256_loadu_pd(y + k), y1 = _mm256_loadu_pd(y + k + 4);
      a0 = _mm256_fmadd_pd(_mm256_loadu_pd(c + k), y0, a0);
      a1 = _mm256_fmadd_pd(_mm256_loadu_pd(c + k + 4), y1, a1);
      b0 = _mm256_fmadd_pd(_mm256_loadu_pd(d + k), y0, b0);
      b1 = _mm256_fmadd_pd(_mm256_loadu_pd(d + k + 4), y1, b1);
    }
  }
  out[0] = tail(n8, n, a, x, c, y, combine_avx2(a0, a1));
  out[1] = tail(n8, n, b, x, d, y, combine_avx2(b0, b1));
}

__attribute__((target("avx2"))) void band_row_avx(int n, bool with_t, double a, const double* t,
                                                  const double* y1, const double* y2, double s1,
                                                  double s2, double d, double* y, double* r,
                                                  double w, double gamma) {
  const __m256d va = _mm256_set1_pd(a), v1 = _mm256_set1_pd(s1), v2 = _mm256_set1_pd(s2),
                vd = _mm256_set1_pd(d), vw = _mm256_set1_pd(w), vg = _mm256_set1_pd(gamma),
                zero = _mm256_setzero_pd();
  int j = 0;
  for (; j + 4 <= n; j += 4) {
    const __m256d tj = _mm256_loadu_pd(t + j);
    const __m256d first = with_t ? _mm256_mul_pd(va, tj) : zero;
    const __m256d u =
        _mm256_sub_pd(_mm256_sub_pd(first, _mm256_mul_pd(v1, _mm256_loadu_pd(y1 + j))),
                      _mm256_mul_pd(v2, _mm256_loadu_pd(y2 + j)));
    const __m256d yj = _mm256_mul_pd(u, vd);
    _mm256_storeu_pd(y + j, yj);
    if (r) {
      const __m256d term = _mm256_mul_pd(vw, _mm256_sub_pd(tj, _mm256_mul_pd(vg, yj)));
      _mm256_storeu_pd(r + j, _mm256_add_pd(_mm256_loadu_pd(r + j), term));
    }
  }
  band_row_scalar(j, n, with_t, a, t, y1, y2, s1, s2, d, y, r, w, gamma);
}

/// fnmadd_sweep()'s entries [i, i + 4 V) (the last vector's lanes under `mask`), in V registers
/// across the whole sum.
template <int V>
__attribute__((target("avx2,fma"))) inline void fnmadd_block(int i, __m256i mask, int np,
                                                             const double* x, int ldx,
                                                             const double* y, int ldy, double* c) {
  __m256d acc[V];
  for (int v = 0; v + 1 < V; ++v) acc[v] = _mm256_loadu_pd(c + i + 4 * v);
  acc[V - 1] = _mm256_maskload_pd(c + i + 4 * (V - 1), mask);
  for (int p = 0; p < np; ++p) {
    const __m256d yp = _mm256_broadcast_sd(y + p * ldy);
    const double* xp = x + p * ldx + i;
    for (int v = 0; v + 1 < V; ++v)
      acc[v] = _mm256_fnmadd_pd(_mm256_loadu_pd(xp + 4 * v), yp, acc[v]);
    acc[V - 1] = _mm256_fnmadd_pd(_mm256_maskload_pd(xp + 4 * (V - 1), mask), yp, acc[V - 1]);
  }
  for (int v = 0; v + 1 < V; ++v) _mm256_storeu_pd(c + i + 4 * v, acc[v]);
  _mm256_maskstore_pd(c + i + 4 * (V - 1), mask, acc[V - 1]);
}

/// c_i = fma(-x_p[i], y_p, c_i) for p = 0 .. np - 1 in order, i < m (x_p = x + p ldx, y_p =
/// y[p ldy]): 16 entries at a time in four registers across the whole sum, the last 1-16 with
/// the lanes beyond m under a mask (neither read nor written).
__attribute__((target("avx2,fma"))) void fnmadd_sweep(int m, int np, const double* x, int ldx,
                                                      const double* y, int ldy, double* c) {
  const __m256i all = _mm256_set1_epi64x(-1);
  int i = 0;
  for (; i + 16 < m; i += 16) fnmadd_block<4>(i, all, np, x, ldx, y, ldy, c);
  const int left = m - i;  // 0 .. 16
  if (left <= 0) return;
  const int last = left - 4 * ((left - 1) / 4);  // lanes of the last vector, 1 .. 4
  const __m256i mask =
      _mm256_setr_epi64x(-1, last > 1 ? -1 : 0, last > 2 ? -1 : 0, last > 3 ? -1 : 0);
  switch ((left + 3) / 4) {
    case 1:
      return fnmadd_block<1>(i, mask, np, x, ldx, y, ldy, c);
    case 2:
      return fnmadd_block<2>(i, mask, np, x, ldx, y, ldy, c);
    case 3:
      return fnmadd_block<3>(i, mask, np, x, ldx, y, ldy, c);
    default:
      return fnmadd_block<4>(i, mask, np, x, ldx, y, ldy, c);
  }
}

/// lu_factor()'s steps in Crout's order: every entry takes the same fused multiply-adds in the
/// same order as the row updates (the same bits and pivots), but each is loaded and stored once,
/// not at every step, and a's rows are never swapped (read through the permutation). Step k:
/// column k at rows >= k from the final rows of L (column-major, lc) and column k of U; the
/// pivot; L's column k; then row k of U from U's rows above. L goes into lu's lower triangle at
/// the end.
__attribute__((target("avx2,fma"))) bool lu_factor_avx2(int n, const double* a, double* lu,
                                                        int* rows) {
  thread_local std::vector<double> lc_buffer, c_buffer;
  lc_buffer.resize(static_cast<std::size_t>(n) * n);
  c_buffer.resize(n);
  double* lc = lc_buffer.data();  // lc[p n + i] = L_ip at the current row positions
  double* c = c_buffer.data();
  for (int i = 0; i < n; ++i) rows[i] = i;
  for (int k = 0; k < n; ++k) {
    const int m = n - k;  // rows k .. n - 1
    const double* col = a + k * n;
    for (int i = 0; i < m; ++i) c[i] = col[rows[k + i]];
    fnmadd_sweep(m, k, lc + k, n, lu + k, n, c);
    int p = 0;
    for (int i = 1; i < m; ++i)
      if (std::abs(c[i]) > std::abs(c[p])) p = i;
    if (p != 0) {
      std::swap(rows[k], rows[k + p]);
      for (int q = 0; q < k; ++q) std::swap(lc[q * n + k], lc[q * n + k + p]);
      std::swap(c[0], c[p]);
    }
    const double pivot = c[0];
    if (!(std::isfinite(pivot) && pivot != 0)) return false;
    lu[k * n + k] = pivot;
    for (int i = 1; i < m; ++i) lc[k * n + k + i] = c[i] / pivot;
    double* u = lu + k * n + k + 1;
    const int r = rows[k];
    for (int j = 0; j + 1 < m; ++j) u[j] = a[(k + 1 + j) * n + r];
    fnmadd_sweep(m - 1, k, lu + k + 1, n, lc + k, n, u);
  }
  for (int i = 1; i < n; ++i)
    for (int j = 0; j < i; ++j) lu[i * n + j] = lc[j * n + i];
  return true;
}

/// cholesky_factor()'s columns: column j from the diagonal down swept by the columns p < j of L
/// (fnmadd_sweep(): 16 entries in registers across the whole sum), then scaled by its root.
__attribute__((target("avx2,fma"))) bool cholesky_factor_avx2(int n, const double* a, double* l) {
  for (int j = 0; j < n; ++j) {
    double* c = l + j * n + j;
    std::copy(a + j * n + j, a + (j + 1) * n, c);
    fnmadd_sweep(n - j, j, l + j, n, l + j, n, c);
    if (!(c[0] > 0 && std::isfinite(c[0]))) return false;
    const double d = std::sqrt(c[0]);
    c[0] = d;
    for (int i = 1; i < n - j; ++i) c[i] /= d;
  }
  return true;
}

__attribute__((target("avx2,fma"))) double lane_dot_avx2(int n, const double* a, const double* b) {
  __m256d s = _mm256_setzero_pd();
  const int n4 = n / 4 * 4;
  for (int k = 0; k < n4; k += 4)
    s = _mm256_fmadd_pd(_mm256_loadu_pd(a + k), _mm256_loadu_pd(b + k), s);
  alignas(32) double l[4];
  _mm256_store_pd(l, s);
  double r = (l[0] + l[1]) + (l[2] + l[3]);
  for (int k = n4; k < n; ++k) r = std::fma(a[k], b[k], r);
  return r;
}

/// The entries p_l[o] of four lanes as one vector.
__attribute__((target("avx2"))) inline __m256d at(const double* const* p, int o) {
  return _mm256_setr_pd(p[0][o], p[1][o], p[2][o], p[3][o]);
}

/// Stores the four lanes of v to p_l[o].
__attribute__((target("avx2"))) inline void put(__m256d v, double* const* p, int o) {
  const __m128d lo = _mm256_castpd256_pd128(v), hi = _mm256_extractf128_pd(v, 1);
  _mm_storel_pd(p[0] + o, lo);
  _mm_storeh_pd(p[1] + o, lo);
  _mm_storel_pd(p[2] + o, hi);
  _mm_storeh_pd(p[3] + o, hi);
}

/// band_lockstep8()'s steps, the lanes as two vectors of four (no fused multiply-add: the
/// scalar expression's roundings), y_k+1 and y_k+2 carried in registers from step to step.
__attribute__((target("avx2"))) void band_lockstep8_avx2(int t0, int t1, double* const* y,
                                                         const double* const* d, double s1,
                                                         double s2) {
  const __m256d v1 = _mm256_set1_pd(s1), v2 = _mm256_set1_pd(s2);
  __m256d a1 = at(y, 1 - t0), a2 = at(y, 2 - t0), b1 = at(y + 4, 1 - t0), b2 = at(y + 4, 2 - t0);
  for (int t = t0; t < t1; ++t) {
    const __m256d a = _mm256_mul_pd(
        _mm256_sub_pd(_mm256_sub_pd(at(y, -t), _mm256_mul_pd(v1, a1)), _mm256_mul_pd(v2, a2)),
        at(d, -t));
    const __m256d b = _mm256_mul_pd(
        _mm256_sub_pd(_mm256_sub_pd(at(y + 4, -t), _mm256_mul_pd(v1, b1)), _mm256_mul_pd(v2, b2)),
        at(d + 4, -t));
    put(a, y, -t);
    put(b, y + 4, -t);
    a2 = a1, a1 = a, b2 = b1, b1 = b;
  }
}

/// lower_solve()'s columns: x_i = fma(-L_ip, x_p, x_i) below each solved x_p.
__attribute__((target("avx2,fma"))) void lower_solve_avx2(int n, const double* l, double* x) {
  for (int p = 0; p < n; ++p) {
    const double v = x[p] / l[p * n + p];
    x[p] = v;
    fnmadd_sweep(n - p - 1, 1, l + p * n + p + 1, n, &v, 1, x + p + 1);
  }
}

__attribute__((target("avx2"))) int sign_mismatches_avx2(int n, const double* a, const double* b,
                                                         std::vector<int>& out) {
  const __m256d zero = _mm256_setzero_pd();
  int k = 0;
  for (; k + 8 <= n; k += 8) {
    const __m256d x0 = _mm256_xor_pd(_mm256_cmp_pd(_mm256_loadu_pd(a + k), zero, _CMP_GT_OQ),
                                     _mm256_cmp_pd(_mm256_loadu_pd(b + k), zero, _CMP_GT_OQ));
    const __m256d x1 = _mm256_xor_pd(_mm256_cmp_pd(_mm256_loadu_pd(a + k + 4), zero, _CMP_GT_OQ),
                                     _mm256_cmp_pd(_mm256_loadu_pd(b + k + 4), zero, _CMP_GT_OQ));
    const int mask = _mm256_movemask_pd(x0) | (_mm256_movemask_pd(x1) << 4);
    if (mask == 0) continue;
    for (int l = 0; l < 8; ++l)
      if (mask & (1 << l)) out.push_back(k + l);
  }
  return k;
}

__attribute__((target("avx2"))) int first_positive_avx2(const double* a, int n) {
  const __m256d zero = _mm256_setzero_pd();
  int k = 0;
  for (; k + 4 <= n; k += 4) {
    const int mask = _mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(a + k), zero, _CMP_GT_OQ));
    if (mask) return k + __builtin_ctz(static_cast<unsigned>(mask));
  }
  for (; k < n; ++k)
    if (a[k] > 0) return k;
  return n;
}

__attribute__((target("avx2"))) int last_positive_avx2(const double* a, int n) {
  const __m256d zero = _mm256_setzero_pd();
  int k = n;
  for (; k >= 4; k -= 4) {
    const int mask =
        _mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(a + k - 4), zero, _CMP_GT_OQ));
    if (mask) return k - 4 + 31 - __builtin_clz(static_cast<unsigned>(mask));
  }
  for (--k; k >= 0; --k)
    if (a[k] > 0) return k;
  return -1;
}

__attribute__((target("avx2"))) int count_positive_avx2(const double* a, int n) {
  const __m256d zero = _mm256_setzero_pd();
  int k = 0, count = 0;
  for (; k + 4 <= n; k += 4)
    count += __builtin_popcount(static_cast<unsigned>(
        _mm256_movemask_pd(_mm256_cmp_pd(_mm256_loadu_pd(a + k), zero, _CMP_GT_OQ))));
  for (; k < n; ++k) count += a[k] > 0 ? 1 : 0;
  return count;
}

__attribute__((target("avx2"))) void min_max_fill_avx2(int* lo, int* hi, int n, int v_lo,
                                                       int v_hi) {
  const __m256i vl = _mm256_set1_epi32(v_lo), vh = _mm256_set1_epi32(v_hi);
  int k = 0;
  for (; k + 8 <= n; k += 8) {
    __m256i* pl = reinterpret_cast<__m256i*>(lo + k);
    __m256i* ph = reinterpret_cast<__m256i*>(hi + k);
    _mm256_storeu_si256(pl, _mm256_min_epi32(_mm256_loadu_si256(pl), vl));
    _mm256_storeu_si256(ph, _mm256_max_epi32(_mm256_loadu_si256(ph), vh));
  }
  for (; k < n; ++k) lo[k] = std::min(lo[k], v_lo), hi[k] = std::max(hi[k], v_hi);
}

/// small_gemm()'s rows [i0, i0 + 4 v) x columns [j0, j0 + w), v <= 3 vectors, w <= 4.
template <int V, int W>
__attribute__((target("avx2,fma"))) inline void gemm_block(int i0, int j0, int k, const double* A,
                                                           int lda, const double* B, int ldb,
                                                           double* C, int ldc, bool accumulate) {
  __m256d acc[V][W];
  for (int v = 0; v < V; ++v)
    for (int w = 0; w < W; ++w) acc[v][w] = _mm256_setzero_pd();
  for (int p = 0; p < k; ++p) {
    __m256d a[V];
    for (int v = 0; v < V; ++v) a[v] = _mm256_loadu_pd(A + p * lda + i0 + 4 * v);
    for (int w = 0; w < W; ++w) {
      const __m256d b = _mm256_broadcast_sd(B + (j0 + w) * ldb + p);
      for (int v = 0; v < V; ++v) acc[v][w] = _mm256_fmadd_pd(a[v], b, acc[v][w]);
    }
  }
  for (int w = 0; w < W; ++w)
    for (int v = 0; v < V; ++v) {
      double* c = C + (j0 + w) * ldc + i0 + 4 * v;
      _mm256_storeu_pd(
          c, _mm256_add_pd(acc[v][w], accumulate ? _mm256_loadu_pd(c) : _mm256_setzero_pd()));
    }
}

template <int W>
__attribute__((target("avx2,fma"))) void gemm_columns(int m, int j0, int k, const double* A,
                                                      int lda, const double* B, int ldb, double* C,
                                                      int ldc, bool accumulate) {
  int i = 0;
  for (; i + 12 <= m; i += 12) gemm_block<3, W>(i, j0, k, A, lda, B, ldb, C, ldc, accumulate);
  for (; i + 4 <= m; i += 4) gemm_block<1, W>(i, j0, k, A, lda, B, ldb, C, ldc, accumulate);
  if (i == m) return;
  // The last m % 4 rows as one masked vector (the same operations per entry; masked lanes are
  // neither read nor written).
  const __m256i mask = _mm256_setr_epi64x(-1, m - i > 1 ? -1 : 0, m - i > 2 ? -1 : 0, 0);
  __m256d acc[W];
  for (int w = 0; w < W; ++w) acc[w] = _mm256_setzero_pd();
  for (int p = 0; p < k; ++p) {
    const __m256d a = _mm256_maskload_pd(A + p * lda + i, mask);
    for (int w = 0; w < W; ++w)
      acc[w] = _mm256_fmadd_pd(a, _mm256_broadcast_sd(B + (j0 + w) * ldb + p), acc[w]);
  }
  for (int w = 0; w < W; ++w) {
    double* c = C + (j0 + w) * ldc + i;
    const __m256d old = accumulate ? _mm256_maskload_pd(c, mask) : _mm256_setzero_pd();
    _mm256_maskstore_pd(c, mask, _mm256_add_pd(acc[w], old));
  }
}

__attribute__((target("avx2,fma"))) void small_gemm_avx2(int m, int n, int k, const double* A,
                                                         int lda, const double* B, int ldb,
                                                         double* C, int ldc, bool accumulate) {
  int j = 0;
  for (; j + 4 <= n; j += 4) gemm_columns<4>(m, j, k, A, lda, B, ldb, C, ldc, accumulate);
  for (; j < n; ++j) gemm_columns<1>(m, j, k, A, lda, B, ldb, C, ldc, accumulate);
}
#endif

}  // namespace

void small_gemm(int m, int n, int k, const double* A, int lda, const double* B, int ldb, double* C,
                int ldc, bool accumulate) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2_fma()) return small_gemm_avx2(m, n, k, A, lda, B, ldb, C, ldc, accumulate);
#endif
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i) {
      double s = 0.0;
      for (int p = 0; p < k; ++p) s = std::fma(A[p * lda + i], B[j * ldb + p], s);
      double* c = C + j * ldc + i;
      *c = s + (accumulate ? *c : 0.0);
    }
}

int count_positive(const double* a, int n) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2()) return count_positive_avx2(a, n);
#endif
  int count = 0;
  for (int k = 0; k < n; ++k) count += a[k] > 0 ? 1 : 0;
  return count;
}

void min_max_fill(int* lo, int* hi, int n, int v_lo, int v_hi) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2()) return min_max_fill_avx2(lo, hi, n, v_lo, v_hi);
#endif
  for (int k = 0; k < n; ++k) lo[k] = std::min(lo[k], v_lo), hi[k] = std::max(hi[k], v_hi);
}

int first_positive(const double* a, int n) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2()) return first_positive_avx2(a, n);
#endif
  int k = 0;
  while (k < n && !(a[k] > 0)) ++k;
  return k;
}

int last_positive(const double* a, int n) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2()) return last_positive_avx2(a, n);
#endif
  int k = n - 1;
  while (k >= 0 && !(a[k] > 0)) --k;
  return k;
}

void sign_mismatches(int n, const double* a, const double* b, std::vector<int>& out) {
  int k = 0;
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2()) k = sign_mismatches_avx2(n, a, b, out);
#endif
  for (; k < n; ++k)
    if ((a[k] > 0) != (b[k] > 0)) out.push_back(k);
}

bool lu_factor(int n, const double* a, double* lu, int* rows) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2_fma()) return lu_factor_avx2(n, a, lu, rows);
#endif
  // The row-major copy, then the row updates of the stated steps.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) lu[i * n + j] = a[j * n + i];
  for (int i = 0; i < n; ++i) rows[i] = i;
  for (int k = 0; k < n; ++k) {
    if (!lu_pivot(n, lu, rows, k)) return false;
    const double pivot = lu[k * n + k];
    const double* rk = lu + k * n + k + 1;
    for (int i = k + 1; i < n; ++i) {
      double* ri = lu + i * n;
      const double l = ri[k] / pivot;
      ri[k] = l;
      for (int j = 0; j < n - k - 1; ++j) ri[k + 1 + j] = std::fma(-l, rk[j], ri[k + 1 + j]);
    }
  }
  return true;
}

bool cholesky_factor(int n, const double* a, double* l) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2_fma()) return cholesky_factor_avx2(n, a, l);
#endif
  for (int j = 0; j < n; ++j) {
    double* c = l + j * n + j;
    std::copy(a + j * n + j, a + (j + 1) * n, c);
    for (int p = 0; p < j; ++p) {
      const double* x = l + p * n + j;
      const double y = x[0];
      for (int i = 0; i < n - j; ++i) c[i] = std::fma(-x[i], y, c[i]);
    }
    if (!(c[0] > 0 && std::isfinite(c[0]))) return false;
    const double d = std::sqrt(c[0]);
    c[0] = d;
    for (int i = 1; i < n - j; ++i) c[i] /= d;
  }
  return true;
}

void lower_solve(int n, const double* l, double* x) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2_fma()) return lower_solve_avx2(n, l, x);
#endif
  for (int p = 0; p < n; ++p) {
    const double v = x[p] / l[p * n + p];
    x[p] = v;
    for (int i = p + 1; i < n; ++i) x[i] = std::fma(-l[p * n + i], v, x[i]);
  }
}

void lower_transpose_solve(int n, const double* l, double* x) {
  double (*dot)(int, const double*, const double*) = lane_dot_scalar;
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2_fma()) dot = lane_dot_avx2;
#endif
  for (int i = n - 1; i >= 0; --i)
    x[i] = (x[i] - dot(n - i - 1, l + i * n + i + 1, x + i + 1)) / l[i * n + i];
}

void square_product(int n, const double* a, const double* x, double* y) {
  thread_local std::vector<double> negated;
  negated.resize(n);
  for (int p = 0; p < n; ++p) negated[p] = -x[p];
  for (int i = 0; i < n; ++i) y[i] = 0;
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2_fma()) return fnmadd_sweep(n, n, a, n, negated.data(), 1, y);
#endif
  for (int i = 0; i < n; ++i)
    for (int p = 0; p < n; ++p) y[i] = std::fma(-a[p * n + i], negated[p], y[i]);
}

void band_lockstep8(int t0, int t1, double* const* y, const double* const* d, double s1,
                    double s2) {
  if (t1 <= t0) return;
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2()) return band_lockstep8_avx2(t0, t1, y, d, s1, s2);
#endif
  for (int t = t0; t < t1; ++t)
    for (int l = 0; l < 8; ++l)
      y[l][-t] = (y[l][-t] - s1 * y[l][1 - t] - s2 * y[l][2 - t]) * d[l][-t];
}

void band_row(int n, bool with_t, double a, const double* t, const double* y1, const double* y2,
              double s1, double s2, double d, double* y, double* r, double w, double gamma) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2()) return band_row_avx(n, with_t, a, t, y1, y2, s1, s2, d, y, r, w, gamma);
#endif
  band_row_scalar(0, n, with_t, a, t, y1, y2, s1, s2, d, y, r, w, gamma);
}

void pair_dots(int n, const double* a, const double* b, const double* x, const double* c,
               const double* d, const double* y, double out[2]) {
#ifdef MODALTYRE_CELL_KERNELS_AVX2
  if (avx2_fma()) return pair_dots_avx2(n, a, b, x, c, d, y, out);
#endif
  pair_dots_scalar(n, a, b, x, c, d, y, out);
}

}  // namespace modaltyre::transient::detail
