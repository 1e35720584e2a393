#include "modaltyre/transient/tread_window.h"

#include <algorithm>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::transient {

namespace {

/// The forces on the m candidates and the sinking of a solved footprint.
StaticContact contact_of(const TransientModel& M, const contact::FootprintResult& fr) {
  StaticContact c;
  c.f = Eigen::VectorXd::Zero(M.m);
  std::size_t k = 0;
  for (int i = 0; i < M.m; ++i)
    if (fr.active[i]) c.f(i) = fr.units.at(k++).fz_N;
  c.sinking_m = fr.sinking_m;
  return c;
}

}  // namespace

StaticContact static_contact(const TransientModel& M, double load_N) {
  if (load_N <= 0) return StaticContact{Eigen::VectorXd::Zero(M.m), 0.0, {}};
  const contact::FootprintResult fr =
      contact::solve_footprint(M.tyre, contact::LoadCase{load_N, 0});
  if (!fr.ok()) throw ComputationError("static initial state: " + fr.message);
  return contact_of(M, fr);
}

std::optional<StaticContact> bounding_contact(const TransientModel& M, const ScenarioPlan& plan,
                                              const StaticContact& initial) {
  // The largest load of the scenario: F(t) is monotone between breakpoints (ramps and holds).
  double F_max = std::max(plan.load(0.0), plan.load(plan.duration_s));
  for (double t : plan.breakpoints) F_max = std::max(F_max, plan.load(t));
  if (F_max <= plan.initial_load_N) return initial;
  // A load beyond what the window's footprint carries: no bound (every unit is kept).
  const contact::FootprintResult fr =
      contact::solve_footprint(M.tyre, contact::LoadCase{2 * F_max - plan.initial_load_N, 0});
  if (!fr.ok()) return std::nullopt;
  return contact_of(M, fr);
}

UnitRange touchable_units(const TransientModel& M, const ScenarioPlan& plan,
                          const StaticContact& bound) {
  // Static carcass displacement u = T xi, xi = Cq q + Cr r.
  const StaticCarcass s = static_carcass(M, bound.f);
  Eigen::VectorXd xi = M.Cq * s.q;
  if (M.nr > 0) xi += M.Cr * s.r;
  const Eigen::VectorXd p = (bound.sinking_m - M.tyre.sag.array() - (M.T * xi).array()).matrix();
  const double level = -(kTouchMarginFraction * bound.sinking_m +
                         plan.road_height_bound());
  int lo = 0, hi = M.m - 1;
  while (lo <= hi && !(p(lo) > level)) ++lo;
  while (hi >= lo && !(p(hi) > level)) --hi;
  if (hi < lo) {  // nothing near the road: the unit of least sag
    M.tyre.sag.minCoeff(&lo);
    hi = lo;
  }
  return UnitRange{lo, hi};
}

}  // namespace modaltyre::transient
