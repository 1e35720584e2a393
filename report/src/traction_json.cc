#include "modaltyre/report/traction_json.h"

#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::report {

nlohmann::json traction_case_json(const contact::TractionResult& r, bool with_pass) {
  const double deg = 180 / M_PI;
  nlohmann::json j = {{"slip", r.slip},
                      {"load_N", r.load_N},
                      {"soil_sinkage_mm", round_sig(r.soil_sinkage_m * 1e3)},
                      {"rut_depth_mm", round_sig(r.rut_depth_m * 1e3)},
                      {"sinking_mm", round_sig(r.sinking_m * 1e3)},
                      {"tyre_deflection_mm", round_sig(r.tyre_deflection_m * 1e3)},
                      {"drawbar_pull_N", round_sig(r.drawbar_pull_N)},
                      {"thrust_N", round_sig(r.thrust_N)},
                      {"motion_resistance_N", round_sig(r.motion_resistance_N)},
                      {"torque_Nm", round_sig(r.torque_Nm)},
                      {"entry_angle_deg", round_sig(r.entry_angle_rad * deg)},
                      {"exit_angle_deg", round_sig(r.exit_angle_rad * deg)},
                      {"contact_length_mm", round_sig(r.contact_length_m * 1e3)},
                      {"bekker_width_mm", round_sig(r.bekker_width_m * 1e3)},
                      {"converged", r.ok()},
                      {"iterations", r.iterations}};
  if (with_pass) j["pass"] = r.pass;
  return j;
}

nlohmann::json traction_json(const contact::TyreConfig& config, const ground::GroundSettings& g,
                             const std::vector<contact::TractionResult>& results, bool rigid,
                             int passes) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& r : results) cases.push_back(traction_case_json(r, passes > 1));
  nlohmann::json ground = {
      {"model", ground::to_string(g.model)}, {"name", g.name}, {"source", g.source}};
  if (g.model == ground::GroundModel::bekker) {
    ground["bekker"] = {{"n", g.bekker.n},
                        {"k_c", g.bekker.k_c},
                        {"k_phi", g.bekker.k_phi},
                        {"cohesion_kPa", g.bekker_shear.cohesion_kPa},
                        {"friction_angle_deg", g.bekker_shear.friction_angle_deg},
                        {"shear_modulus_K_mm", g.bekker_shear.shear_modulus_K_mm},
                        {"rigid_plastic", !g.bekker.unloading.has_value()}};
  }
  return {
      {"tyre", config.name},
      {"config", config.source},
      {"model", rigid ? "rigid cylinder (tyre.rigid)" : "flexible tyre, 2D patch"},
      {"outer_radius_mm", config.outer_radius_m * 1e3},
      {"width_mm", config.tread.width_m * 1e3},
      {"slip_definition", "Wong: driven s = 1 - V/(omega R0) > 0, braked s = omega R0/V - 1 < 0"},
      {"ground", ground},
      {"passes", passes},
      {"cases", cases}};
}

void require_traction_converged(const std::vector<contact::TractionResult>& results) {
  for (const auto& r : results) {
    if (r.ok()) continue;
    std::ostringstream msg;
    msg << "traction at load " << r.load_N << " N, slip " << r.slip << ", pass " << r.pass << ": "
        << r.message;
    throw ComputationError(msg.str());
  }
}

}  // namespace modaltyre::report
