#include "modaltyre/report/footprint_json.h"

#include <cmath>
#include <sstream>

#include "modaltyre/contact/validity.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::report {

std::vector<contact::OperatingConditions> footprint_cases(
    const contact::TyreConfig& config, const std::vector<double>& loads_N,
    std::optional<double> horizontal_force_N) {
  std::vector<contact::OperatingConditions> cases;
  const double fx = horizontal_force_N ? *horizontal_force_N : config.horizontal_force_N;
  for (double f : loads_N.empty() ? config.loads_N : loads_N) {
    // The range of the config's loads_N (contact/tyre_config.h), for callers without the CLI's
    // check of --load.
    if (!(f >= contact::kMinLoad_N && f <= contact::kMaxLoad_N)) {
      throw InputError({"--load", 0, ""},
                       "vertical load must be a number in [1e-06, 1e+07] N (below 1e-6 N no "
                       "contact forms; 1e7 N exceeds any tyre)");
    }
    if (config.ground.model != ground::GroundModel::rigid && fx != 0) {
      throw InputError({"--fx", 0, ""},
                       std::string("a ground other than the flat rigid road (ground.model: ") +
                           ground::to_string(config.ground.model) +
                           ") takes no horizontal force; on a soil the tyre pulls by rolling "
                           "with slip: modaltyre traction");
    }
    if (config.footprint_3d && fx != 0) {
      throw InputError({"--fx", 0, ""},
                       "the config's 3D patch (footprint_3d) takes no horizontal force");
    }
    // Uniform traction f_x = (F_x/F_z) f_z needs adhesion; beyond |F_x| = 1.5 F_z no tyre holds.
    if (!(std::abs(fx) <= 1.5 * f)) {
      throw InputError({"--fx", 0, ""},
                       "horizontal force must satisfy |F_x| <= 1.5 F_z "
                       "(no rubber-road adhesion carries more)");
    }
    contact::OperatingConditions c = config.default_conditions(f);
    c.horizontal_force_N = fx;
    cases.push_back(c);
  }
  return cases;
}

std::vector<std::string> enabled_effects(const contact::EffectsConfig& effects) {
  std::vector<std::string> names;
  for (const auto& e : contact::effect_catalogue()) {
    if (!e.is_option() && effects.enabled(e.id)) names.push_back(e.name);
  }
  return names;
}

void require_converged(const std::vector<contact::Prediction>& cases) {
  for (const auto& p : cases) {
    if (!p.ok()) {
      const auto& r = p.footprint;
      std::ostringstream msg;
      msg << "load case " << r.load.load_N << " N did not converge after " << r.iterations
          << " iterations: " << p.message;
      throw ComputationError(msg.str());
    }
  }
}

nlohmann::json pressure_map_json(const contact::Patch3dResult& r) {
  const contact::PressureMap map = contact::pressure_map(r);
  auto rounded = [](const std::vector<double>& v) {
    std::vector<double> out;
    for (double x : v) out.push_back(round_sig(x, 6));
    return out;
  };
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : map.pressure_kPa) rows.push_back(rounded(row));
  return {{"x_mm", rounded(map.x_mm)}, {"y_mm", rounded(map.y_mm)}, {"pressure_kPa", rows}};
}

