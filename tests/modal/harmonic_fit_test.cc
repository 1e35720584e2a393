// Trigonometric-series fit of ring mode shapes (seed 001 eq. 20-21): planted orders, amplitudes
// and phases are recovered from N equally spaced noisy samples; orders >= N/2 fold as expected.
#include "modaltyre/modal/harmonic_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "modal_test_constants.h"

namespace modaltyre::modal {
namespace {

using test::kPi;
// Noise-free data: the least-squares fit is exact up to rounding of an N <= 24 QR solve.
constexpr double kExactTol = 1e-12;
// Gaussian noise sigma per point gives a fitted coefficient error per component of
// sigma*sqrt(2/N) (sigma/sqrt(N) for orders 0 and N/2); 4.5 such sigmas bound the error vector
// with probability 1 - 4e-5 per draw (Rayleigh tail), so a fixed-seed run never grazes it.
constexpr double kSigmas = 4.5;
// Residual noise energy is chi-square with N-1..N-2 dof; its 99.99 % quantile at 6 dof is 4.5x
// its mean, so 5x the mean share bounds it.
constexpr double kNoiseShareFactor = 5.0;

std::vector<double> angles(int N) {
  std::vector<double> th(N);
  for (int i = 0; i < N; ++i) th[i] = 2 * kPi * i / N;
  return th;
}

/// Samples a * cos(k (theta - psi)) + noise.
std::vector<double> ring_shape(const std::vector<double>& th, int k, double a, double psi,
                               double sigma, std::mt19937& rng) {
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<double> y(th.size());
  for (std::size_t i = 0; i < th.size(); ++i) y[i] = a * std::cos(k * (th[i] - psi)) + noise(rng);
  return y;
}

/// Relative error bound on the complex coefficient of order k at noise fraction `noise`.
double coefficient_tol(int N, int k, double noise) {
  const bool single = k == 0 || (N % 2 == 0 && k == N / 2);
  return kSigmas * noise * std::sqrt((single ? 1.0 : 2.0) / N);
}

// Noise-free shapes: every order k < N/2 is found exactly, with c = a e^{-i k psi}.
TEST(HarmonicFit, ExactRecoveryWithoutNoise) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0, 2 * kPi);
  for (int N : {7, 8, 12, 13, 18, 24}) {
    const auto th = angles(N);
    for (int k = 1; 2 * k < N; ++k) {
      const double psi = U(rng), a = 0.657;
      const auto s = fit_harmonics(th, ring_shape(th, k, a, psi, 0.0, rng));
      ASSERT_EQ(s.dominant_order(), k) << "N=" << N;
      const std::complex<double> expect = std::polar(a, -k * psi);
      EXPECT_LT(std::abs(s.coefficient(k) - expect), kExactTol) << "N=" << N << " k=" << k;
      EXPECT_NEAR(s.r2(k), 1.0, kExactTol);
      // The other harmonics are empty.
      for (int j = 0; j <= s.max_order; ++j) {
        if (j != k) {
          EXPECT_LT(std::abs(s.coefficient(j)), kExactTol);
        }
      }
    }
  }
}

