// modaltyre identify METHOD [FILE] [options] [--json] [--plot FILE] [--write-config FILE]
//                   [--into-config TYRE.yaml --out-config OUT.yaml]
// Rheological parameters from simple tyre and soil tests (seed 000); with --into-config the
// parameters the footprint model uses are written into a copy of the tyre config as effects.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/contact/effects.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/rheology/contact_geometry.h"
#include "modaltyre/rheology/contact_stress.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/slope_factors.h"
#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"
#include "modaltyre/studies/stiffness_calibration.h"

namespace modaltyre::app {
namespace {

namespace rh = modaltyre::rheology;

struct IdentifyArgs {
  std::string method;
  std::string file;
  std::string config;
  double r0_mm = -1, tread_width_mm = -1, mass_kg = -1, contact_length_mm = -1;
  double section_height_mm = -1, pressure_kPa = -1;
  std::string static_file;
  bool json = false;
  std::string plot;
  std::string write_config;
  std::string into_config, out_config;  ///< --into-config TYRE.yaml --out-config OUT.yaml
  int samples = 6;
  std::string sampling = "deflection";
  bool intercept = false;
  double max_h_r0 = 0.117;
};

// Geometry in SI from the options, falling back to the tyre config (read directly: rheology
// does not depend on contact/). 0 = not given.
struct Geometry {
  double r0_m = 0, tread_width_m = 0, pressure_Pa = -1;
};

// The config the tyre geometry comes from: --config, else for the methods that test the tyre
// itself (not the rigid soil-test wheel) the --into-config target, which is the same tyre.
std::string geometry_config(const IdentifyArgs& a) {
  if (!a.config.empty()) return a.config;
  const bool tests_the_tyre = a.method == "load-deflection" || a.method == "free-vibration";
  return tests_the_tyre ? a.into_config : std::string();
}

Geometry resolve_geometry(const IdentifyArgs& a) {
  Geometry g;
  const std::string config = geometry_config(a);
  if (!config.empty()) {
    const ConfigTree tree = ConfigTree::load(config);
    const ConfigSection root = tree.root();
    if (root.has("tyre")) {
      const ConfigSection tyre = root.section("tyre");
      if (tyre.has("outer_radius_mm")) g.r0_m = tyre.positive("outer_radius_mm", 0, 5000) * 1e-3;
      if (tyre.has("inflation_pressure_kPa"))
        g.pressure_Pa = tyre.number("inflation_pressure_kPa", 0, 0, 1e5) * 1e3;
    }
    if (root.has("tread")) {
      const ConfigSection tread = root.section("tread");
      if (tread.has("contact_width_mm"))
        g.tread_width_m = tread.positive("contact_width_mm", 0, 5000) * 1e-3;
    }
  }
  auto opt = [](double v, const char* name) {
    if (v < 0) return -1.0;
    if (!(v > 0)) throw InputError({name, 0, ""}, "must be > 0");
    return v;
  };
  if (opt(a.r0_mm, "--r0-mm") > 0) g.r0_m = a.r0_mm * 1e-3;
  if (opt(a.tread_width_mm, "--tread-width-mm") > 0) g.tread_width_m = a.tread_width_mm * 1e-3;
  if (a.pressure_kPa >= 0) g.pressure_Pa = a.pressure_kPa * 1e3;
  return g;
}

double positive_or_zero(double v, const char* name) {
  if (v < 0 && v != -1) throw InputError({name, 0, ""}, "must be > 0");
  if (v == 0) throw InputError({name, 0, ""}, "must be > 0");
  return v > 0 ? v : 0.0;
}

nlohmann::json report_json(const rh::FitReport& r) {
  nlohmann::json params = nlohmann::json::object();
  for (const auto& p : r.parameters)
    params[p.name] = {
        {"value", round_sig(p.value)}, {"unit", p.unit}, {"std_error", round_sig(p.std_error, 6)}};
  return {{"method", r.method},
          {"parameters", params},
          {"residual_rms", round_sig(r.residual_rms, 6)},
          {"residual_unit", r.residual_unit},
          {"rows", r.rows},
          {"notes", r.notes}};
}

void print_report(const rh::FitReport& r, const std::string& source) {
  std::cout << "identify " << r.method << (source.empty() ? "" : " " + source) << ": " << r.rows
            << " rows, residual RMS " << round_sig(r.residual_rms, 4) << " " << r.residual_unit
            << "\n\n";
  std::cout << "  parameter                      value           std_error       unit\n";
  for (const auto& p : r.parameters) {
    char line[256];
    std::snprintf(line, sizeof line, "  %-28s %-15.6g %-15.3g %s\n", p.name.c_str(), p.value,
                  p.std_error, p.unit.c_str());
    std::cout << line;
  }
  if (!r.notes.empty()) std::cout << "\n";
  for (const auto& n : r.notes) std::cout << "  note: " << n << "\n";
}

void write_rheology_yaml(const IdentifyArgs& a, const nlohmann::json& out) {
  YAML::Emitter e;
  e.SetDoublePrecision(8);
  e << YAML::BeginMap << YAML::Key << "rheology" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "method" << YAML::Value << a.method;
  if (!a.file.empty()) e << YAML::Key << "data" << YAML::Value << a.file;
  if (!a.config.empty()) e << YAML::Key << "tyre_config" << YAML::Value << a.config;
  if (out.contains("pressure_unit"))
    e << YAML::Key << "pressure_unit" << YAML::Value << out["pressure_unit"].get<std::string>();
  e << YAML::Key << "parameters" << YAML::Value << YAML::BeginMap;
  for (auto it = out["parameters"].begin(); it != out["parameters"].end(); ++it) {
    e << YAML::Key << it.key() << YAML::Value << YAML::Flow << YAML::BeginMap;
    e << YAML::Key << "value" << YAML::Value << it.value()["value"].get<double>();
    e << YAML::Key << "unit" << YAML::Value << it.value()["unit"].get<std::string>();
    e << YAML::Key << "std_error" << YAML::Value << it.value()["std_error"].get<double>();
    e << YAML::EndMap;
  }
  e << YAML::EndMap;
  e << YAML::Key << "residual_rms" << YAML::Value << out["residual_rms"].get<double>();
  e << YAML::Key << "residual_unit" << YAML::Value << out["residual_unit"].get<std::string>();
  e << YAML::Key << "rows" << YAML::Value << out["rows"].get<int>();
  e << YAML::EndMap << YAML::EndMap;
  std::string text =
      "# Rheological parameters identified by 'modaltyre identify " + a.method +
      "' (seed 000).\n# A separate document: the tyre config reader rejects unknown keys, so "
      "these values are\n# kept next to the tyre config rather than inside it "
      "(docs/rheology.md).\n";
  text += e.c_str();
  text += "\n";
  write_file_atomically(a.write_config, text);
}

// ---- --into-config: identified parameters -> effects of the tyre config (docs/rheology.md) ---

// What an identification determines in the tyre config's `effects:` section.
struct EffectMapping {
  std::vector<std::string> enabled;                    ///< effect names switched on
  std::vector<std::pair<std::string, double>> values;  ///< dotted key, value in the key's unit
  std::vector<std::string> notes;                      ///< how each value was obtained, why
};

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// Sets effects.EFFECT.PARAM = value, refusing a value outside the catalogue's range (the tyre
// config reader would refuse it too, but without saying that it was identified).
void set_effect(EffectMapping& m, const std::string& effect, const std::string& param,
                double value) {
  const contact::EffectInfo* info = contact::find_effect(effect);
  if (!info) throw ComputationError("identify: no effect named " + effect);
  const auto p = std::find_if(info->parameters.begin(), info->parameters.end(),
                              [&](const auto& q) { return q.name == param; });
  if (p == info->parameters.end()) throw ComputationError("identify: no parameter " + param);
  const std::string key = info->key(*p);
  if (!std::isfinite(value) || value < p->min || value > p->max)
    throw InputError({"--into-config", 0, key},
                     "the identified value " + number_text(value) + " " + p->unit +
                         " is outside the range [" + number_text(p->min) + ", " +
                         number_text(p->max) + "] the tyre config accepts; check the data");
  if (std::find(m.enabled.begin(), m.enabled.end(), effect) == m.enabled.end())
    m.enabled.push_back(effect);
  m.values.emplace_back(key, value);
}

// Whether the footprint model uses what the method identifies (docs/rheology.md section 6).
// Why the footprint model has no place for what the method identifies; empty when it has one
// (docs/rheology.md 6.4). The one list both --into-config and --write-config consult.
std::string nothing_for_the_tyre_config(const IdentifyArgs& a) {
  if (a.method == "b-factors")
    return "the slope factors B1, B2 (eq. 6, 10) are constants of the seed's approximations; the "
           "footprint model uses nothing they determine (use --write-config for a separate "
           "document)";
  if (a.method == "free-vibration" && a.static_file.empty())
    return "without --static, free-vibration identifies only the viscosity eta1 (eq. 22), which "
           "the static footprint model does not use; give --static LOOP.csv to identify the dry "
           "friction chi (eq. 18)";
  return "";
}

bool feeds_tyre_config(const IdentifyArgs& a) { return nothing_for_the_tyre_config(a).empty(); }

// Methods whose results the footprint model has no place for refuse --into-config (exit 2)
// before any fitting; so does a half-given pair of options.
void check_into_config_use(const IdentifyArgs& a) {
  if (a.into_config.empty() && a.out_config.empty()) return;
  if (a.out_config.empty())
    throw InputError({"--out-config", 0, ""},
                     "--into-config " + a.into_config +
                         " needs --out-config OUT.yaml, the file "
                         "to write the tyre config with the identified effects to");
  if (a.into_config.empty())
    throw InputError({"--into-config", 0, ""},
                     "--out-config needs --into-config TYRE.yaml, the tyre config to start from");
  if (const std::string why = nothing_for_the_tyre_config(a); !why.empty())
    throw InputError("identify " + a.method + " --into-config: " + why);
  namespace fs = std::filesystem;
  std::error_code ec_in, ec_out;
  const fs::path in = fs::weakly_canonical(a.into_config, ec_in);
  const fs::path out = fs::weakly_canonical(a.out_config, ec_out);
  if (!ec_in && !ec_out && in == out)
    throw InputError({"--out-config", 0, ""},
                     a.out_config +
                         " is the tyre config itself: write the augmented config to "
                         "another file (its comments would be lost)");
}

// Saint-Venant force of the three-element model, the third term of eq. (14) with
// sgn dh/dt = +-1 (eq. 18 solved for P_Zv): P_Zv = 2 B_tr chi E1 r0 phi1 cos phi1 [N]
// (~ chi E1 B_tr L_C for small phi1).
double dry_friction_force_N(double chi, double E1_Pa, double tread_width_m, double r0_m,
                            double phi1_rad) {
  return 2.0 * tread_width_m * chi * E1_Pa * r0_m * phi1_rad * std::cos(phi1_rad);
}

// Three-element model (static loop + free decay) -> effects.dry_friction.friction_force_N.
// F_f is evaluated at the free-vibration test point: the contact length L_C of eq. (22) at the
// friction-free deflection h_Z0 (sin phi1 = L_C / (2 r0)).
EffectMapping map_three_element(const rh::FreeVibrationResult& res, const rh::StaticLoop& loop,
                                const rh::ThreeElementOptions& o) {
  const rh::StaticLoopFit& s = *res.static_fit;
  const double s_half = res.contact_length_m / (2.0 * o.r0_m);
  if (!(s_half > 0 && s_half < 1))
    throw InputError({"--contact-length-mm", 0, ""},
                     "the contact length L_C = " + number_text(res.contact_length_m * 1e3) +
                         " mm is not below the diameter 2 r0");
  const double phi1 = std::asin(s_half);
  const double ff = dry_friction_force_N(s.chi, s.E1_Pa, o.tread_width_m, o.r0_m, phi1);
  EffectMapping m;
  set_effect(m, "dry_friction", "friction_force_N", ff);
  double hmin = 1e300, hmax = 0;
  for (const auto& r : loop.rows)
    hmin = std::min(hmin, r.deflection_m), hmax = std::max(hmax, r.deflection_m);
  auto ff_at = [&](double h) {
    return dry_friction_force_N(s.chi, s.E1_Pa, o.tread_width_m, o.r0_m,
                                rh::half_contact_angle(h, o.r0_m));
  };
  m.notes.push_back(
      "effects.dry_friction.friction_force_N = F_f = 2 B_tr chi E1 r0 phi1 cos phi1 "
      "(seed eq. 14, 18) = " +
      number_text(round_sig(ff, 5)) + " N with chi = " + number_text(round_sig(s.chi, 5)) +
      ", E1 = " + number_text(round_sig(s.E1_Pa * 1e-6, 5)) +
      " MPa, B_tr = " + number_text(o.tread_width_m * 1e3) +
      " mm, r0 = " + number_text(o.r0_m * 1e3) + " mm at the test's contact length L_C = " +
      number_text(round_sig(res.contact_length_m * 1e3, 5)) +
      " mm (phi1 = " + number_text(round_sig(phi1, 4)) + " rad)");
  m.notes.push_back(
      "the three-element force grows with the contact: " + number_text(round_sig(ff_at(hmin), 4)) +
      " N at h_Z = " + number_text(round_sig(hmin * 1e3, 4)) + " mm to " +
      number_text(round_sig(ff_at(hmax), 4)) + " N at " + number_text(round_sig(hmax * 1e3, 4)) +
      " mm of the static loop; the footprint model's F_f is constant");
  m.notes.push_back("eta1 (eq. 22) is not written: the footprint model is static");
  return m;
}

// Kelvin-Voigt soil (rolling tests) -> effects.soil_compliance.modulus_MPa = E2 and layer_mm =
// the layer depth A of the tests (the Winkler stiffness of the static part is E2 / A).
EffectMapping map_soil(const rh::SoilData& data, const rh::SoilResult& res) {
  double amin = 1e300, amax = 0, sum = 0;
  for (const auto& r : data.rows) {
    amin = std::min(amin, r.layer_m), amax = std::max(amax, r.layer_m), sum += r.layer_m;
  }
  const double layer_m = sum / static_cast<double>(data.rows.size());
  EffectMapping m;
  set_effect(m, "soil_compliance", "modulus_MPa", res.E2_Pa * 1e-6);
  set_effect(m, "soil_compliance", "layer_mm", layer_m * 1e3);
  m.notes.push_back("effects.soil_compliance.modulus_MPa = E2 (eq. 23, 27) = " +
                    number_text(round_sig(res.E2_Pa * 1e-6, 5)) + " MPa");
  m.notes.push_back("effects.soil_compliance.layer_mm = the layer depth A of the rolling tests = " +
                    number_text(round_sig(layer_m * 1e3, 5)) + " mm" +
                    (amax - amin > 1e-9 * amax ? " (mean of " + number_text(amin * 1e3) + "-" +
                                                     number_text(amax * 1e3) + " mm)"
                                               : std::string()));
  m.notes.push_back("the soil acts on rows with surface: soil only; eta2 and k_E = " +
                    number_text(round_sig(res.k_E, 3)) +
                    " (plastic share) are not written: the static Winkler soil is elastic");
  return m;
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
EffectMapping map_load_deflection(const rh::LoadDeflectionData& data, double tyre_pressure_kPa) {
  std::vector<double> loads, pressures;
  for (const auto& r : data.rows) loads.push_back(r.load_N), pressures.push_back(r.pressure_Pa);
  EffectMapping m;
  if (distinct_values(loads) > 1) {
    const double mean = std::accumulate(loads.begin(), loads.end(), 0.0) / loads.size();
    set_effect(m, "load_stiffening", "exponent", 0.25);
    set_effect(m, "load_stiffening", "reference_load_N", mean);
    m.notes.push_back(
        "effects.load_stiffening: exponent = 1/4 (h ~ P^3/4 of eq. 3: secant "
        "compliance ~ P^-1/4), reference_load_N = the mean test load " +
        number_text(round_sig(mean, 6)) + " N");
  } else {
    m.notes.push_back(
        "one load only: the P^3/4 law of eq. (3) is the seed's, not identified by "
        "these data; effects.load_stiffening left as in the tyre config");
  }
  if (distinct_values(pressures) > 1) {
    set_effect(m, "inflation_pressure", "exponent", 1.0);
    set_effect(m, "inflation_pressure", "modal_test_pressure_kPa", tyre_pressure_kPa);
    m.notes.push_back(
        "effects.inflation_pressure: exponent = 1 ((1 + p_W)^-1 of eq. 3, p_W in "
        "bar), modal_test_pressure_kPa = tyre.inflation_pressure_kPa = " +
        number_text(tyre_pressure_kPa) + " kPa");
  } else {
    m.notes.push_back(
        "one pressure only: the (1 + p_W)^-1 law of eq. (3) is the seed's, not "
        "identified by these data; effects.inflation_pressure left as in the "
        "tyre config");
  }
  return m;
}

// OUT = TYRE with the mapping applied as overrides, modal.hammer_csv re-anchored to OUT's
// folder, checked by the tyre config reader (InputError naming the key otherwise).
struct OutConfig {
  std::string text;
  contact::TyreConfig config;
};

OutConfig compose_out_config(const IdentifyArgs& a, const contact::TyreConfig& tyre,
                             const EffectMapping& m) {
  namespace fs = std::filesystem;
  std::vector<std::string> ov;
  for (const auto& e : m.enabled) ov.push_back("effects." + e + ".enabled=true");
  for (const auto& [key, value] : m.values) ov.push_back(key + "=" + number_text(value));
  const fs::path folder = fs::absolute(fs::path(a.out_config)).parent_path();
  ov.push_back("modal.hammer_csv=" +
               fs::relative(fs::absolute(tyre.hammer_csv), folder).generic_string());
  OutConfig out;
  out.text = "# Written by modaltyre identify " + a.method + " from " + a.into_config +
             (a.file.empty() ? "" : " and " + a.file) + " (seed 000, docs/rheology.md).\n";
  for (const auto& n : m.notes) out.text += "# " + n + "\n";
  out.text += ConfigTree::load(a.into_config, ov).dump() + "\n";
  // Read back as OUT: its re-anchored modal.hammer_csv resolves against OUT's folder to TYRE's
  // file.
  out.config = contact::read_tyre_config(ConfigTree::from_string(out.text, a.out_config));
  return out;
}

void write_into_config(const IdentifyArgs& a, const contact::TyreConfig& tyre,
                       const EffectMapping& m) {
  write_file_atomically(a.out_config, compose_out_config(a, tyre, m).text);
}

// The target tyre config (read before any fitting) and what the method determined in it.
struct IntoConfig {
  contact::TyreConfig tyre;
  EffectMapping mapping;
};

// The carcass level modal.compliance_scale at which OUT's footprint model sinks `target_mm` under
// `load_N` at the tyre's pressure (docs/rheology.md 6.5, 6.6). OUT is TYRE with the mapping so
// far applied, so the effects the method switched on act during the calibration.
struct CarcassLevel {
  contact::TyreConfig fed;                          ///< OUT with the calibrated scale
  std::unique_ptr<const contact::TyreModel> model;  ///< OUT's model (before the calibration)
  studies::ScaleCalibration cal;
};

CarcassLevel calibrate_carcass_level(const IdentifyArgs& a, const IntoConfig& into, double load_N,
                                     double target_mm) {
  CarcassLevel level;
  level.fed = compose_out_config(a, into.tyre, into.mapping).config;
  level.model = std::make_unique<const contact::TyreModel>(contact::build_tyre_model(level.fed));
  contact::OperatingConditions at = level.fed.default_conditions(load_N);
  at.pressure_kPa = level.fed.inflation_pressure_Pa * 1e-3;
  level.cal = studies::calibrate_compliance_scale(*level.model, contact::parameters_of(level.fed),
                                                  at, target_mm);
  if (!level.cal.converged)
    throw ComputationError("identify " + a.method + " --into-config: " + level.cal.message);
  level.fed.compliance_scale = level.cal.compliance_scale;
  return level;
}

void note_carcass_level(const CarcassLevel& level, IntoConfig& into, const std::string& through,
                        double load_N) {
  into.mapping.values.emplace_back("modal.compliance_scale", level.cal.compliance_scale);
  into.mapping.notes.push_back(
      "modal.compliance_scale = " + number_text(round_sig(level.cal.compliance_scale, 6)) +
      " (was " + number_text(into.tyre.compliance_scale) + "): calibrated on " + through +
      ", so that the footprint model sinks " + number_text(round_sig(level.cal.target_mm, 5)) +
      " mm at " + number_text(round_sig(load_N, 6)) + " N and " +
      number_text(round_sig(level.fed.inflation_pressure_Pa * 1e-3, 6)) + " kPa (" +
      std::to_string(level.cal.evaluations) + " footprints)");
}

// K_Z -> modal.compliance_scale (docs/rheology.md 6.5): the carcass level at which OUT's
// footprint model sinks eq. (3)'s h_Z at the mean test load and the tyre's pressure; then every
// test row is predicted by OUT's model, so the note says how far the modal model with the
// seed's laws follows the test (the laws scale the carcass only; the tread is in series).
void map_stiffness_level(const IdentifyArgs& a, const rh::LoadDeflectionData& data,
                         const rh::LoadDeflectionResult& res, IntoConfig& into) {
  double mean_load = 0;
  for (const auto& r : data.rows) mean_load += r.load_N / data.rows.size();
  const double target_mm =
      rh::law_deflection(res.K_Z_m, mean_load, into.tyre.inflation_pressure_Pa) * 1e3;
  const CarcassLevel level = calibrate_carcass_level(a, into, mean_load, target_mm);
  double sum_sq = 0, worst = 0;
  for (const auto& r : data.rows) {
    contact::OperatingConditions c = level.fed.default_conditions(r.load_N);
    c.pressure_kPa = r.pressure_Pa * 1e-3;
    const contact::Prediction p =
        contact::predict(*level.model, contact::parameters_of(level.fed), c);
    if (!p.ok)
      throw ComputationError("identify load-deflection --into-config: footprint at " +
                             number_text(r.load_N) + " N: " + p.message);
    const double e = p.sinking_mm / (r.deflection_m * 1e3) - 1;
    sum_sq += e * e;
    worst = std::max(worst, std::abs(e));
  }
  const double rms = std::sqrt(sum_sq / data.rows.size());
  std::vector<double> pressures;
  for (const auto& r : data.rows) pressures.push_back(r.pressure_Pa);
  const double tyre_Pa = into.tyre.inflation_pressure_Pa;
  if (distinct_values(pressures) == 1 && std::abs(pressures.front() - tyre_Pa) > 1e-6 * tyre_Pa) {
    into.mapping.notes.push_back(
        "the test's pressure " + number_text(pressures.front() * 1e-3) +
        " kPa is not the tyre "
        "config's " +
        number_text(tyre_Pa * 1e-3) +
        " kPa: the level was carried over with eq. "
        "(3)'s (1 + p_W)^-1, and the row comparison below mixes the two pressures");
  }
  note_carcass_level(level, into,
                     "all " + std::to_string(data.rows.size()) + " rows of " + a.file +
                         " through K_Z (eq. 3's h_Z at the mean test load)",
                     mean_load);
  into.mapping.notes.push_back("with it, the footprint model gives the test's deflections to " +
                               number_text(round_sig(100 * rms, 3)) + " % RMS (worst row " +
                               number_text(round_sig(100 * worst, 3)) +
                               " %), each row at its own load and pressure");
}

// K1 and h_Z from a contact-stress profile -> modal.compliance_scale (docs/rheology.md 6.6): the
// profile is one operating point of the tyre, the deflection h_Z under the load P_Z it carries
// (eq. 8). OUT's footprint sinks h_Z under P_Z; its contact length and peak pressure are then
// predictions, compared with the profile's 2 r0 sin(phi1) and K1 Delta_P(0).
void map_contact_stress_level(const IdentifyArgs& a, const rh::ContactStressResult& res,
                              double r0_m, IntoConfig& into) {
  const CarcassLevel level = calibrate_carcass_level(a, into, res.load_N, res.deflection_m * 1e3);
  const contact::Prediction p = contact::predict(*level.model, contact::parameters_of(level.fed),
                                                 level.fed.default_conditions(res.load_N));
  if (!p.ok)
    throw ComputationError("identify contact-stress --into-config: footprint at " +
                           number_text(res.load_N) + " N: " + p.message);
  note_carcass_level(level, into,
                     "the profile of " + a.file + " through K1 and h_Z (the load P_Z = " +
                         number_text(round_sig(res.load_N, 5)) + " N of eq. 8)",
                     res.load_N);
  const double length_mm = 2e3 * r0_m * std::sin(rh::half_contact_angle(res.deflection_m, r0_m));
  const double peak_kPa = rh::contact_stress_law(res.K1_Pa_per_m, 0, res.deflection_m, r0_m) * 1e-3;
  double model_peak_kPa = 0;
  for (const auto& u : p.footprint.units)
    model_peak_kPa = std::max(model_peak_kPa, u.pressure_Pa * 1e-3);
  into.mapping.notes.push_back("predicted by OUT at that load: contact length " +
                               number_text(round_sig(p.length_mm, 4)) +
                               " mm (profile: " + number_text(round_sig(length_mm, 4)) + " mm, " +
                               number_text(round_sig(100 * (p.length_mm / length_mm - 1), 3)) +
                               " %), peak pressure " + number_text(round_sig(model_peak_kPa, 4)) +
                               " kPa (profile: " + number_text(round_sig(peak_kPa, 4)) + " kPa)");
  into.mapping.notes.push_back(
      "K1 and C_P themselves are not written: the footprint model's "
      "carcass is the modal one, scaled");
}

nlohmann::json mapping_json(const IdentifyArgs& a, const EffectMapping& m) {
  nlohmann::json set = nlohmann::json::object();
  for (const auto& [key, value] : m.values) set[key] = value;
  return {{"tyre_config", a.into_config},
          {"out_config", a.out_config},
          {"enabled", m.enabled},
          {"set", set},
          {"notes", m.notes}};
}

// ---- methods --------------------------------------------------------------------------------

nlohmann::json run_load_deflection(const IdentifyArgs& a, const Geometry& g, IntoConfig* into) {
  const auto data = rh::read_load_deflection_csv(a.file);
  rh::LoadDeflectionOptions o;
  o.r0_m = g.r0_m;
  o.reference_pressure_Pa = g.pressure_Pa;
  const auto res = rh::identify_load_deflection(data, o);
  nlohmann::json out = report_json(res.report);
  out["pressure_unit"] = rh::kPressureUnitName;
  out["reference_pressure_kPa"] = round_sig(res.reference_pressure_Pa * 1e-3);
  out["law"] = "h_Z[mm] = K_Z P_Z[N]^(3/4) / (1 + p_W[bar, gauge])";
  if (into) {
    into->mapping = map_load_deflection(data, into->tyre.inflation_pressure_Pa * 1e-3);
    map_stiffness_level(a, data, res, *into);
  }
  if (!a.plot.empty()) {
    std::map<long long, PlotSeries> meas, fit;
    double pmax = 0;
    for (const auto& r : data.rows) pmax = std::max(pmax, r.load_N);
    for (const auto& r : data.rows) {
      const long long key = std::llround(r.pressure_Pa * 1e-3);
      auto& m = meas[key];
      m.title = "measured " + std::to_string(key) + " kPa";
      m.style = "points";
      m.x.push_back(r.load_N);
      m.y.push_back(r.deflection_m * 1e3);
    }
    PlotPanel p{"eq. (3): K_Z = " + fixed(res.K_Z_m * 1e3, 4) + " mm N^{-3/4}",
                "load P_Z [N]",
                "deflection h_Z [mm]",
                {}};
    for (auto& [key, m] : meas) {
      PlotSeries f{"eq. (3) at " + std::to_string(key) + " kPa", {}, {}, "lines"};
      for (int i = 0; i <= 60; ++i) {
        const double P = pmax * 1.05 * i / 60;
        f.x.push_back(P);
        f.y.push_back(rh::law_deflection(res.K_Z_m, P, key * 1e3) * 1e3);
      }
      p.series.push_back(m);
      p.series.push_back(f);
    }
    render_plot(PlotFigure{{p}}, a.plot);
  }
  return out;
}

nlohmann::json run_b_factors(const IdentifyArgs& a) {
  rh::SlopeFactorOptions o;
  o.samples = a.samples;
  o.max_relative_deflection = a.max_h_r0;
  o.through_origin = !a.intercept;
  o.sampling = a.sampling == "angle" ? rh::SlopeSampling::uniform_angle
                                     : rh::SlopeSampling::uniform_deflection;
  const auto res = rh::compute_slope_factors(o);
  nlohmann::json out = report_json(res.report);
  out["seed"] = {{"B1", rh::kSeedB1}, {"B2", rh::kSeedB2}, {"R", 0.995}};
  if (!a.plot.empty()) {
    PlotPanel p1{"eq. (6): B1 = " + fixed(res.B1, 4),
                 "sin phi1 - phi1 cos phi1",
                 "(1 - cos phi1)^{4/3}",
                 {}};
    PlotPanel p2{"eq. (10): B2 = " + fixed(res.B2, 4),
                 "cos phi1 (phi1 - cos phi1 atanh sin phi1)",
                 "(1 - cos phi1)^{4/3}",
                 {}};
    p1.series.push_back({"exact", res.x1, res.y, "points"});
    p2.series.push_back({"exact", res.x2, res.y, "points"});
    PlotSeries l1{"B1 x",
                  {0, res.x1.back()},
                  {res.intercept1, res.intercept1 + res.B1 * res.x1.back()},
                  "lines"};
    PlotSeries l2{"B2 x",
                  {0, res.x2.back()},
                  {res.intercept2, res.intercept2 + res.B2 * res.x2.back()},
                  "lines"};
    p1.series.push_back(l1);
    p2.series.push_back(l2);
    render_plot(PlotFigure{{p1, p2}, 1200, 500}, a.plot);
  }
  return out;
}

nlohmann::json run_contact_stress(const IdentifyArgs& a, const Geometry& g, IntoConfig* into) {
  const auto data = rh::read_contact_stress_csv(a.file);
  rh::ContactStressOptions o;
  o.r0_m = g.r0_m;
  o.tread_width_m = g.tread_width_m;
  o.contact_length_m = positive_or_zero(a.contact_length_mm, "--contact-length-mm") * 1e-3;
  const auto res = rh::identify_contact_stress(data, o);
  if (into) map_contact_stress_level(a, res, o.r0_m, *into);
  nlohmann::json out = report_json(res.report);
  out["pressure_unit"] = rh::kPressureUnitName;
  if (!a.plot.empty()) {
    PlotSeries m{"measured", {}, {}, "points"}, f{"sigma = K1 Delta_P", {}, {}, "lines"};
    double xmax = 0;
    for (const auto& r : data.rows) {
      m.x.push_back(r.x_m * 1e3);
      m.y.push_back(r.stress_Pa * 1e-3);
      xmax = std::max(xmax, std::abs(r.x_m));
    }
    for (int i = -100; i <= 100; ++i) {
      const double x = xmax * i / 100.0;
      f.x.push_back(x * 1e3);
      f.y.push_back(rh::contact_stress_law(res.K1_Pa_per_m, x, res.deflection_m, o.r0_m) * 1e-3);
    }
    render_plot(
        PlotFigure{{PlotPanel{"eq. (8)-(12): K1 = " + fixed(res.K1_Pa_per_m * 1e-6, 3) + " MPa/m",
                              "x along the road [mm]",
                              "contact stress [kPa]",
                              {m, f}}}},
        a.plot);
  }
  return out;
}

nlohmann::json run_free_vibration(const IdentifyArgs& a, const Geometry& g, IntoConfig* into) {
  const auto signal = rh::read_free_vibration_csv(a.file);
  rh::ThreeElementOptions o;
  o.r0_m = g.r0_m;
  o.tread_width_m = g.tread_width_m;
  o.mass_kg = positive_or_zero(a.mass_kg, "--mass-kg");
  o.contact_length_m = positive_or_zero(a.contact_length_mm, "--contact-length-mm") * 1e-3;
  o.section_height_m = positive_or_zero(a.section_height_mm, "--section-height-mm") * 1e-3;
  std::unique_ptr<rh::StaticLoop> loop;
  if (!a.static_file.empty())
    loop = std::make_unique<rh::StaticLoop>(rh::read_static_loop_csv(a.static_file));
  const auto res = rh::identify_free_vibration(signal, loop.get(), o);
  if (into) into->mapping = map_three_element(res, *loop, o);  // --static: check_into_config_use
  nlohmann::json out = report_json(res.report);
  nlohmann::json amps = nlohmann::json::array();
  for (std::size_t i = 0; i < res.decay.amplitude_m.size(); ++i)
    amps.push_back({{"t_s", round_sig(res.decay.extremum_t_s[i])},
                    {"amplitude_mm", round_sig(res.decay.amplitude_m[i] * 1e3, 6)}});
  out["amplitudes"] = amps;
  if (!a.plot.empty()) {
    PlotSeries m{"measured", signal.t_s, {}, "points"}, f{"fitted damped sine", {}, {}, "lines"};
    for (double y : signal.deflection_m) m.y.push_back(y * 1e3);
    const double t0 = signal.t_s.front(), t1 = signal.t_s.back();
    for (int i = 0; i <= 1000; ++i) {
      const double t = t0 + (t1 - t0) * i / 1000.0;
      f.x.push_back(t);
      f.y.push_back(rh::decay_value(res.decay, t) * 1e3);
    }
    PlotFigure fig{{PlotPanel{"T = " + fixed(res.decay.period_s * 1e3, 2) +
                                  " ms, delta = " + fixed(res.decay.log_decrement, 4),
                              "time [s]",
                              "deflection h_Z [mm]",
                              {m, f}}}};
    if (res.static_fit) {
      PlotPanel sp{"static loop: E1 = " + fixed(res.static_fit->E1_Pa * 1e-6, 3) +
                       " MPa, chi = " + fixed(res.static_fit->chi, 4),
                   "deflection h_Z [mm]",
                   "load P_Z [N]",
                   {}};
      PlotSeries ml{"loading", {}, {}, "points"}, mu{"unloading", {}, {}, "points"};
      double hmax = 0;
      for (const auto& r : loop->rows) {
        auto& s = r.loading ? ml : mu;
        s.x.push_back(r.deflection_m * 1e3);
        s.y.push_back(r.load_N);
        hmax = std::max(hmax, r.deflection_m);
      }
      PlotSeries fl{"eq. (14) loading", {}, {}, "lines"}, fu{"eq. (14) unloading", {}, {}, "lines"};
      for (int i = 1; i <= 60; ++i) {
        const double h = hmax * i / 60;
        fl.x.push_back(h * 1e3);
        fu.x.push_back(h * 1e3);
        fl.y.push_back(
            rh::static_loop_load(res.static_fit->E1_Pa, res.static_fit->chi, h, true, o));
        fu.y.push_back(
            rh::static_loop_load(res.static_fit->E1_Pa, res.static_fit->chi, h, false, o));
      }
      sp.series = {ml, mu, fl, fu};
      fig.panels.push_back(sp);
      fig.width_px = 1200;
    }
    render_plot(fig, a.plot);
  }
  return out;
}

nlohmann::json run_soil(const IdentifyArgs& a, const Geometry& g, IntoConfig* into) {
  const auto data = rh::read_soil_rolling_csv(a.file);
  rh::SoilOptions o{g.r0_m, g.tread_width_m};
  const auto res = rh::identify_soil(data, o);
  if (into) into->mapping = map_soil(data, res);
  nlohmann::json out = report_json(res.report);
  if (!a.plot.empty()) {
    PlotSeries z{"P_Z", {}, {}, "points"}, x{"P_X", {}, {}, "points"}, d{"equal", {}, {}, "lines"};
    double fmax = 0;
    for (std::size_t i = 0; i < data.rows.size(); ++i) {
      z.x.push_back(data.rows[i].load_N);
      z.y.push_back(res.predicted_load_N[i]);
      x.x.push_back(data.rows[i].longitudinal_force_N);
      x.y.push_back(res.predicted_longitudinal_N[i]);
      fmax = std::max({fmax, data.rows[i].load_N, std::abs(data.rows[i].longitudinal_force_N)});
    }
    d.x = {0, fmax * 1.05};
    d.y = d.x;
    render_plot(
        PlotFigure{{PlotPanel{"eq. (25)-(28): E2 = " + fixed(res.E2_Pa * 1e-6, 3) +
                                  " MPa, eta2 = " + fixed(res.eta2_Pa_s * 1e-3, 3) + " kPa s",
                              "measured force [N]",
                              "model force [N]",
                              {z, x, d}}}},
        a.plot);
  }
  return out;
}

}  // namespace

void register_identify(CLI::App& app) {
  auto args = std::make_shared<IdentifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "identify",
      "Identify rheological parameters from tyre and soil tests (seed 000): K_Z and C_P from "
      "load-deflection data, the slope factors B1 and B2, K1 and C_P from a contact-stress "
      "profile, the three-element model (eta1 from a free decay, E1 and chi from a static loop) "
      "and a Kelvin-Voigt soil from rolling tests. Formats and derivations: docs/rheology.md.");
  cmd->add_option("METHOD", args->method,
                  "load-deflection | b-factors | contact-stress | free-vibration | soil-rolling")
      ->required()
      ->check(CLI::IsMember(
          {"load-deflection", "b-factors", "contact-stress", "free-vibration", "soil-rolling"}));
  cmd->add_option("FILE", args->file, "measurement CSV (not for b-factors)");
  cmd->add_option("--config", args->config,
                  "tyre config: tyre.outer_radius_mm, tyre.inflation_pressure_kPa, "
                  "tread.contact_width_mm");
  // Ranges of the numbers (README, "Input ranges"): wider than any tyre or test rig, so
  // that only a unit error or a typo falls outside.
  cmd->add_option("--r0-mm", args->r0_mm, "free (outer) radius r0 [mm]")
      ->check(physical_range(0, 5000, "mm", "no tyre or test wheel has a free radius above 5 m"));
  cmd->add_option("--tread-width-mm", args->tread_width_mm, "tread / contact width B_tr [mm]")
      ->check(physical_range(0, 5000, "mm", "no tread or test wheel is wider than 5 m"));
  cmd->add_option("--mass-kg", args->mass_kg, "reduced oscillating mass m (free-vibration) [kg]")
      ->check(physical_range(0, 1e5, "kg",
                             "a wheel with rim and fixture; 100 t exceeds any tyre test rig"));
  cmd->add_option("--contact-length-mm", args->contact_length_mm,
                  "contact length L_C (free-vibration; fixes the deflection in contact-stress)")
      ->check(physical_range(0, 10000, "mm", "a contact is shorter than the tyre's diameter"));
  cmd->add_option("--section-height-mm", args->section_height_mm,
                  "section height H of eps1 = Delta_P / H (free-vibration with --static)")
      ->check(physical_range(0, 5000, "mm", "a section is lower than the free radius"));
  cmd->add_option("--static", args->static_file,
                  "static loop CSV load_N,deflection_mm,branch for E1 and chi (free-vibration)");
  cmd->add_option("--pressure-kPa", args->pressure_kPa,
                  "gauge pressure at which load-deflection reports C_P (default: the config's, "
                  "else the median of the data)")
      ->check(physical_range(
          0, 10000, "kPa", "a gauge pressure; aircraft tyres, the hardest, run at ~1.5 MPa", true));
  cmd->add_option("--samples", args->samples, "b-factors: points over the range (default 6)");
  cmd->add_option("--sampling", args->sampling, "b-factors: uniform in 'deflection' or 'angle'")
      ->check(CLI::IsMember({"deflection", "angle"}));
  cmd->add_flag("--intercept", args->intercept, "b-factors: fit y = B x + c instead of y = B x");
  cmd->add_option("--max-h-r0", args->max_h_r0, "b-factors: upper end of h_Z/r0 (default 0.117)");
  cmd->add_flag("--json", args->json, "print JSON instead of a table");
  cmd->add_option("--plot", args->plot, "draw the fitted curve over the data (.svg/.png)");
  cmd->add_option("--write-config", args->write_config,
                  "with --config TYRE: write TYRE with the identified parameters set, a tyre "
                  "config the footprint model runs (as --into-config TYRE --out-config FILE); "
                  "b-factors, free-vibration without --static, or no --config: a 'rheology:' "
                  "YAML record of the parameters");
  cmd->add_option("--into-config", args->into_config,
                  "tyre config (YAML) to write the identified effects into (with --out-config; "
                  "load-deflection, contact-stress, free-vibration with --static, soil-rolling)");
  cmd->add_option("--out-config", args->out_config,
                  "write the tyre config of --into-config with the identified effects switched "
                  "on and set here (YAML)");
  cmd->callback([args] {
    IdentifyArgs a = *args;
    // --write-config FILE with a tyre config (--config) writes a tyre config the footprint
    // model runs (the same as --into-config CONFIG --out-config FILE) for every method whose
    // results it uses; otherwise the standalone 'rheology:' record.
    const bool tyre_config_out = !a.write_config.empty() && a.into_config.empty() &&
                                 a.out_config.empty() && !a.config.empty() && feeds_tyre_config(a);
    if (tyre_config_out) {
      a.into_config = a.config;
      a.out_config = a.write_config;
      a.write_config.clear();
    }
    if (a.method == "b-factors") {
      if (!a.file.empty())
        throw InputError({a.file, 0, ""}, "b-factors takes no FILE (it samples eq. 6 and 10)");
    } else if (a.file.empty()) {
      throw InputError("identify " + a.method + " needs a measurement FILE (docs/rheology.md)");
    }
    if (!a.static_file.empty() && a.method != "free-vibration")
      throw InputError({"--static", 0, ""}, "--static is only used by free-vibration");
    check_into_config_use(a);
    std::optional<IntoConfig> into;
    if (!a.into_config.empty()) into = IntoConfig{contact::load_tyre_config(a.into_config), {}};
    IntoConfig* ic = into ? &*into : nullptr;
    const Geometry g = resolve_geometry(a);
    nlohmann::json out;
    if (a.method == "load-deflection")
      out = run_load_deflection(a, g, ic);
    else if (a.method == "b-factors")
      out = run_b_factors(a);
    else if (a.method == "contact-stress")
      out = run_contact_stress(a, g, ic);
    else if (a.method == "free-vibration")
      out = run_free_vibration(a, g, ic);
    else
      out = run_soil(a, g, ic);
    if (!a.file.empty()) out["file"] = a.file;
    check_finite(out);
    if (!a.write_config.empty()) write_rheology_yaml(a, out);
    if (into) {
      for (auto it = out["parameters"].begin(); it != out["parameters"].end(); ++it)
        into->mapping.notes.push_back("identified " + it.key() + " = " +
                                      number_text(it.value()["value"].get<double>()) + " " +
                                      it.value()["unit"].get<std::string>() + " (standard error " +
                                      number_text(it.value()["std_error"].get<double>()) + ")");
      write_into_config(a, into->tyre, into->mapping);
      out["into_config"] = mapping_json(a, into->mapping);
    }
    if (a.json) {
      print_json(out);
    } else {
      rh::FitReport r;
      r.method = out["method"];
      r.rows = out["rows"];
      r.residual_rms = out["residual_rms"];
      r.residual_unit = out["residual_unit"];
      for (auto it = out["parameters"].begin(); it != out["parameters"].end(); ++it)
        r.parameters.push_back(
            {it.key(), it.value()["value"], it.value()["unit"], it.value()["std_error"]});
      for (const auto& n : out["notes"]) r.notes.push_back(n);
      if (out.contains("pressure_unit"))
        r.notes.push_back(std::string("p_W in (1 + p_W) is gauge pressure in ") +
                          out["pressure_unit"].get<std::string>());
      print_report(r, a.file);
      if (into) {
        std::cout << "\naugmented tyre config: " << a.out_config << " (from " << a.into_config
                  << ")\n";
        for (const auto& n : into->mapping.notes) std::cout << "  " << n << "\n";
      }
    }
  });
}

}  // namespace modaltyre::app
