#pragma once
// The units that can touch the road in a scenario, fixed once per run (docs/transient.md
// section 2, "Tread states only where units can touch").
//
// A unit that never touches has f_i = 0 for the whole run and, at rest or ahead of the patch when
// rolling, e_i = 0 for ever (c' De_i/Dt + k' e_i = f_i with e = 0 entering at the front); behind
// the patch its e_i is advected rubber that never comes back (material flows backwards through
// the ground-fixed units). Its tread state changes no force, so the ODE keeps tread states (and
// force evaluations) only for the units that can touch: a contiguous range around the unit of
// least sag, those whose sag lies below a bound of the sinking plus the cleat height plus a
// margin for the carcass's dynamic deflection. The bound comes from the static sinkings at the
// scenario's loads:
//   - the load never rises above the initial one (free vibration released downwards in load,
//     rolling, cleat): the initial static sinking z0. For a release from the equilibrium under
//     F0 to F1 < F0 this is exact: the energy U - F1 z does not grow (damping, relaxation and
//     the residual orders only dissipate) and the equilibrium minimises U - F0 z, so
//     (F0 - F1) z <= (F0 - F1) z0;
//   - the load rises (load-hold, a release upwards): z0 + 2 (z1 - z0), z1 the static sinking at
//     the largest load: a step load on a hardening contact (convex load-sinking curve) overshoots
//     by less than the linear spring's factor 2; a ramp by less again.
// The driver checks the bound during the run (TransientSystem::escaped()): should a unit outside
// the range ever reach the road, the run is repeated with every unit.
#include <Eigen/Dense>
#include <optional>

#include "modaltyre/transient/model.h"
#include "modaltyre/transient/scenario.h"

namespace modaltyre::transient {

/// A contiguous range of candidate units [lo, hi] (empty if hi < lo).
struct UnitRange {
  int lo = 0, hi = -1;
  int size() const { return hi >= lo ? hi - lo + 1 : 0; }
  bool contains(int i) const { return i >= lo && i <= hi; }
};

/// The static footprint of the transient model under a load (the footprint solver, relaxed
/// tread): forces on the m candidates and sinking (0 and zero forces for load_N <= 0).
struct StaticContact {
  Eigen::VectorXd f;
  double sinking_m = 0;
  /// On a soil (soil_contact.h): its surface depth under every candidate (empty on a road).
  Eigen::VectorXd soil_depth_m;
};
StaticContact static_contact(const TransientModel& model, double load_N);

/// Margin of the touchable range, as a fraction of the bounding sinking: the carcass's dynamic
/// deflection at the patch edges against its static shape (docs/transient.md section 6: in the
/// four bundled scenarios no unit touched beyond the bounding static patch itself).
inline constexpr double kTouchMarginFraction = 0.05;

/// The static contact at the scenario's bounding load (above): the initial one when the load
/// never rises above it, else the static footprint under 2 F_max - F0; none when that
/// footprint does not converge in the window (the run then keeps every unit).
std::optional<StaticContact> bounding_contact(const TransientModel& model, const ScenarioPlan& plan,
                                              const StaticContact& initial);

/// Units whose static penetration in `bound` (z - s_i - u_i, u the carcass's static
/// displacement; minus the gap outside the patch) exceeds -(margin + cleat height).
UnitRange touchable_units(const TransientModel& model, const ScenarioPlan& plan,
                          const StaticContact& bound);

}  // namespace modaltyre::transient
