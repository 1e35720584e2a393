#include "modaltyre/solvers/arrow_lu.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace modaltyre::solvers {

bool ArrowLu::factor(const CscMatrix& J, double gamma, int64_t nx) {
  n_ = J.n;
  nx_ = nx;
  ne_ = n_ - nx;
  d_.setOnes(ne_);
  s1_.setZero(ne_);
  s2_.setZero(ne_);
  Eigen::MatrixXd mxx = Eigen::MatrixXd::Identity(nx, nx);
  // First pass: the E blocks and the coupled range.
  lo_ = ne_;
  hi_ = -1;
  std::vector<char> row_used(nx, 0), col_used(nx, 0);
  for (int64_t c = 0; c < n_; ++c) {
    for (int64_t p = J.col_ptr[c]; p < J.col_ptr[c + 1]; ++p) {
      const int64_t r = J.row[p];
      const double v = -gamma * J.value[p];
      if (r < nx && c < nx) {
        mxx(r, c) += v;
      } else if (r >= nx && c >= nx) {
        const int64_t i = r - nx, off = c - r;
        if (off == 0)
          d_(i) += v;
        else if (off == 1)
          s1_(i) = v;
        else if (off == 2)
          s2_(i) = v;
        else if (v != 0)
          return false;     // not an upper band of width 2
      } else if (r < nx) {  // M_XE
        if (v == 0) continue;
        row_used[r] = 1;
        lo_ = std::min(lo_, c - nx), hi_ = std::max(hi_, c - nx);
      } else {  // M_EX
        if (v == 0) continue;
        col_used[c] = 1;
        lo_ = std::min(lo_, r - nx), hi_ = std::max(hi_, r - nx);
      }
    }
  }
  rows_.clear();
  cols_.clear();
  std::vector<int64_t> row_pos(nx, -1), col_pos(nx, -1);
  for (int64_t k = 0; k < nx; ++k) {
    if (row_used[k]) row_pos[k] = static_cast<int64_t>(rows_.size()), rows_.push_back(k);
    if (col_used[k]) col_pos[k] = static_cast<int64_t>(cols_.size()), cols_.push_back(k);
  }
  const int64_t range = coupled_range();
  xe_.setZero(range, static_cast<Eigen::Index>(rows_.size()));  // stored transposed
  ex_.setZero(range, static_cast<Eigen::Index>(cols_.size()));
  if (range > 0) {
    for (int64_t c = 0; c < n_; ++c) {
      for (int64_t p = J.col_ptr[c]; p < J.col_ptr[c + 1]; ++p) {
        const int64_t r = J.row[p];
        if ((r < nx) == (c < nx)) continue;
        const double v = -gamma * J.value[p];
        if (v == 0) continue;  // explicit zeros may lie outside the coupled range
        if (r < nx && row_pos[r] >= 0)
          xe_(c - nx - lo_, row_pos[r]) = v;
        else if (c < nx && col_pos[c] >= 0)
          ex_(r - nx - lo_, col_pos[c]) = v;
      }
    }
    // Y = M_EE^-1 M_EX on the coupled range: back substitution from its last row (M_EX is zero
    // beyond it, so Y is too; rows before the range are not needed by M_XE).
    Eigen::MatrixXd y = ex_;
    for (int64_t i = range - 1; i >= 0; --i) {
      const int64_t e = lo_ + i;
      if (i + 1 < range) y.row(i) -= s1_(e) * y.row(i + 1);
      if (i + 2 < range) y.row(i) -= s2_(e) * y.row(i + 2);
      y.row(i) /= d_(e);
    }
    // S[rows, cols] -= M_XE Y, coefficient-based (Eigen's blocked GEMM would start OpenMP
    // threads for a product this small).
    // Both factors by columns: each entry is a contiguous dot product.
    const Eigen::MatrixXd upd = xe_.transpose().lazyProduct(y);
    for (std::size_t a = 0; a < rows_.size(); ++a)
      for (std::size_t b = 0; b < cols_.size(); ++b) mxx(rows_[a], cols_[b]) -= upd(a, b);
  }
  if (!d_.allFinite() || (d_.array() == 0).any() || !mxx.allFinite()) return false;
  {
    // Eigen's blocked LU multiplies its panels by GEMM, which for a 90 x 90 matrix starts OpenMP
    // threads (the library is built with OpenMP for sweeps): their start and spinning cost
    // more than the factorisation. The thread count is a per-thread setting of OpenMP.
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    lu_.compute(mxx);
    omp_set_num_threads(threads);
  }
  const Eigen::VectorXd piv = lu_.matrixLU().diagonal();
  if (!piv.allFinite() || (piv.array() == 0).any()) return false;
  tmp_x_.resize(nx);
  tmp_e_.resize(ne_);
  tmp_r_.resize(static_cast<Eigen::Index>(rows_.size()));
  tmp_c_.resize(static_cast<Eigen::Index>(cols_.size()));
  return true;
}

void ArrowLu::solve_ee(double* y) const {
  for (int64_t i = ne_ - 1; i >= 0; --i) {
    double v = y[i];
    if (i + 1 < ne_) v -= s1_(i) * y[i + 1];
    if (i + 2 < ne_) v -= s2_(i) * y[i + 2];
    y[i] = v / d_(i);
  }
}

void ArrowLu::solve(double* x) const {
  double* xe = x + nx_;
  Eigen::Map<Eigen::VectorXd> xx(x, nx_);
  const int64_t range = coupled_range();
  if (range > 0) {
    // Block elimination: b_X - M_XE M_EE^-1 b_E, then S x_X, then M_EE^-1 (b_E - M_EX x_X).
    Eigen::Map<Eigen::VectorXd> be(xe, ne_);
    tmp_e_ = be;  // keep b_E
    solve_ee(xe);
    tmp_r_.noalias() = xe_.transpose() * be.segment(lo_, range);
    for (std::size_t a = 0; a < rows_.size(); ++a) xx(rows_[a]) -= tmp_r_(a);
    tmp_x_ = lu_.solve(xx);
    xx = tmp_x_;
    be = tmp_e_;
    for (std::size_t b = 0; b < cols_.size(); ++b) tmp_c_(b) = xx(cols_[b]);
    be.segment(lo_, range).noalias() -= ex_ * tmp_c_;
    solve_ee(xe);
  } else {
    tmp_x_ = lu_.solve(xx);
    xx = tmp_x_;
    solve_ee(xe);
  }
}

}  // namespace modaltyre::solvers
