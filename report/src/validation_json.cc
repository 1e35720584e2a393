#include "modaltyre/report/validation_json.h"

#include "modaltyre/core/number_format.h"
#include "modaltyre/report/footprint_json.h"

namespace modaltyre::report {

contact::Validity row_validity(const contact::TyreConfig& config, const studies::ValidationRow& r) {
  return contact::validity(config, r.sinking_mm * 1e-3, r.length_mm * 1e-3);
}

namespace {

nlohmann::json opt_json(const std::optional<double>& v, double scale = 1.0) {
  return v ? nlohmann::json(round_sig(*v * scale, 8)) : nlohmann::json();
}

nlohmann::json row_json(const studies::ValidationRow& r, bool with_conditions,
                        const contact::Validity& v) {
  nlohmann::json row = {
      {"row", r.measured.row},
      {"load_N", r.measured.conditions.load_N},
      {"calibration", r.calibration},
      {"measured",
       {{"sinking_mm", opt_json(r.measured.value("sinking_mm"))},
        {"length_mm", opt_json(r.measured.value("length_mm"))},
        {"width_mm", opt_json(r.measured.value("width_mm"))}}},
      {"predicted",
       {{"sinking_mm", round_sig(r.sinking_mm, 8)}, {"length_mm", round_sig(r.length_mm, 8)}}},
      {"rel_error",
       {{"sinking_mm", opt_json(r.sinking_rel_error)},
        {"length_mm", opt_json(r.length_rel_error)}}}};
  // Width is compared only where it was measured (the 2D model takes it as an input unless
  // contact_width is on).
  if (r.measured.value("width_mm")) {
    row["predicted"]["width_mm"] = round_sig(r.width_mm, 8);
    row["rel_error"]["width_mm"] = opt_json(r.width_rel_error);
  }
  if (with_conditions) row["conditions"] = conditions_json(r.measured.conditions);
  row["valid"] = v.valid;
  if (!v.valid) row["validity"] = v.reason;
  return row;
}

}  // namespace

nlohmann::json conditions_json(const contact::OperatingConditions& c) {
  return {{"load_N", c.load_N},
          {"horizontal_force_N", c.horizontal_force_N},
          {"pressure_kPa", c.pressure_kPa},
          {"hold_s", c.hold_s},
          {"speed_kmh", c.speed_kmh},
          {"branch", contact::branch_name(c.branch)},
          {"surface", contact::surface_name(c.surface)}};
}

nlohmann::json validation_json(const studies::ValidationReport& rep) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : rep.rows) {
    rows.push_back(row_json(r, rep.with_conditions, row_validity(rep.model.config, r)));
  }
  nlohmann::json rms = nlohmann::json::object();
  for (const auto& [k, v] : rep.rms_rel_error) rms[k] = round_sig(v, 8);
  nlohmann::json calibrated = nlohmann::json::object();
  nlohmann::json initial = nlohmann::json::object();
  nlohmann::json at_bound = nlohmann::json::object();
  const auto& c = rep.calibration;
  nlohmann::json std_errors = nlohmann::json::object();
  for (std::size_t i = 0; i < c.keys.size(); ++i) {
    calibrated[c.keys[i]] = round_sig(c.values[i], 8);
    if (i < c.std_errors.size()) std_errors[c.keys[i]] = round_sig(c.std_errors[i], 4);
    initial[c.keys[i]] = c.initial_values[i];
    if (!c.at_bound[i].empty()) at_bound[c.keys[i]] = c.at_bound[i];
  }
  return {{"config", rep.model.config.source},
          {"effects", nlohmann::json(enabled_effects(rep.model.config.effects))},
          {"rows", rows},
          {"rms_rel_error", rms},
          {"predicted_rows", rep.predicted_rows},
          {"calibrated", calibrated},
          {"calibration",
           {{"rows", c.rows},
            {"observables", c.observables},
            {"initial", initial},
            {"at_bound", at_bound},
            {"rms_rel_residual", round_sig(c.rms_rel_residual, 8)},
            {"converged", c.ok()},
            {"evaluations", c.evaluations},
            {"std_errors", std_errors},
            {"correlation", c.correlation},
            {"covariance", c.covariance_note},
            {"weights", c.noise_weighted ? "the rows' stated noise (*_std columns)"
                                         : "equal (relative residuals)"}}}};
}

}  // namespace modaltyre::report
