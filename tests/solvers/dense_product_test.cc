// DenseCompliance::apply(): every right-hand side's product equals Eigen's matrix-vector product
// to the bit on each kernel path (solvers/dense_product.h; run again with
// MODALTYRE_ISA=portable, tests/CMakeLists.txt), over the sizes around its blocks of 8 and 4 rows,
// two right-hand sides and Eigen's column blocks (16 columns from 128 on; 4 when the leading
// dimension reaches 4000 doubles).
#include "modaltyre/solvers/dense_product.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "modaltyre/solvers/compliance_operator.h"

namespace {

using modaltyre::solvers::DenseCompliance;

Eigen::MatrixXd dense_product_random(std::mt19937& rng, int rows, int cols) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd m(rows, cols);
  for (int j = 0; j < cols; ++j)
    for (int i = 0; i < rows; ++i) m(i, j) = u(rng) * (1 + 1e3 * (i % 7 == 0));
  return m;
}

// The same bits: every entry's sum in Eigen's order, not only close.
void expect_eigens_bits(const Eigen::MatrixXd& C, int r0, int nr, int c0, int nc, int nrhs,
                        std::mt19937& rng) {
  const Eigen::MatrixXd X = dense_product_random(rng, nc, nrhs);
  Eigen::MatrixXd Y = Eigen::MatrixXd::Constant(nr, nrhs, 7.0);  // overwritten, not added to
  DenseCompliance(C).apply(r0, nr, c0, nc, X, Y);
  for (int c = 0; c < nrhs; ++c) {
    Eigen::VectorXd want(nr);
    want.noalias() = C.block(r0, c0, nr, nc) * X.col(c);
    for (int i = 0; i < nr; ++i)
      ASSERT_EQ(std::memcmp(&Y(i, c), &want(i), sizeof(double)), 0)
          << "row " << i << " of " << nr << ", column " << c << " of " << nrhs << ", nc " << nc
          << ", leading dimension " << C.rows() << ": " << Y(i, c) << " vs " << want(i);
  }
}

TEST(DenseProduct, EqualsEigensMatrixVectorProductToTheBit) {
  std::mt19937 rng(47);
  const Eigen::MatrixXd C = dense_product_random(rng, 300, 300);
  for (int nr : {1, 2, 4, 5, 7, 8, 9, 12, 13, 17, 37, 100, 290})
    for (int nc : {1, 3, 16, 127, 128, 145, 290})
      for (int nrhs : {1, 2, 3}) expect_eigens_bits(C, 5, nr, 7, nc, nrhs, rng);
  // Leading dimension >= 4000 doubles: Eigen's blocks of 4 columns.
  const Eigen::MatrixXd tall = dense_product_random(rng, 4003, 150);
  for (int nr : {9, 4003})
    for (int nrhs : {1, 2}) expect_eigens_bits(tall, 0, nr, 3, 140, nrhs, rng);
}

// CellNewton::solve() adds the products as Eigen's `r += A x` and `r += g (A x)` do (each row's
// sum c, then r + c and r + g c): the same bits from dense_product() and one addition, on the
// capacitance's sizes (rank + 1 ~ 10-40) and a few more.
TEST(DenseProduct, AddedProductsEqualEigensCompoundAssignmentsToTheBit) {
  std::mt19937 rng(4747);
  for (int n : {2, 9, 13, 37, 41}) {
    const Eigen::MatrixXd A = dense_product_random(rng, n, n);
    const Eigen::VectorXd x = dense_product_random(rng, n, 1).col(0);
    const Eigen::VectorXd r0 = dense_product_random(rng, n, 1).col(0);
    const double g = 3.7e-5;
    Eigen::VectorXd want_sum = r0, want_scaled = r0, prod(n);
    want_sum.noalias() += A * x;
    want_scaled.noalias() += g * (A * x);
    modaltyre::solvers::detail::dense_product(n, n, A.data(), n, x, prod);
    const Eigen::VectorXd sum = r0 + prod;
    Eigen::VectorXd scaled = r0;
    scaled += g * prod;
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(std::memcmp(&sum(i), &want_sum(i), sizeof(double)), 0) << n << " row " << i;
      ASSERT_EQ(std::memcmp(&scaled(i), &want_scaled(i), sizeof(double)), 0) << n << " row " << i;
    }
  }
}

}  // namespace
