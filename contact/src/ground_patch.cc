#include "modaltyre/contact/ground_patch.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "modaltyre/contact/ground_contact.h"
#include "modaltyre/core/errors.h"
#include "patch_result.h"

namespace modaltyre::contact {
namespace {

// One solve at a fixed Bekker width b (ignored off a Bekker soil).
FootprintResult solve_at_width(const TyreModel& model, const PatchOperator& op,
                               const LoadCase& load, const ground::GroundSettings& g,
                               const GroundPatchInput& in, double b) {
  const int m = model.candidates();
  const solvers::DenseCompliance dense(op.compliance);
  const solvers::ComplianceOperator& C =
      op.compliance_operator ? *op.compliance_operator
                             : static_cast<const solvers::ComplianceOperator&>(dense);
  GroundContactProblem P;
  P.compliance = &C;
  P.initial_gap = model.sag;
  P.load_N = load.load_N;
  const double R0 = model.config.outer_radius_m;
  if (g.model == ground::GroundModel::profile) {
    for (int i = 0; i < m; ++i)
      P.initial_gap(i) -= g.profile->height_at(in.position_m + R0 * std::sin(model.theta[i]));
  }
  if (!in.gap_offset_m.empty()) {
    for (int i = 0; i < m; ++i) P.initial_gap(i) += in.gap_offset_m[i];
  }
  std::unique_ptr<ground::PressureSinkage> law;
  if (g.soil()) {
    law = g.normal_law(b, in.slip);
    P.law = law.get();
    P.area_m2.resize(m);
    for (int i = 0; i < m; ++i)
      P.area_m2[i] = op.width_m * model.unit_length_m * std::cos(model.theta[i]);
    P.z_max_m.assign(in.z_max_m.begin(), in.z_max_m.end());
    if (in.rate) P.rate = *in.rate;
    P.unit_law.assign(in.unit_law.begin(), in.unit_law.end());
    if (static_cast<int>(in.initial_force_N.size()) == m)
      P.initial_force = Eigen::Map<const Eigen::VectorXd>(in.initial_force_N.data(), m);
    if (!P.z_max_m.empty() && static_cast<int>(P.z_max_m.size()) != m)
      throw std::invalid_argument("soil memory: one z_max per candidate unit");
  }
  GroundContactOptions opt;
  opt.contact.max_iterations = model.config.solver.max_iterations;
  opt.contact.gap_tolerance = model.config.solver.gap_tolerance;
  // Cells under their own law (Wong and Reece's flowing rear, wong_reece_flexible.h): its kink
  // from the rigid surface to flow is met by the linearisation one side at a time, settling
  // linearly there; measured at most ~400 steps on the 100x stiffer tyre.
  if (!in.unit_law.empty()) opt.max_iterations = 1000;
  const GroundContactSolution s = solve_ground_contact(P, opt, in.warm_active);
  solvers::ContactSolution cs;
  cs.status = s.status;
  cs.message = s.message;
  cs.iterations = s.contact_iterations;
  if (s.ok()) {
    cs.force = s.force;
    cs.gap = s.gap;
    cs.approach_m = s.approach_m;
    cs.active = s.active;
    cs.equilibrium_residual = s.equilibrium_residual;
    cs.complementarity_residual = s.complementarity_residual;
  }
  FootprintResult r = detail::patch_result(model, op, load, cs, s.soil_compliance);
  if (!r.ok()) return r;
  r.message = s.message;
  if (g.soil()) {
    r.on_soil = true;
    r.bekker_width_m = b;
    r.soil_depth_m.assign(s.soil_sinkage.data(), s.soil_sinkage.data() + m);
    std::size_t k = 0;
    for (int i = 0; i < m; ++i) {
      if (!r.active[i]) continue;
      r.soil_sinkage_m = std::max(r.soil_sinkage_m, s.soil_sinkage(i));
      if (k < r.units.size()) r.units[k++].soil_depth_m = s.soil_sinkage(i);
    }
    r.tyre_deflection_m = r.sinking_m - r.soil_sinkage_m;
  }
  return r;
}

}  // namespace

FootprintResult solve_ground_patch(const TyreModel& model, PatchOperator op, const LoadCase& load,
                                   const ground::GroundSettings& g, const GroundPatchInput& in) {
  MODALTYRE_CHECK(load.load_N > 0, "load must be positive");
  if (op.horizontal_ratio != 0.0 || !op.symmetric) {
    FootprintResult r;
    r.load = load;
    r.message =
        "a ground other than the flat rigid road takes no horizontal force and no "
        "rolling_speed effect (a symmetric operator)";
    return r;
  }
  if (g.model == ground::GroundModel::rigid && in.gap_offset_m.empty())
    return solve_patch(model, std::move(op), load, in.warm_active);
  const double width = op.width_m;
  double b = in.bekker_width_m > 0 ? in.bekker_width_m : width;
  FootprintResult r = solve_at_width(model, op, load, g, in, b);
  // Bekker's b = min(contact width, contact length) (only k_c / b depends on it): a plain fixed
  // point; the length grows slowly with b (as b^(1/(2n+1))), so it contracts.
  const bool b_acts = g.model == ground::GroundModel::bekker && g.bekker.k_c > 0;
  if (in.fixed_bekker_width || !b_acts) return r;
  for (int it = 0; it < 50 && r.ok(); ++it) {
    const double next = std::min(width, r.contact_length_m);
    if (std::abs(next - b) <= 1e-7 * width) return r;
    b = it < 10 ? next : 0.5 * (b + next);  // damped once it has not settled quickly
    GroundPatchInput warm = in;
    warm.warm_active = r.active;
    r = solve_at_width(model, op, load, g, warm, b);
  }
  if (r.ok()) {
    r.status = SolveStatus::max_iterations;
    r.message = "Bekker's width b = min(width, contact length) did not settle in 50 steps";
  }
  return r;
}

}  // namespace modaltyre::contact
