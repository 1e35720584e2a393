#include "modaltyre/studies/identified_config.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

#include "modaltyre/contact/effects.h"
#include "modaltyre/core/config_edit.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/rheology/contact_geometry.h"

namespace modaltyre::studies {
namespace rh = modaltyre::rheology;
namespace {

// Sets effects.EFFECT.PARAM = value, refusing a value outside the catalogue's range (the tyre
// config reader would refuse it too, but without saying that it was identified).
void set_effect(ConfigTarget& t, const std::string& effect, const std::string& param,
                double value) {
  ConfigMapping& m = t.mapping;
  const contact::EffectInfo* info = contact::find_effect(effect);
  if (!info) throw ComputationError("identify: no effect named " + effect);
  const auto p = std::find_if(info->parameters.begin(), info->parameters.end(),
                              [&](const auto& q) { return q.name == param; });
  if (p == info->parameters.end()) throw ComputationError("identify: no parameter " + param);
  const std::string key = info->key(*p);
  if (!std::isfinite(value) || value < p->min || value > p->max)
    throw InputError({t.tyre_path, 0, key}, "the identified value " + number_text(value) + " " +
                                                p->unit + " is outside the range [" +
                                                number_text(p->min) + ", " + number_text(p->max) +
                                                "] the tyre config accepts; check the data");
  if (std::find(m.enabled.begin(), m.enabled.end(), effect) == m.enabled.end())
    m.enabled.push_back(effect);
  m.values.emplace_back(key, value);
}

// Number of different values (relative tolerance 1e-6 of the largest).
int distinct_values(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const double tol = 1e-6 * std::max(std::abs(v.front()), std::abs(v.back()));
  int n = v.empty() ? 0 : 1;
  for (std::size_t i = 1; i < v.size(); ++i) n += v[i] - v[i - 1] > tol ? 1 : 0;
  return n;
}

// Load-deflection (eq. 3, h_Z = K_Z P_Z^3/4 (1 + p_W)^-1) -> the two laws it states, each only
// when the data span its variable: load_stiffening (exponent 1/4, reference the mean test load)
// and inflation_pressure (exponent 1, the hammer test at the tyre config's pressure).
void map_load_deflection_laws(const rh::LoadDeflectionData& data, ConfigTarget& t) {
  const double tyre_pressure_kPa = t.tyre.inflation_pressure_Pa * 1e-3;
  std::vector<double> loads, pressures;
  for (const auto& r : data.rows) loads.push_back(r.load_N), pressures.push_back(r.pressure_Pa);
  std::vector<std::string>& notes = t.mapping.notes;
  if (distinct_values(loads) > 1) {
    const double mean = std::accumulate(loads.begin(), loads.end(), 0.0) / loads.size();
    set_effect(t, "load_stiffening", "exponent", 0.25);
    set_effect(t, "load_stiffening", "reference_load_N", mean);
    notes.push_back(
        "effects.load_stiffening: exponent = 1/4 (h ~ P^3/4 of eq. 3: secant "
        "compliance ~ P^-1/4), reference_load_N = the mean test load " +
        number_text(round_sig(mean, 6)) + " N");
  } else {
    notes.push_back(
        "one load only: the P^3/4 law of eq. (3) is the seed's, not identified by "
        "these data; effects.load_stiffening left as in the tyre config");
  }
  if (distinct_values(pressures) > 1) {
    set_effect(t, "inflation_pressure", "exponent", 1.0);
    set_effect(t, "inflation_pressure", "modal_test_pressure_kPa", tyre_pressure_kPa);
    notes.push_back(
        "effects.inflation_pressure: exponent = 1 ((1 + p_W)^-1 of eq. 3, p_W in "
        "bar), modal_test_pressure_kPa = tyre.inflation_pressure_kPa = " +
        number_text(tyre_pressure_kPa) + " kPa");
  } else {
    notes.push_back(
        "one pressure only: the (1 + p_W)^-1 law of eq. (3) is the seed's, not "
        "identified by these data; effects.inflation_pressure left as in the "
        "tyre config");
  }
}

void note_carcass_level(const CarcassLevel& level, ConfigTarget& t, const std::string& through,
                        double load_N) {
  t.mapping.values.emplace_back("modal.compliance_scale", level.cal.compliance_scale);
  t.mapping.notes.push_back(
      "modal.compliance_scale = " + number_text(round_sig(level.cal.compliance_scale, 6)) +
      " (was " + number_text(t.tyre.compliance_scale) + "): calibrated on " + through +
      ", so that the footprint model sinks " + number_text(round_sig(level.cal.target_mm, 5)) +
      " mm at " + number_text(round_sig(load_N, 6)) + " N and " +
      number_text(round_sig(level.fed.inflation_pressure_Pa * 1e-3, 6)) + " kPa (" +
      std::to_string(level.cal.evaluations) + " footprints)");
}

// "identified NAME = value unit (standard error se)" for every parameter, by name (as the JSON
// output lists them).
void note_identified_parameters(const rh::FitReport& report, ConfigMapping& m) {
  std::vector<rh::Parameter> params = report.parameters;
  std::sort(params.begin(), params.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });
  for (const auto& p : params)
    m.notes.push_back("identified " + p.name + " = " + number_text(round_sig(p.value)) + " " +
                      p.unit + " (standard error " + number_text(round_sig(p.std_error, 6)) + ")");
}

}  // namespace

