// The transient model's contact basis ([psi V] = T [Cq Cr]) and the Newton solver built on its
// low rank (contact_newton.h): exact reformulations, so they are checked against the plain
// shapes and against a dense LU of Newton's matrix assembled from the sparse Jacobian.
#include "modaltyre/transient/contact_newton.h"

#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/transient/transient.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
// Both are exact up to rounding: the basis drops singular values below 1e-13 of the largest,
// the solver's Woodbury capacitance matrix is of order one.
constexpr double kBasisTol = 1e-12;
constexpr double kSolveTol = 1e-9;

TransientModel model_with(const std::vector<std::string>& extra) {
  std::vector<std::string> o = {"contact.unit_length_mm=5", "contact.window_mm=220",
                                "transient.dynamic_max_order=16"};
  o.insert(o.end(), extra.begin(), extra.end());
  return build_transient_model(build_tyre_model(load_tyre_config(kConfig, o)));
}

/// I - gamma J at (t, y), dense, from the sparse Jacobian.
Eigen::MatrixXd dense_newton_matrix(const TransientSystem& sys, double t,
                                    const std::vector<double>& y, double gamma) {
  solvers::CscMatrix J;
  sys.jacobian(t, y.data(), J);
  const int n = sys.size();
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n);
  for (int c = 0; c < n; ++c)
    for (int64_t p = J.col_ptr[c]; p < J.col_ptr[c + 1]; ++p) A(J.row[p], c) -= gamma * J.value[p];
  return A;
}

/// newton.solve() of A x = b against A's dense LU (b a fixed smooth vector).
void expect_solve_equals_dense_lu(ContactNewton& newton, const Eigen::MatrixXd& A) {
  const Eigen::Index n = A.rows();
  Eigen::VectorXd b(n);
  for (int k = 0; k < n; ++k) b(k) = std::cos(0.7 * k) * (1.0 + k % 5);
  Eigen::VectorXd x = b;
  newton.solve(x.data());
  const Eigen::VectorXd want = A.partialPivLu().solve(b);
  EXPECT_LT((x - want).cwiseAbs().maxCoeff(), kSolveTol * want.cwiseAbs().maxCoeff());
  EXPECT_LT((A * x - b).cwiseAbs().maxCoeff(), kSolveTol * b.cwiseAbs().maxCoeff());
}

/// ContactNewton's solve of (I - gamma J) x = b at (t, y) against a dense LU of the matrix
/// assembled from the sparse Jacobian, for each gamma.
void expect_solves_like_dense_lu(const TransientModel& M, const TransientSystem& sys, double t,
                                 const std::vector<double>& y, const std::vector<double>& gammas) {
  for (const double gamma : gammas) {
    SCOPED_TRACE(gamma);
    ContactNewton newton(M, sys);
    ASSERT_TRUE(newton.setup(t, y.data(), gamma, false));
    expect_solve_equals_dense_lu(newton, dense_newton_matrix(sys, t, y, gamma));
  }
}

struct Carcass {
  const char* name;
  std::vector<std::string> overrides;
};
const Carcass kCarcasses[] = {{"measured_orders", {}},
                              {"extended_with_residual", {"modal.extend_orders=true"}}};
void PrintTo(const Carcass& c, std::ostream* os) { *os << c.name; }

class ContactNewtonTest : public ::testing::TestWithParam<Carcass> {};

TEST_P(ContactNewtonTest, ContactBasisReproducesTheShapes) {
  const TransientModel M = model_with(GetParam().overrides);
  ASSERT_GT(M.rank, 0);
  ASSERT_LE(M.rank, M.nq + M.nr);
  const double scale = std::max(M.psi.cwiseAbs().maxCoeff(), 1e-300);
  EXPECT_LT((M.T * M.Cq - M.psi).cwiseAbs().maxCoeff(), kBasisTol * scale);
  if (M.nr > 0) {
    EXPECT_LT((M.T * M.Cr - M.V).cwiseAbs().maxCoeff(), kBasisTol * M.V.cwiseAbs().maxCoeff());
  }
}

