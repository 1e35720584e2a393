#include "modaltyre/transient/cell_soil.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::transient {
namespace {

/// Bekker's b = min(width, length) of the static footprint is iterated to this share of b (as
/// `footprint` on a 3D config, contact/predictor.cc): plain steps, then averaged ones.
constexpr double kBekkerTolerance = 1e-7;
constexpr int kBekkerPlainSteps = 10;
constexpr int kBekkerMaxSteps = 50;
/// Rolling onto a soil the tyre sinks deeper than the static footprint at the same load (the
/// rear of the contact rests on the rut, the front carries the load: 2D, 15.8 against 11.4 mm
/// at 3 kN on LETE sand, docs/soil.md section 8), so the contact outgrows the static bound and a
/// bound at the load itself made every rolling run repeat with every section. The bounding
/// footprint is taken at this multiple of the load (the front half carrying it all, doubled
/// as tread_window.h's margin for a rise).
constexpr double kRollingBoundFactor = 2.0;

}  // namespace

CellSoil::CellSoil(const CellModel& cm, const ground::GroundSettings& ground, double bekker_width_m,
                   std::function<double(double)> distance)
    : cm_(cm), bekker_width_m_(bekker_width_m) {
  const TransientModel& M = cm.M();
  // A cell's road area dy ds cos theta_i (the 3D static footprint's, patch3d.cc).
  Eigen::VectorXd area(M.m);
  for (int i = 0; i < M.m; ++i)
    area(i) = cm.classes.dy_m * M.tyre.unit_length_m * std::cos(M.tyre.theta[i]);
  for (int c = 0; c < cm.classes.size(); ++c)
    rows_.push_back(std::make_unique<SoilContact>(ground, area, cm.k_contact, M.x_road,
                                                  bekker_width_m, distance));
}

void CellSoil::set_memory(const Eigen::MatrixXd& depth_m, double t) {
  const int m = cm_.M().m;
  for (int c = 0; c < classes(); ++c)
    rows_[c]->set_memory(
        depth_m.size() > 0 ? Eigen::VectorXd(depth_m.col(c)) : Eigen::VectorXd::Zero(m), t);
}

void CellSoil::forces(double t, const std::vector<UnitRange>& ranges,
                      const std::vector<int>& offsets, double* g, double* kd) const {
  for (int c = 0; c < classes(); ++c) {
    const UnitRange& r = ranges[c];
    if (r.size() == 0) continue;
    const SoilContact& row = *rows_[c];
    row.forces(t, r.lo, r.size(), g + offsets[c]);
    for (int k = 0; k < r.size(); ++k) kd[offsets[c] + k] = row.stiffness(r.lo + k);
  }
}

void CellSoil::accept(double t, const std::vector<UnitRange>& ranges) {
  for (int c = 0; c < classes(); ++c) rows_[c]->accept(t, ranges[c].lo, ranges[c].hi);
}

double CellSoil::deepest_loaded_m(const std::vector<UnitRange>& ranges,
                                  const std::vector<int>& offsets, const Eigen::VectorXd& f) const {
  double deepest = 0;
  for (int c = 0; c < classes(); ++c)
    for (int k = 0; k < ranges[c].size(); ++k)
      if (f(offsets[c] + k) > 0) deepest = std::max(deepest, depth(c, ranges[c].lo + k));
  return deepest;
}

double CellSoil::compaction_resistance_N(const std::vector<UnitRange>& ranges,
                                         const std::vector<int>& offsets,
                                         const Eigen::VectorXd& f) const {
  const TransientModel& M = cm_.M();
  const Eigen::VectorXd& x = M.x_road;
  double R = 0;
  for (int c = 0; c < classes(); ++c) {
    const UnitRange& r = ranges[c];
    double Rc = 0;
    for (int i = std::max(r.lo, 1); i <= std::min(r.hi, M.m - 2); ++i) {
      const double fi = f(offsets[c] + i - r.lo);
      if (fi > 0) Rc += fi * (depth(c, i - 1) - depth(c, i + 1)) / (x(i + 1) - x(i - 1));
    }
    R += cm_.classes.multiplicity[c] * Rc;
  }
  return R;
}