// With 3 % and 5 % noise, for N = 8, 12, 18, 24 (and odd N), every k < N/2 is recovered as the
// apparent order with amplitude and phase inside the statistical error of the estimator.
TEST(HarmonicFit, RecoversOrderAmplitudePhaseWithNoise) {
  std::mt19937 rng(20240601);
  std::uniform_real_distribution<double> U(0, 2 * kPi);
  std::uniform_real_distribution<double> amp(0.3, 1.0);
  for (double noise : {0.03, 0.05}) {
    for (int N : {8, 9, 12, 18, 24}) {
      const auto th = angles(N);
      for (int k = 0; 2 * k < N; ++k) {
        for (int trial = 0; trial < 25; ++trial) {
          const double a = amp(rng), psi = U(rng);
          const auto s = fit_harmonics(th, ring_shape(th, k, a, psi, noise * a, rng));
          ASSERT_EQ(s.dominant_order(), k) << "N=" << N << " noise=" << noise;
          const std::complex<double> c = s.coefficient(k);
          const std::complex<double> expect = std::polar(a, -k * psi);
          const double tol = coefficient_tol(N, k, noise);
          // |c - expect| <= tol*a bounds both amplitude and phase errors.
          EXPECT_LT(std::abs(c - expect) / a, tol) << "N=" << N << " k=" << k;
          EXPECT_LT(std::abs(std::abs(c) - a) / a, tol);
          EXPECT_LT(std::abs(std::arg(c / expect)), std::asin(tol));
          // The noise left outside order k has expected share 2 noise^2 (k >= 1) of the
          // energy; kNoiseShareFactor covers its chi-square spread.
          EXPECT_GT(s.r2(k), 1.0 - kNoiseShareFactor * 2 * noise * noise);
        }
      }
    }
  }
}

// 5 % noise, the amplitude error is "a few %" at the 12-point resolution of the bundled test.
TEST(HarmonicFit, AmplitudeWithinFewPercentAt12Points) {
  // The amplitude error is the coefficient error along c: standard deviation sigma*sqrt(2/N),
  // 2.0 % at N = 12 and 5 % noise; 2000 draws estimate that RMS to +-1.6 %, hence +10 %.
  const double kRmsAmplitudeTol = 0.05 * std::sqrt(2.0 / 12) * 1.1;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0, 2 * kPi);
  const auto th = angles(12);
  double se = 0;
  int n = 0;
  for (int k = 1; k < 6; ++k) {
    for (int trial = 0; trial < 400; ++trial) {
      const auto s = fit_harmonics(th, ring_shape(th, k, 1.0, U(rng), 0.05, rng));
      const double e = std::abs(s.coefficient(k)) - 1.0;
      se += e * e;
      ++n;
    }
  }
  EXPECT_LT(std::sqrt(se / n), kRmsAmplitudeTol);
}

// Even N: order N/2 lands in the Nyquist term (its cosine part at the samples), and orders
// N - k and N + k fold onto apparent order k with the same amplitude (spatial aliasing).
TEST(HarmonicFit, NyquistAndAliasedOrders) {
  std::mt19937 rng(3);
  for (int N : {8, 12, 18, 24}) {
    const auto th = angles(N);
    const int h = N / 2;
    // Nyquist: samples are (-1)^i a cos(h psi).
    const double psi = 0.1;
    const auto s = fit_harmonics(th, ring_shape(th, h, 1.0, psi, 0.0, rng));
    EXPECT_EQ(s.dominant_order(), h);
    EXPECT_NEAR(s.nyquist, std::cos(h * psi), kExactTol);
    EXPECT_NEAR(s.r2(h), 1.0, kExactTol);
    for (int k = 1; k < h; ++k) {
      for (int true_k : {N - k, N + k}) {
        const auto sa = fit_harmonics(th, ring_shape(th, true_k, 0.8, 0.37, 0.0, rng));
        EXPECT_EQ(sa.dominant_order(), k) << "N=" << N << " true order " << true_k;
        EXPECT_NEAR(std::abs(sa.coefficient(k)), 0.8, kExactTol);
      }
    }
  }
}

// Uneven sampling (general least squares, eq. 20): still exact when noise free.
TEST(HarmonicFit, LeastSquaresOnUnevenAngles) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<double> th = angles(12);
  for (double& t : th) t += jitter(rng);
  std::vector<double> y(th.size());
  for (std::size_t i = 0; i < th.size(); ++i)
    y[i] = 0.2 + 0.5 * std::cos(2 * th[i]) - 0.3 * std::sin(3 * th[i]);
  const auto s = fit_harmonics(th, y);
  EXPECT_NEAR(s.A[0], 0.2, 1e-10);  // conditioning of the uneven design costs two digits
  EXPECT_NEAR(s.A[2], 0.5, 1e-10);
  EXPECT_NEAR(s.B[3], -0.3, 1e-10);
  EXPECT_EQ(s.dominant_order(), 2);
}

