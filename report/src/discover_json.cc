#include "modaltyre/report/discover_json.h"

#include <cmath>

#include "modaltyre/core/number_format.h"

namespace modaltyre::report {
namespace {

nlohmann::json gaps(const std::map<std::string, double>& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& kv : m) j[kv.first] = round_sig(kv.second, 6);
  return j;
}

nlohmann::json values(const std::map<std::string, double>& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& kv : m) j[kv.first] = round_sig(kv.second, 8);
  return j;
}

// Standard errors: null when a parameter is not identifiable from the data.
nlohmann::json errors(const std::map<std::string, double>& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& kv : m) {
    j[kv.first] = std::isfinite(kv.second) ? nlohmann::json(round_sig(kv.second, 4))
                                           : nlohmann::json(nullptr);
  }
  return j;
}

// A named parameter's band at two standard errors (profile_band.h): [lower, upper] and whether
// each side reaches the parameter's range bound.
nlohmann::json bands(const std::map<std::string, discover::ParameterBand>& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, b] : m) {
    j[key] = {{"lower", round_sig(b.lower, 6)},
              {"upper", round_sig(b.upper, 6)},
              {"lower_at_bound", b.lower_at_bound},
              {"upper_at_bound", b.upper_at_bound}};
  }
  return j;
}

// A named effect's mesh shift (mesh_bias.h): the fitted values' move on half the unit length,
// or the note saying why there is none; null when the check was off.
nlohmann::json mesh_shift(const discover::MeshBias& m) {
  if (m.unit_length_mm <= 0) return nullptr;
  nlohmann::json j = {{"unit_length_mm", round_sig(m.unit_length_mm, 6)},
                      {"fine_unit_length_mm", round_sig(m.fine_unit_length_mm, 6)},
                      {"shift", values(m.shift)}};
  if (m.change_rms >= 0) {
    j["prediction_change_rms"] = round_sig(m.change_rms, 4);
    j["residual_rms"] = round_sig(m.residual_rms, 4);
    j["mesh_is_coarse"] = discover::mesh_is_coarse(m);
  }
  if (!m.note.empty()) j["note"] = m.note;
  return j;
}

// The candidate's detection limit (issue 23), null with a reason where there is none: an
// untestable or named candidate, or one whose limit cannot be computed.
void put_limit(const discover::CandidateScore& c, nlohmann::json& j) {
  const discover::DetectionLimit& l = c.limit;
  std::string reason = !c.testable        ? "not testable: " + c.reason
                       : l.effect.empty() ? "named"
                       : !l.computed()    ? l.reason
                                          : "";
  if (!reason.empty()) {
    j["detection_limit"] = nullptr;
    j["detection_limit_reason"] = reason;
    if (!l.effect.empty()) j["power_at_default"] = round_sig(l.power_at_default, 3);
    return;
  }
  j["detection_limit"] = {{"parameter", l.parameter},
                          {"value", round_sig(l.value, 4)},
                          {"unit", l.unit},
                          {"times_default", round_sig(l.magnitude, 3)},
                          {"bound", l.at_most ? "at most" : "at least"},
                          {"probability", 0.8},
                          {"observable_rms_rel", gaps(l.observable_rms_rel)}};
  j["power_at_default"] = round_sig(l.power_at_default, 3);
  if (!l.two_sided) return;
  // The side below the neutral value (detection_limit.h): null with a reason when none.
  nlohmann::json lower = {{"reference_value", round_sig(l.lower_reference_value, 4)},
                          {"power_at_reference", round_sig(l.power_at_lower_reference, 3)}};
  if (l.lower_reason.empty()) {
    lower["value"] = round_sig(l.lower_value, 4);
    lower["bound"] = "at most";
  } else {
    lower["value"] = nullptr;
    lower["reason"] = l.lower_reason;
  }
  j["detection_limit"]["below_neutral"] = lower;
}

nlohmann::json more_rows_json(const discover::MoreRows& m) {
  return {{"effect", m.effect},
          {"condition", m.condition},
          {"power_at_default", round_sig(m.power_at_default, 3)},
          {"replicas", m.replicas > 0 ? nlohmann::json(m.replicas) : nullptr},
          {"extra_rows", m.replicas > 0 ? nlohmann::json(m.extra_rows) : nullptr},
          {"text", m.text}};
}

