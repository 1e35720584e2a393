#pragma once
// Load-controlled unilateral contact of a compliant body against a rigid flat obstacle.
//
// Unknowns: non-negative contact forces f_i on m candidate points and the approach delta (the
// rigid-body motion of the body towards the obstacle, "sinking"). With compliance C (displacement
// of point i away from the obstacle per unit force at j) and initial gaps s_i >= 0 at delta = 0:
//   g = s + C f - delta 1 >= 0,  f >= 0,  f_i g_i = 0,  1^T f = F.
// For symmetric positive definite C this is the KKT system of the convex QP
//   min 1/2 f^T C f + s^T f  s.t. f >= 0, 1^T f = F,
// delta being the multiplier of the load equation. On a trial active set S the equalities give
// f_S = delta a - b with C_SS a = 1, C_SS b = s_S and delta = (F + 1^T b) / 1^T a; the set is
// updated by a primal-dual active-set rule (drop tension, add penetration) with a switch to
// one-at-a-time updates if a set repeats.
//
// C enters only through entries and block products (compliance_operator.h), so a structured
// compliance can be given without assembling it: the gap check is one product of C's columns on
// the contact set, the inner systems are solved by conjugate gradients on C_SS products.
#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "modaltyre/core/solve_status.h"
#include "modaltyre/solvers/compliance_operator.h"

namespace modaltyre::solvers {

struct ContactProblem {
  Eigen::MatrixXd compliance;  ///< C [m/N], m x m (unused when compliance_operator is set)
  /// C given as an operator instead (not owned; must outlive the solve). Takes precedence.
  const ComplianceOperator* compliance_operator = nullptr;
  Eigen::VectorXd initial_gap; ///< s [m], m
  double load_N = 0;           ///< F > 0
  bool symmetric = true;       ///< C symmetric positive definite (Cholesky); else LU
};

struct ContactOptions {
  int max_iterations = 200;
  /// Gap tolerance relative to the approach: a point counts as penetrating below -tol * delta.
  double gap_tolerance = 1e-10;
  /// The conjugate gradients take the operator's own preconditioner where it has one
  /// (ComplianceOperator::preconditioner); false: Jacobi on every operator.
  bool operator_preconditioner = true;
};

struct ContactSolution {
  SolveStatus status = SolveStatus::max_iterations;  ///< or converged, singular
  Eigen::VectorXd force;        ///< f [N]
  Eigen::VectorXd gap;          ///< g [m]
  double approach_m = 0;        ///< delta
  int iterations = 0;
  int cg_iterations = 0;        ///< conjugate-gradient iterations of the inner solves, all sets
  std::vector<char> active;     ///< 1 where the point is in contact
  double equilibrium_residual = 0;     ///< |1^T f - F| / F
  double complementarity_residual = 0; ///< max |f_i g_i| / (F delta)
  double max_penetration_m = 0;        ///< max(-g_i, 0)
  double max_tension_N = 0;            ///< max(-f_i, 0)
  std::string message;
  bool ok() const { return modaltyre::ok(status); }
};

/// Solves the problem; `warm_active` (size m: a previous solution's contact set) is the start
/// set; empty or of another size: a cold start.
ContactSolution solve_unilateral_contact(const ContactProblem& problem,
                                         const ContactOptions& options = {},
                                         std::span<const char> warm_active = {});

}  // namespace modaltyre::solvers
