// Leading eigenpairs by tridiagonal inverse iteration against Eigen's full symmetric solver.
#include "modaltyre/solvers/leading_eigenpairs.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

namespace modaltyre::solvers {
namespace {

// Rounding of an O(n^3) factorisation of an n ~ 200 matrix: residuals and orthogonality to
// 1e-12 of |A|, eigenvalues to 1e-12 of the largest.
constexpr double kTol = 1e-12;

Eigen::MatrixXd random_symmetric(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  Eigen::MatrixXd a(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) a(i, j) = g(rng);
  return 0.5 * (a + a.transpose());
}

// Symmetric circulant: every eigenvalue but one (two for even n) is exactly double.
Eigen::MatrixXd circulant(int n) {
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int d = std::min((i - j + n) % n, (j - i + n) % n);
      a(i, j) = 1.0 / (1.0 + d * d);  // decaying kernel, like a compliance lag kernel
    }
  return a;
}

void expect_eigenpairs_of(const Eigen::MatrixXd& a, const EigenPairs& e, double fraction) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> full(a);
  const Eigen::VectorXd& lam = full.eigenvalues();
  const double lmax = lam.cwiseAbs().maxCoeff();
  EXPECT_NEAR(e.largest_abs, lmax, kTol * lmax);
  int count = 0;
  for (int i = 0; i < lam.size(); ++i) count += lam(i) >= fraction * lmax ? 1 : 0;
  ASSERT_EQ(e.values.size(), count);
  ASSERT_EQ(e.vectors.cols(), count);
  for (int k = 0; k < count; ++k) {
    EXPECT_NEAR(e.values(k), lam(lam.size() - 1 - k), kTol * lmax) << k;
    const Eigen::VectorXd r = a * e.vectors.col(k) - e.values(k) * e.vectors.col(k);
    EXPECT_LT(r.norm(), kTol * lmax * 10) << "eigenpair " << k;
  }
  const Eigen::MatrixXd gram = e.vectors.transpose() * e.vectors;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff(), 10 * kTol);
  // The kept subspace is the full solver's (projectors agree when the threshold does not cut
  // through a cluster).
  const Eigen::MatrixXd vf = full.eigenvectors().rightCols(count);
  const Eigen::MatrixXd dp = e.vectors * e.vectors.transpose() - vf * vf.transpose();
  EXPECT_LT(dp.cwiseAbs().maxCoeff(), 1e-9);
}

TEST(LeadingEigenpairs, RandomSymmetricMatchesFullSolver) {
  const Eigen::MatrixXd a = random_symmetric(200, 3);
  expect_eigenpairs_of(a, leading_eigenpairs(a, 0.3), 0.3);
}

TEST(LeadingEigenpairs, ExactlyDoubleEigenvaluesGiveAnOrthonormalBasisOfEachPair) {
  const Eigen::MatrixXd a = circulant(181);
  const EigenPairs e = leading_eigenpairs(a, 0.3);
  ASSERT_GE(e.values.size(), 5);  // the largest alone, then pairs
  EXPECT_NEAR(e.values(1), e.values(2), 1e-12 * e.values(0));
  expect_eigenpairs_of(a, e, 0.3);
}

TEST(LeadingEigenpairs, WholeSpectrumWhenFractionKeepsEverythingPositive) {
  // A positive definite matrix with fraction tiny: every pair, as the full solver gives.
  const Eigen::MatrixXd r = random_symmetric(60, 9);
  const Eigen::MatrixXd a = r * r.transpose() + Eigen::MatrixXd::Identity(60, 60);
  expect_eigenpairs_of(a, leading_eigenpairs(a, 1e-12), 1e-12);
}

}  // namespace
}  // namespace modaltyre::solvers
