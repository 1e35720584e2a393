// The 3D patch's Newton solver (cell_newton.h) against a dense LU of Newton's matrix I - gamma J,
// J by central differences of the cells' right-hand side. At rest the solver is an exact
// reformulation once its semismooth update has given every cell the contact stiffness of the
// current iterate (docs/transient.md section 7), also after several updates in a row: each
// changes the capacitance matrix by low-rank products (cell_newton_update.cc), which must keep
// it equal to I - gamma H K of the current contact set.
#include "modaltyre/transient/cell_newton.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/data_paths.h"
#include "dense_lu_check.h"
#include "modaltyre/transient/cell_model.h"
#include "modaltyre/transient/cell_system.h"
#include "modaltyre/transient/transient.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig3d;
// The right-hand side is piecewise linear in the state (the contact's kink only), so central
// differences away from a kink are exact but for rounding: ~1e-8 of the matrix's entries at
// these steps, and the solve is compared to 1e-6 of the solution.
constexpr double kCellSolveTol = 1e-6;

struct Fixture {
  TyreModel tyre;
  TransientModel model;
  CellModel cells;
};

/// A coarse crowned 3D patch (4 mm sections, 15 mm columns: 10 columns in 5 mirror classes).
Fixture& fixture() {
  static Fixture* f = [] {
    auto* x = new Fixture{build_tyre_model(load_tyre_config(
                              kConfig3d, {"contact.unit_length_mm=4", "contact.window_mm=240",
                                          "footprint_3d.lateral_cell_mm=15"})),
                          {},
                          {}};
    x->model = build_transient_model(x->tyre);
    x->cells = build_cell_model(x->model);
    return x;
  }();
  return *f;
}

/// I - gamma J at (t, y), J column by column from central differences of rhs().
Eigen::MatrixXd newton_matrix(const CellSystem& sys, double t, const std::vector<double>& y,
                              double gamma) {
  const int n = sys.size();
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n);
  std::vector<double> yp = y, ym = y, fp(n), fm(n);
  for (int k = 0; k < n; ++k) {
    const double h = 1e-9 * std::max(1.0, std::abs(y[k]) * 1e3);
    yp[k] = y[k] + h;
    ym[k] = y[k] - h;
    sys.rhs(t, yp.data(), fp.data());
    sys.rhs(t, ym.data(), fm.data());
    for (int r = 0; r < n; ++r) A(r, k) -= gamma * (fp[r] - fm[r]) / (2 * h);
    yp[k] = ym[k] = y[k];
  }
  return A;
}

/// Number of cells whose contact differs between the forces of two states.
int switched_cells(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  int n = 0;
  for (int k = 0; k < a.size(); ++k) n += (a(k) > 0) != (b(k) > 0);
  return n;
}

TEST(CellNewton, SolvesNewtonsSystemAtRestLikeADenseLuAfterSemismoothUpdates) {
  const Fixture& F = fixture();
  ASSERT_GT(F.cells.classes.size(), 1);  // the semismooth solver (a flat crown is one class)
  const ScenarioPlan plan = plan_scenario(F.model, Scenario::free_vibration);
  const CellSystem sys(F.cells, plan);
  ASSERT_GT(sys.tread_states(), 0);
  const double t = 0.01;
  ASSERT_EQ(sys.spin(t), 0.0);
  const std::vector<double> y0 = sys.state_from(static_cells(F.cells, 4000));
  const int Z = F.model.z_index(), n = sys.size();
  // The matrix is set up at the static state; the iterates then push the hub down by 0.4 mm
  // (cells enter at the patch's ends and sides) and lift it by 0.8 mm (they leave, and more).
  const double gamma = 4e-4;
  CellNewton newton(F.cells, sys);
  ASSERT_TRUE(newton.setup(t, y0.data(), gamma, false));
  EXPECT_TRUE(newton.symmetric_at_rest());  // the capacitance matrix's Cholesky form
  std::vector<double> ydot(n);
  sys.rhs(t, y0.data(), ydot.data());
  const Eigen::VectorXd f0 = sys.last_forces();
  const Eigen::VectorXd b = smooth_rhs(n);
  for (const double dz_m : {4e-4, -4e-4}) {
    SCOPED_TRACE(dz_m);
    std::vector<double> y = y0;
    y[Z] += dz_m;
    const Eigen::MatrixXd A = newton_matrix(sys, t, y, gamma);
    sys.rhs(t, y.data(), ydot.data());  // the iterate whose contact set the update takes
    EXPECT_GT(switched_cells(sys.last_forces(), f0), 4);
    const Eigen::VectorXd x = expect_solve_near_dense_lu(newton, A, kCellSolveTol);
    // Normwise backward error (the tread rows' entries gamma k / c' are large).
    const double scale =
        A.cwiseAbs().rowwise().sum().maxCoeff() * x.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff();
    EXPECT_LT((A * x - b).cwiseAbs().maxCoeff(), kCellSolveTol * scale);
  }
}

TEST(CellNewton, SolvesNewtonsSystemRollingLikeADenseLuAtItsContactSet) {
  // Rolling, M_EE is a band along each class (the tread advected): its back substitution first
  // serves the gather over the contact's sections only, then the tread states' solution whole.
  // Exact at the contact set of the setup (no cell switched: the update is then a no-op).
  const Fixture& F = fixture();
  const ScenarioPlan plan = plan_scenario(F.model, Scenario::rolling);
  const CellSystem sys(F.cells, plan);
  ASSERT_GT(sys.tread_states(), 0);
  const double t = 0.5 * plan.duration_s;
  ASSERT_GT(std::abs(sys.spin(t)), 0.0);
  const std::vector<double> y = sys.state_from(static_cells(F.cells, 4000));
  const int n = sys.size();
  const double gamma = 4e-4;
  CellNewton newton(F.cells, sys);
  ASSERT_TRUE(newton.setup(t, y.data(), gamma, false));
  EXPECT_FALSE(newton.symmetric_at_rest());
  std::vector<double> ydot(n);
  sys.rhs(t, y.data(), ydot.data());
  expect_solve_near_dense_lu(newton, newton_matrix(sys, t, y, gamma), kCellSolveTol);
}

}  // namespace
}  // namespace modaltyre::transient
