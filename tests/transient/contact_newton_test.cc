// The transient model's contact basis ([psi V] = T [Cq Cr]) and the Newton solver built on its
// low rank (contact_newton.h): exact reformulations, so they are checked against the plain
// shapes and against a dense LU of Newton's matrix assembled from the sparse Jacobian.
#include "modaltyre/transient/contact_newton.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/data_paths.h"
#include "dense_lu_check.h"
#include "modaltyre/transient/transient.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig2d;
// The basis reproduces the shapes to its cutoff (transient.contact_basis_cutoff of the largest
// singular value, which the Frobenius norm bounds) plus rounding; the solver is exact up to
// rounding, its Woodbury capacitance matrix of order one.
constexpr double kRounding = 1e-12;
constexpr double kSolveTol = 1e-9;

/// `exact_basis`: the contact basis to rounding (cutoff 1e-13), so that the low-rank solver can
/// be compared with the sparse Jacobian of the shapes themselves; the default cutoff moves the
/// forces by ~1e-8 (test ContactBasisCutoffMovesNoForce).
TransientModel newton_model(const std::vector<std::string>& extra, bool exact_basis = true) {
  std::vector<std::string> o = {"contact.unit_length_mm=5", "contact.window_mm=220",
                                "transient.dynamic_max_order=16"};
  o.insert(o.end(), extra.begin(), extra.end());
  TyreConfig cfg = load_tyre_config(kConfig2d, o);
  if (exact_basis) cfg.transient.contact_basis_cutoff = 1e-13;
  return build_transient_model(build_tyre_model(cfg));
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
  const Eigen::VectorXd x = expect_solve_near_dense_lu(newton, A, kSolveTol);
  const Eigen::VectorXd b = smooth_rhs(A.rows());
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
  const TransientModel M = newton_model(GetParam().overrides, /*exact_basis=*/false);
  ASSERT_GT(M.rank, 0);
  ASSERT_LE(M.rank, M.nq + M.nr);
  Eigen::MatrixXd B(M.m, M.nq + M.nr), TC(M.m, M.nq + M.nr);
  B << M.psi, M.V;
  TC << M.T * M.Cq, M.T * M.Cr;
  // To the cutoff of the largest singular value (the first dropped one), which the Frobenius
  // norm bounds, plus rounding.
  const double bound = (M.settings.contact_basis_cutoff + kRounding) * B.norm();
  EXPECT_LT((TC - B).cwiseAbs().maxCoeff(), bound);
}

TEST_P(ContactNewtonTest, ContactBasisCutoffMovesNoForce) {
  // The default cutoff against rounding level (1e-13): fewer basis shapes, the same model. The
  // right-hand side of both at a perturbed static state (the contact forces through u = T xi,
  // the generalised forces through Cq^T T^T f) agree to 1e-7 of its largest entry per block.
  // (Whole runs agree only to their integration error: a rounding-level change moves a coarse
  // free vibration's step sequence, and with it its period by ~3e-4.)
  std::vector<std::string> o = {"contact.unit_length_mm=5", "contact.window_mm=220",
                                "transient.dynamic_max_order=16"};
  o.insert(o.end(), GetParam().overrides.begin(), GetParam().overrides.end());
  TyreConfig cfg = load_tyre_config(kConfig2d, o);
  const TransientModel cut = build_transient_model(build_tyre_model(cfg));
  cfg.transient.contact_basis_cutoff = 1e-13;
  const TransientModel full = build_transient_model(build_tyre_model(cfg));
  ASSERT_LT(cut.rank, full.rank) << "the default cutoff must drop a shape to be a test";
  const ScenarioPlan plan = plan_scenario(full, Scenario::free_vibration);
  const TransientSystem sa(cut, plan), sb(full, plan);
  ASSERT_EQ(sa.size(), sb.size());
  std::vector<double> y = sb.static_state(4000);
  for (int k = 0; k < full.z_index(); ++k) y[k] *= 1.0 + 0.05 * std::sin(1.7 * k);
  std::vector<double> fa(sa.size()), fb(sb.size());
  sa.rhs(0.01, y.data(), fa.data());
  sb.rhs(0.01, y.data(), fb.data());
  const Eigen::Map<const Eigen::VectorXd> a(fa.data(), sa.size()), b(fb.data(), sb.size());
  // Per block (q', v', r', z', w', e'): their scales differ by orders of magnitude.
  const int nq = full.nq, nr = full.nr, Z = full.z_index();
  const std::vector<std::pair<int, int>> blocks = {
      {0, nq}, {nq, nq}, {2 * nq, nr}, {Z, 2}, {full.e_index(), sb.tread_states()}};
  for (const auto& [at, n] : blocks) {
    if (n == 0) continue;
    const double scale = b.segment(at, n).cwiseAbs().maxCoeff();
    EXPECT_LE((a.segment(at, n) - b.segment(at, n)).cwiseAbs().maxCoeff(), 1e-7 * scale)
        << "block at " << at;
  }
}

TEST_P(ContactNewtonTest, SolvesNewtonsSystemLikeADenseLu) {
  // Rolling during the speed ramp (advection, rolling pair terms, Omega' != 0), relaxation on,
  // a perturbed static state: every block of Newton's matrix is non-trivial.
  std::vector<std::string> o = GetParam().overrides;
  o.push_back("transient.rolling.ramp_s=1");
  const TransientModel M = newton_model(o);
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
  const TransientModel M = newton_model(GetParam().overrides);
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
  const TransientModel M = newton_model(GetParam().overrides);
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
