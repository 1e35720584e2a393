// The coupled cell solve's preconditioner (contact/src/patch3d_preconditioner.cc): the exact
// inverse of the cell operator on a full rectangle of cells, and on a crowned patch the same
// contact solution as the Jacobi-preconditioned solve in far fewer conjugate-gradient iterations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../../contact/src/patch3d_operators.h"
#include "modaltyre/solvers/unilateral_contact.h"

namespace modaltyre::contact {
namespace {

// A cell grid of the SF-350's size on 2 mm sections and 5 mm columns (tread 150 mm, radius
// 294.8 mm, tread springs of E = 3 MPa over 8 mm), a smooth SPD carcass kernel of its level.
struct Grid {
  static constexpr int S = 90, n = 30;
  static constexpr double ds = 0.002, dy = 0.005, R0 = 0.2948, k = 3e6 * dy * ds / 0.008;
  std::vector<double> theta, cos_theta, t_tangential;
  Eigen::MatrixXd carcass;
  Grid() {
    carcass.resize(S, S);
    for (int i = 0; i < S; ++i) {
      theta.push_back((i - 0.5 * (S - 1)) * ds / R0);
      cos_theta.push_back(std::cos(theta.back()));
      const double s = std::sin(theta.back());
      t_tangential.push_back(s * s * 2 * (1 + 0.5) / k);  // G = E / (2 (1 + nu))
      for (int j = 0; j < S; ++j)
        carcass(i, j) = 2e-6 * std::exp(-std::abs(i - j) * ds / 0.03) + (i == j ? 1e-6 : 0.0);
    }
  }
};

TEST(Patch3dCoupledSolve, ThePreconditionerInvertsTheOperatorOnAFullRectangle) {
  const Grid g;
  const solvers::DenseCompliance carcass(g.carcass);
  for (double l : {0.004, 0.0114, 0.05}) {
    const detail::CoupledTread tread(g.k, l, g.ds, g.dy, Grid::S, Grid::n, g.cos_theta);
    const detail::CellCompliance op(carcass, Grid::n, g.t_tangential, nullptr, &tread);
    std::vector<int> S;
    for (int a = 20 * Grid::n; a < 60 * Grid::n; ++a) S.push_back(a);
    const auto M = op.preconditioner(S);
    ASSERT_TRUE(M);
    const int m = static_cast<int>(S.size());
    Eigen::MatrixXd X = Eigen::MatrixXd::Random(m, 2), CX(m, 2), Z;
    op.apply(S.front(), m, S.front(), m, X, CX);
    M->apply(CX, Z);
    EXPECT_LT((Z - X).norm(), 1e-9 * X.norm()) << l;
  }
}

TEST(Patch3dCoupledSolve, TheCrownedPatchSolvesAsWithJacobiInFewerIterations) {
  const Grid g;
  const solvers::DenseCompliance carcass(g.carcass);
  for (double l : {0.0114, 0.05}) {
    const detail::CoupledTread tread(g.k, l, g.ds, g.dy, Grid::S, Grid::n, g.cos_theta);
    const detail::CellCompliance op(carcass, Grid::n, g.t_tangential, nullptr, &tread);
    solvers::ContactProblem p;
    p.compliance_operator = &op;
    p.load_N = 5000;
    p.initial_gap.resize(Grid::S * Grid::n);
    for (int i = 0; i < Grid::S; ++i) {
      for (int j = 0; j < Grid::n; ++j) {
        const double y = (j + 0.5 - 0.5 * Grid::n) * g.dy;  // a circular crown of 1 m radius
        p.initial_gap(i * Grid::n + j) = g.R0 * (1 - g.cos_theta[i]) + y * y / 2.0;
      }
    }
    solvers::ContactOptions jacobi;
    jacobi.operator_preconditioner = false;
    const solvers::ContactSolution a = solvers::solve_unilateral_contact(p, {});
    const solvers::ContactSolution b = solvers::solve_unilateral_contact(p, jacobi);
    ASSERT_TRUE(a.ok()) << a.message;
    ASSERT_TRUE(b.ok()) << b.message;
    EXPECT_EQ(a.active, b.active) << l;
    EXPECT_NEAR(a.approach_m, b.approach_m, 1e-10 * b.approach_m) << l;
    EXPECT_LT((a.force - b.force).cwiseAbs().maxCoeff(), 1e-9 * p.load_N) << l;
    EXPECT_LT(a.equilibrium_residual, 1e-12) << l;
    EXPECT_EQ(a.iterations, b.iterations) << l;  // the same active sets
    EXPECT_GT(b.cg_iterations, 0) << l;
    EXPECT_LT(3 * a.cg_iterations, b.cg_iterations) << l;
  }
}

}  // namespace
}  // namespace modaltyre::contact
