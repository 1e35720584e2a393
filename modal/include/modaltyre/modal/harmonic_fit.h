#pragma once
// Trigonometric-series fit of a mode shape sampled at N points (seed 001 eq. 20-21):
//   y(theta) = A0 + sum_{j=1..n} (Aj cos j theta + Bj sin j theta),  2n + 1 < N,
// solved by least squares. For equally spaced points this equals the discrete Fourier
// coefficients of eq. (21), which is how it is computed: Fourier projection refined to the
// least-squares solution for a spacing that is off by a little, O(N n) (a dense QR only for
// points far from equal spacing). For even N the Nyquist term A_{N/2} cos(N/2 theta) is fitted
// too, because an order-N/2 (or aliased higher) shape puts all its energy there; its sine part
// is invisible at the sample points. Orders above kMaxFittedOrder are not fitted (a hammer test
// with hundreds of points resolves no tyre mode that high; their energy stays in the residual,
// so such a shape has no dominant fitted order).
#include <complex>
#include <vector>

namespace modaltyre::modal {

/// Highest order fitted: n = min((N-1)/2, kMaxFittedOrder).
constexpr int kMaxFittedOrder = 50;

struct HarmonicSeries {
  int points = 0;
  int max_order = 0;         ///< n = min(floor((N-1)/2), kMaxFittedOrder)
  std::vector<double> A;     ///< A_0..A_n
  std::vector<double> B;     ///< B_0..B_n (B_0 = 0)
  double nyquist = 0.0;      ///< coefficient of cos(N/2 theta); 0 unless nyquist_fitted
  bool nyquist_fitted = false;  ///< even N with every order below N/2 fitted
  double energy = 0.0;       ///< sum of y_i^2 over the points

  /// The Nyquist order N/2 is part of the fit (even N, orders not capped).
  bool has_nyquist() const { return nyquist_fitted; }
  /// Energy of order k at the sample points (sum over points of its term squared).
  double order_energy(int k) const;
  /// Order with the largest energy, 0..n or N/2 (Nyquist).
  int dominant_order() const;
  /// Uncentred R^2 of the single harmonic k: its share of sum y_i^2.
  double r2(int k) const;
  /// Complex coefficient c with y_k(theta) = Re(c e^{i k theta}).
  std::complex<double> coefficient(int k) const;
};

HarmonicSeries fit_harmonics(const std::vector<double>& angle_rad,
                             const std::vector<double>& values);

}  // namespace modaltyre::modal
