#include "modaltyre/contact/ground_contact.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "patch3d_operators.h"

namespace modaltyre::contact {
namespace {

Eigen::VectorXd product(const solvers::ComplianceOperator& C, const Eigen::VectorXd& f) {
  const int m = C.size();
  Eigen::MatrixXd out(m, 1);
  C.apply(0, m, 0, m, f, out);
  return out.col(0);
}

}  // namespace

GroundContactSolution solve_ground_contact(const GroundContactProblem& P,
                                           const GroundContactOptions& o,
                                           std::span<const char> warm) {
  MODALTYRE_CHECK(P.compliance && P.load_N > 0, "incomplete ground contact problem");
  const int m = P.compliance->size();
  MODALTYRE_CHECK(P.initial_gap.size() == m, "gap size");
  const bool soil = P.law != nullptr;
  MODALTYRE_CHECK(!soil || static_cast<int>(P.area_m2.size()) == m, "areas");
  auto zmax = [&](int i) { return P.z_max_m.empty() ? 0.0 : P.z_max_m[i]; };
  auto law = [&](int i) { return P.unit_law.empty() || !P.unit_law[i] ? P.law : P.unit_law[i]; };
  auto Z = [&](int i, double f) {
    return P.rate.sinkage_m(i, law(i)->sinkage_m(std::max(f, 0.0) / P.area_m2[i], zmax(i)));
  };
  GroundContactSolution out;
  std::vector<char> active(warm.begin(), warm.end());
  Eigen::VectorXd f;  // current iterate (empty before the first solve)
  if (soil && P.initial_force.size() == m && P.initial_force.sum() > 0) {
    f = P.initial_force.cwiseMax(0.0);
    f *= P.load_N / f.sum();  // a feasible start: the line search stays in the feasible set
  }
  // A pressure scale for the tangent where the virgin curve is vertical at p = 0 (n > 1): the
  // mean pressure over the candidates' area.
  double mean_area = 0;
  if (soil) {
    for (double a : P.area_m2) mean_area += a;
    mean_area /= m;
  }
  // J(x) = 1/2 x^T C x + s^T x + sum A W(x / A), given C x (the line search moves along a line,
  // so C x there is C f + alpha C step: two operator products per step, not one per trial).
  auto objective = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& Cx) {
    double J = 0.5 * x.dot(Cx) + P.initial_gap.dot(x);
    for (int i = 0; i < m; ++i)
      if (x(i) > 0) {
        const double p = x(i) / P.area_m2[i];
        J += P.area_m2[i] * P.rate.work_J_m2(i, p, law(i)->work_J_m2(p, zmax(i)));
      }
    return J;
  };
  // The step's model of Z: the secant through the unloaded point (0, Z(0)) and the current one
  // while steps are cut back (for a convex Z it over-estimates the sinkage between them, a
  // Kacanov step that converges from afar), the tangent (Newton) once a full step is taken.
  bool secant = f.size() == 0;  // a warm start (initial_force) begins with Newton
  for (int it = 1; it <= o.max_iterations; ++it) {
    out.iterations = it;
    std::vector<double> d(m, 0.0);
    Eigen::VectorXd gap = P.initial_gap;
    if (soil) {
      for (int i = 0; i < m; ++i) {
        const double fi = f.size() ? std::max(f(i), 0.0) : 0.0;
        const double A = P.area_m2[i];
        const double p_floor = 1e-3 * P.load_N / (mean_area * m);
        const double p = std::max(fi / A, p_floor);
        double dzdp = law(i)->compliance_m_per_Pa(p, zmax(i));
        if (secant) {
          const double z0 = law(i)->sinkage_m(0.0, zmax(i));
          dzdp = std::max(dzdp, (law(i)->sinkage_m(p, zmax(i)) - z0) / p);
          // Below the point's previous maximum a rigid-plastic branch is vertical: a model
          // without the virgin curve beyond p_max would load the point without bound.
          const double p_max = zmax(i) > 0 ? law(i)->loading_Pa(zmax(i)) : 0.0;
          if (p < p_max) dzdp = std::max(dzdp, law(i)->compliance_m_per_Pa(p_max, zmax(i)));
        }
        d[i] = dzdp * P.rate.scale(i) / A;  // the rate term scales the law (soil_rate_term.h)
        gap(i) += Z(i, fi) - d[i] * fi;
      }
    }
    const detail::DiagonalShifted op(*P.compliance, d);
    solvers::ContactProblem lp;
    lp.compliance_operator = &op;
    lp.initial_gap = gap;
    lp.load_N = P.load_N;
    const solvers::ContactSolution s = solvers::solve_unilateral_contact(lp, o.contact, active);
    out.contact_iterations += s.iterations;
    if (!s.ok()) {
      out.status = s.status;
      out.message = "ground contact, linear step " + std::to_string(it) + ": " + s.message;
      return out;
    }
    active = s.active;
    const double change = f.size() ? (s.force - f).cwiseAbs().maxCoeff() : 1e300;
    // The linearisation's error at the linear solution: where it is below the gap tolerance on
    // every point in contact, the linear solution solves the nonlinear problem (off contact the
    // tangent of a convex Z under-estimates Z, so those gaps stay open).
    double lin_error = 0;
    if (soil && f.size()) {
      for (int i = 0; i < m; ++i) {
        if (!s.active[i]) continue;
        const double fi = std::max(f(i), 0.0);
        const double lin = Z(i, fi) + d[i] * (s.force(i) - fi);
        lin_error = std::max(lin_error, std::abs(Z(i, s.force(i)) - lin));
      }
    }
    const double gap_tol = o.gap_tolerance * std::max(std::abs(s.approach_m), 1e-6);
    if (!soil || change <= o.force_tolerance * P.load_N || (f.size() && lin_error <= gap_tol)) {
      f = s.force;
      out.approach_m = s.approach_m;
      out.soil_compliance = d;
      break;
    }
    if (f.size() == 0) {
      f = s.force;
      secant = true;
    } else {
      // Backtracking on the convex objective along the step to the linear solution.
      const Eigen::VectorXd step = s.force - f;
      const Eigen::VectorXd Cf = product(*P.compliance, f), Cstep = product(*P.compliance, step);
      const double J0 = objective(f, Cf);
      double alpha = 1;
      for (int k = 0; k < 30 && objective(f + alpha * step, Cf + alpha * Cstep) > J0; ++k)
        alpha *= 0.5;
      f += alpha * step;
      // Newton (the tangent) after a full step, back to the secant whenever a step is cut.
      secant = alpha < 1;
    }
    if (it == o.max_iterations) {
      out.status = SolveStatus::max_iterations;
      std::ostringstream msg;
      msg << "ground contact: the soil's linearisation did not settle in " << it
          << " steps (last force change " << change / P.load_N << " of the load)";
      out.message = msg.str();
      return out;
    }
  }
  out.force = f;
  out.active = active;
  const Eigen::VectorXd Cf = product(*P.compliance, f);
  out.soil_sinkage = Eigen::VectorXd::Zero(m);
  out.gap.resize(m);
  double total = 0, comp = 0;
  for (int i = 0; i < m; ++i) {
    if (soil) out.soil_sinkage(i) = Z(i, f(i));
    out.gap(i) = P.initial_gap(i) + Cf(i) + out.soil_sinkage(i) - out.approach_m;
    total += f(i);
    comp = std::max(comp, std::abs(f(i) * out.gap(i)));
  }
  out.equilibrium_residual = std::abs(total - P.load_N) / P.load_N;
  out.complementarity_residual = comp / (P.load_N * std::max(std::abs(out.approach_m), 1e-12));
  out.status = SolveStatus::converged;
  std::ostringstream msg;
  msg << "converged in " << out.iterations << " soil linearisations (" << out.contact_iterations
      << " active-set iterations)";
  out.message = msg.str();
  return out;
}

}  // namespace modaltyre::contact
