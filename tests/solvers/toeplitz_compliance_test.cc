// Matrix-free Toeplitz compliance: FFT products against the direct sums and the assembled
// matrix, and the contact solver's answer with the operator against the one with the matrix.
#include "modaltyre/solvers/toeplitz_compliance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "modaltyre/solvers/unilateral_contact.h"

namespace {

using namespace modaltyre::solvers;

// FFT convolution against direct sums: rounding of O(log n) operations on O(1) numbers.
constexpr double kRounding = 1e-13;

/// Smooth kernels with the structure of the carcass ones: K_00, K_11 even, K_01(l) = K_10(-l)
/// odd (reciprocity), decaying over ~20 lags, on `lags` lags.
LagConvolution2x2 carcass_like(int lags) {
  std::array<std::vector<double>, 4> k;
  for (auto& v : k) v.resize(2 * static_cast<std::size_t>(lags) - 1);
  for (int l = 1 - lags; l < lags; ++l) {
    const std::size_t i = static_cast<std::size_t>(l + lags - 1);
    const double e = std::exp(-std::abs(l) / 20.0);
    k[0][i] = 2.0 * e * std::cos(0.1 * l);
    k[1][i] = 0.3 * e * std::sin(0.05 * l);
    k[2][i] = -0.3 * e * std::sin(0.05 * l);
    k[3][i] = 1.0 * e;
  }
  return LagConvolution2x2(std::move(k), lags);
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

TEST(ToeplitzCompliance, FastLengthsAreSmoothMultiplesOfFour) {
  for (int n : {1, 5, 97, 1000, 2917}) {
    const int f = fast_fft_length(n);
    EXPECT_GE(f, n);
    EXPECT_EQ(f % 4, 0);
    int v = f;
    for (int p : {2, 3, 5})
      while (v % p == 0) v /= p;
    EXPECT_EQ(v, 1) << f;
  }
}

TEST(ToeplitzCompliance, FftConvolutionEqualsDirectSumOnEveryKindOfBlock) {
  const int m = 300;
  const LagConvolution2x2 K = carcass_like(m);
  std::vector<double> v0(m), v1(m);
  for (int j = 0; j < m; ++j) v0[j] = std::sin(0.37 * j) + 1, v1[j] = std::cos(0.11 * j);
  // Square diagonal blocks (the CG products), full rows against a column range (the gap check),
  // and off-diagonal blocks on either side.
  struct Block {
    int r0, nr, c0, nc;
  };
  for (const Block b : {Block{0, m, 0, m}, Block{100, 120, 100, 120}, Block{0, m, 120, 60},
                        Block{0, 50, 250, 50}, Block{250, 50, 0, 50}, Block{7, 1, 3, 1}}) {
    std::vector<double> fu0(b.nr), fu1(b.nr), du0(b.nr), du1(b.nr);
    K.apply(b.r0, b.nr, b.c0, b.nc, &v0[b.c0], &v1[b.c0], fu0.data(), fu1.data());
    K.apply_direct(b.r0, b.nr, b.c0, b.nc, &v0[b.c0], &v1[b.c0], du0.data(), du1.data());
    const double scale = std::max(max_abs(du0), max_abs(du1));
    for (int p = 0; p < b.nr; ++p) {
      EXPECT_NEAR(fu0[p], du0[p], kRounding * scale) << b.r0 << " " << b.c0 << " " << p;
      EXPECT_NEAR(fu1[p], du1[p], kRounding * scale) << b.r0 << " " << b.c0 << " " << p;
    }
  }
}

// apply_direct() on either kernel path (MODALTYRE_ISA, run again with =portable:
// tests/CMakeLists.txt) gives the bits of the plain sum over the columns in order, u = u +
// (K_a0(l) v0 + K_a1(l) v1) from u = 0: the AVX2 path's rows of 8 and 4 and its remainder, on
// blocks above, below and across the diagonal.
TEST(ToeplitzCompliance, DirectSumEqualsThePlainColumnSumToTheBit) {
  const int m = 300;
  const LagConvolution2x2 K = carcass_like(m);
  std::vector<double> v0(m), v1(m);
  for (int j = 0; j < m; ++j) v0[j] = std::sin(0.37 * j) + 1e-3 * j, v1[j] = std::cos(0.11 * j);
  struct Block {
    int r0, nr, c0, nc;
  };
  std::vector<Block> blocks;
  for (int nr : {1, 3, 4, 5, 7, 8, 9, 12, 13, 16, 17, 37, 150})
    for (int nc : {1, 2, 9, 40}) {
      blocks.push_back({20, nr, 20, nc});
      blocks.push_back({0, nr, 100, nc});
      blocks.push_back({120, nr, 10, nc});
    }
  blocks.push_back({0, m, 0, m});
  for (const Block b : blocks) {
    std::vector<double> u0(b.nr, 7.0), u1(b.nr, 7.0);  // overwritten, not added to
    K.apply_direct(b.r0, b.nr, b.c0, b.nc, &v0[b.c0], &v1[b.c0], u0.data(), u1.data());
    for (int p = 0; p < b.nr; ++p) {
      double w0 = 0.0, w1 = 0.0;
      for (int q = 0; q < b.nc; ++q) {
        const int l = (b.r0 + p) - (b.c0 + q), j = b.c0 + q;
        w0 += K.kernel(0, 0, l) * v0[j] + K.kernel(0, 1, l) * v1[j];
        w1 += K.kernel(1, 0, l) * v0[j] + K.kernel(1, 1, l) * v1[j];
      }
      ASSERT_EQ(std::memcmp(&u0[p], &w0, sizeof(double)), 0)
          << b.r0 << " " << b.nr << " " << b.c0 << " " << b.nc << " row " << p;
      ASSERT_EQ(std::memcmp(&u1[p], &w1, sizeof(double)), 0)
          << b.r0 << " " << b.nr << " " << b.c0 << " " << b.nc << " row " << p;
    }
  }
}

WeightedToeplitzCompliance ring_operator(int m) {
  std::vector<double> w0(m), w1(m), d(m);
  for (int i = 0; i < m; ++i) {
    const double th = (i - m / 2) * 0.002;
    w0[i] = std::cos(th), w1[i] = std::sin(th), d[i] = 5.0 + std::sin(th) * std::sin(th);
  }
  return WeightedToeplitzCompliance(carcass_like(m), w0, w1, d);
}

TEST(ToeplitzCompliance, BlockProductsEqualTheAssembledMatrix) {
  const int m = 257;
  const auto C = ring_operator(m);
  const Eigen::MatrixXd dense = C.dense();
  EXPECT_EQ(C.entry(10, 200), dense(10, 200));
  Eigen::MatrixXd X(m, 2);
  for (int i = 0; i < m; ++i) X(i, 0) = 1.0, X(i, 1) = std::exp(-0.01 * i);
  struct Block {
    int r0, nr, c0, nc;
  };
  for (const Block b :
       {Block{0, m, 0, m}, Block{60, 140, 60, 140}, Block{0, m, 90, 80}, Block{30, 10, 200, 40}}) {
    Eigen::MatrixXd Y(b.nr, 2);
    C.apply(b.r0, b.nr, b.c0, b.nc, X.middleRows(b.c0, b.nc), Y);
    const Eigen::MatrixXd ref = dense.block(b.r0, b.c0, b.nr, b.nc) * X.middleRows(b.c0, b.nc);
    EXPECT_LE((Y - ref).cwiseAbs().maxCoeff(), kRounding * ref.cwiseAbs().maxCoeff()) << b.r0;
  }
}

TEST(ToeplitzCompliance, ContactSolutionEqualsTheOneWithTheAssembledMatrix) {
  // A rigid ring (sag R(1 - cos)) on this compliance: same unique solution either way.
  const int m = 401;
  const auto C = ring_operator(m);
  ContactProblem dense;
  dense.compliance = C.dense();
  dense.initial_gap.resize(m);
  for (int i = 0; i < m; ++i) dense.initial_gap(i) = 0.3 * (1 - std::cos((i - m / 2) * 0.002));
  dense.load_N = 1e-2;
  ContactProblem free = dense;
  free.compliance.resize(0, 0);
  free.compliance_operator = &C;
  const auto a = solve_unilateral_contact(dense);
  const auto b = solve_unilateral_contact(free);
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_TRUE(b.ok()) << b.message;
  EXPECT_GT(std::count(a.active.begin(), a.active.end(), 1), 96);  // the CG route is exercised
  EXPECT_EQ(a.active, b.active);
  EXPECT_NEAR(b.approach_m, a.approach_m, 1e-12 * a.approach_m);
  for (int i = 0; i < m; ++i) EXPECT_NEAR(b.force(i), a.force(i), 1e-12 * dense.load_N) << i;
  EXPECT_LT(b.equilibrium_residual, 1e-12);
  EXPECT_LE(b.max_penetration_m, 1e-10 * b.approach_m);
}

}  // namespace
