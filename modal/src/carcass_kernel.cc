#include "modaltyre/modal/carcass_kernel.h"

#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "modaltyre/core/errors.h"

namespace modaltyre::modal {
namespace {

using cd = std::complex<double>;

/// Complex modal receptance of a term, including its weight (seed 001 eq. 2 and 5).
cd receptance(const ModalTerm& t, const RollingState& rolling) {
  const double w = t.omega_rad_s;
  if (rolling.speed_m_s <= 0) return cd(t.weight / (w * w), 0.0);
  const double f = t.order * rolling.speed_m_s / rolling.radius_m;  // k Omega
  return t.weight / cd(w * w - f * f, -2.0 * t.damping_ratio * w * f);
}

}  // namespace

Transfer2x2 transfer(const ModalBasis& basis, double delta_rad, const RollingState& rolling) {
  Transfer2x2 h;
  for (const auto& t : basis.terms) {
    const cd e = receptance(t, rolling) * std::polar(1.0, t.order * delta_rad);
    h.r_from_r += (t.P_rr * e).real();
    h.r_from_t += (t.P_rt * e).real();
    h.t_from_r += (std::conj(t.P_rt) * e).real();
    h.t_from_t += (t.P_tt * e).real();
  }
  return h;
}

LagKernels build_lag_kernels(const ModalBasis& basis, double dtheta_rad, int lags,
                             const RollingState& rolling) {
  MODALTYRE_CHECK(lags >= 1 && dtheta_rad > 0, "bad kernel grid");
  LagKernels K;
  K.dtheta_rad = dtheta_rad;
  K.lags = lags;
  const std::size_t size = 2 * static_cast<std::size_t>(lags) - 1;
  K.r_from_r.assign(size, 0.0);
  K.r_from_t.assign(size, 0.0);
  K.t_from_r.assign(size, 0.0);
  K.t_from_t.assign(size, 0.0);
  const std::size_t mid = static_cast<std::size_t>(lags) - 1;
  for (const auto& t : basis.terms) {
    const cd D = receptance(t, rolling);
    const cd a_rr = t.P_rr * D, a_rt = t.P_rt * D, a_tr = std::conj(t.P_rt) * D,
             a_tt = t.P_tt * D;
    const cd step = std::polar(1.0, t.order * dtheta_rad);
    cd z(1.0, 0.0);  // e^{i k j dtheta}
    for (int j = 0; j < lags; ++j) {
      // Re-anchor the recurrence every 64 steps to keep rounding at machine precision.
      if ((j & 63) == 0) z = std::polar(1.0, double(t.order) * j * dtheta_rad);
      const cd zc = std::conj(z);
      K.r_from_r[mid + j] += (a_rr * z).real();
      K.r_from_t[mid + j] += (a_rt * z).real();
      K.t_from_r[mid + j] += (a_tr * z).real();
      K.t_from_t[mid + j] += (a_tt * z).real();
      if (j > 0) {
        K.r_from_r[mid - j] += (a_rr * zc).real();
        K.r_from_t[mid - j] += (a_rt * zc).real();
        K.t_from_r[mid - j] += (a_tr * zc).real();
        K.t_from_t[mid - j] += (a_tt * zc).real();
      }
      z *= step;
    }
  }
  return K;
}

int fft_friendly_size(int n) {
  auto smooth = [](int v) {
    for (int f : {2, 3, 5})
      while (v % f == 0) v /= f;
    return v == 1;
  };
  for (int d = 0;; ++d) {
    if (n - d >= 8 && smooth(n - d)) return n - d;
    if (smooth(n + d)) return n + d;
  }
}

LagKernels build_periodic_kernels(const ModalBasis& basis, int n, int lags,
                                  const RollingState& rolling) {
  MODALTYRE_CHECK(n >= 8 && lags >= 1 && 2 * (lags - 1) < n, "bad periodic kernel grid");
  // Per-order coefficients G_ab[k] = sum over terms of order k of w P_ab D_k.
  std::vector<std::vector<cd>> G(4, std::vector<cd>(n, cd(0, 0)));
  for (const auto& t : basis.terms) {
    MODALTYRE_CHECK(2 * t.order <= n, "modal order above the grid's Nyquist order");
    const cd D = receptance(t, rolling);
    G[0][t.order] += t.P_rr * D;
    G[1][t.order] += t.P_rt * D;
    G[2][t.order] += std::conj(t.P_rt) * D;
    G[3][t.order] += t.P_tt * D;
  }
  LagKernels K;
  K.dtheta_rad = 2 * M_PI / n;
  K.lags = lags;
  std::vector<double>* out[4] = {&K.r_from_r, &K.r_from_t, &K.t_from_r, &K.t_from_t};
  Eigen::FFT<double> fft;
  std::vector<cd> x;
  const std::size_t mid = static_cast<std::size_t>(lags) - 1;
  for (int f = 0; f < 4; ++f) {
    // x_j = sum_k G_k e^{2 pi i k j / n}; Eigen's inverse transform divides by n.
    fft.inv(x, G[f]);
    auto& v = *out[f];
    v.assign(2 * static_cast<std::size_t>(lags) - 1, 0.0);
    for (int j = 0; j < lags; ++j) {
      v[mid + j] = x[j].real() * n;
      if (j > 0) v[mid - j] = x[n - j].real() * n;
    }
  }
  return K;
}

}  // namespace modaltyre::modal
