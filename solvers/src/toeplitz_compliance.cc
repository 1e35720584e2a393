#include "modaltyre/solvers/toeplitz_compliance.h"

#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/FFT>
#include <utility>

#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/dense_product.h"
#include "modaltyre/solvers/instruction_set.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define MODALTYRE_LAG_DIRECT_AVX2
#endif

namespace modaltyre::solvers {

namespace {

using cd = std::complex<double>;

bool smooth(int v) {
  for (int f : {2, 3, 5})
    while (v % f == 0) v /= f;
  return v == 1;
}

/// Real half-spectrum transforms, unscaled; kissfft keeps a plan per length: one set per thread,
/// reused by every convolution the thread applies (plans depend on the length only).
Eigen::FFT<double>& thread_fft() {
  thread_local Eigen::FFT<double> fft = [] {
    Eigen::FFT<double> f;
    f.SetFlag(Eigen::FFT<double>::HalfSpectrum);
    f.SetFlag(Eigen::FFT<double>::Unscaled);
    return f;
  }();
  return fft;
}

/// apply_direct()'s sums from column pointers: kab_q = K_ab + mid + r0 - c0 - q is column q's
/// lags for the block's rows p = 0 .. nr - 1. Per entry in the columns' order:
/// u0 = u0 + (k00 a + k01 b), u1 = u1 + (k10 a + k11 b) from u = 0.
struct LagKernels {
  const double *k00, *k01, *k10, *k11;
};

void lag_direct_portable(int nr, int nc, LagKernels k, const double* v0, const double* v1,
                         double* u0, double* u1) {
  std::fill(u0, u0 + nr, 0.0);
  std::fill(u1, u1 + nr, 0.0);
  for (int q = 0; q < nc; ++q) {
    const double *k00 = k.k00 - q, *k01 = k.k01 - q, *k10 = k.k10 - q, *k11 = k.k11 - q;
    const double a = v0[q], b = v1[q];
    for (int p = 0; p < nr; ++p) {
      u0[p] += k00[p] * a + k01[p] * b;
      u1[p] += k10[p] * a + k11[p] * b;
    }
  }
}

#ifdef MODALTYRE_LAG_DIRECT_AVX2
/// Rows [p, p + 4 V) in registers across all the columns (AVX2 without FMA: the target has
/// none, so nothing is contracted and every entry sees the portable loop's operations in its
/// order, from the same +0.0).
template <int V>
__attribute__((target("avx2"))) inline void lag_rows(int p, int nc, LagKernels k, const double* v0,
                                                     const double* v1, double* u0, double* u1) {
  __m256d s0[V], s1[V];
  for (int v = 0; v < V; ++v) s0[v] = _mm256_setzero_pd(), s1[v] = _mm256_setzero_pd();
  for (int q = 0; q < nc; ++q) {
    const __m256d a = _mm256_broadcast_sd(v0 + q), b = _mm256_broadcast_sd(v1 + q);
    const int o = p - q;
    for (int v = 0; v < V; ++v) {
      const int i = o + 4 * v;
      const __m256d t0 = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(k.k00 + i), a),
                                       _mm256_mul_pd(_mm256_loadu_pd(k.k01 + i), b));
      const __m256d t1 = _mm256_add_pd(_mm256_mul_pd(_mm256_loadu_pd(k.k10 + i), a),
                                       _mm256_mul_pd(_mm256_loadu_pd(k.k11 + i), b));
      s0[v] = _mm256_add_pd(s0[v], t0);
      s1[v] = _mm256_add_pd(s1[v], t1);
    }
  }
  for (int v = 0; v < V; ++v) {
    _mm256_storeu_pd(u0 + p + 4 * v, s0[v]);
    _mm256_storeu_pd(u1 + p + 4 * v, s1[v]);
  }
}

