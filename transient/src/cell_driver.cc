// run_transient_3d(): a scenario on the 3D patch's cells (cell_model.h, patch_ode_3d.cc,
// docs/transient.md section 7) through the run loop (run_loop.cc), with tread states on the
// sections each class can touch, repeated with every section should one outside reach the road.
#include <algorithm>
#include <chrono>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/transient/cell_soil.h"
#include "modaltyre/transient/cell_system.h"
#include "modaltyre/transient/driver.h"
#include "modaltyre/transient/soil_contact.h"
#include "patch_ode.h"

namespace modaltyre::transient {
namespace {

/// The sections each class can touch in the scenario (touchable_sections() under the bounding
/// static footprint of tread_window.h: the initial one, or at 2 F_max - F0 when the load rises).
std::vector<UnitRange> touchable_cells(const CellModel& cm, const ScenarioPlan& plan,
                                       const StaticCells& initial) {
  double F_max = std::max(plan.load(0.0), plan.load(plan.duration_s));
  for (double t : plan.breakpoints) F_max = std::max(F_max, plan.load(t));
  StaticCells bound = initial;
  if (F_max > plan.initial_load_N) {
    try {
      bound = static_cells(cm, 2 * F_max - plan.initial_load_N);
    } catch (const ComputationError&) {
      return {};  // every section for every class
    }
  }
  return touchable_sections(cm, plan, bound);
}

}  // namespace

TransientResult run_transient_3d(const TransientModel& M, Scenario scenario,
                                 const TransientRunOptions& options) {
  const auto wall0 = std::chrono::steady_clock::now();
  const ScenarioPlan plan = plan_scenario(M, scenario);
  const double cleat_width = scenario == Scenario::cleat ? M.settings.cleat.width_m : 0.0;
  const CellModel cm = build_cell_model(M, cleat_width, !options.per_column_cells);
  for (double t : options.map_times_s) {
    if (!(t >= 0 && t <= plan.duration_s)) {
      std::ostringstream msg;
      msg << "map time " << t << " s outside the scenario's 0 .. " << plan.duration_s << " s";
      throw InputError(InputLocation{"--map-times", 0, ""}, msg.str());
    }
  }
  // On a soil (docs/soil.md section 8.3): the initial and the bounding contact on it.
  const bool on_soil = M.tyre.config.ground.soil();
  if (on_soil) refuse_on_soil(M, scenario, /*cells=*/true);
  StaticCells initial, soil_bound;
  std::unique_ptr<CellSoil> soil;
  bool bounded = true;
  if (on_soil)
    soil = cell_soil_for_plan(cm, plan, initial, soil_bound, bounded);
  else
    initial = static_cells(cm, plan.initial_load_N);
  std::vector<UnitRange> ranges;
  if (!options.all_tread_states) {
    if (!on_soil)
      ranges = touchable_cells(cm, plan, initial);
    else if (bounded)
      ranges = touchable_sections(cm, plan, soil_bound);
  }
  bool escaped = false;
  TransientResult res = detail::run_plan(
      *detail::make_cells_ode(cm, plan, initial, ranges, soil.get()), M, plan, options, escaped);
  if (escaped) {
    escaped = false;
    if (soil) soil->set_memory(initial.soil_depth_m, 0.0);  // the soil as it started
    res = detail::run_plan(*detail::make_cells_ode(cm, plan, initial, {}, soil.get()), M, plan,
                           options, escaped);
    res.units_escaped = true;
  }
  res.on_soil = on_soil;
  if (soil) {
    for (int c = 0; c < soil->classes(); ++c)
      for (int i = 0; i < M.m; ++i)
        res.rut_depth_m = std::max(res.rut_depth_m, soil->rut_m(c, i, res.simulated_s));
  }
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

TransientResult run_scenario(const TransientModel& M, Scenario scenario,
                             const TransientRunOptions& options) {
  if (M.tyre.config.footprint_3d) return run_transient_3d(M, scenario, options);
  if (!options.map_times_s.empty())
    throw InputError({"--map-times", 0, ""},
                     "contact maps need the 3D patch (a config with footprint_3d:)");
  return run_transient(M, scenario, options);
}

}  // namespace modaltyre::transient
