// The share of a candidate's evidence the model's uncertain inputs could produce
// (discover/model_uncertainty.h), against its closed form for one input: D = s^2 I,
// C = j j^T, g = a j: g^T (D + C)^-1 g = a^2 |j|^2 / (s^2 + |j|^2), so f = |j|^2 / (s^2 + |j|^2);
// and 0 for a change the input cannot make (g orthogonal to j).
#include "modaltyre/discover/model_uncertainty.h"

#include <gtest/gtest.h>

namespace modaltyre::discover {
namespace {

constexpr double kRound = 1e-12;

TEST(ModelUncertainty, ShareOfOneInputMatchesItsClosedForm) {
  ModelUncertainty mu;
  mu.names = {"mode 4 amplitude"};
  const double s2 = 4e-4;  // 2 % noise
  mu.noise_var = Eigen::VectorXd::Constant(4, s2);
  Eigen::VectorXd j(4);
  j << 0.01, -0.02, 0.005, 0.03;
  mu.cov = j * j.transpose();
  const double jj = j.squaredNorm();
  EXPECT_NEAR(uncertain_share(mu, 3.0 * j), jj / (s2 + jj), kRound);
  Eigen::VectorXd g(4);
  g << 0.02, 0.01, 0.0, 0.0;  // j . g = 0
  EXPECT_NEAR(uncertain_share(mu, g), 0.0, kRound);
  // No uncertain input: no share, whatever the change.
  mu.names.clear();
  EXPECT_EQ(uncertain_share(mu, j), 0.0);
}

}  // namespace
}  // namespace modaltyre::discover
