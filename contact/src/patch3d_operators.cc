#include "patch3d_operators.h"

#include <algorithm>

namespace modaltyre::contact::detail {

void DiagonalShifted::gather(const std::vector<int>& S, Eigen::MatrixXd& A) const {
  base_.gather(S, A);
  for (std::size_t a = 0; a < S.size(); ++a) A(a, a) += d_[S[a]];
}

void DiagonalShifted::apply(int r0, int nr, int c0, int nc,
                            const Eigen::Ref<const Eigen::MatrixXd>& X,
                            Eigen::Ref<Eigen::MatrixXd> Y) const {
  base_.apply(r0, nr, c0, nc, X, Y);
  for (int i = std::max(r0, c0); i < std::min(r0 + nr, c0 + nc); ++i) {
    Y.row(i - r0) += d_[i] * X.row(i - c0);
  }
}

void CellCompliance::apply(int r0, int nr, int c0, int nc,
                           const Eigen::Ref<const Eigen::MatrixXd>& X,
                           Eigen::Ref<Eigen::MatrixXd> Y) const {
  const int n = columns_;
  // Section resultants of the column block (its first and last sections may be partial).
  const int s0 = c0 / n, s1 = (c0 + nc - 1) / n;
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(s1 - s0 + 1, X.cols());
  for (int b = 0; b < nc; ++b) F.row((c0 + b) / n - s0) += X.row(b);
  // Carcass displacement of the row block's sections, spread to their cells.
  const int q0 = r0 / n, q1 = (r0 + nr - 1) / n;
  Eigen::MatrixXd W(q1 - q0 + 1, X.cols());
  carcass_.apply(q0, q1 - q0 + 1, s0, s1 - s0 + 1, F, W);
  for (int a = 0; a < nr; ++a) Y.row(a) = W.row((r0 + a) / n - q0);
  // Each cell's own tread.
  for (int a = std::max(r0, c0); a < std::min(r0 + nr, c0 + nc); ++a) {
    Y.row(a - r0) += t_[a / n] * X.row(a - c0);
  }
}

}  // namespace modaltyre::contact::detail