TEST_P(ContactNewtonTest, SolvesNewtonsSystemLikeADenseLu) {
  // Rolling during the speed ramp (advection, rolling pair terms, Omega' != 0), relaxation on,
  // a perturbed static state: every block of Newton's matrix is non-trivial.
  std::vector<std::string> o = GetParam().overrides;
  o.push_back("transient.rolling.ramp_s=1");
  const TransientModel M = model_with(o);
  const ScenarioPlan plan = plan_scenario(M, Scenario::rolling);
  TransientSystem sys(M, plan);
  std::vector<double> y = sys.static_state(4000);
  for (int k = 0; k < M.z_index(); ++k) y[k] *= 1.0 + 0.05 * std::sin(1.7 * k);
  const double t = 0.5;
  expect_solves_like_dense_lu(M, sys, t, y, {1e-5, 4e-4});
}

TEST_P(ContactNewtonTest, SolvesNewtonsSystemAtRestLikeADenseLu) {
  // At rest (free vibration: no advection band, M_EE diagonal, K = T~^T diag(w) T~ symmetric),
  // relaxation on, a perturbed static state with one unit inside the patch lifted off the road
  // by its tread state (a gap in the span of active units, kd = 0 there).
  const TransientModel M = model_with(GetParam().overrides);
  const ScenarioPlan plan = plan_scenario(M, Scenario::free_vibration);
  TransientSystem sys(M, plan);
  std::vector<double> y = sys.static_state(4000);
  for (int k = 0; k < M.z_index(); ++k) y[k] *= 1.0 + 0.05 * std::sin(1.7 * k);
  const double t = 0.01;
  ASSERT_EQ(sys.spin(t), 0.0);
  const Eigen::VectorXd f0 = sys.forces(t, y.data());
  int first = -1, last = -1;
  for (int i = 0; i < M.m; ++i)
    if (f0(i) > 0) last = i, first = first < 0 ? i : first;
  ASSERT_GT(last - first, 4);
  const int lifted = (first + last) / 2;
  y[M.e_index() + lifted] += 1e-3;  // 1 mm more tread deflection: its tip leaves the road
  const Eigen::VectorXd f = sys.forces(t, y.data());
  ASSERT_EQ(f(lifted), 0.0);
  ASSERT_GT(f(lifted - 1), 0.0);
  ASSERT_GT(f(lifted + 1), 0.0);
  expect_solves_like_dense_lu(M, sys, t, y, {1e-5, 4e-4, 1e-2});
}

TEST_P(ContactNewtonTest, SemismoothUpdateSolvesAtTheIteratesContactSet) {
  // At rest the solver gives the units whose side of the contact's kink changed since the setup
  // the stiffness of the current iterate (the last rhs()) and changes K and the capacitance
  // matrix by their rank-one terms: the solve is then the exact one at the iterate, also after
  // a second update in a row (the hub pushed down 2 mm, then lifted 2 mm from the setup's
  // state: units enter at the patch ends, then leave).
  const TransientModel M = model_with(GetParam().overrides);
  const ScenarioPlan plan = plan_scenario(M, Scenario::free_vibration);
  TransientSystem sys(M, plan);
  const std::vector<double> y0 = sys.static_state(4000);
  const double t = 0.01, gamma = 4e-4;
  ASSERT_EQ(sys.spin(t), 0.0);
  ContactNewton newton(M, sys);
  ASSERT_TRUE(newton.setup(t, y0.data(), gamma, false));
  const Eigen::VectorXd f0 = sys.forces(t, y0.data());
  const int n = sys.size(), Z = M.z_index();
  std::vector<double> ydot(n);
  for (const double dz_m : {2e-3, -2e-3}) {
    SCOPED_TRACE(dz_m);
    std::vector<double> y = y0;
    y[Z] += dz_m;
    const Eigen::VectorXd f = sys.forces(t, y.data());
    int switched = 0;
    for (int i = 0; i < M.m; ++i) switched += (f(i) > 0) != (f0(i) > 0);
    EXPECT_GE(switched, 2);
    const Eigen::MatrixXd A = dense_newton_matrix(sys, t, y, gamma);
    sys.rhs(t, y.data(), ydot.data());  // the iterate whose contact set the update takes
    expect_solve_equals_dense_lu(newton, A);
  }
}

INSTANTIATE_TEST_SUITE_P(Carcasses, ContactNewtonTest, ::testing::ValuesIn(kCarcasses),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace modaltyre::transient
