// modaltyre footprint CONFIG [--load N]... [--ground FILE] [--set key=value]... [--json]
//                    [--plot FILE] [--map-csv FILE]
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_support.h"
#include "commands.h"
#include "footprint_map.h"
#include "footprint_report.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/progress.h"
#include "modaltyre/report/condition_settings.h"
#include "modaltyre/report/footprint_json.h"
#include "modaltyre/report/ground_input.h"
#include "modaltyre/report/uncertainty_json.h"
#include "modaltyre/report/validation_json.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::app {

using report::take_condition_settings;
namespace {

struct FootprintArgs {
  std::string config;
  std::vector<double> loads;
  double horizontal = 0;
  bool horizontal_given = false;
  std::vector<std::string> overrides;
  bool json = false;
  std::string plot;
  std::string map_csv;
  std::string ground;
  bool uncertainty = false;
  UncertaintyMethodArgs method;
};

}  // namespace

void register_footprint(CLI::App& app) {
  auto a = std::make_shared<FootprintArgs>();
  CLI::App* cmd = app.add_subcommand(
      "footprint",
      "Static footprint on the ground (a rigid flat road unless --ground or a ground: section "
      "says otherwise): sinking, contact length and pressure distribution "
      "for each vertical load (load control, carcass and tread in series, seed 001); effects "
      "switched on in the config act at its default conditions.");
  cmd->add_option("CONFIG", a->config, "tyre config (YAML), e.g. configs/sf350.yaml")->required();
  // The ranges of the config's loads_N and horizontal_force_N (README, "Input ranges").
  cmd->add_option("--load", a->loads, "vertical load [N]; repeat for several (default: loads_N)")
      ->check(physical_range(contact::kMinLoad_N, contact::kMaxLoad_N, "N",
                             "below 1e-6 N no contact forms; 1e7 N (1000 t on one wheel) "
                             "exceeds any tyre",
                             true));
  cmd->add_option("--fx", a->horizontal, "horizontal force at the axle [N], forward positive")
      ->check(physical_range(-1e7, 1e7, "N", "1e7 N exceeds any tyre", true));
  cmd->add_option("--set", a->overrides,
                  "override a config key, e.g. --set tread.modulus_MPa=8, or state a condition "
                  "for every load: pressure_kPa, hold_s, speed_kmh, branch, surface (as in a "
                  "sweep), e.g. --set hold_s=60 --set surface=soil");
  cmd->add_option("--ground", a->ground,
                  "ground file (YAML with a ground: section: a soil, e.g. "
                  "configs/soils/lete_sand.yaml, or a road profile; --set ground.KEY=... then "
                  "goes to it); default: the config's ground: section (docs/soil.md)");
  cmd->add_flag("--json", a->json, "print JSON");
  cmd->add_option("--plot", a->plot,
                  "draw the pressure distributions (.svg or .png); with footprint_3d: the "
                  "footprint image of each load (pressure map, contour) and the centre-line "
                  "pressure");
  cmd->add_flag("--uncertainty", a->uncertainty,
                "propagate the inputs' uncertainty (the hammer shapes' noise, stated std) to a "
                "band on every output (docs/uncertainty.md)");
  add_uncertainty_method_options(cmd, a->method);
  cmd->add_option("--map-csv", a->map_csv,
                  "write the pressure maps as CSV load_N,x_mm,y_mm,pressure_kPa (footprint_3d:); "
                  "with --uncertainty also pressure_p025_kPa,pressure_p975_kPa");
  cmd->callback([a, cmd] {
    auto overrides = a->overrides;
    const auto settings = take_condition_settings(overrides);
    report::refuse_footprint_settings(settings, "--load", "--fx");
    const auto config = report::config_on_ground(a->config, a->ground, overrides);
    if (cmd->count("--map-csv") && !config.footprint_3d) {
      throw InputError({a->config, 0, "--map-csv"},
                       "a pressure map needs the 3D patch: the config has no footprint_3d: "
                       "section");
    }
    CommandFiles files;  // before anything is computed: no output over an input or another
    report::add_config_inputs(files, config);
    files.input(a->ground, "--ground");
    if (cmd->count("--plot")) files.output(a->plot, "--plot");
    if (cmd->count("--map-csv")) files.output(a->map_csv, "--map-csv");
    files.check();
    const auto model = contact::build_tyre_model(config);
    auto cases = report::footprint_cases(
        config, a->loads, cmd->count("--fx") ? std::optional<double>(a->horizontal) : std::nullopt);
    const auto shown = report::apply_to_footprint_cases(settings, config, cases);
    const auto results = contact::predict_all(model, cases);
    report::require_converged(results);
    warn_outside_validity(config, results);
    std::optional<uncertainty::PropagationResult> bands;
    std::optional<MapBands> map_bands;
    if (a->uncertainty) {
      uncertainty::PropagationOptions uo = a->method.options();
      UncertaintyProgress bar;
      uo.progress = bar.callback();
      // With a map, its cells ride along the same model evaluations (their band: two maps).
      const auto extra =
          a->map_csv.empty() ? uncertainty::ExtraOutputs{} : map_cell_outputs(results);
      bands = uncertainty::propagate(config, contact::config_modes(config), cases, uo, extra);
      bar.finish();
      if (extra.count > 0) map_bands = take_map_bands(*bands);
    }
    std::optional<nlohmann::json> j;
    if (a->json) {
      j = report::footprint_json(model, results);
      (*j)["conditions"] = report::footprint_conditions_json(shown);
      if (bands) report::add_uncertainty_json(*j, *bands);
      check_finite(*j);
    }
    // The files only once everything is computed (a failed band leaves none), the plot (which
    // can still fail in gnuplot) first.
    if (!a->plot.empty()) {
      if (config.footprint_3d) {
        plot_footprint_maps(results, config, a->plot);
      } else {
        plot_pressures(results, config, a->plot);
      }
    }
    if (!a->map_csv.empty()) write_map_csv(results, a->map_csv, map_bands ? &*map_bands : nullptr);
    if (j) {
      print_json(*j);
    } else {
      print_footprint_table(model, results, shown);
      if (bands) print_uncertainty_table(*bands);
    }
  });
}

}  // namespace modaltyre::app