/// The last 1-3 rows [p, nr) as lag_rows<1>, the lanes beyond nr under a mask (neither read nor
/// written: the kernels' arrays may end there).
__attribute__((target("avx2"))) inline void lag_rows_masked(int p, int nr, int nc, LagKernels k,
                                                            const double* v0, const double* v1,
                                                            double* u0, double* u1) {
  const int left = nr - p;
  const __m256i mask = _mm256_setr_epi64x(-1, left > 1 ? -1 : 0, left > 2 ? -1 : 0, 0);
  __m256d s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd();
  for (int q = 0; q < nc; ++q) {
    const __m256d a = _mm256_broadcast_sd(v0 + q), b = _mm256_broadcast_sd(v1 + q);
    const int i = p - q;
    const __m256d t0 = _mm256_add_pd(_mm256_mul_pd(_mm256_maskload_pd(k.k00 + i, mask), a),
                                     _mm256_mul_pd(_mm256_maskload_pd(k.k01 + i, mask), b));
    const __m256d t1 = _mm256_add_pd(_mm256_mul_pd(_mm256_maskload_pd(k.k10 + i, mask), a),
                                     _mm256_mul_pd(_mm256_maskload_pd(k.k11 + i, mask), b));
    s0 = _mm256_add_pd(s0, t0);
    s1 = _mm256_add_pd(s1, t1);
  }
  _mm256_maskstore_pd(u0 + p, mask, s0);
  _mm256_maskstore_pd(u1 + p, mask, s1);
}

/// The portable loop's sums, 8 (then 4, then the last 1-3) rows at a time in registers: u is
/// written once instead of loaded and stored per column (SSE2's 2 doubles an instruction: the
/// static footprint's CG products, ~70 % of a 3D transient's static start).
__attribute__((target("avx2"))) void lag_direct_avx2(int nr, int nc, LagKernels k, const double* v0,
                                                     const double* v1, double* u0, double* u1) {
  int p = 0;
  for (; p + 8 <= nr; p += 8) lag_rows<2>(p, nc, k, v0, v1, u0, u1);
  for (; p + 4 <= nr; p += 4) lag_rows<1>(p, nc, k, v0, v1, u0, u1);
  if (p < nr) lag_rows_masked(p, nr, nc, k, v0, v1, u0, u1);
}
#endif

}  // namespace

int fast_fft_length(int n) {
  int v = std::max(4, (n + 3) / 4 * 4);
  while (!smooth(v)) v += 4;
  return v;
}

void ComplianceOperator::gather(const std::vector<int>& S, Eigen::MatrixXd& A) const {
  const Eigen::Index k = static_cast<Eigen::Index>(S.size());
  A.resize(k, k);
  for (Eigen::Index b = 0; b < k; ++b)
    for (Eigen::Index a = 0; a < k; ++a) A(a, b) = entry(S[a], S[b]);
}

void DenseCompliance::gather(const std::vector<int>& S, Eigen::MatrixXd& A) const { A = C_(S, S); }

void DenseCompliance::apply(int r0, int nr, int c0, int nc,
                            const Eigen::Ref<const Eigen::MatrixXd>& X,
                            Eigen::Ref<Eigen::MatrixXd> Y) const {
  // Eigen's matrix-vector products' bits, all of X's columns in one pass over the block where
  // the CPU runs AVX2 (dense_product.h).
  detail::dense_product(nr, nc, C_.data() + static_cast<Eigen::Index>(c0) * C_.rows() + r0,
                        nc > 0 ? static_cast<int>(C_.rows()) : 1, X, Y);
}

LagConvolution2x2::LagConvolution2x2(std::array<std::vector<double>, 4> kernels, int lags)
    : k_(std::move(kernels)), lags_(lags), cache_(std::make_shared<SpectraCache>()) {
  MODALTYRE_CHECK(lags >= 1, "convolution needs at least one lag");
  for (const auto& k : k_) {
    MODALTYRE_CHECK(k.size() == 2 * static_cast<std::size_t>(lags) - 1, "kernel length");
  }
}

