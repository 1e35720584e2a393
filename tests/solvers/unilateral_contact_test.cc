// Load-controlled unilateral contact: analytic limits of the generic solver.
#include "modaltyre/solvers/unilateral_contact.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

using modaltyre::solvers::ContactProblem;
using modaltyre::solvers::solve_unilateral_contact;

// Direct solves of a well-conditioned system: rounding only.
constexpr double kRoundoff = 1e-10;

/// Rigid ring on a Winkler layer: f_i = k (delta - s_i)_+ and sum f = F, solved exactly by
/// scanning the sorted gaps (independent of the active-set solver).
double winkler_delta(const std::vector<double>& s, double k, double F) {
  std::vector<double> sorted = s;
  std::sort(sorted.begin(), sorted.end());
  double sum = 0;
  for (std::size_t n = 1; n <= sorted.size(); ++n) {
    sum += sorted[n - 1];
    const double delta = (F / k + sum) / n;
    if (n == sorted.size() || delta <= sorted[n]) return delta;
  }
  return NAN;
}

ContactProblem ring_on_winkler(int m, double R, double ds, double k, double F) {
  ContactProblem p;
  p.compliance = Eigen::MatrixXd::Identity(m, m) / k;
  p.initial_gap.resize(m);
  for (int i = 0; i < m; ++i) {
    const double x = (i - m / 2) * ds;
    p.initial_gap(i) = R - std::sqrt(R * R - x * x);
  }
  p.load_N = F;
  return p;
}

TEST(UnilateralContact, RigidRingOnWinklerMatchesClosedForm) {
  const double R = 0.3, ds = 0.5e-3, k = 2e4, F = 3000;
  const auto p = ring_on_winkler(601, R, ds, k, F);
  const auto sol = solve_unilateral_contact(p);
  ASSERT_TRUE(sol.ok()) << sol.message;
  const std::vector<double> s(p.initial_gap.data(), p.initial_gap.data() + p.initial_gap.size());
  const double delta = winkler_delta(s, k, F);
  EXPECT_NEAR(sol.approach_m, delta, kRoundoff * delta);
  for (int i = 0; i < p.initial_gap.size(); ++i) {
    EXPECT_NEAR(sol.force(i), std::max(k * (delta - s[i]), 0.0), kRoundoff * F) << i;
  }
  // Contact half-length is the geometric chord of the approach: x = sqrt(2 R delta) to first
  // order, so the number of loaded units is 2 sqrt(2 R delta) / ds to within one unit each side.
  const long loaded = std::count(sol.active.begin(), sol.active.end(), 1);
  EXPECT_NEAR(loaded * ds, 2 * std::sqrt(2 * R * delta - delta * delta), 2 * ds);
}

/// A smooth, positive definite, long-range compliance (exponential kernel) plus a local part:
/// the Winkler cold start is not exact for it, so the active set has to move.
ContactProblem ring_on_dense_foundation(int m, double F) {
  const double ds = 1e-3, R = 0.3;
  auto p = ring_on_winkler(m, R, ds, 5e4, F);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) p.compliance(i, j) += 2e-6 * std::exp(-std::abs(i - j) * ds / 0.05);
  return p;
}

TEST(UnilateralContact, EquilibriumAndComplementarityOnDenseCompliance) {
  const int m = 301;
  const auto p = ring_on_dense_foundation(m, 4000);
  const auto sol = solve_unilateral_contact(p);
  ASSERT_TRUE(sol.ok()) << sol.message;
  EXPECT_LT(sol.equilibrium_residual, 1e-12);
  EXPECT_LT(sol.complementarity_residual, 1e-9);
  EXPECT_EQ(sol.max_tension_N, 0.0);
  EXPECT_LE(sol.max_penetration_m, 1e-10 * sol.approach_m);
  // Symmetric problem, symmetric answer.
  for (int i = 0; i < m; ++i) EXPECT_NEAR(sol.force(i), sol.force(m - 1 - i), 1e-9 * 4000);
}

TEST(UnilateralContact, WarmStartGivesSameAnswerInFewerIterations) {
  auto p = ring_on_dense_foundation(401, 2000);
  const auto cold = solve_unilateral_contact(p);
  ASSERT_TRUE(cold.ok());
  p.load_N = 2100;
  const auto cold2 = solve_unilateral_contact(p);
  const auto warm2 = solve_unilateral_contact(p, {}, cold.active);
  ASSERT_TRUE(warm2.ok());
  EXPECT_NEAR(warm2.approach_m, cold2.approach_m, kRoundoff * cold2.approach_m);
  EXPECT_LE(warm2.iterations, cold2.iterations);
}

TEST(UnilateralContact, IterationLimitIsReportedNotHidden) {
  auto p = ring_on_dense_foundation(401, 2000);
  modaltyre::solvers::ContactOptions opt;
  opt.max_iterations = 1;
  const auto sol = solve_unilateral_contact(p, opt);
  EXPECT_FALSE(sol.ok());
  EXPECT_NE(sol.message.find("did not settle"), std::string::npos);
}

}  // namespace
