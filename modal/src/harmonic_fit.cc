#include "modaltyre/modal/harmonic_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::modal {
namespace {

// Refinement sweeps before the dense fallback; equally spaced points (the hammer reader allows
// 1 % of the spacing) converge in 2-4. Converged: the last correction is below 1e-13 of the
// coefficients (rounding of the sums sits near 1e-16).
constexpr int kMaxSweeps = 30;
constexpr double kConverged = 1e-13;

// The fitted columns at one angle: 1, cos k th, sin k th (k = 1..n), [cos(N/2 th)], by the
// angle-addition recurrence (O(n), no n trigonometric calls).
void basis_row(double th, int n, bool nyquist, int N, Eigen::VectorXd& b) {
  b(0) = 1.0;
  const double c1 = std::cos(th), s1 = std::sin(th);
  double c = 1.0, s = 0.0;
  for (int k = 1; k <= n; ++k) {
    const double ck = c * c1 - s * s1;
    s = s * c1 + c * s1;
    c = ck;
    b(2 * k - 1) = c;
    b(2 * k) = s;
  }
  if (nyquist) b(b.size() - 1) = std::cos(0.5 * N * th);
}

// Least squares by refinement: c += D^-1 X^T (y - X c), with D = diag(X^T X) at exactly equal
// spacing (N for the mean and the Nyquist term, N/2 for each cosine and sine). At exactly equal
// spacing X^T X = D and one sweep is the discrete Fourier projection of seed 001 eq. (21);
// a spacing off by a little converges geometrically to the least-squares solution of eq. (20).
// One sweep costs O(N n); returns false if it does not converge (far from equal spacing).
bool refine(const std::vector<double>& th, const std::vector<double>& y, int n, bool nyquist,
            Eigen::VectorXd& c) {
  const int N = static_cast<int>(th.size());
  const int cols = static_cast<int>(c.size());
  Eigen::VectorXd d = Eigen::VectorXd::Constant(cols, 0.5 * N);
  d(0) = N;
  if (nyquist) d(cols - 1) = N;
  Eigen::VectorXd b(cols), g(cols);
  c.setZero();
  double last = 0;
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    g.setZero();
    for (int i = 0; i < N; ++i) {
      basis_row(th[i], n, nyquist, N, b);
      g += b * (y[i] - b.dot(c));
    }
    const Eigen::VectorXd step = g.cwiseQuotient(d);
    if (!step.allFinite()) return false;
    c += step;
    const double size = step.norm();
    if (size <= kConverged * c.norm()) return true;
    // Not contracting: the points are too far from equal spacing for the refinement.
    if (sweep > 0 && size > 0.5 * last) return false;
    last = size;
  }
  return false;
}

}  // namespace

HarmonicSeries fit_harmonics(const std::vector<double>& angle_rad,
                             const std::vector<double>& values) {
  const int N = static_cast<int>(angle_rad.size());
  MODALTYRE_CHECK(N == static_cast<int>(values.size()) && N >= 3, "bad harmonic fit input");
  HarmonicSeries s;
  s.points = N;
  s.max_order = std::min((N - 1) / 2, kMaxFittedOrder);
  const int n = s.max_order;
  // The Nyquist term belongs to the complete series only; with orders capped it is not fitted.
  s.nyquist_fitted = N % 2 == 0 && n == (N - 1) / 2;
  const int cols = 1 + 2 * n + (s.nyquist_fitted ? 1 : 0);
  Eigen::VectorXd c(cols);
  if (!refine(angle_rad, values, n, s.nyquist_fitted, c)) {
    // seed 001 eq. (20): dense least squares for points far from equal spacing.
    Eigen::MatrixXd X(N, cols);
    Eigen::VectorXd b(cols);
    for (int i = 0; i < N; ++i) {
      basis_row(angle_rad[i], n, s.nyquist_fitted, N, b);
      X.row(i) = b.transpose();
    }
    c = X.colPivHouseholderQr().solve(Eigen::Map<const Eigen::VectorXd>(values.data(), N));
  }
  s.A.assign(n + 1, 0.0);
  s.B.assign(n + 1, 0.0);
  s.A[0] = c(0);
  for (int k = 1; k <= n; ++k) {
    s.A[k] = c(2 * k - 1);
    s.B[k] = c(2 * k);
  }
  if (s.nyquist_fitted) s.nyquist = c(cols - 1);
  s.energy = 0;
  for (double v : values) s.energy += v * v;
  return s;
}

double HarmonicSeries::order_energy(int k) const {
  // Orthogonality at equally spaced points: sum cos^2(k theta_i) = N/2 for 0 < k < N/2.
  if (k == 0) return points * A[0] * A[0];
  if (has_nyquist() && k == points / 2) return points * nyquist * nyquist;
  MODALTYRE_CHECK(k >= 1 && k <= max_order, "order outside the fitted range");
  return 0.5 * points * (A[k] * A[k] + B[k] * B[k]);
}

int HarmonicSeries::dominant_order() const {
  int best = 0;
  double best_e = order_energy(0);
  const int top = has_nyquist() ? points / 2 : max_order;
  for (int k = 1; k <= top; ++k) {
    const double e = order_energy(k);
    if (e > best_e) {
      best_e = e;
      best = k;
    }
  }
  return best;
}

double HarmonicSeries::r2(int k) const { return energy > 0 ? order_energy(k) / energy : 0.0; }

std::complex<double> HarmonicSeries::coefficient(int k) const {
  if (k == 0) return {A[0], 0.0};
  if (has_nyquist() && k == points / 2) return {nyquist, 0.0};
  return {A[k], -B[k]};  // A cos + B sin = Re((A - iB) e^{ik theta})
}

}  // namespace modaltyre::modal
