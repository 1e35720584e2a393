// modaltyre identify METHOD [FILE] [options] [--json] [--plot FILE] [--write-config FILE]
//                   [--into-config TYRE.yaml --out-config OUT.yaml]
// Rheological parameters from simple tyre and soil tests (seed 000); with --into-config the
// parameters the footprint model uses are written into a copy of the tyre config as effects
// (the mapping is the library's: studies/identified_config.h).
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_support.h"
#include "commands.h"
#include "identify_output.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/rheology/contact_geometry.h"
#include "modaltyre/studies/identified_config.h"

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

// The config the tyre geometry comes from, for the methods that test the tyre itself: --config,
// else the --into-config target, which is the same tyre (so that --config X --write-config F and
// --into-config X --out-config F fit with the same r0, B_tr and pressure). soil-rolling tests a
// rigid wheel, whose r0 and B_tr a tyre config does not hold: --r0-mm, --tread-width-mm only.
std::string geometry_config(const IdentifyArgs& a) {
  const bool tests_the_tyre =
      a.method == "load-deflection" || a.method == "contact-stress" || a.method == "free-vibration";
  if (!tests_the_tyre) return "";
  return a.config.empty() ? a.into_config : a.config;
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

// Why a tyre config has no place for what the method identifies, with what to give instead;
// empty when it has one.
std::string unmapped_reason(const IdentifyArgs& a) {
  const std::string why = studies::unmapped_reason(a.method, !a.static_file.empty());
  if (why.empty()) return why;
  if (a.method == "free-vibration") return why + ": give --static LOOP.csv";
  return why + " (without --config, --write-config FILE writes a standalone 'rheology:' record)";
}

// --write-config with a tyre config (--config) writes a tyre config the footprint model runs, the
// same as --into-config CONFIG --out-config FILE; a method that cannot feed one says what is
// missing rather than write a record that `footprint` would refuse later.
void check_write_config_use(const IdentifyArgs& a) {
  if (a.write_config.empty() || a.config.empty()) return;
  if (const std::string why = unmapped_reason(a); !why.empty())
    throw InputError({"--write-config", 0, ""},
                     "with --config, a tyre config the footprint model runs is written, but " +
                         why +
                         (a.method == "free-vibration"
                              ? " (or, for a standalone 'rheology:' record of eta1, give the "
                                "radius as --r0-mm instead of --config)"
                              : ""));
}

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
  if (const std::string why = unmapped_reason(a); !why.empty())
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

nlohmann::json mapping_json(const IdentifyArgs& a, const studies::ConfigMapping& m,
                            const studies::IdentifiedConfig& written) {
  nlohmann::json set = nlohmann::json::object();
  for (const auto& [key, value] : m.values) set[key] = value;
  return {{"tyre_config", a.into_config},
          {"out_config", a.out_config},
          {"enabled", m.enabled},
          {"set", set},
          {"notes", written.notes}};
}

// ---- methods: fit, map into the target (when given), draw -----------------------------------

using Target = std::optional<studies::ConfigTarget>;

studies::IdentifiedSource source_of(const IdentifyArgs& a) { return {a.method, a.file}; }

nlohmann::json run_load_deflection(const IdentifyArgs& a, const Geometry& g, Target& into) {
  const auto data = rh::read_load_deflection_csv(a.file);
  rh::LoadDeflectionOptions o;
  o.r0_m = g.r0_m;
  o.reference_pressure_Pa = g.pressure_Pa;
  const auto res = rh::identify_load_deflection(data, o);
  nlohmann::json out = report_json(res.report);
  out["pressure_unit"] = rh::kPressureUnitName;
  out["reference_pressure_kPa"] = round_sig(res.reference_pressure_Pa * 1e-3);
  out["law"] = "h_Z[mm] = K_Z P_Z[N]^(3/4) / (1 + p_W[bar, gauge])";
  if (into) studies::map_load_deflection(source_of(a), data, res, *into);
  if (!a.plot.empty()) plot_load_deflection(data, res, a.plot);
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
  if (!a.plot.empty()) plot_b_factors(res, a.plot);
  return out;
}

nlohmann::json run_contact_stress(const IdentifyArgs& a, const Geometry& g, Target& into) {
  const auto data = rh::read_contact_stress_csv(a.file);
  rh::ContactStressOptions o;
  o.r0_m = g.r0_m;
  o.tread_width_m = g.tread_width_m;
  o.contact_length_m = positive_or_zero(a.contact_length_mm, "--contact-length-mm") * 1e-3;
  const auto res = rh::identify_contact_stress(data, o);
  if (into) studies::map_contact_stress(source_of(a), res, o.r0_m, *into);
  nlohmann::json out = report_json(res.report);
  out["pressure_unit"] = rh::kPressureUnitName;
  if (!a.plot.empty()) plot_contact_stress(data, res, o.r0_m, a.plot);
  return out;
}

nlohmann::json run_free_vibration(const IdentifyArgs& a, const Geometry& g, Target& into) {
  const auto signal = rh::read_free_vibration_csv(a.file);
  rh::ThreeElementOptions o;
  o.r0_m = g.r0_m;
  o.tread_width_m = g.tread_width_m;
  o.mass_kg = positive_or_zero(a.mass_kg, "--mass-kg");
  o.contact_length_m = positive_or_zero(a.contact_length_mm, "--contact-length-mm") * 1e-3;
  o.section_height_m = positive_or_zero(a.section_height_mm, "--section-height-mm") * 1e-3;
  std::optional<rh::StaticLoop> loop;
  if (!a.static_file.empty()) loop = rh::read_static_loop_csv(a.static_file);
  const auto res = rh::identify_free_vibration(signal, loop ? &*loop : nullptr, o);
  if (into) studies::map_three_element(res, *loop, o, *into);  // --static: check_into_config_use
  nlohmann::json out = report_json(res.report);
  nlohmann::json amps = nlohmann::json::array();
  for (std::size_t i = 0; i < res.decay.amplitude_m.size(); ++i)
    amps.push_back({{"t_s", round_sig(res.decay.extremum_t_s[i])},
                    {"amplitude_mm", round_sig(res.decay.amplitude_m[i] * 1e3, 6)}});
  out["amplitudes"] = amps;
  if (!a.plot.empty()) plot_free_vibration(signal, loop ? &*loop : nullptr, res, o, a.plot);
  return out;
}

nlohmann::json run_soil(const IdentifyArgs& a, const Geometry& g, Target& into) {
  const auto data = rh::read_soil_rolling_csv(a.file);
  rh::SoilOptions o{g.r0_m, g.tread_width_m};
  const auto res = rh::identify_soil(data, o);
  if (into) studies::map_soil(data, res, *into);
  nlohmann::json out = report_json(res.report);
  if (!a.plot.empty()) plot_soil(data, res, a.plot);
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
    check_write_config_use(a);
    const bool tyre_config_out = !a.write_config.empty() && a.into_config.empty() &&
                                 a.out_config.empty() && !a.config.empty();
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
    Target into;  // read before any fitting: a bad tyre config fails fast
    if (!a.into_config.empty())
      into = studies::ConfigTarget{
          a.into_config, a.out_config, contact::load_tyre_config(a.into_config), {}};
    const Geometry g = resolve_geometry(a);
    nlohmann::json out;
    if (a.method == "load-deflection")
      out = run_load_deflection(a, g, into);
    else if (a.method == "b-factors")
      out = run_b_factors(a);
    else if (a.method == "contact-stress")
      out = run_contact_stress(a, g, into);
    else if (a.method == "free-vibration")
      out = run_free_vibration(a, g, into);
    else
      out = run_soil(a, g, into);
    if (!a.file.empty()) out["file"] = a.file;
    check_finite(out);
    if (!a.write_config.empty())
      write_rheology_record(a.write_config, {a.method, a.file, a.config}, out);
    std::optional<studies::IdentifiedConfig> written;
    if (into) {
      written = studies::compose_identified_config(source_of(a), *into);
      write_file_atomically(a.out_config, written->text);
      out["into_config"] = mapping_json(a, into->mapping, *written);
    }
    if (a.json) {
      print_json(out);
      return;
    }
    print_report(out, a.file);
    if (into) {
      std::cout << "\naugmented tyre config: " << a.out_config << " (from " << a.into_config
                << ")\n";
      for (const auto& n : written->notes) std::cout << "  " << n << "\n";
    }
  });
}

}  // namespace modaltyre::app