const LagConvolution2x2::Spectra& LagConvolution2x2::spectra(int n) const {
  for (const auto& s : seen_)
    if (s->n == n) return *s;
  const std::lock_guard<std::mutex> lock(cache_->mutex);
  for (const auto& s : cache_->all) {
    if (s->n == n) {
      seen_.push_back(s);
      return *s;
    }
  }
  // Circular embedding of length n: index p holds lag p for p < n/2 and lag p - n above, so
  // every lag in [-n/2, n/2 - 1] is represented once (zero beyond the kernels' reach).
  auto s = std::make_shared<Spectra>();
  s->n = n;
  std::vector<double> real(static_cast<std::size_t>(n), 0.0);
  for (int ab = 0; ab < 4; ++ab) {
    for (int p = 0; p < n; ++p) {
      const int l = p < n / 2 ? p : p - n;
      real[p] = std::abs(l) < lags_ ? k_[ab][static_cast<std::size_t>(l + lags_ - 1)] / n : 0.0;
    }
    s->h[ab].resize(static_cast<std::size_t>(n / 2 + 1));
    thread_fft().fwd(s->h[ab].data(), real.data(), n);
  }
  cache_->all.push_back(s);
  seen_.push_back(std::move(s));
  return *seen_.back();
}

void LagConvolution2x2::apply(int r0, int nr, int c0, int nc, const double* v0, const double* v1,
                              double* u0, double* u1) const {
  // The lags the block needs: i - j from r0 - c0 - (nc - 1) to r0 - c0 + nr - 1.
  const int lo = r0 - c0 - (nc - 1), hi = r0 - c0 + nr - 1;
  const int n = fast_fft_length(std::max(2 * (hi + 1), -2 * lo));
  // Six real transforms of length n against 4 nr nc multiply-adds: the direct sum wins on small
  // blocks (the constant is a rough fit on this machine; both give the same product).
  const double fft_cost = 6.0 * 8.0 * n * std::log2(static_cast<double>(n));
  if (4.0 * nr * nc <= fft_cost) {
    apply_direct(r0, nr, c0, nc, v0, v1, u0, u1);
  } else {
    apply_fft(r0, nr, c0, nc, v0, v1, u0, u1);
  }
}

void LagConvolution2x2::apply_direct(int r0, int nr, int c0, int nc, const double* v0,
                                     const double* v1, double* u0, double* u1) const {
  MODALTYRE_CHECK(nc - 1 - (r0 - c0) < lags_ && r0 - c0 + nr - 1 < lags_,
                  "block reaches beyond the kernels' lags");
  const int mid = lags_ - 1, l0 = r0 - c0;
  const LagKernels k{k_[0].data() + mid + l0, k_[1].data() + mid + l0, k_[2].data() + mid + l0,
                     k_[3].data() + mid + l0};
#ifdef MODALTYRE_LAG_DIRECT_AVX2
  if (instruction_set() == InstructionSet::avx2_fma)
    return lag_direct_avx2(nr, nc, k, v0, v1, u0, u1);
#endif
  lag_direct_portable(nr, nc, k, v0, v1, u0, u1);
}

void LagConvolution2x2::apply_fft(int r0, int nr, int c0, int nc, const double* v0,
                                  const double* v1, double* u0, double* u1) const {
  const int lo = r0 - c0 - (nc - 1), hi = r0 - c0 + nr - 1;
  MODALTYRE_CHECK(-lo < lags_ && hi < lags_, "block reaches beyond the kernels' lags");
  const int n = fast_fft_length(std::max(2 * (hi + 1), -2 * lo));
  const Spectra& s = spectra(n);
  const std::size_t half = static_cast<std::size_t>(n / 2 + 1);
  real_.resize(static_cast<std::size_t>(n));
  x0_.resize(half);
  x1_.resize(half);
  y_.resize(half);
  auto forward = [&](const double* v, std::vector<cd>& x) {
    std::copy(v, v + nc, real_.begin());
    std::fill(real_.begin() + nc, real_.end(), 0.0);
    thread_fft().fwd(x.data(), real_.data(), n);
  };
  forward(v0, x0_);
  forward(v1, x1_);
  // Input j sits at p = j - c0, output i at (i - c0) mod n: the lag i - j lies in [lo, hi],
  // which the embedding represents without wrap-around. Outputs are read in at most two runs.
  const int start = ((r0 - c0) % n + n) % n;
  const int first_run = std::min(nr, n - start);
  auto inverse_into = [&](const std::vector<cd>& ha, const std::vector<cd>& hb, double* u) {
    // Spelled out in reals: std::complex's operator* guards against inf/nan (slow path).
    for (std::size_t k = 0; k < half; ++k) {
      const double ar = ha[k].real(), ai = ha[k].imag(), br = hb[k].real(), bi = hb[k].imag();
      const double xr = x0_[k].real(), xi = x0_[k].imag(), zr = x1_[k].real(), zi = x1_[k].imag();
      y_[k] = cd(ar * xr - ai * xi + br * zr - bi * zi, ar * xi + ai * xr + br * zi + bi * zr);
    }
    thread_fft().inv(real_.data(), y_.data(), n);
    std::copy(real_.begin() + start, real_.begin() + start + first_run, u);
    std::copy(real_.begin(), real_.begin() + (nr - first_run), u + first_run);
  };
  inverse_into(s.h[0], s.h[1], u0);
  inverse_into(s.h[2], s.h[3], u1);
}

