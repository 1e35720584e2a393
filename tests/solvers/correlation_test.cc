// Pearson correlation: its defining limits and invariances.
#include "modaltyre/solvers/correlation.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using modaltyre::solvers::pearson_correlation;

TEST(PearsonCorrelation, IsPlusOrMinusOneOnALineAndZeroWithoutSpread) {
  EXPECT_NEAR(pearson_correlation(std::vector<double>{1, 2, 3, 4}, std::vector<double>{2, 4, 6, 8}),
              1.0, 1e-15);
  EXPECT_NEAR(pearson_correlation(std::vector<double>{1, 2, 3, 4}, std::vector<double>{8, 6, 4, 2}),
              -1.0, 1e-15);
  EXPECT_EQ(pearson_correlation(std::vector<double>{1, 1, 1}, std::vector<double>{1, 2, 3}), 0.0);
  EXPECT_EQ(pearson_correlation(std::vector<double>{1}, std::vector<double>{2}), 0.0);
  EXPECT_EQ(pearson_correlation(std::vector<double>{}, std::vector<double>{}), 0.0);
}

TEST(PearsonCorrelation, IsSymmetricAndInvariantUnderPositiveAffineMaps) {
  const std::vector<double> x{0.3, 1.7, 2.2, 4.1, 4.9, 6.4};
  const std::vector<double> y{1.0, 0.4, 2.5, 2.2, 3.9, 3.1};
  const double r = pearson_correlation(x, y);
  EXPECT_GT(r, 0.5);
  EXPECT_LT(r, 1.0);
  EXPECT_NEAR(pearson_correlation(y, x), r, 1e-15);
  std::vector<double> y2, yneg;
  for (double v : y) y2.push_back(250.0 * v - 40.0), yneg.push_back(-3.0 * v);
  EXPECT_NEAR(pearson_correlation(x, y2), r, 1e-14);
  EXPECT_NEAR(pearson_correlation(x, yneg), -r, 1e-14);
}

TEST(PearsonCorrelation, KeepsItsDigitsWithALargeOffset) {
  // Two passes (means first): an offset of 1e9 on spreads of order 1 costs no accuracy that a
  // one-pass sum of squares would lose entirely.
  const std::vector<double> x{1, 2, 3, 4, 5};
  const std::vector<double> y{2, 1, 4, 3, 5};
  std::vector<double> xo;
  for (double v : x) xo.push_back(1e9 + v);
  EXPECT_NEAR(pearson_correlation(xo, y), pearson_correlation(x, y), 1e-9);
  EXPECT_NEAR(pearson_correlation(x, y), 0.8, 1e-15);  // s_xy = 8, s_xx = s_yy = 10
}

TEST(PearsonCorrelation, UsesTheCommonLengthOfUnequalSamples) {
  EXPECT_NEAR(pearson_correlation(std::vector<double>{1, 2, 3, 100}, std::vector<double>{3, 2, 1}),
              -1.0, 1e-15);
}

}  // namespace
