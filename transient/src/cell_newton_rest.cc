// The 3D patch's Newton solver at rest (cell_newton.h, docs/transient.md section 7): the
// capacitance matrix I - gamma H K in its symmetric positive definite form, factored by Cholesky.
// Without spin the modal blocks of D are uncoupled 2 x 2 blocks, so H = P D^-1 Q = -(Cq diag(a)
// Cq^T + Cr diag(b) Cr^T + hub) with a, b > 0: A = -H is symmetric, and positive definite where
// the modes span the contact basis (else the LU of cell_newton.cc stays).
#include <Eigen/Dense>
#include <algorithm>

#include "cell_kernels.h"
#include "modaltyre/transient/cell_newton.h"

namespace modaltyre::transient {

bool CellNewton::rest_basis() {
  // A from H symmetrised (H is symmetric up to the rounding of its products).
  const Eigen::MatrixXd A = -0.5 * (H_ + H_.transpose());
  la_.setZero(np_, np_);
  if (!detail::cholesky_factor(np_, A.data(), la_.data())) return false;
  la_t_ = la_.transpose();
  // L^-1 and L^-T as matrices (once per setup): the capacitance solve's two products with them
  // are independent sums, not the serial chains of triangular solves.
  la_inv_.setIdentity(np_, np_);
  for (int j = 0; j < np_; ++j) detail::lower_solve(np_, la_.data(), la_inv_.col(j).data());
  la_inv_t_ = la_inv_.transpose();
  z_span_.resize(np_, TspanT_.cols());
  if (TspanT_.cols() > 0)
    detail::small_gemm(np_, static_cast<int>(TspanT_.cols()), np_, la_t_.data(), np_,
                       TspanT_.data(), np_, z_span_.data(), np_);
  return true;
}

bool CellNewton::cap_rest(double gamma) {
  // M = I + gamma L^T K L (at each setup; update_rest() changes it between setups).
  rest_work_.resize(np_, np_);
  detail::small_gemm(np_, np_, np_, K_.data(), np_, la_.data(), np_, rest_work_.data(), np_);
  cap_mat_.resize(np_, np_);
  detail::small_gemm(np_, np_, np_, la_t_.data(), np_, rest_work_.data(), np_, cap_mat_.data(),
                     np_);
  cap_mat_ *= gamma;
  cap_mat_.diagonal().array() += 1.0;
  cap_chol_.setZero(np_, np_);
  return detail::cholesky_factor(np_, cap_mat_.data(), cap_chol_.data());
}

void CellNewton::update_rest(double gamma) {
  // dM = gamma L^T dK L = sum over the changed sections of gamma dw_a z_a z_a^T (z_a: Z's column
  // of section a) as (Zc) (gamma diag(dw) Zc^T), on and below the diagonal only (Cholesky reads
  // no more): per block of four columns from its first column's row down.
  const int nchg = static_cast<int>(dw_.size()), span_lo = sys_.sections().lo;
  zc_.resize(np_, nchg);
  wz_.resize(nchg, np_);
  for (int a = 0; a < nchg; ++a) {
    const double* z = z_span_.col(dw_[a].first - span_lo).data();
    const double c = gamma * dw_[a].second;
    double* zc = zc_.col(a).data();
    for (int b = 0; b < np_; ++b) zc[b] = z[b], wz_(a, b) = c * z[b];
  }
  for (int j0 = 0; j0 < np_; j0 += 4) {
    const int cols = std::min(4, np_ - j0);
    detail::small_gemm(np_ - j0, cols, nchg, zc_.data() + j0, np_, wz_.data() + j0 * nchg, nchg,
                       cap_mat_.data() + j0 * np_ + j0, np_, true);
  }
}

void CellNewton::solve_cap_rest(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  // (I - gamma H K)^-1 = L M^-1 L^-1; s and t kept for rest_gamma_kw().
  rest_s_.resize(np_);
  detail::square_product(np_, la_inv_.data(), b.data(), rest_s_.data());
  rest_t_ = rest_s_;
  detail::lower_solve(np_, cap_chol_.data(), rest_t_.data());
  detail::lower_transpose_solve(np_, cap_chol_.data(), rest_t_.data());
  x.resize(np_);
  detail::square_product(np_, la_.data(), rest_t_.data(), x.data());
}

const Eigen::VectorXd& CellNewton::rest_gamma_kw() const {
  rest_s_ -= rest_t_;
  rest_kw_.resize(np_);
  detail::square_product(np_, la_inv_t_.data(), rest_s_.data(), rest_kw_.data());
  return rest_kw_;
}

}  // namespace modaltyre::transient
