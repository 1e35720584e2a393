// Illinois regula falsi: a known root to the tolerance, never outside the bracket, faster than
// plain regula falsi on a convex function, and its three endings.
#include "modaltyre/solvers/bracketed_root.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "modaltyre/core/errors.h"

namespace {

using namespace modaltyre::solvers;
using modaltyre::SolveStatus;

TEST(IllinoisRoot, FindsSqrtTwoInsideTheBracket) {
  std::vector<double> xs;
  auto f = [&](double x) -> std::optional<double> {
    xs.push_back(x);
    return x * x - 2.0;
  };
  IllinoisOptions o;
  o.tolerance = 1e-12;
  const RootResult r = illinois_root(f, 0.0, -2.0, 2.0, 2.0, o);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.x, std::sqrt(2.0), 1e-12);
  EXPECT_LE(std::abs(r.fx), 1e-12);
  EXPECT_EQ(r.iterations, static_cast<int>(xs.size()));
  for (double x : xs) {
    EXPECT_GT(x, 0.0);
    EXPECT_LT(x, 2.0);
  }
}

TEST(IllinoisRoot, NeedsFewerEvaluationsThanPlainRegulaFalsiOnAConvexFunction) {
  // exp(x) - 10 on [0, 5]: plain regula falsi keeps the right end fixed and converges
  // linearly; the Illinois halving moves it and converges superlinearly.
  auto g = [](double x) { return std::exp(x) - 10.0; };
  IllinoisOptions o;
  o.tolerance = 1e-10;
  const RootResult r =
      illinois_root([&](double x) -> std::optional<double> { return g(x); }, 0, g(0), 5, g(5), o);
  ASSERT_TRUE(r.ok());
  EXPECT_NEAR(r.x, std::log(10.0), 1e-10);
  double a = 0, fa = g(0), b = 5, fb = g(5);
  int plain = 0;
  for (; plain < 1000; ++plain) {
    const double c = (a * fb - b * fa) / (fb - fa);
    const double fc = g(c);
    if (std::abs(fc) <= o.tolerance) break;
    if ((fc > 0) == (fb > 0))
      b = c, fb = fc;
    else
      a = c, fa = fc;
  }
  EXPECT_LT(r.iterations, 20);
  EXPECT_GT(plain, 3 * r.iterations);
}

TEST(IllinoisRoot, StopsWhenTheFunctionGivesUpOrTheIterationsRunOut) {
  int calls = 0;
  auto fails_third = [&](double x) -> std::optional<double> {
    if (++calls == 3) return std::nullopt;
    return x * x * x - 0.5;
  };
  const RootResult aborted = illinois_root(fails_third, 0, -0.5, 1, 0.5);
  EXPECT_EQ(aborted.status, SolveStatus::aborted);
  EXPECT_FALSE(aborted.ok());
  EXPECT_EQ(aborted.iterations, 3);

  IllinoisOptions o;
  o.tolerance = 0;
  o.max_iterations = 2;
  const RootResult out = illinois_root(
      [](double x) -> std::optional<double> { return x * x * x - 0.5; }, 0, -0.5, 1, 0.5, o);
  EXPECT_EQ(out.status, SolveStatus::max_iterations);
  EXPECT_EQ(out.iterations, 2);
  EXPECT_GT(out.x, 0.0);
  EXPECT_LT(out.x, 1.0);
}

TEST(IllinoisRoot, RefusesABracketWithoutASignChange) {
  auto f = [](double x) -> std::optional<double> { return x * x + 1; };
  EXPECT_THROW(illinois_root(f, -1, 2, 1, 2), modaltyre::ComputationError);
  EXPECT_THROW(illinois_root(f, -1, 0, 1, 2), modaltyre::ComputationError);
}

}  // namespace
