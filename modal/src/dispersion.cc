#include "modaltyre/modal/dispersion.h"

#include <Eigen/Dense>
#include <cmath>
#include <set>

#include "small_nnls.h"

namespace modaltyre::modal {

namespace {
constexpr double kTwoPi = 6.28318530717958647692;
}

double DispersionFit::freq_hz(int k) const {
  return std::sqrt(std::max(omega_sq(k), 0.0)) / kTwoPi;
}

DispersionFit fit_dispersion(const std::vector<int>& orders, const std::vector<double>& freq_hz) {
  DispersionFit fit;
  std::vector<int> ks;
  std::vector<double> w2;
  std::set<int> distinct;
  for (std::size_t i = 0; i < orders.size(); ++i) {
    if (orders[i] < 2) continue;
    ks.push_back(orders[i]);
    w2.push_back(std::pow(kTwoPi * freq_hz[i], 2));
    distinct.insert(orders[i]);
  }
  fit.orders_used = static_cast<int>(distinct.size());
  if (distinct.size() < 2) {
    fit.reason = "needs resolved radial modes of at least two orders >= 2, got " +
                 std::to_string(distinct.size());
    return fit;
  }
  const int m = static_cast<int>(ks.size());
  Eigen::MatrixXd X(m, 3);
  Eigen::VectorXd y(m);
  // Relative weighting: each row divided by its omega^2, so high orders do not dominate.
  for (int i = 0; i < m; ++i) {
    const double k2 = double(ks[i]) * ks[i];
    X(i, 0) = 1.0 / w2[i];
    X(i, 1) = k2 / w2[i];
    X(i, 2) = k2 * k2 / w2[i];
    y(i) = 1.0;
  }
  Eigen::VectorXd best_s;
  if (!detail::small_nnls(X, y, fit.orders_used, best_s)) {
    fit.reason = "no non-negative dispersion fit exists for these frequencies";
    return fit;
  }
  fit.valid = true;
  fit.s0 = best_s(0);
  fit.s1 = best_s(1);
  fit.s2 = best_s(2);
  double se = 0;
  for (int i = 0; i < m; ++i) {
    const double rel = fit.freq_hz(ks[i]) / (std::sqrt(w2[i]) / kTwoPi) - 1.0;
    se += rel * rel;
  }
  fit.rms_rel_error = std::sqrt(se / m);
  return fit;
}

}  // namespace modaltyre::modal