std::string unmapped_reason(const std::string& method, bool static_loop) {
  if (method == "b-factors")
    return "the slope factors B1, B2 (eq. 6, 10) are constants of the seed's approximations; the "
           "footprint model uses nothing they determine";
  if (method == "free-vibration" && !static_loop)
    return "without a static loop, free-vibration identifies only the viscosity eta1 (eq. 22), "
           "which the static footprint model does not use; the dry friction chi (eq. 18) it uses "
           "comes from a static loop";
  return "";
}

// (~ chi E1 B_tr L_C for small phi1).
double dry_friction_force_N(double chi, double E1_Pa, double tread_width_m, double r0_m,
                            double phi1_rad) {
  return 2.0 * tread_width_m * chi * E1_Pa * r0_m * phi1_rad * std::cos(phi1_rad);
}

// F_f is evaluated at the free-vibration test point: the contact length L_C of eq. (22) at the
// friction-free deflection h_Z0 (sin phi1 = L_C / (2 r0)).
void map_three_element(const rh::FreeVibrationResult& res, const rh::StaticLoop& loop,
                       const rh::ThreeElementOptions& o, ConfigTarget& t) {
  if (!res.static_fit) throw ComputationError("map_three_element: no static loop fit");
  const rh::StaticLoopFit& s = *res.static_fit;
  const double s_half = res.contact_length_m / (2.0 * o.r0_m);
  if (!(s_half > 0 && s_half < 1))
    throw InputError("the contact length L_C = " + number_text(res.contact_length_m * 1e3) +
                     " mm of the free-vibration test is not below the diameter 2 r0 = " +
                     number_text(2e3 * o.r0_m) + " mm");
  const double phi1 = std::asin(s_half);
  const double ff = dry_friction_force_N(s.chi, s.E1_Pa, o.tread_width_m, o.r0_m, phi1);
  set_effect(t, "dry_friction", "friction_force_N", ff);
  double hmin = 1e300, hmax = 0;
  for (const auto& r : loop.rows)
    hmin = std::min(hmin, r.deflection_m), hmax = std::max(hmax, r.deflection_m);
  auto ff_at = [&](double h) {
    return dry_friction_force_N(s.chi, s.E1_Pa, o.tread_width_m, o.r0_m,
                                rh::half_contact_angle(h, o.r0_m));
  };
  std::vector<std::string>& notes = t.mapping.notes;
  notes.push_back(
      "effects.dry_friction.friction_force_N = F_f = 2 B_tr chi E1 r0 phi1 cos phi1 "
      "(seed eq. 14, 18) = " +
      number_text(round_sig(ff, 5)) + " N with chi = " + number_text(round_sig(s.chi, 5)) +
      ", E1 = " + number_text(round_sig(s.E1_Pa * 1e-6, 5)) +
      " MPa, B_tr = " + number_text(o.tread_width_m * 1e3) +
      " mm, r0 = " + number_text(o.r0_m * 1e3) + " mm at the test's contact length L_C = " +
      number_text(round_sig(res.contact_length_m * 1e3, 5)) +
      " mm (phi1 = " + number_text(round_sig(phi1, 4)) + " rad)");
  notes.push_back(
      "the three-element force grows with the contact: " + number_text(round_sig(ff_at(hmin), 4)) +
      " N at h_Z = " + number_text(round_sig(hmin * 1e3, 4)) + " mm to " +
      number_text(round_sig(ff_at(hmax), 4)) + " N at " + number_text(round_sig(hmax * 1e3, 4)) +
      " mm of the static loop; the footprint model's F_f is constant");
  notes.push_back("eta1 (eq. 22) is not written: the footprint model is static");
  note_identified_parameters(res.report, t.mapping);
}

