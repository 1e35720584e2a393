#include "modaltyre/ema/lsfd_covariance.h"

#include <cmath>

#include "lsfd_basis.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::ema {

using cd = std::complex<double>;

LsfdCovariance lsfd_covariance(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf,
                               FrfType type, const std::vector<cd>& poles,
                               const Eigen::VectorXd& weight) {
  const int m = static_cast<int>(poles.size());
  const int no = static_cast<int>(frf.cols());
  const Eigen::MatrixXd a = detail::stack(detail::basis(freq_hz, type, poles));
  const Eigen::MatrixXd y = detail::stack(frf);
  const Eigen::Index rows = a.rows(), np = a.cols();
  LsfdCovariance out;
  // Per FRF: its 2 nf real values less its own linear parameters and its share of the poles'.
  out.dof = double(rows - np) - 2.0 * m / std::max(no, 1);
  if (m == 0 || !(out.dof > 0) || weight.size() != no) {
    throw ComputationError("lsfd_covariance: no degrees of freedom left for the noise (" +
                           std::to_string(rows) + " values, " + std::to_string(np) +
                           " parameters per FRF)");
  }
  // Column scaling as in the fit: resonant and residual terms differ by orders of magnitude.
  Eigen::VectorXd d = a.colwise().norm().transpose();
  for (auto& s : d) s = s > 0 ? 1.0 / s : 1.0;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a * d.asDiagonal());
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(rows, np);
  const Eigen::MatrixXd r_inv = qr.matrixQR().topRows(np).triangularView<Eigen::Upper>().solve(
      Eigen::MatrixXd::Identity(np, np));
  const Eigen::MatrixXd pinv_left = d.asDiagonal() * r_inv;  // A^+ = pinv_left Q^T
  const Eigen::MatrixXd ata_inv = pinv_left * pinv_left.transpose();
  const Eigen::MatrixXd c = pinv_left * (q.transpose() * y);
  out.noise.resize(no);
  for (int o = 0; o < no; ++o) {
    out.noise(o) = std::sqrt((y.col(o) - a * c.col(o)).squaredNorm() / out.dof);
  }

  // d(basis columns 2k, 2k+1) for a change of ln f_k (d lambda = lambda: lambda is w times a
  // function of zeta) and of ln zeta_k (d lambda = zeta d lambda / d zeta).
  Eigen::MatrixXd d_re(rows, 2 * m), d_im(rows, 2 * m);
  for (int k = 0; k < m; ++k) {
    const double w = std::abs(poles[k]), z = -poles[k].real() / w;
    const cd dl_zeta = z * w * cd(-1.0, -z / std::sqrt(1 - z * z));
    Eigen::VectorXcd re, im;
    for (int j = 0; j < 2; ++j) {
      detail::basis_derivative(freq_hz, type, poles[k], j == 0 ? poles[k] : dl_zeta, re, im);
      d_re.col(j * m + k) = detail::stack(re);
      d_im.col(j * m + k) = detail::stack(im);
    }
  }
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(2 * m, 2 * m), meat = s;
  std::vector<Eigen::MatrixXd> g(no);
  for (int o = 0; o < no; ++o) {
    Eigen::MatrixXd j_o(rows, 2 * m);
    for (int p = 0; p < 2 * m; ++p) {
      const int k = p % m;
      j_o.col(p) = d_re.col(p) * c(2 * k, o) + d_im.col(p) * c(2 * k + 1, o);
    }
    const Eigen::MatrixXd qt_j = q.transpose() * j_o;
    const Eigen::MatrixXd k_o = j_o - q * qt_j;  // the projection off A's columns
    const Eigen::MatrixXd ktk = k_o.transpose() * k_o;
    const double w2 = weight(o) * weight(o);
    s += w2 * ktk;
    meat += w2 * w2 * out.noise(o) * out.noise(o) * ktk;
    g[o] = pinv_left * qt_j;
  }
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(s);
  const Eigen::MatrixXd s_inv = ldlt.solve(Eigen::MatrixXd::Identity(2 * m, 2 * m));
  out.pole_cov = s_inv * meat * s_inv;
  if (ldlt.info() != Eigen::Success || !out.pole_cov.allFinite()) {
    throw ComputationError("lsfd_covariance: the poles' normal matrix is singular");
  }

  out.residue_cov.assign(m, Eigen::MatrixXd::Zero(2 * no, 2 * no));
  for (int k = 0; k < m; ++k) {
    auto& cov = out.residue_cov[k];
    for (int o = 0; o < no; ++o) {
      const Eigen::MatrixXd go = g[o].middleRows(2 * k, 2);
      for (int p = o; p < no; ++p) {
        Eigen::Matrix2d block = go * out.pole_cov * g[p].middleRows(2 * k, 2).transpose();
        if (p == o) block += out.noise(o) * out.noise(o) * ata_inv.block(2 * k, 2 * k, 2, 2);
        cov.block(2 * o, 2 * p, 2, 2) = block;
        cov.block(2 * p, 2 * o, 2, 2) = block.transpose();
      }
    }
  }
  return out;
}

Eigen::VectorXd real_shape_std(const LsfdCovariance& cov, int k, cd z, const Eigen::VectorXd& q,
                               int r, double e) {
  const Eigen::Index no = q.size();
  // q_o = Re(z) Re R_ok - Im(z) Im R_ok: the projection of each FRF's residue.
  Eigen::MatrixXd proj = Eigen::MatrixXd::Zero(no, 2 * no);
  for (Eigen::Index o = 0; o < no; ++o) {
    proj(o, 2 * o) = z.real();
    proj(o, 2 * o + 1) = -z.imag();
  }
  const Eigen::MatrixXd cq = proj * cov.residue_cov.at(k) * proj.transpose();
  Eigen::VectorXd out(no);
  const double qr_e = std::pow(std::abs(q(r)), -e);
  for (Eigen::Index o = 0; o < no; ++o) {
    if (o == r) {  // phi_r = q_r^(1-e)
      out(o) = std::abs((1 - e) * qr_e) * std::sqrt(cq(r, r));
      continue;
    }
    // d phi_o = q_r^-e d q_o - e q_o q_r^(-e-1) d q_r
    const double go = qr_e, gr = -e * q(o) * qr_e / q(r);
    out(o) =
        std::sqrt(std::max(0.0, go * go * cq(o, o) + 2 * go * gr * cq(o, r) + gr * gr * cq(r, r)));
  }
  return out;
}

}  // namespace modaltyre::ema
