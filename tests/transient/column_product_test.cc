// The transient's products (column_product.h), column_product and column_dots, against their
// stated order of fused multiply-adds to the bit (the same on every CPU) and against Eigen's
// products to rounding.
#include "modaltyre/transient/column_product.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace modaltyre::transient {
namespace {

TEST(ColumnProduct, SumsInItsStatedOrderWithFusedMultiplyAdds) {
  // column_product: out_i = fma(A_i,cols-1, x_cols-1, ... fma(A_i0, x_0, 0)) (+ out_i): the
  // same bits on the AVX2 path and the portable one (std::fma), and Eigen's A * x to rounding.
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int rows : {1, 3, 13, 63, 64, 65, 253, 729}) {
    for (int cols : {1, 4, 13, 14, 44}) {
      Eigen::MatrixXd A(rows + 5, cols);  // a block of rows of a taller matrix, as T's reach
      for (Eigen::Index k = 0; k < A.size(); ++k) A.data()[k] = u(rng) * std::exp(8 * u(rng));
      Eigen::VectorXd x(cols), base(rows);
      for (int j = 0; j < cols; ++j) x(j) = u(rng);
      for (int i = 0; i < rows; ++i) base(i) = u(rng);
      const auto block = A.middleRows(2, rows);
      Eigen::VectorXd got(rows), added = base;
      column_product(block, x, got);
      column_product(block, x, added, /*accumulate=*/true);
      const Eigen::VectorXd eigen = block * x;
      for (int i = 0; i < rows; ++i) {
        double s = 0.0;
        for (int j = 0; j < cols; ++j) s = std::fma(block(i, j), x(j), s);
        ASSERT_EQ(s + 0.0, got(i)) << rows << " x " << cols << " " << i;
        ASSERT_EQ(s + base(i), added(i)) << rows << " x " << cols << " " << i;
        ASSERT_NEAR(eigen(i), s, 1e-13 * block.row(i).cwiseAbs().dot(x.cwiseAbs()));
      }
    }
  }
}

TEST(ColumnProduct, ColumnDotsSumInTheirStatedOrder) {
  // column_dots: four partial sums of fused multiply-adds over the rows i mod 4, (s0 + s1) +
  // (s2 + s3), then the last rows % 4 in order (the same bits on the AVX2 and the portable
  // path), alpha times it added.
  std::mt19937 rng(212121);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int rows : {1, 3, 4, 5, 13, 64, 67, 210, 253, 729}) {
    for (int cols : {1, 2, 3, 4, 5, 13, 14, 44}) {
      Eigen::MatrixXd A(rows + 5, cols);
      for (Eigen::Index k = 0; k < A.size(); ++k) A.data()[k] = u(rng) * std::exp(8 * u(rng));
      Eigen::VectorXd v(rows), base(cols);
      for (int i = 0; i < rows; ++i) v(i) = u(rng);
      for (int k = 0; k < cols; ++k) base(k) = u(rng);
      const auto block = A.middleRows(1, rows);
      Eigen::VectorXd got = base;
      column_dots(block, v, got, -0.5, /*accumulate=*/true);
      Eigen::VectorXd assigned(cols);
      column_dots(block, v, assigned);
      for (int k = 0; k < cols; ++k) {
        double s[4] = {0, 0, 0, 0};
        const int r4 = rows / 4 * 4;
        for (int i = 0; i < r4; ++i) s[i % 4] = std::fma(block(i, k), v(i), s[i % 4]);
        double sum = (s[0] + s[1]) + (s[2] + s[3]);
        for (int i = r4; i < rows; ++i) sum = std::fma(block(i, k), v(i), sum);
        ASSERT_EQ(base(k) + -0.5 * sum, got(k)) << rows << " x " << cols << " " << k;
        ASSERT_EQ(0.0 + sum, assigned(k)) << rows << " x " << cols << " " << k;
        // And the product itself to rounding.
        const double exact = block.col(k).dot(v);
        ASSERT_NEAR(exact, sum, 1e-13 * block.col(k).cwiseAbs().dot(v.cwiseAbs()));
      }
    }
  }
}

}  // namespace
}  // namespace modaltyre::transient
