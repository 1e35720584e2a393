#include "modaltyre/report/identify_run.h"

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/rheology/contact_geometry.h"

namespace modaltyre::report {
namespace {

namespace rh = modaltyre::rheology;

// Geometry in SI from the inputs, falling back to the tyre config (read directly: rheology
// does not depend on contact/). 0 = not given.
struct Geometry {
  double r0_m = 0, tread_width_m = 0, pressure_Pa = -1;
};

Geometry resolve_geometry(const IdentifyInputs& a) {
  Geometry g;
  if (!a.geometry_config.empty()) {
    const ConfigTree tree = ConfigTree::load(a.geometry_config);
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

IdentifyRun load_deflection(const IdentifyInputs& a, const Geometry& g) {
  LoadDeflectionRun run{rh::read_load_deflection_csv(a.file), {}};
  rh::LoadDeflectionOptions o;
  o.r0_m = g.r0_m;
  o.reference_pressure_Pa = g.pressure_Pa;
  run.result = rh::identify_load_deflection(run.data, o);
  nlohmann::json out = fit_report_json(run.result.report);
  out["pressure_unit"] = rh::kPressureUnitName;
  out["reference_pressure_kPa"] = round_sig(run.result.reference_pressure_Pa * 1e-3);
  out["law"] = "h_Z[mm] = K_Z P_Z[N]^(3/4) / (1 + p_W[bar, gauge])";
  return {std::move(run), out};
}

IdentifyRun b_factors(const IdentifyInputs& a) {
  rh::SlopeFactorOptions o;
  o.samples = a.samples;
  o.max_relative_deflection = a.max_h_r0;
  o.through_origin = !a.intercept;
  o.sampling = a.sampling == "angle" ? rh::SlopeSampling::uniform_angle
                                     : rh::SlopeSampling::uniform_deflection;
  SlopeFactorRun run{rh::compute_slope_factors(o)};
  nlohmann::json out = fit_report_json(run.result.report);
  out["seed"] = {{"B1", rh::kSeedB1}, {"B2", rh::kSeedB2}, {"R", 0.995}};
  return {std::move(run), out};
}

IdentifyRun contact_stress(const IdentifyInputs& a, const Geometry& g) {
  ContactStressRun run{rh::read_contact_stress_csv(a.file), {}, {}};
  run.options.r0_m = g.r0_m;
  run.options.tread_width_m = g.tread_width_m;
  run.options.contact_length_m =
      positive_or_zero(a.contact_length_mm, "--contact-length-mm") * 1e-3;
  run.result = rh::identify_contact_stress(run.data, run.options);
  nlohmann::json out = fit_report_json(run.result.report);
  out["pressure_unit"] = rh::kPressureUnitName;
  return {std::move(run), out};
}

IdentifyRun free_vibration(const IdentifyInputs& a, const Geometry& g) {
  FreeVibrationRun run{rh::read_free_vibration_csv(a.file), {}, {}, {}};
  auto& o = run.options;
  o.r0_m = g.r0_m;
  o.tread_width_m = g.tread_width_m;
  o.mass_kg = positive_or_zero(a.mass_kg, "--mass-kg");
  o.contact_length_m = positive_or_zero(a.contact_length_mm, "--contact-length-mm") * 1e-3;
  o.section_height_m = positive_or_zero(a.section_height_mm, "--section-height-mm") * 1e-3;
  if (!a.static_file.empty()) run.loop = rh::read_static_loop_csv(a.static_file);
  run.result = rh::identify_free_vibration(run.signal, run.loop ? &*run.loop : nullptr, o);
  nlohmann::json out = fit_report_json(run.result.report);
  nlohmann::json amps = nlohmann::json::array();
  const auto& d = run.result.decay;
  for (std::size_t i = 0; i < d.amplitude_m.size(); ++i)
    amps.push_back({{"t_s", round_sig(d.extremum_t_s[i])},
                    {"amplitude_mm", round_sig(d.amplitude_m[i] * 1e3, 6)}});
  out["amplitudes"] = amps;
  return {std::move(run), out};
}

IdentifyRun soil(const IdentifyInputs& a, const Geometry& g) {
  SoilRun run{rh::read_soil_rolling_csv(a.file), {}};
  run.result = rh::identify_soil(run.data, rh::SoilOptions{g.r0_m, g.tread_width_m});
  nlohmann::json out = fit_report_json(run.result.report);
  return {std::move(run), out};
}

IdentifyRun bevameter(const IdentifyInputs& a) {
  BevameterRun run{rh::read_plate_sinkage_csv(a.file), {}};
  run.result = rh::identify_bevameter(run.data);
  nlohmann::json out = fit_report_json(run.result.report);
  out["law"] = "p[kPa] = (k_c/b + k_phi) z[m]^n; unloading p = p_max - (k0 + Au z_max)(z_max - z)";
  const bool circular = run.data.shape == rh::PlateShape::circular;
  out["plate_shape"] = circular ? "circular" : "rectangular";
  out["bekker_b"] = circular ? "the plate's radius" : "the plate's width";
  out["warnings"] = run.result.warnings;
  return {std::move(run), out};
}

IdentifyRun shear(const IdentifyInputs& a) {
  ShearRun run{rh::read_shear_csv(a.file), {}};
  run.result = rh::identify_shear(run.data);
  nlohmann::json out = fit_report_json(run.result.report);
  out["law"] = "tau = (c + sigma tan phi)(1 - exp(-j/K))";
  return {std::move(run), out};
}

}  // namespace

std::string identify_geometry_config(const std::string& method, const std::string& config) {
  const bool tests_the_tyre =
      method == "load-deflection" || method == "contact-stress" || method == "free-vibration";
  return tests_the_tyre ? config : "";
}

nlohmann::json fit_report_json(const rh::FitReport& r) {
  nlohmann::json params = nlohmann::json::object();
  for (const auto& p : r.parameters)
    // std_error 0 is a value computed in closed form from as many data as unknowns (no
    // redundancy, no error estimate), not an exact one: said so (issue 38).
    params[p.name] = {{"value", round_sig(p.value)},
                      {"unit", p.unit},
                      {"std_error", round_sig(p.std_error, 6)},
                      {"closed_form", p.std_error == 0}};
  return {{"method", r.method},
          {"parameters", params},
          {"residual_rms", round_sig(r.residual_rms, 6)},
          {"residual_unit", r.residual_unit},
          {"rows", r.rows},
          {"notes", r.notes}};
}

void check_identify_inputs(const IdentifyInputs& a) {
  const bool known = a.method == "load-deflection" || a.method == "b-factors" ||
                     a.method == "contact-stress" || a.method == "free-vibration" ||
                     a.method == "soil-rolling" || a.method == "bevameter" || a.method == "shear";
  if (!known) {
    throw InputError({"METHOD", 0, ""},
                     "'" + a.method +
                         "' is not one of load-deflection, b-factors, contact-stress, "
                         "free-vibration, soil-rolling, bevameter, shear");
  }
  if (a.method == "b-factors") {
    if (!a.file.empty())
      throw InputError({a.file, 0, ""}, "b-factors takes no FILE (it samples eq. 6 and 10)");
  } else if (a.file.empty()) {
    throw InputError("identify " + a.method + " needs a measurement FILE (docs/rheology.md)");
  }
  if (!a.static_file.empty() && a.method != "free-vibration")
    throw InputError({"--static", 0, ""}, "--static is only used by free-vibration");
  if (a.sampling != "deflection" && a.sampling != "angle")
    throw InputError({"--sampling", 0, ""}, "must be 'deflection' or 'angle'");
  // The ranges of the command's options (README, "Input ranges"), for callers without them;
  // -1 is "not given".
  const struct {
    double value, hi;
    const char* name;
    bool zero_allowed;
  } ranges[] = {{a.r0_mm, 5000, "--r0-mm", false},
                {a.tread_width_mm, 5000, "--tread-width-mm", false},
                {a.mass_kg, 1e5, "--mass-kg", false},
                {a.contact_length_mm, 1e4, "--contact-length-mm", false},
                {a.section_height_mm, 5000, "--section-height-mm", false},
                {a.pressure_kPa, 1e4, "--pressure-kPa", true}};
  for (const auto& r : ranges) {
    if (r.value == -1) continue;
    const bool low_ok = r.zero_allowed ? r.value >= 0 : r.value > 0;
    if (!(low_ok && r.value <= r.hi)) {
      throw InputError({r.name, 0, ""}, "must be in " + std::string(r.zero_allowed ? "[" : "(") +
                                            "0, " + number_text(r.hi) + "]");
    }
  }
}

IdentifyRun run_identify(const IdentifyInputs& a) {
  check_identify_inputs(a);
  const Geometry g = resolve_geometry(a);
  IdentifyRun run;
  if (a.method == "load-deflection")
    run = load_deflection(a, g);
  else if (a.method == "b-factors")
    run = b_factors(a);
  else if (a.method == "contact-stress")
    run = contact_stress(a, g);
  else if (a.method == "free-vibration")
    run = free_vibration(a, g);
  else if (a.method == "bevameter")
    run = bevameter(a);
  else if (a.method == "shear")
    run = shear(a);
  else
    run = soil(a, g);
  if (!a.file.empty()) run.document["file"] = a.file;
  return run;
}

}  // namespace modaltyre::report
