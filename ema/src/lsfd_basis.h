#pragma once
// The LSFD model's basis (lsfd.h) and its derivative with respect to the poles, shared by the
// fit, the pole refinement and the covariance of both (lsfd_covariance.h).
#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <vector>

#include "modaltyre/ema/frf_set.h"

namespace modaltyre::ema::detail {

inline constexpr double kTwoPi = 6.283185307179586;
inline constexpr int kResiduals = 4;

// Columns 2k and 2k+1: the terms of Re R_k and Im R_k; then the residuals UR, LR and their
// next terms (j w)^2 UR2 and LR2 / (j w)^4; all times (j w)^p.
inline Eigen::MatrixXcd basis(const std::vector<double>& freq_hz, FrfType type,
                              const std::vector<std::complex<double>>& poles) {
  using cd = std::complex<double>;
  const int nf = static_cast<int>(freq_hz.size());
  const int m = static_cast<int>(poles.size());
  const int p = static_cast<int>(type);
  Eigen::MatrixXcd a(nf, 2 * m + kResiduals);
  for (int f = 0; f < nf; ++f) {
    const cd jw(0.0, kTwoPi * freq_hz[f]);
    const cd gain = std::pow(jw, p);
    for (int k = 0; k < m; ++k) {
      const cd u = 1.0 / (jw - poles[k]), v = 1.0 / (jw - std::conj(poles[k]));
      a(f, 2 * k) = gain * (u + v);
      a(f, 2 * k + 1) = gain * cd(0, 1) * (u - v);
    }
    a(f, 2 * m) = gain;
    a(f, 2 * m + 1) = gain / (jw * jw);
    a(f, 2 * m + 2) = gain * jw * jw;
    a(f, 2 * m + 3) = gain / (jw * jw * jw * jw);
  }
  return a;
}

/// Derivatives of basis columns 2k and 2k+1 with respect to a change d_lambda of pole k (and
/// conj(d_lambda) of its conjugate): d/d lambda 1/(jw - lambda) = 1/(jw - lambda)^2.
inline void basis_derivative(const std::vector<double>& freq_hz, FrfType type,
                             std::complex<double> pole, std::complex<double> d_lambda,
                             Eigen::VectorXcd& d_re, Eigen::VectorXcd& d_im) {
  using cd = std::complex<double>;
  const int nf = static_cast<int>(freq_hz.size());
  const int p = static_cast<int>(type);
  d_re.resize(nf);
  d_im.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const cd jw(0.0, kTwoPi * freq_hz[f]);
    const cd gain = std::pow(jw, p);
    const cd u = 1.0 / (jw - pole), v = 1.0 / (jw - std::conj(pole));
    const cd du = u * u * d_lambda, dv = v * v * std::conj(d_lambda);
    d_re(f) = gain * (du + dv);
    d_im(f) = gain * cd(0, 1) * (du - dv);
  }
}

/// Real and imaginary parts stacked: the real least-squares form of a complex fit.
inline Eigen::MatrixXd stack(const Eigen::MatrixXcd& z) {
  Eigen::MatrixXd s(2 * z.rows(), z.cols());
  s.topRows(z.rows()) = z.real();
  s.bottomRows(z.rows()) = z.imag();
  return s;
}

}  // namespace modaltyre::ema::detail
