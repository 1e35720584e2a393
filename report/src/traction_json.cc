#include "modaltyre/report/traction_json.h"

#include <cmath>
#include <optional>
#include <sstream>

#include "modaltyre/contact/traction_curve.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/report/ground_input.h"

namespace modaltyre::report {

nlohmann::json traction_case_json(const contact::TractionResult& r, bool with_pass) {
  const double deg = 180 / M_PI;
  if (!r.ok()) {  // a failed slip: its reason, no numbers
    nlohmann::json j = {{"slip", r.slip}, {"load_N", r.load_N},     {"converged", false},
                        {"valid", false}, {"validity", r.validity}, {"error", r.message}};
    if (with_pass) j["pass"] = r.pass;
    return j;
  }
  nlohmann::json j = {{"slip", r.slip},
                      {"load_N", r.load_N},
                      {"soil_sinkage_mm", round_sig(r.soil_sinkage_m * 1e3)},
                      {"rut_depth_mm", round_sig(r.rut_depth_m * 1e3)},
                      {"sinking_mm", round_sig(r.sinking_m * 1e3)},
                      {"tyre_deflection_mm", round_sig(r.tyre_deflection_m * 1e3)},
                      {"drawbar_pull_N", round_sig(r.drawbar_pull_N)},
                      {"thrust_N", round_sig(r.thrust_N)},
                      {"motion_resistance_N", round_sig(r.motion_resistance_N)},
                      {"compaction_resistance_N", round_sig(r.compaction_resistance_N)},
                      {"flexing_resistance_N", round_sig(r.flexing_resistance_N)},
                      {"bulldozing_resistance_N", round_sig(r.bulldozing_resistance_N)},
                      {"torque_Nm", round_sig(r.torque_Nm)},
                      {"entry_angle_deg", round_sig(r.entry_angle_rad * deg)},
                      {"exit_angle_deg", round_sig(r.exit_angle_rad * deg)},
                      {"contact_length_mm", round_sig(r.contact_length_m * 1e3)},
                      {"bekker_width_mm", round_sig(r.bekker_width_m * 1e3)},
                      {"rolling_radius_mm", round_sig(r.rolling_radius_m * 1e3)},
                      {"loaded_radius_mm", round_sig(r.loaded_radius_m * 1e3)},
                      {"window_mm", round_sig(r.window_m * 1e3)},
                      {"tractive_efficiency", round_sig(r.tractive_efficiency)},
                      {"converged", r.ok()},
                      {"valid", r.valid},
                      {"validity", r.valid ? nlohmann::json(nullptr) : nlohmann::json(r.validity)},
                      {"iterations", r.iterations}};
  if (with_pass) j["pass"] = r.pass;
  // Only on the cases it concerns (docs/soil.md section 10, "Mesh"): the run's other keys as ever.
  if (r.rut_reach_units >= 0) j["wong_reece_rut_reach_units"] = r.rut_reach_units;
  return j;
}

namespace {

nlohmann::json point_json(const std::optional<contact::CurvePoint>& p, const char* value_key) {
  if (!p) return nullptr;
  return {{"slip", round_sig(p->slip)}, {value_key, round_sig(p->value)}};
}

}  // namespace

nlohmann::json traction_curves_json(const std::vector<contact::TractionResult>& results) {
  nlohmann::json out = nlohmann::json::array();
  for (const contact::TractionCurve& c : contact::traction_curves(results))
    out.push_back({{"load_N", c.load_N},
                   {"pass", c.pass},
                   {"towed_point", point_json(c.towed, "drawbar_pull_N")},
                   {"self_propelled_point", point_json(c.self_propelled, "torque_Nm")}});
  return out;
}

nlohmann::json traction_json(const contact::TyreConfig& config, const ground::GroundSettings& g,
                             const std::vector<contact::TractionResult>& results, bool rigid,
                             int passes, contact::SlipReference reference, double speed_km_h) {
  nlohmann::json cases = nlohmann::json::array();
  bool patch_3d = false;  // the 3D patch's results carry the track per column
  for (const auto& r : results) {
    cases.push_back(traction_case_json(r, passes > 1));
    patch_3d = patch_3d || !r.column_z_max_m.empty();
  }
  nlohmann::json ground = {
      {"model", ground::to_string(g.model)}, {"name", g.name}, {"source", g.source}};
  if (g.model == ground::GroundModel::bekker) {
    ground["bekker"] = {{"n", g.bekker.n},
                        {"k_c", g.bekker.k_c},
                        {"k_phi", g.bekker.k_phi},
                        {"cohesion_kPa", g.bekker_shear.cohesion_kPa},
                        {"friction_angle_deg", g.bekker_shear.friction_angle_deg},
                        {"shear_modulus_K_mm", g.bekker_shear.shear_modulus_K_mm},
                        {"rigid_plastic", !g.bekker.unloading.has_value()},
                        {"wong_reece", g.wong_reece.enabled},
                        {"slip_sinkage", g.slip_sinkage.enabled},
                        {"bulldozing", g.bulldozing.enabled}};
  }
  const bool rolling = reference == contact::SlipReference::rolling;
  const nlohmann::json curves = traction_curves_json(results);
  nlohmann::json doc = {
      {"tyre", config.name},
      {"config", config.source},
      {"model", rigid      ? "rigid cylinder (tyre.rigid)"
                : patch_3d ? "flexible tyre, 3D patch"
                           : "flexible tyre, 2D patch"},
      {"outer_radius_mm", config.outer_radius_m * 1e3},
      {"width_mm",
       (config.footprint_3d ? config.footprint_3d->tread_width_m : config.tread.width_m) * 1e3},
      {"slip_reference", rolling ? "rolling" : "unloaded"},
      {"slip_definition",
       rolling ? "ISTVS: driven s = 1 - V/(omega r_e) > 0, braked s = omega r_e/V - 1 < 0, r_e the "
                 "rolling radius of the same tyre at the same load free-rolling on the rigid "
                 "road (rolling_radius_mm)"
               : "driven s = 1 - V/(omega R0) > 0, braked s = omega R0/V - 1 < 0, R0 the outer "
                 "radius"},
      {"ground", ground},
      {"speed_km_h", speed_km_h},
      {"passes", passes},
      {"cases", cases},
      {"curves", curves}};
  if (curves.size() == 1) {
    doc["towed_point"] = curves[0]["towed_point"];
    doc["self_propelled_point"] = curves[0]["self_propelled_point"];
  }
  return doc;
}

}  // namespace modaltyre::report
