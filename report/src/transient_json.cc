#include "modaltyre/report/transient_json.h"

#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::report {

nlohmann::json transient_json(const transient::TransientModel& model,
                              const transient::TransientResult& r) {
  const auto& fin = r.samples.back();
  nlohmann::json j;
  j["scenario"] = transient::to_string(r.scenario);
  j["simulated_s"] = round_sig(r.simulated_s);
  j["wall_s"] = round_sig(r.wall_s, 4);
  j["real_time_factor"] = round_sig(r.real_time_factor(), 4);
  j["steps"] = r.stats.steps;
  j["final"] = {{"load_N", round_sig(fin.load_N)},
                {"sinking_mm", round_sig(fin.sinking_m * 1e3)},
                {"contact_length_mm", round_sig(fin.contact_length_m * 1e3)},
                {"rolling_resistance_N", round_sig(r.rolling_resistance_N)},
                {"hub_displacement_mm", round_sig(fin.hub_displacement_m * 1e3)},
                {"pressure_centre_mm", round_sig(fin.pressure_centre_m * 1e3)},
                {"contact_units", fin.contact_units}};
  if (r.patch_3d) {
    j["patch"] = "3d";
    j["final"]["width_mm"] = round_sig(fin.width_m * 1e3);
    j["final"]["contact_area_mm2"] = round_sig(fin.contact_area_m2 * 1e6);
  }
  if (r.on_soil) {  // docs/soil.md section 8
    j["ground"] = ground::to_string(model.tyre.config.ground.model);
    j["final"]["soil_sinkage_mm"] = round_sig(fin.soil_sinkage_m * 1e3);
    j["final"]["compaction_resistance_N"] = round_sig(fin.soil_resistance_N);
    j["final"]["tyre_deflection_mm"] = round_sig((fin.sinking_m - fin.soil_sinkage_m) * 1e3);
    // The 3D run keeps the soil's memory per cell: the deepest rut at the run's end.
    if (r.patch_3d) j["final"]["rut_depth_mm"] = round_sig(r.rut_depth_m * 1e3);
  }
  if (r.extremes.valid) {
    // Over the integrator's steps and inside them (dense output), not over the output grid.
    auto range = [](const transient::SignalRange& x) {
      return nlohmann::json{{"min", round_sig(x.min)},
                            {"max", round_sig(x.max)},
                            {"t_min_s", round_sig(x.t_min_s)},
                            {"t_max_s", round_sig(x.t_max_s)}};
    };
    j["extremes"] = {{"load_N", range(r.extremes.load_N)},
                     {"longitudinal_force_N", range(r.extremes.longitudinal_force_N)},
                     {"taken_over", "integrator steps"},
                     {"steps_searched", r.extremes.searches}};
  }
  if (r.scenario == transient::Scenario::rolling || r.scenario == transient::Scenario::cleat) {
    // The carcass's critical speed (modal/critical_speed.h): speeds at or beyond it are
    // refused; from kNearCriticalShare of it the standing wave grows.
    const modal::CriticalSpeed c = transient::critical_speed_of(model);
    const auto& T = model.settings;
    const double v =
        r.scenario == transient::Scenario::rolling ? T.rolling.speed_m_s : T.cleat.speed_m_s;
    j["critical_speed"] = {{"speed_km_h", round_sig(c.speed_km_h())},
                           {"order", c.order},
                           {"share", round_sig(v / c.speed_m_s, 4)},
                           {"near", v >= transient::kNearCriticalShare * c.speed_m_s}};
  }
  j["output_step_ms"] = round_sig(r.output_grid.step_s * 1e3);
  j["output_grid"] = r.output_grid.describe();
  if (r.scenario == transient::Scenario::free_vibration) {
    const transient::BounceDecay d = transient::bounce_decay(r);
    if (d.peaks >= 2) {
      j["free_vibration"] = {{"period_s", round_sig(d.period_s)},
                             {"frequency_hz", round_sig(1 / d.period_s)},
                             {"log_decrement", round_sig(d.log_decrement)},
                             {"damping_ratio", round_sig(d.damping_ratio())},
                             {"peaks", d.peaks},
                             {"taken_over", d.from_steps ? "integrator steps" : "output samples"}};
    }
  }
  j["contact_switches"] = r.contact_events;
  j["solver"] = {{"rhs_evals", r.stats.rhs_evals},
                 {"jacobian_evals", r.stats.jac_evals},
                 {"linear_setups", r.stats.lin_setups},
                 {"nonlinear_iterations", r.stats.nonlin_iters},
                 {"error_test_fails", r.stats.error_test_fails},
                 {"restarts", r.stats.reinits}};
  j["model"] = {{"dynamic_coordinates", model.nq},
                {"residual_coordinates", model.nr},
                {"candidate_units", model.m},
                {"states", r.states},  // the ODE of the run: tread states of the touchable units
                {"touchable_units", r.units_hi - r.units_lo + 1},
                {"tread_time_constant_s", round_sig(model.tread_time_constant_s)},
                {"residual_time_constant_s", round_sig(model.tau_residual_s)}};
  j["samples"] = r.samples.size();
  return j;
}

std::vector<std::pair<std::string, std::vector<double>>> transient_series(
    const transient::TransientResult& r) {
  std::vector<std::pair<std::string, std::vector<double>>> cols = {{"t_s", {}},
                                                                   {"load_N", {}},
                                                                   {"hub_displacement_mm", {}},
                                                                   {"sinking_mm", {}},
                                                                   {"contact_length_mm", {}},
                                                                   {"longitudinal_force_N", {}}};
  if (r.patch_3d) {
    cols.push_back({"width_mm", {}});
    cols.push_back({"contact_area_mm2", {}});
  }
  for (const auto& s : r.samples) {
    if (r.patch_3d) {
      cols[6].second.push_back(s.width_m * 1e3);
      cols[7].second.push_back(s.contact_area_m2 * 1e6);
    }
    const double row[] = {s.t_s,
                          s.load_N,
                          s.hub_displacement_m * 1e3,
                          s.sinking_m * 1e3,
                          s.contact_length_m * 1e3,
                          s.longitudinal_force_N};
    for (std::size_t c = 0; c < 6; ++c) cols[c].second.push_back(row[c]);
  }
  if (r.on_soil) {
    cols.push_back({"soil_sinkage_mm", {}});
    for (const auto& s : r.samples) cols.back().second.push_back(s.soil_sinkage_m * 1e3);
    cols.push_back({"compaction_resistance_N", {}});
    for (const auto& s : r.samples) cols.back().second.push_back(s.soil_resistance_N);
  }
  return cols;
}

}  // namespace modaltyre::report
