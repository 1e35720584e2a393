// The tread's cosine modes (patch3d_cosine.h), by folding the columns about the tread's centre:
// phi_m(n - 1 - j) = (-1)^m phi_m(j), so the even modes see only x(j) + x(n - 1 - j) and the odd
// ones only x(j) - x(n - 1 - j) (the middle column, for n odd, only the even modes: phi_m there
// is cos(pi m / 2)). Two half-size products instead of one full: half the multiplications of
// the dense n x n transform, the same sums up to rounding (test: against phi to 1e-12).
#include "patch3d_cosine.h"

#include <algorithm>
#include <cmath>

namespace modaltyre::contact::detail {

CosineModes::CosineModes(int n) : n_(n), half_(n / 2), even_((n + 1) / 2), odd_(n / 2) {
  phi_.resize(n, n);
  for (int m = 0; m < n; ++m) {
    const double norm = std::sqrt((m == 0 ? 1.0 : 2.0) / n);
    for (int j = 0; j < n; ++j) phi_(j, m) = norm * std::cos(M_PI * m * (j + 0.5) / n);
  }
  // Folded rows: j < n / 2, and for n odd the middle column (folded with nothing).
  e_.resize(even_, even_);
  o_.resize(half_, odd_);
  for (int j = 0; j < even_; ++j)
    for (int p = 0; p < even_; ++p) e_(j, p) = phi_(j, 2 * p);
  for (int j = 0; j < half_; ++j)
    for (int p = 0; p < odd_; ++p) o_(j, p) = phi_(j, 2 * p + 1);
  e_t_ = e_.transpose();
  o_t_ = o_.transpose();
}

void CosineModes::forward(const Eigen::MatrixXd& x, Eigen::MatrixXd& c) const {
  const Eigen::Index rows = x.rows();
  Eigen::MatrixXd a, b, ce, co;  // folded inputs, even and odd products
  a.resize(rows, even_);
  b.resize(rows, half_);
  for (int j = 0; j < half_; ++j) {
    a.col(j) = x.col(j) + x.col(n_ - 1 - j);
    b.col(j) = x.col(j) - x.col(n_ - 1 - j);
  }
  if (even_ > half_) a.col(half_) = x.col(half_);
  small_product(a, e_, ce);
  small_product(b, o_, co);
  c.resize(rows, n_);
  for (int k = 0; k < even_; ++k) c.col(2 * k) = ce.col(k);
  for (int k = 0; k < odd_; ++k) c.col(2 * k + 1) = co.col(k);
}

void CosineModes::backward(const Eigen::MatrixXd& c, Eigen::MatrixXd& x) const {
  const Eigen::Index rows = c.rows();
  Eigen::MatrixXd a, b, ce, co;  // folded inputs, even and odd products
  a.resize(rows, even_);
  b.resize(rows, odd_);
  for (int k = 0; k < even_; ++k) a.col(k) = c.col(2 * k);
  for (int k = 0; k < odd_; ++k) b.col(k) = c.col(2 * k + 1);
  small_product(a, e_t_, ce);  // the even modes' part at j < n / 2 (and the middle)
  small_product(b, o_t_, co);  // the odd modes' part at j < n / 2
  x.resize(rows, n_);
  for (int j = 0; j < half_; ++j) {
    x.col(j) = ce.col(j) + co.col(j);
    x.col(n_ - 1 - j) = ce.col(j) - co.col(j);
  }
  if (even_ > half_) x.col(half_) = ce.col(half_);
}

namespace {

// out(s .. s + R, m .. m + M) = A(s .. s + R, :) B(:, m .. m + M), accumulated in registers.
template <int R, int M>
void block_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& out,
                   Eigen::Index s, Eigen::Index m) {
  double acc[M][R] = {};
  const Eigen::Index k = A.cols();
  for (Eigen::Index l = 0; l < k; ++l) {
    const double* a = &A.coeffRef(s, l);
    for (int q = 0; q < M; ++q) {
      const double b = B(l, m + q);
      for (int i = 0; i < R; ++i) acc[q][i] += b * a[i];
    }
  }
  for (int q = 0; q < M; ++q)
    for (int i = 0; i < R; ++i) out(s + i, m + q) = acc[q][i];
}

}  // namespace

void small_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& out) {
  const Eigen::Index rows = A.rows(), cols = B.cols();
  out.resize(rows, cols);
  constexpr int R = 4, M = 4;
  const Eigen::Index r4 = rows - rows % R, m4 = cols - cols % M;
  for (Eigen::Index m = 0; m < m4; m += M) {
    for (Eigen::Index s = 0; s < r4; s += R) block_product<R, M>(A, B, out, s, m);
    for (Eigen::Index s = r4; s < rows; ++s) block_product<1, M>(A, B, out, s, m);
  }
  for (Eigen::Index m = m4; m < cols; ++m) {
    for (Eigen::Index s = 0; s < r4; s += R) block_product<R, 1>(A, B, out, s, m);
    for (Eigen::Index s = r4; s < rows; ++s) block_product<1, 1>(A, B, out, s, m);
  }
}

}  // namespace modaltyre::contact::detail
