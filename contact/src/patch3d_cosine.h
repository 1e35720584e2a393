#pragma once
// The tread's cosine modes across the road (patch3d_tread.cc): the orthonormal DCT-II of size n,
// phi_m(j) = sqrt((m == 0 ? 1 : 2) / n) cos(pi m (j + 1/2) / n), applied to every section of a
// block of cells at once (rows: sections, columns: the tread's columns).
#include <Eigen/Dense>

namespace modaltyre::contact::detail {

class CosineModes {
 public:
  explicit CosineModes(int n);
  int size() const { return n_; }
  /// phi_m(j) at (j, m).
  const Eigen::MatrixXd& dense() const { return phi_; }
  /// c = x phi: each row's modal coefficients.
  void forward(const Eigen::MatrixXd& x, Eigen::MatrixXd& c) const;
  /// x = c phi^T: back to the cells.
  void backward(const Eigen::MatrixXd& c, Eigen::MatrixXd& x) const;

 private:
  int n_, half_, even_, odd_;  ///< n / 2 (floor), the even and the odd modes' counts
  Eigen::MatrixXd phi_;
  Eigen::MatrixXd e_, o_, e_t_, o_t_;  ///< the folded blocks and their transposes
};

/// out = A B for the transforms' small products (rows: sections), register-blocked over four
/// sections and four outputs; Eigen's lazy product reads A's rows with a stride, and its blocked
/// GEMM would start OpenMP threads for these sizes.
void small_product(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, Eigen::MatrixXd& out);

}  // namespace modaltyre::contact::detail