nlohmann::json candidates_json(const std::vector<discover::CandidateScore>& cs, bool with_limits) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& c : cs) {
    nlohmann::json j = {{"name", c.name}, {"testable", c.testable}};
    if (with_limits) put_limit(c, j);
    if (c.testable) {
      j["delta_bic"] = round_sig(c.delta_bic, 6);
      j["uncertainty_discount"] = round_sig(c.uncertainty_discount, 6);
      j["cv_rms_before"] = round_sig(c.cv_rms_before, 6);
      j["cv_rms_after"] = round_sig(c.cv_rms_after, 6);
      j["rms_after"] = round_sig(c.rms_after, 6);
      j["significant"] = c.significant;
      j["parameters"] = values(c.parameters);
      j["standard_errors"] = errors(c.standard_errors);
      j["cv_before"] = gaps(c.cv_before);
      j["cv_after"] = gaps(c.cv_after);
      if (c.failures) j["failed_rows"] = c.failures;
    } else {
      j["reason"] = c.reason;
    }
    a.push_back(j);
  }
  return a;
}

}  // namespace

nlohmann::json discover_json(const discover::DiscoverReport& r, const std::string& measured_path,
                             std::size_t rows) {
  nlohmann::json effects = nlohmann::json::array();
  for (const auto& e : r.effects) {
    effects.push_back({{"name", e.name},
                       {"parameters", values(e.parameters)},
                       {"standard_errors", errors(e.standard_errors)},
                       {"bands_two_standard_errors", bands(e.bands)},
                       {"at_bound", e.at_bound},
                       {"mesh_shift", mesh_shift(e.mesh)},
                       {"bands_with_mesh", bands(e.bands_with_mesh)},
                       {"delta_bic", round_sig(e.delta_bic, 6)},
                       {"cv_rms_before", round_sig(e.cv_rms_before, 6)},
                       {"cv_rms_after", round_sig(e.cv_rms_after, 6)}});
  }
  nlohmann::json regimes = nlohmann::json::array();
  for (const auto& f : r.regimes) {
    regimes.push_back({{"observable", f.observable},
                       {"variable", f.variable},
                       {"correlation", round_sig(f.correlation, 4)},
                       {"mean_residual", round_sig(f.mean_residual, 4)},
                       {"summary", f.summary}});
  }
  nlohmann::json rounds = nlohmann::json::array();
  for (std::size_t k = 0; k < r.rounds.size(); ++k)
    rounds.push_back(candidates_json(r.rounds[k], k + 1 == r.rounds.size()));
  nlohmann::json residuals = nlohmann::json::array();
  for (const auto& row : r.rows) {
    residuals.push_back({{"row", row.row},
                         {"before", gaps(row.before)},
                         {"after", gaps(row.after)},
                         {"cv_before", gaps(row.cv_before)},
                         {"cv_after", gaps(row.cv_after)}});
  }
  nlohmann::json j = {
      {"measured", measured_path},
      {"rows", rows},
      {"evaluation_mesh", r.evaluation_mesh},
      {"gap_unit",
       "relative RMS of (predicted - measured) / measured (a traction row's drawbar_pull_N and "
       "torque_Nm: / max(|measured|, 0.1 load_N) and max(|measured|, 0.1 load_N R0))"},
      {"gap_config", gaps(r.gap_config)},
      {"gap_before", gaps(r.gap_before)},
      {"gap_after", gaps(r.gap_after)},
      {"cv_gap_before", gaps(r.cv_gap_before)},
      {"cv_gap_after", gaps(r.cv_gap_after)},
      {"regime", r.regimes.empty()
                     ? nlohmann::json{{"variable", ""}, {"correlation", 0}}
                     : nlohmann::json{{"variable", r.regimes.front().variable},
                                      {"correlation", round_sig(r.regimes.front().correlation, 4)},
                                      {"observable", r.regimes.front().observable}}},
      {"regimes", regimes},
      {"worst_rows", r.worst_rows},
      {"effects", effects},
      {"candidates", r.rounds.empty() ? nlohmann::json::array()
                                      : candidates_json(r.rounds.front(), r.rounds.size() == 1)},
      {"rounds", rounds},
      {"baseline_parameters", values(r.baseline_parameters)},
      {"final_parameters", values(r.final_parameters)},
      {"residuals", residuals},
      {"fits", r.fits},
      {"evaluations", r.evaluations},
      {"footprints", r.footprints},
      {"traction_cases", r.traction_cases},
      {"method", r.method},
      {"uncertainty_inputs", r.uncertainty_inputs},
      {"conclusion", r.conclusion}};
  if (!r.more_rows.effect.empty()) j["more_rows"] = more_rows_json(r.more_rows);
  if (!r.traction_windows.empty()) {
    // Only with traction rows: a footprint-only run's document stays as it was.
    nlohmann::json w = nlohmann::json::array();
    for (const auto& t : r.traction_windows)
      w.push_back({{"load_N", t.load_N},
                   {"speed_kmh", t.speed_kmh},
                   {"window_mm", round_sig(t.window.window_m * 1e3, 6)},
                   {"grown", t.window.grown},
                   {"why", t.window.why}});
    j["traction_windows"] = w;
  }
  return j;
}

}  // namespace modaltyre::report