nlohmann::json footprint_json(const contact::TyreModel& model,
                              const std::vector<contact::Prediction>& predictions) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& p : predictions) {
    const auto& r = p.footprint;
    nlohmann::json units = nlohmann::json::array();
    for (const auto& u : r.units) {
      units.push_back({{"x_mm", round_sig(u.x_m * 1e3)},
                       {"dx_mm", round_sig(u.dx_m * 1e3)},
                       {"fz_N", round_sig(u.fz_N)},
                       {"fx_N", round_sig(u.fx_N)},
                       {"pressure_kPa", round_sig(u.pressure_Pa * 1e-3)}});
      if (r.on_soil) units.back()["soil_depth_mm"] = round_sig(u.soil_depth_m * 1e3);
    }
    const double peak = peak_pressure_Pa(p);
    const contact::Validity v = contact::validity(model.config, r);
    cases.push_back({{"load_N", r.load.load_N},
                     {"valid", v.valid},
                     {"validity", v.valid ? nlohmann::json(nullptr) : nlohmann::json(v.reason)},
                     {"horizontal_force_N", r.load.horizontal_force_N},
                     {"sinking_mm", round_sig(r.sinking_m * 1e3)},
                     {"contact_length_mm", round_sig(r.contact_length_m * 1e3)},
                     {"rear_edge_x_mm", round_sig(r.rear_edge_x_m * 1e3)},
                     {"front_edge_x_mm", round_sig(r.front_edge_x_m * 1e3)},
                     {"vertical_stiffness_N_mm", round_sig(r.vertical_stiffness_N_m() * 1e-3)},
                     {"peak_pressure_kPa", round_sig(peak * 1e-3)},
                     {"width_mm", round_sig(p.width_mm)},
                     {"rolling_resistance_N", round_sig(p.rolling_resistance_N)},
                     {"converged", r.ok()},
                     {"iterations", r.iterations},
                     {"residuals",
                      {{"vertical_equilibrium", r.equilibrium_residual},
                       {"complementarity", r.complementarity_residual}}},
                     {"units", units}});
    if (r.on_soil) {  // docs/soil.md section 4
      cases.back()["soil_sinkage_mm"] = round_sig(r.soil_sinkage_m * 1e3);
      cases.back()["tyre_deflection_mm"] = round_sig(r.tyre_deflection_m * 1e3);
      cases.back()["bekker_width_mm"] = round_sig(r.bekker_width_m * 1e3);
    }
    if (p.patch3d) {
      cases.back()["contact_area_mm2"] = round_sig(cell_area_in_contact_m2(*p.patch3d) * 1e6);
      cases.back()["map"] = pressure_map_json(*p.patch3d);
    }
  }
  const auto& c = model.config;
  nlohmann::json out = {{"tyre", c.name},
                        {"config", c.source},
                        {"effects", enabled_effects(c.effects)},
                        {"ground", ground::to_string(c.ground.model)},
                        {"model",
                         {{"outer_radius_mm", c.outer_radius_m * 1e3},
                          {"unit_length_mm", round_sig(model.unit_length_m * 1e3)},
                          {"units_around", model.units_around},
                          {"candidate_units", model.candidates()},
                          {"max_order", model.basis.max_order},
                          {"measured_modal_terms", model.basis.measured_terms},
                          {"patch", c.footprint_3d ? "3d" : "2d"}}},
                        {"cases", cases}};
  auto& m = out["model"];
  if (c.footprint_3d) {  // the width is a result; units[].pressure_kPa is the centre line's
    const auto& s = *c.footprint_3d;
    m["tread_width_mm"] = s.tread_width_m * 1e3;
    m["lateral_cell_mm"] = round_sig(s.lateral_cell_m * 1e3);
    m["lateral_belt"] = s.lateral_belt.enabled;
  } else {
    m["contact_width_mm"] = c.tread.width_m * 1e3;
  }
  // Where the modal masses came from (docs/ring_model.md): the ring's tension, a stated mass,
  // or the shapes' own scale, and the tension they imply against the membrane's net tension.
  const auto& d = model.carcass;
  m["carcass"] = {{"normalisation", d.ring ? "ring" : "shapes"},
                  {"mass_per_length_kg_m", round_sig(d.mass_per_length_kg_m, 6)},
                  {"mass_source", d.mass_source},
                  {"implied_tension_N", round_sig(d.tension_N, 6)},
                  {"membrane_tension_N", d.membrane_tension_N > 0
                                             ? nlohmann::json(round_sig(d.membrane_tension_N, 6))
                                             : nlohmann::json(nullptr)},  // no belt width
                  // membrane_tension_N is this share of p b R (docs/ring_model.md section 3a).
                  {"net_tension_share", round_sig(c.carcass.net_tension_share, 6)},
                  {"test_pressure_kPa", round_sig(d.test_pressure_Pa * 1e-3, 6)},
                  {"operating_pressure_kPa", round_sig(d.operating_pressure_Pa * 1e-3, 6)}};
  return out;
}

}  // namespace modaltyre::report
