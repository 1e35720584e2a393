#pragma once
// The tyre's contact points on a deformable ground in series with the tyre (docs/soil.md
// section 4): unknown vertical forces f_i >= 0 on the candidate points and the approach delta,
//   g_i = s_i + (C f)_i + Z_i(f_i / A_i) - delta >= 0,   f_i g_i = 0,   sum f = F,
// C the tyre's compliance (carcass and tread), s_i the gap at zero load (sag, road height,
// offsets), A_i the point's road area and Z_i the ground's sinkage under the pressure
// f_i / A_i for the point's memory z_max,i (ground/pressure_sinkage.h; Z_i(0) = the rut).
// Z_i is continuous and non-decreasing, so this is the KKT system of the convex problem
//   min 1/2 f^T C f + s^T f + sum_i A_i W_i(f_i / A_i),  f >= 0, sum f = F,
// W_i the soil's work (int Z dp). Solved by sequential linearisation: Z_i replaced by its tangent
// at the current pressure (a diagonal compliance and a gap offset), the linear contact problem
// solved by the active-set solver (solvers/unilateral_contact.h), and a backtracking line search
// on the convex objective; converged when the linear problem's solution is its own
// linearisation point (then the KKT system above holds).
#include <span>
#include <string>
#include <vector>

#include "modaltyre/contact/soil_rate_term.h"
#include "modaltyre/core/solve_status.h"
#include "modaltyre/ground/pressure_sinkage.h"
#include "modaltyre/solvers/compliance_operator.h"
#include "modaltyre/solvers/unilateral_contact.h"

namespace modaltyre::contact {

struct GroundContactProblem {
  const solvers::ComplianceOperator* compliance = nullptr;  ///< C, symmetric positive definite
  Eigen::VectorXd initial_gap;                              ///< s [m]
  double load_N = 0;
  const ground::PressureSinkage* law = nullptr;  ///< null: a rigid ground (one linear solve)
  std::vector<double> area_m2;                   ///< A_i > 0
  std::vector<double> z_max_m;                   ///< memory per point (empty: virgin)
  /// The Kelvin-Voigt soil's rate term in steady rolling: Z_i = w z_a + (1 - w) Z_el
  /// (soil_rate_term.h); off: the law itself.
  SoilRate rate;
  /// A point's own law in place of `law` (empty, or null at a point: `law`), e.g. Wong and
  /// Reece's rear region on the rolling tyre (contact/src/wong_reece_flexible.h).
  std::vector<const ground::PressureSinkage*> unit_law;
  /// Forces to linearise the soil at first (e.g. a neighbouring solution, scaled to the load);
  /// empty: the soil's tangent at zero pressure.
  Eigen::VectorXd initial_force;
};

struct GroundContactOptions {
  solvers::ContactOptions contact;
  int max_iterations = 100;  ///< linearisation steps
  /// Converged when max |df| <= tolerance F: far below what any output resolves; the units at
  /// the patch edges (pressures near 0, where the tangent is a poor model) settle linearly.
  double force_tolerance = 1e-7;
  /// Or converged when the soil's linearisation errs by at most this share of the approach at
  /// the linear solution on every point in contact (then that solution solves the nonlinear
  /// problem to this gap): where the tyre is far stiffer than the soil the forces are
  /// ill-determined while the gaps are not.
  double gap_tolerance = 1e-7;
};

struct GroundContactSolution {
  SolveStatus status = SolveStatus::failed;
  std::string message;
  Eigen::VectorXd force;                ///< f [N]
  Eigen::VectorXd soil_sinkage;         ///< Z_i(f_i / A_i) [m] (the rut where f_i = 0)
  Eigen::VectorXd gap;                  ///< g [m]
  std::vector<double> soil_compliance;  ///< dZ/df at the solution (the last linearisation) [m/N]
  double approach_m = 0;
  int iterations = 0, contact_iterations = 0;
  std::vector<char> active;
  double equilibrium_residual = 0;      ///< |sum f - F| / F
  double complementarity_residual = 0;  ///< max |f g| / (F max(|delta|, 1e-12))
  bool ok() const { return modaltyre::ok(status); }
};

GroundContactSolution solve_ground_contact(const GroundContactProblem& problem,
                                           const GroundContactOptions& options = {},
                                           std::span<const char> warm_active = {});

}  // namespace modaltyre::contact
