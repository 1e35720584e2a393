// modaltyre identify METHOD [FILE] [options] [--json] [--plot FILE] [--write-config FILE]
//                   [--into-config TYRE.yaml --out-config OUT.yaml]
// Rheological parameters from simple tyre and soil tests (seed 000); with --into-config the
// parameters the footprint model uses are written into a copy of the tyre config as effects
// (the mapping is the library's: studies/identified_config.h).
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <variant>

#include "cli_support.h"
#include "commands.h"
#include "identify_output.h"
#include "identify_soil_plots.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/report/identified_ground.h"
#include "modaltyre/report/identify_run.h"
#include "modaltyre/studies/identified_config.h"

namespace modaltyre::app {
namespace {

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
  std::string into_config, out_config;    ///< --into-config TYRE.yaml --out-config OUT.yaml
  std::string write_ground, into_ground;  ///< --write-ground OUT.yaml [--into-ground BASE.yaml]
  int samples = 6;
  std::string sampling = "deflection";
  bool intercept = false;
  double max_h_r0 = 0.117;
};

// The library's inputs of the fit (report/identify_run.h) from the options.
report::IdentifyInputs inputs_of(const IdentifyArgs& a) {
  report::IdentifyInputs in;
  in.method = a.method;
  in.file = a.file;
  // --config, else the --into-config target, which is the same tyre (so that --config X
  // --write-config F and --into-config X --out-config F fit with the same r0, B_tr and pressure).
  in.geometry_config =
      report::identify_geometry_config(a.method, a.config.empty() ? a.into_config : a.config);
  in.r0_mm = a.r0_mm;
  in.tread_width_mm = a.tread_width_mm;
  in.mass_kg = a.mass_kg;
  in.contact_length_mm = a.contact_length_mm;
  in.section_height_mm = a.section_height_mm;
  in.pressure_kPa = a.pressure_kPa;
  in.static_file = a.static_file;
  in.samples = a.samples;
  in.sampling = a.sampling;
  in.intercept = a.intercept;
  in.max_h_r0 = a.max_h_r0;
  return in;
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
}

// --write-ground / --into-ground take the soil tests only, and --into-ground names the file the
// identified keys go into, written to --write-ground (never over it).
void check_ground_file_use(const IdentifyArgs& a) {
  if (a.write_ground.empty() && a.into_ground.empty()) return;
  if (a.method != "bevameter" && a.method != "shear")
    throw InputError(
        {a.write_ground.empty() ? "--into-ground" : "--write-ground", 0, ""},
        "a soil file takes the soil tests: identify bevameter or shear (not " + a.method + ")");
  if (a.write_ground.empty())
    throw InputError({"--into-ground", 0, ""},
                     "--into-ground " + a.into_ground +
                         " needs --write-ground OUT.yaml, the soil file to write");
  if (!a.into_config.empty() || !a.write_config.empty())
    throw InputError({"--write-ground", 0, ""},
                     "write the soil into a soil file (--write-ground) or into a tyre config "
                     "(--into-config / --write-config), not both at once");
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

// Maps the fit into the tyre config (when given) and draws it (when asked).
void map_and_draw(const IdentifyArgs& a, const report::IdentifyRun& run, Target& into) {
  if (const auto* r = std::get_if<report::LoadDeflectionRun>(&run.fit)) {
    if (into) studies::map_load_deflection(source_of(a), r->data, r->result, *into);
    if (!a.plot.empty()) plot_load_deflection(r->data, r->result, a.plot);
  } else if (const auto* r = std::get_if<report::SlopeFactorRun>(&run.fit)) {
    if (!a.plot.empty()) plot_b_factors(r->result, a.plot);
  } else if (const auto* r = std::get_if<report::ContactStressRun>(&run.fit)) {
    if (into) studies::map_contact_stress(source_of(a), r->result, r->options.r0_m, *into);
    if (!a.plot.empty()) plot_contact_stress(r->data, r->result, r->options.r0_m, a.plot);
  } else if (const auto* r = std::get_if<report::FreeVibrationRun>(&run.fit)) {
    // --into-config needs --static here (check_into_config_use), so the loop is there.
    if (into) studies::map_three_element(r->result, *r->loop, r->options, *into);
    const rheology::StaticLoop* loop = r->loop ? &*r->loop : nullptr;
    if (!a.plot.empty()) plot_free_vibration(r->signal, loop, r->result, r->options, a.plot);
  } else if (const auto* r = std::get_if<report::SoilRun>(&run.fit)) {
    if (into) studies::map_soil(r->data, r->result, *into);
    if (!a.plot.empty()) plot_soil(r->data, r->result, a.plot);
  } else if (const auto* r = std::get_if<report::BevameterRun>(&run.fit)) {
    if (into) studies::map_bevameter(r->result, *into);
    if (!a.plot.empty()) plot_bevameter(r->data, r->result, a.plot);
  } else if (const auto* r = std::get_if<report::ShearRun>(&run.fit)) {
    if (into) studies::map_shear(r->result, *into);
    if (!a.plot.empty()) plot_shear(r->data, r->result, a.plot);
  }
}

}  // namespace

void register_identify(CLI::App& app) {
  auto args = std::make_shared<IdentifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "identify",
      "Identify rheological parameters from tyre and soil tests (seed 000): K_Z and C_P from "
      "load-deflection data, the slope factors B1 and B2, K1 and C_P from a contact-stress "
      "profile, the three-element model (eta1 from a free decay, E1 and chi from a static loop) "
      "and a Kelvin-Voigt soil from rolling tests; Bekker-Wong soil parameters from plate-sinkage "
      "tests and Janosi-Hanamoto shear parameters from shear tests. Formats and derivations: "
      "docs/rheology.md, docs/soil.md.");
  cmd->add_option("METHOD", args->method,
                  "load-deflection | b-factors | contact-stress | free-vibration | soil-rolling | "
                  "bevameter | shear")
      ->required()
      ->check(CLI::IsMember({"load-deflection", "b-factors", "contact-stress", "free-vibration",
                             "soil-rolling", "bevameter", "shear"}));
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
  cmd->add_option("--write-ground", args->write_ground,
                  "bevameter | shear: write a soil file (YAML, ground: section) that --ground "
                  "reads (a shear test needs --into-ground: it has no pressure-sinkage law)");
  cmd->add_option("--into-ground", args->into_ground,
                  "a soil file to set the identified keys into (its comments kept), written to "
                  "--write-ground: both soil tests in one file");
  cmd->callback([args, cmd] {
    IdentifyArgs a = *args;
    const bool plot_given = cmd->count("--plot") > 0;
    const bool write_config_given = cmd->count("--write-config") > 0;
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
    const report::IdentifyInputs inputs = inputs_of(a);
    report::check_identify_inputs(inputs);
    check_into_config_use(a);
    check_ground_file_use(a);
    Target into;  // read before any fitting: a bad tyre config fails fast
    if (!a.into_config.empty())
      into = studies::ConfigTarget{
          a.into_config, a.out_config, contact::load_tyre_config(a.into_config), {}};
    CommandFiles files;  // no output over a measurement, a tyre config or another output
    files.input(a.file, "FILE");
    files.input(a.static_file, "--static");
    files.input(a.config, "--config");
    if (into) report::add_config_inputs(files, into->tyre, "--into-config");
    if (plot_given) files.output(a.plot, "--plot");
    if (write_config_given && !tyre_config_out) files.output(a.write_config, "--write-config");
    if (!a.out_config.empty())
      files.output(a.out_config, tyre_config_out ? "--write-config" : "--out-config");
    files.input(a.into_ground, "--into-ground");
    if (!a.write_ground.empty()) files.output(a.write_ground, "--write-ground");
    files.check();
    const report::IdentifyRun run = report::run_identify(inputs);
    map_and_draw(a, run, into);
    nlohmann::json out = run.document;
    check_finite(out);
    if (!a.write_config.empty())
      write_rheology_record(a.write_config, {a.method, a.file, a.config}, out);
    std::optional<report::IdentifiedGround> soil_file;
    if (!a.write_ground.empty()) {
      soil_file = report::identified_ground_file(run, a.file, a.into_ground, a.write_ground);
      write_file_atomically(a.write_ground, soil_file->text);
      out["ground_file"] = {
          {"path", a.write_ground},
          {"into", a.into_ground.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.into_ground)},
          {"notes", soil_file->notes}};
    }
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
    if (soil_file) {
      std::cout << "\nsoil file: " << a.write_ground
                << (a.into_ground.empty() ? "" : " (from " + a.into_ground + ")") << "\n";
      for (const auto& n : soil_file->notes) std::cout << "  " << n << "\n";
    }
    if (into) {
      std::cout << "\naugmented tyre config: " << a.out_config << " (from " << a.into_config
                << ")\n";
      for (const auto& n : written->notes) std::cout << "  " << n << "\n";
    }
  });
}

}  // namespace modaltyre::app
