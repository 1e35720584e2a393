#include "modaltyre/solvers/unilateral_contact.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "modaltyre/core/errors.h"

namespace modaltyre::solvers {

namespace {

struct RestrictedSolve {
  bool ok = false;
  Eigen::VectorXd f_S;
  double delta = 0;
};

/// Solutions of C_SS a = 1 and C_SS b = s from the previous active set, indexed by point, used
/// as the initial guess of the iterative solver when the set changes by a few points.
struct SolveWorkspace {
  Eigen::VectorXd a, b;
  Eigen::MatrixXd A, P_span, Y_span;
};

// Above this many contact points the symmetric system is solved by conjugate gradients:
// C = tread diagonal + smooth carcass kernel is well conditioned and each iteration is one
// product with C_SS (O(k^2) assembled, O(k log k) for a Toeplitz operator), against O(k^3) for
// a factorisation.
constexpr int kIterativeThreshold = 96;
// CG relative residual: far below what the load multiplier and forces need (1e-9).
constexpr double kCgTolerance = 1e-13;

/// Preconditioned conjugate gradients for several right-hand sides in lockstep (one product A X
/// per iteration serves all columns). `product(P, AP)` sets AP = A P, `precondition(R, Z)` sets
/// Z = M^-1 R. Returns false without convergence; `iterations` counts the products.
template <class Product, class Precondition>
bool lockstep_cg(const Product& product, const Precondition& precondition, const Eigen::MatrixXd& B,
                 Eigen::MatrixXd& X, double tol, int max_iterations, int& iterations) {
  Eigen::MatrixXd AP(B.rows(), B.cols());
  product(X, AP);
  Eigen::MatrixXd R = B - AP;
  Eigen::MatrixXd Z(B.rows(), B.cols());
  precondition(R, Z);
  Eigen::MatrixXd P = Z;
  const Eigen::Index nrhs = B.cols();
  Eigen::VectorXd rz(nrhs), bnorm(nrhs);
  for (Eigen::Index c = 0; c < nrhs; ++c) {
    rz(c) = R.col(c).dot(Z.col(c));
    bnorm(c) = std::max(B.col(c).norm(), 1e-300);
  }
  std::vector<char> moved(nrhs);
  for (int it = 0; it < max_iterations; ++it) {
    bool done = true;
    for (Eigen::Index c = 0; c < nrhs; ++c) done = done && R.col(c).norm() <= tol * bnorm(c);
    if (done) return true;
    product(P, AP);
    ++iterations;
    for (Eigen::Index c = 0; c < nrhs; ++c) {
      const double pAp = P.col(c).dot(AP.col(c));
      moved[c] = pAp > 0;
      if (!moved[c]) continue;  // this column has converged exactly (or A is not SPD)
      const double alpha = rz(c) / pAp;
      X.col(c) += alpha * P.col(c);
      R.col(c) -= alpha * AP.col(c);
    }
    precondition(R, Z);
    for (Eigen::Index c = 0; c < nrhs; ++c) {
      if (!moved[c]) continue;
      const double rz_new = R.col(c).dot(Z.col(c));
      P.col(c) = Z.col(c) + (rz_new / rz(c)) * P.col(c);
      rz(c) = rz_new;
    }
  }
  return false;
}

bool contiguous(const std::vector<int>& S) {
  return !S.empty() && S.back() - S.front() + 1 == static_cast<int>(S.size());
}

/// Y = C_SS X. A contiguous set (the usual patch) is one block product; a scattered one is
/// spread over the span of its points with zeros elsewhere and gathered back.
void product_on_set(const ComplianceOperator& C, const std::vector<int>& S,
                    const Eigen::MatrixXd& X, Eigen::MatrixXd& Y, SolveWorkspace& ws) {
  const int k = static_cast<int>(S.size());
  if (contiguous(S)) {
    C.apply(S[0], k, S[0], k, X, Y);
    return;
  }
  const int span = S.back() - S.front() + 1;
  ws.P_span.setZero(span, X.cols());
  ws.Y_span.resize(span, X.cols());
  for (int a = 0; a < k; ++a) ws.P_span.row(S[a] - S[0]) = X.row(a);
  C.apply(S[0], span, S[0], span, ws.P_span, ws.Y_span);
  for (int a = 0; a < k; ++a) Y.row(a) = ws.Y_span.row(S[a] - S[0]);
}

RestrictedSolve solve_on_set(const ContactProblem& p, const ComplianceOperator& C,
                             const std::vector<int>& S, SolveWorkspace& ws,
                             bool use_operator_preconditioner, int& cg_iterations) {
  const int k = static_cast<int>(S.size());
  Eigen::MatrixXd rhs(k, 2);
  for (int a = 0; a < k; ++a) {
    rhs(a, 0) = 1.0;
    rhs(a, 1) = p.initial_gap(S[a]);
  }
  RestrictedSolve r;
  Eigen::MatrixXd x(k, 2);
  bool solved = false;
  if (p.symmetric && k > kIterativeThreshold) {
    for (int a = 0; a < k; ++a) x(a, 0) = ws.a(S[a]), x(a, 1) = ws.b(S[a]);
    const auto product = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) {
      product_on_set(C, S, X, Y, ws);
    };
    const std::unique_ptr<SetPreconditioner> M =
        use_operator_preconditioner ? C.preconditioner(S) : nullptr;
    if (M) {
      const auto precondition = [&](const Eigen::MatrixXd& R, Eigen::MatrixXd& Z) {
        M->apply(R, Z);
      };
      solved = lockstep_cg(product, precondition, rhs, x, kCgTolerance, 4 * k, cg_iterations);
    } else {
      Eigen::VectorXd inv_diag(k);
      for (int a = 0; a < k; ++a) inv_diag(a) = 1.0 / C.entry(S[a], S[a]);
      const auto jacobi = [&](const Eigen::MatrixXd& R, Eigen::MatrixXd& Z) {
        Z = inv_diag.asDiagonal() * R;
      };
      solved = lockstep_cg(product, jacobi, rhs, x, kCgTolerance, 4 * k, cg_iterations);
    }
  }
  if (!solved) {
    C.gather(S, ws.A);
    if (p.symmetric) {
      Eigen::LLT<Eigen::MatrixXd> llt(ws.A);
      if (llt.info() != Eigen::Success) return r;
      x = llt.solve(rhs);
    } else {
      Eigen::PartialPivLU<Eigen::MatrixXd> lu(ws.A);
      x = lu.solve(rhs);
    }
  }
  for (int a = 0; a < k; ++a) ws.a(S[a]) = x(a, 0), ws.b(S[a]) = x(a, 1);
  const double one_a = x.col(0).sum();
  if (!(std::abs(one_a) > 0) || !x.allFinite()) return r;
  r.delta = (p.load_N + x.col(1).sum()) / one_a;
  r.f_S = r.delta * x.col(0) - x.col(1);
  r.ok = r.f_S.allFinite() && std::isfinite(r.delta);
  return r;
}

/// g = s + C f - delta over all points; only the columns of the loaded points contribute.
Eigen::VectorXd gaps(const ContactProblem& p, const ComplianceOperator& C,
                     const std::vector<int>& S, const RestrictedSolve& rs) {
  const int m = C.size();
  const int span = S.back() - S.front() + 1;
  Eigen::MatrixXd f_span = Eigen::MatrixXd::Zero(span, 1);
  for (std::size_t a = 0; a < S.size(); ++a) f_span(S[a] - S[0], 0) = rs.f_S(a);
  Eigen::MatrixXd Cf(m, 1);
  C.apply(0, m, S[0], span, f_span, Cf);
  return p.initial_gap.array() - rs.delta + Cf.col(0).array();
}

}  // namespace