StaticCells static_soil_cells(const CellModel& cm, double load_N, double bekker_width_m,
                              double* bekker_used) {
  const TransientModel& M = cm.M();
  const int nc = cm.classes.size();
  StaticCells s;
  s.F = Eigen::VectorXd::Zero(M.m);
  s.f = Eigen::MatrixXd::Zero(M.m, nc);
  s.d = -M.tyre.sag;
  s.soil_depth_m = Eigen::MatrixXd::Zero(M.m, nc);
  if (bekker_used) *bekker_used = bekker_width_m;
  if (load_N <= 0) return s;
  const ground::GroundSettings& G = M.tyre.config.ground;
  const bool b_acts = bekker_width_m <= 0 && G.model == ground::GroundModel::bekker;
  double b = bekker_width_m > 0 ? bekker_width_m : cm.patch.tread_width_m;
  std::vector<char> warm;
  for (int it = 0;; ++it) {
    const auto law = G.normal_law(b);
    contact::Patch3dPhysics physics;
    physics.soil = law.get();
    const contact::Patch3d patch(M.tyre, cm.patch, physics);
    const contact::Patch3dResult r = patch.solve(load_N, warm);
    if (!r.ok()) throw ComputationError("static 3D contact on the soil: " + r.message);
    const double next = std::min(r.width_m, r.length_m);
    if (b_acts && next > 0 && std::abs(next - b) > kBekkerTolerance * b) {
      if (it == kBekkerMaxSteps)
        throw ComputationError("static 3D contact on the soil: Bekker's width did not settle");
      warm = r.section_active;
      b = it < kBekkerPlainSteps ? next : 0.5 * (b + next);
      continue;
    }
    for (int i = 0; i < M.m; ++i) {
      s.F(i) = r.section_force_N[i];
      s.d(i) = r.section_approach_m[i];
      for (int j = 0; j < r.columns; ++j) {
        const int c = cm.classes.column_class[j];
        s.f(i, c) = r.cell_force(i, j);
        s.soil_depth_m(i, c) = r.soil_depth_m[std::size_t(i) * r.columns + j];
      }
    }
    s.sinking_m = r.sinking_m;
    if (bekker_used) *bekker_used = b;
    return s;
  }
}

std::unique_ptr<CellSoil> cell_soil_for_plan(const CellModel& cm, const ScenarioPlan& plan,
                                             StaticCells& initial, StaticCells& bound,
                                             bool& bounded) {
  // Bekker's b at the scenario's largest load (where the sinkage is made), as the 2D run.
  double F_max = std::max({plan.load(0.0), plan.load(plan.duration_s), plan.initial_load_N});
  for (double t : plan.breakpoints) F_max = std::max(F_max, plan.load(t));
  double b = 0;
  static_soil_cells(cm, F_max, 0.0, &b);
  if (!(b > 0)) b = cm.patch.tread_width_m;
  std::function<double(double)> distance;
  if (plan.speed_m_s != 0) distance = [&plan](double t) { return plan.distance(t); };
  auto soil = std::make_unique<CellSoil>(cm, cm.M().tyre.config.ground, b, distance);
  initial = static_soil_cells(cm, plan.initial_load_N, b);
  soil->set_memory(initial.soil_depth_m, 0.0);
  // The bounding contact (cell_driver.cc's touchable_cells(), on the soil).
  bounded = true;
  bound = initial;
  double F_rise = std::max(plan.load(0.0), plan.load(plan.duration_s));
  for (double t : plan.breakpoints) F_rise = std::max(F_rise, plan.load(t));
  if (plan.speed_m_s != 0) F_rise *= kRollingBoundFactor;
  if (F_rise > plan.initial_load_N) {
    try {
      bound = static_soil_cells(cm, 2 * F_rise - plan.initial_load_N, b);
    } catch (const ComputationError&) {
      bounded = false;
    }
  }
  return soil;
}

}  // namespace modaltyre::transient