WeightedToeplitzCompliance::WeightedToeplitzCompliance(LagConvolution2x2 convolution,
                                                       std::vector<double> w0,
                                                       std::vector<double> w1,
                                                       std::vector<double> diagonal)
    : conv_(std::move(convolution)),
      w0_(std::move(w0)),
      w1_(std::move(w1)),
      d_(std::move(diagonal)) {
  MODALTYRE_CHECK(w0_.size() == d_.size() && w1_.size() == d_.size(), "operator sizes disagree");
  MODALTYRE_CHECK(conv_.lags() >= static_cast<int>(d_.size()), "kernels shorter than the grid");
}

double WeightedToeplitzCompliance::entry(int i, int j) const {
  const int l = i - j;
  const double ur = conv_.kernel(0, 0, l) * w0_[j] + conv_.kernel(0, 1, l) * w1_[j];
  const double ut = conv_.kernel(1, 0, l) * w0_[j] + conv_.kernel(1, 1, l) * w1_[j];
  return w0_[i] * ur + w1_[i] * ut + (i == j ? d_[i] : 0.0);
}

void WeightedToeplitzCompliance::gather(const std::vector<int>& S, Eigen::MatrixXd& A) const {
  const Eigen::Index k = static_cast<Eigen::Index>(S.size());
  A.resize(k, k);
  for (Eigen::Index b = 0; b < k; ++b) {
    const int j = S[b];
    const double w0j = w0_[j], w1j = w1_[j];
    for (Eigen::Index a = 0; a < k; ++a) {
      const int i = S[a], l = i - j;
      const double ur = conv_.kernel(0, 0, l) * w0j + conv_.kernel(0, 1, l) * w1j;
      const double ut = conv_.kernel(1, 0, l) * w0j + conv_.kernel(1, 1, l) * w1j;
      A(a, b) = w0_[i] * ur + w1_[i] * ut;
    }
    A(b, b) += d_[j];
  }
}

void WeightedToeplitzCompliance::apply(int r0, int nr, int c0, int nc,
                                       const Eigen::Ref<const Eigen::MatrixXd>& X,
                                       Eigen::Ref<Eigen::MatrixXd> Y) const {
  v0_.resize(static_cast<std::size_t>(nc));
  v1_.resize(static_cast<std::size_t>(nc));
  u0_.resize(static_cast<std::size_t>(nr));
  u1_.resize(static_cast<std::size_t>(nr));
  // Rows and columns shared by the block carry the local compliance.
  const int d0 = std::max(r0, c0), d1 = std::min(r0 + nr, c0 + nc);
  for (Eigen::Index c = 0; c < X.cols(); ++c) {
    for (int q = 0; q < nc; ++q) {
      v0_[q] = w0_[c0 + q] * X(q, c);
      v1_[q] = w1_[c0 + q] * X(q, c);
    }
    conv_.apply(r0, nr, c0, nc, v0_.data(), v1_.data(), u0_.data(), u1_.data());
    for (int p = 0; p < nr; ++p) Y(p, c) = w0_[r0 + p] * u0_[p] + w1_[r0 + p] * u1_[p];
    for (int i = d0; i < d1; ++i) Y(i - r0, c) += d_[i] * X(i - c0, c);
  }
}

Eigen::MatrixXd WeightedToeplitzCompliance::dense() const {
  const int m = size();
  Eigen::MatrixXd C(m, m);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) C(i, j) = entry(i, j);
  return C;
}

}  // namespace modaltyre::solvers