// E2 -> modulus_MPa, the layer depth A of the tests -> layer_mm (the Winkler stiffness of the
// static part is E2 / A).
void map_soil(const rh::SoilData& data, const rh::SoilResult& res, ConfigTarget& t) {
  double amin = 1e300, amax = 0, sum = 0;
  for (const auto& r : data.rows) {
    amin = std::min(amin, r.layer_m), amax = std::max(amax, r.layer_m), sum += r.layer_m;
  }
  const double layer_m = sum / static_cast<double>(data.rows.size());
  set_effect(t, "soil_compliance", "modulus_MPa", res.E2_Pa * 1e-6);
  set_effect(t, "soil_compliance", "layer_mm", layer_m * 1e3);
  std::vector<std::string>& notes = t.mapping.notes;
  notes.push_back("effects.soil_compliance.modulus_MPa = E2 (eq. 23, 27) = " +
                  number_text(round_sig(res.E2_Pa * 1e-6, 5)) + " MPa");
  notes.push_back("effects.soil_compliance.layer_mm = the layer depth A of the rolling tests = " +
                  number_text(round_sig(layer_m * 1e3, 5)) + " mm" +
                  (amax - amin > 1e-9 * amax ? " (mean of " + number_text(amin * 1e3) + "-" +
                                                   number_text(amax * 1e3) + " mm)"
                                             : std::string()));
  notes.push_back("the soil acts on rows with surface: soil only; eta2 and k_E = " +
                  number_text(round_sig(res.k_E, 3)) +
                  " (plastic share) are not written: the static Winkler soil is elastic");
  note_identified_parameters(res.report, t.mapping);
}

void map_bevameter(const rh::BevameterResult& res, ConfigTarget& t) {
  ConfigMapping& m = t.mapping;
  auto set = [&](const std::string& key, double value, double lo, double hi) {
    if (!std::isfinite(value) || value < lo || value > hi)
      throw InputError({t.tyre_path, 0, key}, "the identified value " + number_text(value) +
                                                  " is outside the range [" + number_text(lo) +
                                                  ", " + number_text(hi) + "] the reader takes");
    m.values.emplace_back(key, round_sig(value, 8));
  };
  m.words.emplace_back("ground.model", "bekker");
  set("ground.bekker.n", res.n, 1e-9, 3);
  set("ground.bekker.k_c", res.k_c, 0, 1e9);
  set("ground.bekker.k_phi", res.k_phi, 0, 1e12);
  m.notes.push_back(
      "ground.model = bekker; n, k_c [kN/m^(n+1)], k_phi [kN/m^(n+2)] from the "
      "plate-sinkage rows (Bekker's law, docs/soil.md section 6)");
  if (res.has_unloading) {
    set("ground.bekker.unloading.k0", std::max(res.k0, 0.0), 0, 1e12);
    set("ground.bekker.unloading.Au", std::max(res.Au, 0.0), 0, 1e15);
    m.notes.push_back(
        "ground.bekker.unloading: Wong's k_u = k0 + Au z_max from the unloading "
        "cycles (a negative estimate is written as 0)");
  }
  note_identified_parameters(res.report, m);
}

