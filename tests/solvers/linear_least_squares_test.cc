// Linear least squares: planted coefficients, the textbook standard errors of a straight line,
// unknowns of very different units, and the refusals of a design that cannot separate them.
#include "modaltyre/solvers/linear_least_squares.h"

#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/core/errors.h"

namespace {

using modaltyre::ComputationError;
using modaltyre::solvers::solve_linear_least_squares;

TEST(LinearLeastSquares, RecoversPlantedCoefficientsOfAConsistentSystem) {
  Eigen::MatrixXd A(6, 3);
  Eigen::VectorXd b(6);
  for (int i = 0; i < 6; ++i) {
    const double x = 0.5 * i;
    A.row(i) << 1.0, x, x * x;
    b(i) = 2.0 - 3.0 * x + 0.25 * x * x;
  }
  const auto fit = solve_linear_least_squares(A, b);
  EXPECT_NEAR(fit.coef(0), 2.0, 1e-12);
  EXPECT_NEAR(fit.coef(1), -3.0, 1e-12);
  EXPECT_NEAR(fit.coef(2), 0.25, 1e-12);
  EXPECT_LT(fit.residual_rms, 1e-12);
  EXPECT_LT(fit.residuals.cwiseAbs().maxCoeff(), 1e-12);
}

TEST(LinearLeastSquares, StandardErrorsOfALineMatchTheTextbookFormula) {
  // y = a + b x with alternating residuals +-e: s^2 = RSS / (n - 2), se(b) = s / sqrt(Sxx),
  // se(a) = s sqrt(1/n + xbar^2 / Sxx).
  const int n = 8;
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) {
    A.row(i) << 1.0, static_cast<double>(i);
    y(i) = 1.0 + 0.5 * i + (i % 2 == 0 ? 0.1 : -0.1);
  }
  const auto fit = solve_linear_least_squares(A, y);
  const double xbar = 3.5;
  double sxx = 0;
  for (int i = 0; i < n; ++i) sxx += (i - xbar) * (i - xbar);
  const double s = std::sqrt(fit.residuals.squaredNorm() / (n - 2));
  EXPECT_NEAR(fit.std_error(1), s / std::sqrt(sxx), 1e-12);
  EXPECT_NEAR(fit.std_error(0), s * std::sqrt(1.0 / n + xbar * xbar / sxx), 1e-12);
  EXPECT_NEAR(fit.residual_rms, std::sqrt(fit.residuals.squaredNorm() / n), 1e-15);
  // The residual is orthogonal to the design's columns (normal equations).
  EXPECT_LT((A.transpose() * fit.residuals).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(LinearLeastSquares, SeparatesUnknownsOfVeryDifferentUnits) {
  // Columns ~1e7 and ~1e-3 (a modulus in Pa against a length in m): the column scaling keeps
  // the rank decision and the answer independent of the units.
  Eigen::MatrixXd A(5, 2);
  Eigen::VectorXd b(5);
  for (int i = 0; i < 5; ++i) {
    A.row(i) << 1e7 * (1 + i), 1e-3 * (1 + i * i);
    b(i) = A(i, 0) * 2e-7 + A(i, 1) * 3e3;
  }
  const auto fit = solve_linear_least_squares(A, b);
  EXPECT_NEAR(fit.coef(0) / 2e-7, 1.0, 1e-12);
  EXPECT_NEAR(fit.coef(1) / 3e3, 1.0, 1e-12);
  EXPECT_EQ(fit.std_error.size(), 2);
}

TEST(LinearLeastSquares, RefusesAZeroColumnAndDependentColumns) {
  Eigen::MatrixXd A(4, 2);
  A << 1, 0, 2, 0, 3, 0, 4, 0;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(4, 1, 4);
  EXPECT_THROW(solve_linear_least_squares(A, b), ComputationError);
  A.col(1) = 2.0 * A.col(0);
  EXPECT_THROW(solve_linear_least_squares(A, b), ComputationError);
}

}  // namespace