/// Dense least squares of eq. (20) over orders 0..n (and the Nyquist term): the reference the
/// O(N n) refinement must reproduce.
Eigen::VectorXd dense_fit(const std::vector<double>& th, const std::vector<double>& y, int n,
                          bool nyquist) {
  const int N = static_cast<int>(th.size()), cols = 1 + 2 * n + (nyquist ? 1 : 0);
  Eigen::MatrixXd X(N, cols);
  for (int i = 0; i < N; ++i) {
    X(i, 0) = 1;
    for (int k = 1; k <= n; ++k) {
      X(i, 2 * k - 1) = std::cos(k * th[i]);
      X(i, 2 * k) = std::sin(k * th[i]);
    }
    if (nyquist) X(i, cols - 1) = std::cos(0.5 * N * th[i]);
  }
  return X.colPivHouseholderQr().solve(Eigen::Map<const Eigen::VectorXd>(y.data(), N));
}

// Issue 16 item 3: the fit is Fourier projection refined to least squares (O(N n)); on points
// off equal spacing by up to the hammer reader's 1 % it equals the dense least-squares
// solution, with and without the order cap (12 and 4000 points, 5 % noise).
TEST(HarmonicFit, RefinementEqualsDenseLeastSquares) {
  std::mt19937 rng(16);
  for (int N : {12, 13, 4000}) {
    std::uniform_real_distribution<double> jitter(-0.01 * 2 * kPi / N, 0.01 * 2 * kPi / N);
    auto th = angles(N);
    for (double& t : th) t += jitter(rng);
    std::vector<double> y = ring_shape(th, 3, 0.6, 0.4, 0.03, rng);
    for (std::size_t i = 0; i < y.size(); ++i) y[i] += 0.2 * std::sin(7 * th[i]);
    const auto s = fit_harmonics(th, y);
    EXPECT_EQ(s.max_order, std::min((N - 1) / 2, kMaxFittedOrder));
    EXPECT_EQ(s.has_nyquist(), N == 12);
    const Eigen::VectorXd ref = dense_fit(th, y, s.max_order, s.has_nyquist());
    EXPECT_NEAR(s.A[0], ref(0), 1e-12) << "N=" << N;
    for (int k = 1; k <= s.max_order; ++k) {
      EXPECT_NEAR(s.A[k], ref(2 * k - 1), 1e-12) << "N=" << N << " k=" << k;
      EXPECT_NEAR(s.B[k], ref(2 * k), 1e-12) << "N=" << N << " k=" << k;
    }
    if (s.has_nyquist()) {
      EXPECT_NEAR(s.nyquist, ref(ref.size() - 1), 1e-12);
    }
    EXPECT_EQ(s.dominant_order(), 3);
  }
}

// Many points: orders above kMaxFittedOrder are not fitted; their energy stays outside every
// fitted order, so a shape made of such an order has no dominant fitted harmonic (R2 ~ 0).
TEST(HarmonicFit, OrdersAboveTheCapAreNotFitted) {
  std::mt19937 rng(1);
  const auto th = angles(1000);
  const auto high = fit_harmonics(th, ring_shape(th, kMaxFittedOrder + 10, 1.0, 0.2, 0.0, rng));
  EXPECT_FALSE(high.has_nyquist());
  EXPECT_LT(high.r2(high.dominant_order()), 1e-12);
  const auto low = fit_harmonics(th, ring_shape(th, kMaxFittedOrder, 1.0, 0.2, 0.0, rng));
  EXPECT_EQ(low.dominant_order(), kMaxFittedOrder);
  EXPECT_NEAR(low.r2(kMaxFittedOrder), 1.0, 1e-12);
}

}  // namespace
}  // namespace modaltyre::modal