void map_shear(const rh::ShearResult& res, ConfigTarget& t) {
  const auto model = t.tyre.ground.model;
  if (!t.tyre.ground.soil())
    throw InputError({t.tyre_path, 0, "ground.model"},
                     "identify shear --into-config sets the shear keys of the config's soil; "
                     "this config's ground is not a soil (run identify bevameter into it first, "
                     "or set ground.model)");
  const std::string section =
      model == ground::GroundModel::bekker ? "ground.bekker." : "ground.kelvin_voigt.";
  ConfigMapping& m = t.mapping;
  m.values.emplace_back(section + "cohesion_kPa", round_sig(std::max(res.cohesion_kPa, 0.0), 8));
  m.values.emplace_back(section + "friction_angle_deg",
                        round_sig(std::clamp(res.friction_angle_deg, 0.0, 89.0), 8));
  m.values.emplace_back(section + "shear_modulus_K_mm", round_sig(res.K_mm, 8));
  m.notes.push_back(section +
                    "{cohesion_kPa, friction_angle_deg, shear_modulus_K_mm} from the "
                    "shear rows (Janosi-Hanamoto, docs/soil.md section 6)");
  note_identified_parameters(res.report, m);
}

namespace {

// The mapping as overrides of TYRE's keys ("key=value", the form of --set).
std::vector<std::string> mapping_overrides(const ConfigMapping& m) {
  std::vector<std::string> ov;
  for (const auto& e : m.enabled) ov.push_back("effects." + e + ".enabled=true");
  for (const auto& [key, value] : m.values) ov.push_back(key + "=" + number_text(value));
  for (const auto& [key, word] : m.words) ov.push_back(key + "=" + word);
  return ov;
}

// A key of validation.calibrate that the mapping sets would be recalibrated by `validate`, which
// would overwrite the identified value: it is dropped from the list (with calibration_rows when
// nothing is left to calibrate), and the header says so.
void drop_recalibrated_keys(const ConfigTarget& t, std::vector<std::string>& overrides,
                            std::vector<std::string>& notes) {
  auto set_here = [&](const std::string& key) {
    return std::any_of(t.mapping.values.begin(), t.mapping.values.end(),
                       [&](const auto& kv) { return kv.first == key; });
  };
  auto list = [](const std::vector<std::string>& keys) {
    std::string text;
    for (const auto& k : keys) text += (text.empty() ? "" : ", ") + k;
    return text;
  };
  std::vector<std::string> kept_keys, dropped_keys;
  for (const auto& key : t.tyre.validation.calibrate)
    (set_here(key) ? dropped_keys : kept_keys).push_back(key);
  if (dropped_keys.empty()) return;
  const std::string kept = list(kept_keys), dropped = list(dropped_keys);
  overrides.push_back("validation.calibrate=[" + kept + "]");
  if (kept.empty()) overrides.push_back("validation.calibration_rows=[]");
  notes.push_back("validation.calibrate: " + dropped +
                  " removed, since it is set here and `validate` would recalibrate it, "
                  "overwriting the identified value; " +
                  (kept.empty() ? "nothing is calibrated (calibration_rows emptied)"
                                : "still calibrated: " + kept));
}

}  // namespace

