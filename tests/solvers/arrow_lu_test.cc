// The arrow-structured Newton solver (Schur complement on the dense states) against Eigen's
// dense LU of the same matrix I - gamma J.
#include "modaltyre/solvers/arrow_lu.h"

#include <gtest/gtest.h>

#include <ostream>
#include <random>

namespace modaltyre::solvers {
namespace {

// Rounding of two LU factorisations of a well-conditioned matrix of size ~100.
constexpr double kSolveTol = 1e-11;

/// A random J with the arrow structure: nx dense states, ne band states (upper band of width 2)
/// coupled to the dense ones on [lo, hi] only, with explicit zeros outside that range.
CscMatrix arrow_jacobian(int nx, int ne, int lo, int hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = nx + ne;
  CscMatrix J;
  J.clear(n);
  for (int c = 0; c < n; ++c) {
    J.col_ptr[c] = static_cast<int64_t>(J.row.size());
    auto push = [&](int r, double v) {
      J.row.push_back(r);
      J.value.push_back(v);
    };
    if (c < nx) {
      for (int r = 0; r < nx; ++r) push(r, u(rng));
      for (int e = 0; e < ne; ++e)
        if (e >= lo - 2 && e <= hi + 2) push(nx + e, e >= lo && e <= hi ? u(rng) : 0.0);
    } else {
      const int e = c - nx;
      for (int r = 0; r < nx; ++r)
        if (e >= lo && e <= hi && r % 3 != 0) push(r, u(rng));  // some rows never coupled
      if (e >= 2) push(c - 2, u(rng));
      if (e >= 1) push(c - 1, u(rng));
      push(c, -5.0 + u(rng));  // the tread relaxation: stable diagonal
    }
  }
  J.col_ptr[n] = static_cast<int64_t>(J.row.size());
  return J;
}

Eigen::MatrixXd newton_matrix(const CscMatrix& J, double gamma) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(J.n, J.n);
  for (int64_t c = 0; c < J.n; ++c)
    for (int64_t p = J.col_ptr[c]; p < J.col_ptr[c + 1]; ++p) M(J.row[p], c) -= gamma * J.value[p];
  return M;
}

struct ArrowCase {
  const char* name;
  int nx, ne, lo, hi;
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const ArrowCase& c, std::ostream* os) { *os << c.name; }

class ArrowLuTest : public ::testing::TestWithParam<ArrowCase> {};

TEST_P(ArrowLuTest, SolvesLikeDenseLu) {
  const ArrowCase c = GetParam();
  const CscMatrix J = arrow_jacobian(c.nx, c.ne, c.lo, c.hi, 7);
  const double gamma = 0.05;
  ArrowLu lu;
  ASSERT_TRUE(lu.factor(J, gamma, c.nx));
  const Eigen::MatrixXd M = newton_matrix(J, gamma);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd b(J.n);
  for (int i = 0; i < J.n; ++i) b(i) = u(rng);
  Eigen::VectorXd x = b;
  lu.solve(x.data());
  const Eigen::VectorXd ref = M.partialPivLu().solve(b);
  EXPECT_LT((x - ref).cwiseAbs().maxCoeff(), kSolveTol * ref.cwiseAbs().maxCoeff());
  EXPECT_LT((M * x - b).cwiseAbs().maxCoeff(), kSolveTol * b.cwiseAbs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(Shapes, ArrowLuTest,
                         ::testing::Values(ArrowCase{"CoupledInTheMiddle", 30, 120, 40, 80},
                                           ArrowCase{"CoupledToTheEnds", 12, 60, 0, 59},
                                           ArrowCase{"NoBandStates", 20, 0, 0, -1},
                                           ArrowCase{"Uncoupled", 10, 40, 0, -1}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(ArrowLu, RefusesEntriesOutsideTheStructure) {
  CscMatrix J = arrow_jacobian(5, 20, 5, 10, 3);
  // An entry below the band block's diagonal (row E_13, column E_10): no back substitution.
  const int64_t c = 5 + 10;
  J.row.insert(J.row.begin() + J.col_ptr[c + 1], 5 + 13);
  J.value.insert(J.value.begin() + J.col_ptr[c + 1], 1.0);
  for (int64_t k = c + 1; k <= J.n; ++k) ++J.col_ptr[k];
  ArrowLu lu;
  EXPECT_FALSE(lu.factor(J, 0.1, 5));
}

}  // namespace
}  // namespace modaltyre::solvers
