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
                      {"rolling_radius_mm", round_sig(r.rolling_radius_m * 1e3)},
                      {"loaded_radius_mm", round_sig(r.loaded_radius_m * 1e3)},
                      {"tractive_efficiency", round_sig(r.tractive_efficiency)},
                      {"converged", r.ok()},
                      {"iterations", r.iterations}};
  if (with_pass) j["pass"] = r.pass;
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
                             int passes, contact::SlipReference reference) {
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
                        {"rigid_plastic", !g.bekker.unloading.has_value()}};
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
      {"passes", passes},
      {"cases", cases},
      {"curves", curves}};
  if (curves.size() == 1) {
    doc["towed_point"] = curves[0]["towed_point"];
    doc["self_propelled_point"] = curves[0]["self_propelled_point"];
  }
  return doc;
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

TractionSetup traction_setup(const std::string& config_path, const std::string& ground_path,
                             const std::vector<std::string>& overrides) {
  TractionSetup s;
  s.config = config_on_ground(config_path, ground_path, overrides);
  s.rigid = s.config.rigid;
  s.ground = s.config.ground;
  s.ground_source = ground_path.empty() ? config_path : ground_path;
  if (!s.ground.soil())
    throw InputError({s.ground_source, 0, "ground.model"},
                     "traction needs a soil: model bekker or kelvin_voigt");
  return s;
}

void use_2d_patch_of_3d(contact::TyreConfig& config) {
  if (!config.footprint_3d) return;
  config.tread.width_m = config.footprint_3d->tread_width_m;
  config.footprint_3d.reset();
}

std::vector<contact::TractionResult> run_traction(const TractionSetup& setup,
                                                  const std::vector<double>& loads_N,
                                                  const std::vector<double>& slips, int passes) {
  if (loads_N.empty()) throw InputError({"loads_N", 0, ""}, "give at least one load [N]");
  if (slips.empty()) throw InputError({"slips", 0, ""}, "give at least one slip");
  // The command's ranges (app/cmd_traction.cc): a braked wheel locks at s = -1, a driven one
  // spins in place at s = 1; 1e7 N exceeds any tyre; passes 1-20.
  for (double s : slips)
    if (!(s >= -0.99 && s <= 1))
      throw InputError({"slips", 0, ""}, "slip " + std::to_string(s) + " outside [-0.99, 1]");
  for (double F : loads_N)
    if (!(F >= contact::kMinLoad_N && F <= contact::kMaxLoad_N))
      throw InputError({"loads_N", 0, ""}, "load " + std::to_string(F) + " N outside [1e-6, 1e7]");
  if (passes < 1 || passes > 20) throw InputError({"passes", 0, ""}, "passes must be 1-20");
  contact::TyreConfig config = setup.config;
  if (setup.patch_2d || setup.rigid) use_2d_patch_of_3d(config);
  config.ground = setup.ground;
  contact::TractionOptions opt;
  opt.rigid = setup.rigid;
  opt.passes = passes;
  opt.slip_reference = setup.slip_reference;
  std::vector<contact::TractionCase> cases;
  for (double load : loads_N)
    for (double s : slips) cases.push_back({load, s});
  const contact::TyreModel model = contact::build_tyre_model(config);
  auto results = contact::steady_traction(model, setup.ground, cases, opt);
  require_traction_converged(results);
  return results;
}

}  // namespace modaltyre::report
