// The tread's cosine-mode transform (contact/src/patch3d_cosine.cc), folded about the tread's
// centre, against its dense definition phi_m(j) = sqrt((m == 0 ? 1 : 2) / n) cos(pi m (j + 1/2) /
// n) on odd and even widths and row counts off the register blocks.
#include "../../contact/src/patch3d_cosine.h"

#include <gtest/gtest.h>

#include <cmath>

namespace modaltyre::contact::detail {
namespace {

Eigen::MatrixXd dct_definition(int n) {
  Eigen::MatrixXd phi(n, n);
  for (int j = 0; j < n; ++j)
    for (int m = 0; m < n; ++m)
      phi(j, m) = std::sqrt((m == 0 ? 1.0 : 2.0) / n) * std::cos(M_PI * m * (j + 0.5) / n);
  return phi;
}

TEST(CosineModes, ForwardAndBackwardAreTheDenseModesAndTheirTranspose) {
  for (int n : {1, 2, 3, 4, 7, 15, 18, 29, 30}) {
    const Eigen::MatrixXd phi = dct_definition(n);
    const CosineModes modes(n);
    EXPECT_LT((modes.dense() - phi).cwiseAbs().maxCoeff(), 1e-15) << n;
    for (int rows : {1, 3, 4, 9, 70}) {
      const Eigen::MatrixXd x = Eigen::MatrixXd::Random(rows, n);
      Eigen::MatrixXd c, back;
      modes.forward(x, c);
      EXPECT_LT((c - x * phi).cwiseAbs().maxCoeff(), 1e-12) << n << " x " << rows;
      modes.backward(c, back);
      EXPECT_LT((back - c * phi.transpose()).cwiseAbs().maxCoeff(), 1e-12) << n << " x " << rows;
      EXPECT_LT((back - x).cwiseAbs().maxCoeff(), 1e-12) << n << " x " << rows;  // orthonormal
    }
  }
}

TEST(CosineModes, TheBlockedProductIsTheMatrixProduct) {
  for (int rows : {1, 4, 5, 11}) {
    for (int cols : {1, 4, 6, 15}) {
      const Eigen::MatrixXd A = Eigen::MatrixXd::Random(rows, 7),
                            B = Eigen::MatrixXd::Random(7, cols);
      Eigen::MatrixXd out;
      small_product(A, B, out);
      EXPECT_LT((out - A * B).cwiseAbs().maxCoeff(), 1e-13) << rows << " x " << cols;
    }
  }
}

}  // namespace
}  // namespace modaltyre::contact::detail