ContactSolution solve_unilateral_contact(const ContactProblem& p, const ContactOptions& opt,
                                         std::span<const char> warm_active) {
  const int m = static_cast<int>(p.initial_gap.size());
  const DenseCompliance dense(p.compliance);
  const ComplianceOperator& C = p.compliance_operator
                                    ? *p.compliance_operator
                                    : static_cast<const ComplianceOperator&>(dense);
  MODALTYRE_CHECK(
      m > 0 && C.size() == m &&
          (p.compliance_operator || (p.compliance.rows() == m && p.compliance.cols() == m)),
      "contact problem sizes disagree");
  MODALTYRE_CHECK(p.load_N > 0, "contact load must be positive");
  ContactSolution sol;
  std::vector<char> in(m, 0);
  if (static_cast<int>(warm_active.size()) == m) in.assign(warm_active.begin(), warm_active.end());
  if (std::find(in.begin(), in.end(), 1) == in.end()) {
    // Cold start: the set a Winkler layer with each point's own compliance C_ii would load,
    // f_i = (delta - s_i)_+ / C_ii with sum f = F (a short patch; the iteration grows it).
    std::vector<int> order(m);
    for (int i = 0; i < m; ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return p.initial_gap(a) < p.initial_gap(b); });
    double sum_k = 0, sum_ks = 0;
    for (int n = 0; n < m; ++n) {
      const int i = order[n];
      const double k = 1.0 / C.entry(i, i);
      sum_k += k;
      sum_ks += k * p.initial_gap(i);
      in[i] = 1;
      const double delta = (p.load_N + sum_ks) / sum_k;
      if (n + 1 == m || delta <= p.initial_gap(order[n + 1])) break;
    }
  }
  std::set<std::vector<char>> visited;
  bool single_step = false;
  SolveWorkspace ws;
  ws.a = Eigen::VectorXd::Zero(m);
  ws.b = Eigen::VectorXd::Zero(m);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m);
  for (int it = 1; it <= opt.max_iterations; ++it) {
    sol.iterations = it;
    std::vector<int> S;
    for (int i = 0; i < m; ++i)
      if (in[i]) S.push_back(i);
    const RestrictedSolve rs =
        solve_on_set(p, C, S, ws, opt.operator_preconditioner, sol.cg_iterations);
    if (!rs.ok) {
      sol.status = SolveStatus::singular;
      sol.message = "the compliance restricted to " + std::to_string(S.size()) +
                    " contact points is not positive definite";
      return sol;
    }
    f.setZero();
    for (std::size_t a = 0; a < S.size(); ++a) f(S[a]) = rs.f_S(a);
    Eigen::VectorXd g = gaps(p, C, S, rs);
    const double gtol = opt.gap_tolerance * std::max(std::abs(rs.delta), 1e-12);
    const double ftol = 1e-13 * p.load_N;

    std::vector<char> next = in;
    int worst_drop = -1, worst_add = -1;
    double most_negative_f = 0, most_negative_g = 0;
    for (int i = 0; i < m; ++i) {
      if (in[i] && f(i) < -ftol) {
        next[i] = 0;
        if (f(i) < most_negative_f) most_negative_f = f(i), worst_drop = i;
      } else if (!in[i] && g(i) < -gtol) {
        next[i] = 1;
        if (g(i) < most_negative_g) most_negative_g = g(i), worst_add = i;
      }
    }
    if (next == in) {
      sol.status = SolveStatus::converged;
      sol.force = f.cwiseMax(0.0);
      sol.gap = g;
      for (int i = 0; i < m; ++i)
        if (in[i]) sol.gap(i) = std::max(sol.gap(i), 0.0);
      sol.approach_m = rs.delta;
      sol.active = in;
      sol.equilibrium_residual = std::abs(sol.force.sum() - p.load_N) / p.load_N;
      double comp = 0, pen = 0;
      for (int i = 0; i < m; ++i) {
        comp = std::max(comp, std::abs(f(i) * g(i)));
        pen = std::max(pen, -g(i));
      }
      sol.complementarity_residual = comp / (p.load_N * std::max(std::abs(rs.delta), 1e-12));
      sol.max_penetration_m = std::max(pen, 0.0);
      sol.max_tension_N = std::max(-f.minCoeff(), 0.0);
      sol.message = "converged in " + std::to_string(it) + " active-set iterations";
      return sol;
    }
    if (!single_step && !visited.insert(in).second) single_step = true;
    if (single_step) {
      // One change at a time: drop the worst tension first, else add the worst penetration.
      next = in;
      if (worst_drop >= 0) {
        next[worst_drop] = 0;
      } else if (worst_add >= 0) {
        next[worst_add] = 1;
      }
    }
    if (std::find(next.begin(), next.end(), 1) == next.end()) {
      Eigen::Index imin = 0;
      g.minCoeff(&imin);
      next[imin] = 1;
    }
    in = std::move(next);
  }
  sol.status = SolveStatus::max_iterations;
  sol.force = f;
  sol.message = "active set did not settle in " + std::to_string(opt.max_iterations) +
                " iterations";
  return sol;
}

}  // namespace modaltyre::solvers