IdentifiedConfig compose_identified_config(const IdentifiedSource& source, const ConfigTarget& t) {
  namespace fs = std::filesystem;
  std::vector<std::string> ov = mapping_overrides(t.mapping);
  const fs::path folder = fs::absolute(fs::path(t.out_path)).parent_path();
  if (!t.tyre.hammer_csv.empty())  // a frequency list has no file to re-anchor
    ov.push_back("modal.hammer_csv=" +
                 fs::relative(fs::absolute(t.tyre.hammer_csv), folder).generic_string());
  IdentifiedConfig out;
  out.notes = t.mapping.notes;
  drop_recalibrated_keys(t, ov, out.notes);
  out.text = "# Written by modaltyre identify " + source.method + " from " + t.tyre_path +
             (source.data_file.empty() ? "" : " and " + source.data_file) +
             " (seed 000, docs/rheology.md).\n";
  for (const auto& n : out.notes) out.text += "# " + n + "\n";
  // TYRE's own text with the keys set in place, so that its comments stay; its tree re-emitted
  // (comments lost, said so) when a key cannot be set in place.
  const std::string marker = "set by modaltyre identify";
  const std::optional<std::string> edited =
      set_keys_in_text(read_yaml_file(t.tyre_path, "a tyre config"), t.tyre_path, ov, marker);
  if (edited) {
    out.text += "# Below: " + t.tyre_path + " with its comments; lines marked '" + marker +
                "' were set here.\n" + *edited;
  } else {
    out.text += "# Below: the keys of " + t.tyre_path +
                " (its comments are not kept: a key set here could not be set in its text).\n" +
                ConfigTree::load(t.tyre_path, ov).dump();
  }
  // Read back as OUT: its re-anchored modal.hammer_csv resolves against OUT's folder to TYRE's
  // file.
  out.config = contact::read_tyre_config(ConfigTree::from_string(out.text, t.out_path));
  return out;
}

CarcassLevel calibrate_carcass_level(const IdentifiedSource& source, const ConfigTarget& t,
                                     double load_N, double target_mm) {
  CarcassLevel level;
  // TYRE with the mapping so far: what OUT will read as (its text is composed once, at the end).
  level.fed =
      contact::read_tyre_config(ConfigTree::load(t.tyre_path, mapping_overrides(t.mapping)));
  level.model = std::make_unique<const contact::TyreModel>(contact::build_tyre_model(level.fed));
  contact::OperatingConditions at = level.fed.default_conditions(load_N);
  at.pressure_kPa = level.fed.inflation_pressure_Pa * 1e-3;
  level.cal =
      calibrate_compliance_scale(*level.model, contact::parameters_of(level.fed), at, target_mm);
  if (!level.cal.ok())
    throw ComputationError("identify " + source.method + " --into-config: " + level.cal.message);
  level.fed.compliance_scale = level.cal.compliance_scale;
  return level;
}

