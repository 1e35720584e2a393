#include "modaltyre/modal/harmonic_fit.h"

#include <Eigen/Dense>
#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::modal {

HarmonicSeries fit_harmonics(const std::vector<double>& angle_rad,
                             const std::vector<double>& values) {
  const int N = static_cast<int>(angle_rad.size());
  MODALTYRE_CHECK(N == static_cast<int>(values.size()) && N >= 3, "bad harmonic fit input");
  HarmonicSeries s;
  s.points = N;
  s.max_order = (N - 1) / 2;
  const int n = s.max_order;
  const int cols = 1 + 2 * n + (N % 2 == 0 ? 1 : 0);
  Eigen::MatrixXd X(N, cols);
  Eigen::VectorXd y(N);
  for (int i = 0; i < N; ++i) {
    const double th = angle_rad[i];
    X(i, 0) = 1.0;
    for (int k = 1; k <= n; ++k) {
      X(i, 2 * k - 1) = std::cos(k * th);
      X(i, 2 * k) = std::sin(k * th);
    }
    if (N % 2 == 0) X(i, cols - 1) = std::cos(0.5 * N * th);
    y(i) = values[i];
  }
  // seed 001 eq. (20): least squares for the undetermined coefficients.
  const Eigen::VectorXd c = X.colPivHouseholderQr().solve(y);
  s.A.assign(n + 1, 0.0);
  s.B.assign(n + 1, 0.0);
  s.A[0] = c(0);
  for (int k = 1; k <= n; ++k) {
    s.A[k] = c(2 * k - 1);
    s.B[k] = c(2 * k);
  }
  if (N % 2 == 0) s.nyquist = c(cols - 1);
  s.energy = y.squaredNorm();
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
