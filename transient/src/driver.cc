// run_transient(): a scenario on the 2D patch (patch_ode_2d.cc) through the run loop
// (run_loop.cc), on the units that can touch (tread_window.h), repeated with every unit should
// one outside them reach the road.
#include "modaltyre/transient/driver.h"

#include <chrono>

#include "modaltyre/core/errors.h"
#include "modaltyre/transient/soil_contact.h"
#include "modaltyre/transient/tread_window.h"
#include "patch_ode.h"

namespace modaltyre::transient {

TransientResult run_transient(const TransientModel& M, Scenario scenario,
                              const TransientRunOptions& options) {
  const auto wall0 = std::chrono::steady_clock::now();
  const ScenarioPlan plan = plan_scenario(M, scenario);
  if (scenario == Scenario::cleat && M.settings.cleat.width_m > 0) {
    throw InputError(InputLocation{M.tyre.config.source, 0, "transient.cleat.width_mm"},
                     "the 2D patch's road is uniform across the tread: a cleat narrower than the "
                     "tread needs the 3D patch (a config with footprint_3d:)");
  }
  // On a soil (docs/soil.md section 8): the initial contact and the bounding one on it.
  const bool on_soil = M.tyre.config.ground.soil();
  if (on_soil) refuse_on_soil(M, scenario);
  StaticContact initial;
  std::unique_ptr<SoilContact> soil;
  if (on_soil)
    soil = soil_for_plan(M, plan, initial);
  else
    initial = static_contact(M, plan.initial_load_N);
  const UnitRange all{0, M.m - 1};
  UnitRange units = all;
  if (!options.all_tread_states) {
    const std::optional<StaticContact> bound =
        on_soil ? bounding_soil_contact(M, plan, initial, soil->bekker_width_m())
                : bounding_contact(M, plan, initial);
    if (bound) units = touchable_units(M, plan, *bound);
  }
  bool escaped = false;
  TransientResult res = detail::run_plan(
      *detail::make_units_ode(M, plan, initial, units, soil.get()), M, plan, options, escaped);
  if (escaped) {
    // A unit outside the range reached the road: the bound did not hold (section 2 of
    // docs/transient.md); the run is repeated with every unit (on the soil as it started).
    escaped = false;
    if (soil) soil->set_memory(initial.soil_depth_m, 0.0);
    res = detail::run_plan(*detail::make_units_ode(M, plan, initial, all, soil.get()), M, plan,
                           options, escaped);
    res.units_escaped = true;
  }
  res.on_soil = on_soil;
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace modaltyre::transient