// Every test row is then predicted by OUT's model, so the note says how far the modal model with
// the seed's laws follows the test (the laws scale the carcass only; the tread is in series).
void map_load_deflection(const IdentifiedSource& source, const rh::LoadDeflectionData& data,
                         const rh::LoadDeflectionResult& res, ConfigTarget& t) {
  map_load_deflection_laws(data, t);
  double mean_load = 0;
  for (const auto& r : data.rows) mean_load += r.load_N / data.rows.size();
  const double target_mm =
      rh::law_deflection(res.K_Z_m, mean_load, t.tyre.inflation_pressure_Pa) * 1e3;
  const CarcassLevel level = calibrate_carcass_level(source, t, mean_load, target_mm);
  double sum_sq = 0, worst = 0;
  for (const auto& r : data.rows) {
    contact::OperatingConditions c = level.fed.default_conditions(r.load_N);
    c.pressure_kPa = r.pressure_Pa * 1e-3;
    const contact::Prediction p =
        contact::predict(*level.model, contact::parameters_of(level.fed), c);
    if (!p.ok())
      throw ComputationError("identify load-deflection --into-config: footprint at " +
                             number_text(r.load_N) + " N: " + p.message);
    const double e = p.sinking_mm / (r.deflection_m * 1e3) - 1;
    sum_sq += e * e;
    worst = std::max(worst, std::abs(e));
  }
  const double rms = std::sqrt(sum_sq / data.rows.size());
  std::vector<double> pressures;
  for (const auto& r : data.rows) pressures.push_back(r.pressure_Pa);
  const double tyre_Pa = t.tyre.inflation_pressure_Pa;
  if (distinct_values(pressures) == 1 && std::abs(pressures.front() - tyre_Pa) > 1e-6 * tyre_Pa) {
    t.mapping.notes.push_back(
        "the test's pressure " + number_text(pressures.front() * 1e-3) +
        " kPa is not the tyre "
        "config's " +
        number_text(tyre_Pa * 1e-3) +
        " kPa: the level was carried over with eq. "
        "(3)'s (1 + p_W)^-1, and the row comparison below mixes the two pressures");
  }
  note_carcass_level(level, t,
                     "all " + std::to_string(data.rows.size()) + " rows of " + source.data_file +
                         " through K_Z (eq. 3's h_Z at the mean test load)",
                     mean_load);
  t.mapping.notes.push_back("with it, the footprint model gives the test's deflections to " +
                            number_text(round_sig(100 * rms, 3)) + " % RMS (worst row " +
                            number_text(round_sig(100 * worst, 3)) +
                            " %), each row at its own load and pressure");
  note_identified_parameters(res.report, t.mapping);
}

// The profile is one operating point of the tyre, the deflection h_Z under the load P_Z it
// carries (eq. 8). OUT's footprint sinks h_Z under P_Z; its contact length and peak pressure are
// then predictions, compared with the profile's 2 r0 sin(phi1) and K1 Delta_P(0).
void map_contact_stress(const IdentifiedSource& source, const rh::ContactStressResult& res,
                        double r0_m, ConfigTarget& t) {
  const CarcassLevel level = calibrate_carcass_level(source, t, res.load_N, res.deflection_m * 1e3);
  const contact::Prediction p = contact::predict(*level.model, contact::parameters_of(level.fed),
                                                 level.fed.default_conditions(res.load_N));
  if (!p.ok())
    throw ComputationError("identify contact-stress --into-config: footprint at " +
                           number_text(res.load_N) + " N: " + p.message);
  note_carcass_level(level, t,
                     "the profile of " + source.data_file + " through K1 and h_Z (the load P_Z = " +
                         number_text(round_sig(res.load_N, 5)) + " N of eq. 8)",
                     res.load_N);
  const double length_mm = 2e3 * r0_m * std::sin(rh::half_contact_angle(res.deflection_m, r0_m));
  const double peak_kPa = rh::contact_stress_law(res.K1_Pa_per_m, 0, res.deflection_m, r0_m) * 1e-3;
  double model_peak_kPa = 0;
  for (const auto& u : p.footprint.units)
    model_peak_kPa = std::max(model_peak_kPa, u.pressure_Pa * 1e-3);
  t.mapping.notes.push_back("predicted by OUT at that load: contact length " +
                            number_text(round_sig(p.length_mm, 4)) +
                            " mm (profile: " + number_text(round_sig(length_mm, 4)) + " mm, " +
                            number_text(round_sig(100 * (p.length_mm / length_mm - 1), 3)) +
                            " %), peak pressure " + number_text(round_sig(model_peak_kPa, 4)) +
                            " kPa (profile: " + number_text(round_sig(peak_kPa, 4)) + " kPa)");
  t.mapping.notes.push_back(
      "K1 and C_P themselves are not written: the footprint model's "
      "carcass is the modal one, scaled");
  note_identified_parameters(res.report, t.mapping);
}

}  // namespace modaltyre::studies
