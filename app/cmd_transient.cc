// modaltyre transient CONFIG --scenario NAME [--ground SOIL.yaml] [--csv FILE] [--json]
//                     [--plot FILE] [--set k=v]...
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/report/condition_settings.h"
#include "modaltyre/report/transient_json.h"
#include "modaltyre/transient/transient.h"
#include "transient_bands.h"

namespace modaltyre::app {

using report::settings_json;
using report::settings_text;
using report::take_condition_settings;
namespace {

struct TransientArgs {
  std::string config;
  std::string scenario;
  std::string csv;
  std::string plot;
  bool json = false;
  bool uncertainty = false;
  UncertaintyMethodArgs method;
  std::vector<std::string> overrides;
  std::vector<double> map_times;
  std::string map_csv;
  std::string ground;
};

// The 3D patch's contact maps at the chosen times: time_s,x_mm,y_mm,pressure_kPa, one row per
// cell (sections in contact and two either side, every column).
std::string map_csv(const transient::TransientResult& r) {
  std::ostringstream o;
  o.precision(10);
  o << "time_s,x_mm,y_mm,pressure_kPa\n";
  for (const auto& m : r.maps)
    for (std::size_t k = 0; k < m.x_mm.size(); ++k)
      o << m.t_s << ',' << m.x_mm[k] << ',' << m.y_mm[k] << ',' << m.pressure_kPa[k] << '\n';
  return o.str();
}

// The CSV of the series report::transient_series gives (one line per sample, 10 digits).
std::string transient_csv(const transient::TransientResult& r) {
  const auto cols = report::transient_series(r);
  std::ostringstream o;
  o.precision(10);
  for (std::size_t c = 0; c < cols.size(); ++c) o << (c ? "," : "") << cols[c].first;
  o << '\n';
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    for (std::size_t c = 0; c < cols.size(); ++c) o << (c ? "," : "") << cols[c].second[i];
    o << '\n';
  }
  return o.str();
}

void transient_plot(const transient::TransientResult& r, const std::string& path) {
  PlotSeries load{"contact load", {}, {}}, sink{"sinking", {}, {}}, len{"contact length", {}, {}},
      fx{"longitudinal force", {}, {}};
  for (const auto& s : r.samples) {
    load.x.push_back(s.t_s), load.y.push_back(s.load_N);
    sink.x.push_back(s.t_s), sink.y.push_back(s.sinking_m * 1e3);
    len.x.push_back(s.t_s), len.y.push_back(s.contact_length_m * 1e3);
    fx.x.push_back(s.t_s), fx.y.push_back(s.longitudinal_force_N);
  }
  PlotFigure fig;
  fig.width_px = 1200;
  fig.height_px = 800;
  const std::string sc = transient::to_string(r.scenario);
  fig.panels.push_back({sc + ": vertical load", "t [s]", "load [N]", {load}});
  fig.panels.push_back({sc + ": sinking", "t [s]", "sinking [mm]", {sink}});
  fig.panels.push_back({sc + ": contact length", "t [s]", "length [mm]", {len}});
  fig.panels.push_back({sc + ": longitudinal force", "t [s]", "F_x [N]", {fx}});
  // Each panel spans at least 1 % of its signal's scale (forces: the largest vertical load):
  // a constant with solver noise, such as F_x = +-1e-11 N while the load is held, is drawn
  // flat instead of being auto-scaled into a signal.
  auto largest = [](const PlotSeries& s) {
    double m = 0;
    for (double y : s.y) m = std::max(m, std::abs(y));
    return m;
  };
  const double force_scale = largest(load);
  std::vector<double> scales = {force_scale, largest(sink), largest(len), force_scale};
  if (r.patch_3d) {  // the 3D patch: the contact width too
    PlotSeries wid{"contact width", {}, {}};
    for (const auto& s : r.samples) wid.x.push_back(s.t_s), wid.y.push_back(s.width_m * 1e3);
    scales.push_back(largest(wid));
    fig.panels.push_back({sc + ": contact width", "t [s]", "width [mm]", {wid}});
    fig.height_px = 1000;
  }
  for (std::size_t i = 0; i < fig.panels.size(); ++i) {
    ensure_min_y_span(fig.panels[i], 0.01 * scales[i]);
  }
  render_plot(fig, path);
}

}  // namespace

void register_transient(CLI::App& app) {
  auto a = std::make_shared<TransientArgs>();
  CLI::App* cmd = app.add_subcommand(
      "transient",
      "Time-domain simulation (CVODE BDF + KLU): modal carcass, Kelvin-Voigt tread relaxation, "
      "hub mass, unilateral contact. Scenarios: load-hold, free-vibration, rolling, cleat "
      "(settings in the config's transient: section, see docs/transient.md).");
  cmd->add_option(
         "CONFIG", a->config,
         "tyre config (YAML): the 3D patch with footprint_3d: (configs/sf350.yaml), else the 2D "
         "patch (configs/sf350_2d_table3.yaml, the fast variant)")
      ->required();
  cmd->add_option("--scenario", a->scenario, "load-hold | free-vibration | rolling | cleat")
      ->required();
  cmd->add_option("--csv", a->csv,
                  "write the time series (t_s,load_N,hub_displacement_mm,sinking_mm,"
                  "contact_length_mm,longitudinal_force_N)");
  cmd->add_flag("--json", a->json, "print a JSON summary");
  cmd->add_option("--ground", a->ground,
                  "soil file (YAML with a ground: section, e.g. configs/soils/lete_sand.yaml; "
                  "--set ground.KEY=... then goes to it): the tyre (3D patch or 2D) onto that "
                  "soil (docs/soil.md section 8); default: the config's ground: section");
  cmd->add_option("--map-times", a->map_times,
                  "3D patch: times [s] of the contact maps, e.g. --map-times 0.1,0.2")
      ->delimiter(',');
  cmd->add_option("--map-csv", a->map_csv,
                  "3D patch: write the contact maps (time_s,x_mm,y_mm,pressure_kPa)");
  cmd->add_option("--plot", a->plot, "draw the time series (.svg or .png)");
  cmd->add_flag("--uncertainty", a->uncertainty,
                "propagate the inputs' uncertainty (the hammer shapes' noise, stated std) to the "
                "run's summary by re-running the scenario (docs/uncertainty.md section 8)");
  add_uncertainty_method_options(cmd, a->method);
  cmd->add_option("--set", a->overrides,
                  "override a config key, e.g. --set transient.load_hold.hold_s=10, or state a "
                  "condition of the scenario: load_N; hold_s (load-hold); speed_kmh (rolling, "
                  "cleat), e.g. --set hold_s=60");
  cmd->callback([a, cmd] {
    const transient::Scenario scenario = transient::parse_scenario(a->scenario);
    auto overrides = a->overrides;
    const auto settings = take_condition_settings(overrides);
    report::map_transient_conditions(settings, scenario, overrides);
    refuse_repeated_overrides(overrides);  // e.g. hold_s=60 and transient.load_hold.hold_s=10
    // With --ground, the ground.* overrides go to the soil file, the rest to the tyre config.
    std::vector<std::string> tyre_overrides, ground_overrides;
    for (const auto& o : overrides)
      (!a->ground.empty() && o.rfind("ground.", 0) == 0 ? ground_overrides : tyre_overrides)
          .push_back(o);
    auto config = contact::load_tyre_config(a->config, tyre_overrides);
    if (!a->ground.empty()) {
      config.ground = ground::load_ground_file(a->ground, ground_overrides);
      if (!config.ground.soil())
        throw InputError({a->ground, 0, "ground.model"},
                         "--ground takes a soil (model bekker or kelvin_voigt); a road is the "
                         "config's ground: section");
      if (config.effects.soil_compliance.enabled)
        throw InputError({a->config, 0, "effects.soil_compliance"},
                         "the soil_compliance effect is a soil of its own: with --ground "
                         "switch it off");
    }
    CommandFiles files;  // before the run: no output over the config or another output
    report::add_config_inputs(files, config);
    files.input(a->ground, "--ground");
    if (cmd->count("--csv")) files.output(a->csv, "--csv");
    if (cmd->count("--plot")) files.output(a->plot, "--plot");
    if (cmd->count("--map-csv")) files.output(a->map_csv, "--map-csv");
    files.check();
    const auto tyre = contact::build_tyre_model(config);
    const auto model = transient::build_transient_model(tyre);

    // Progress bar on a terminal only, once the run has taken more than a second.
    const bool tty = isatty(fileno(stderr)) != 0;
    const auto start = std::chrono::steady_clock::now();
    bool drawn = false;
    transient::TransientRunOptions opts;
    opts.progress = [&](double t, double total) {
      if (!tty) return true;
      const double el =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (el < 1.0) return true;
      const int width = 40;
      const int done = static_cast<int>(width * t / total);
      std::fprintf(stderr, "\r[%s%s] %5.1f%%  t = %.3f / %.3f s", std::string(done, '#').c_str(),
                   std::string(width - done, ' ').c_str(), 100 * t / total, t, total);
      drawn = true;
      return true;
    };
    opts.map_times_s = a->map_times;
    if (!a->map_times.empty() && a->map_csv.empty())
      throw InputError({"--map-times", 0, ""}, "needs --map-csv FILE to write the maps to");
    if (!a->map_csv.empty() && a->map_times.empty())
      throw InputError({"--map-csv", 0, ""}, "needs --map-times T1,T2,... (s)");
    const transient::TransientResult r = transient::run_scenario(model, scenario, opts);
    if (drawn) std::fprintf(stderr, "\n");
    if (!r.ok()) throw ComputationError(r.message);
    std::optional<TransientBands> bands;
    if (a->uncertainty) {
      uncertainty::PropagationOptions uo = a->method.options();
      UncertaintyProgress bar;
      uo.progress = bar.callback();
      bands = transient_bands(config, scenario, r, uo);
      bar.finish();
    }

    if (!a->csv.empty()) write_file_atomically(a->csv, transient_csv(r));
    if (!a->plot.empty()) transient_plot(r, a->plot);
    if (!a->map_csv.empty()) write_file_atomically(a->map_csv, map_csv(r));
    const auto& fin = r.samples.back();
    if (a->json) {
      auto j = report::transient_json(model, r);
      j["conditions"] = settings_json(settings);
      if (bands) add_transient_bands_json(j, *bands);
      print_json(j);
    } else {
      std::cout << "scenario " << transient::to_string(scenario) << ": " << r.message << "\n";
      if (!settings.empty()) std::cout << "conditions: " << settings_text(settings) << "\n";
      std::cout << "simulated " << fixed(r.simulated_s, 3) << " s in " << fixed(r.wall_s, 3)
                << " s (real-time factor " << fixed(r.real_time_factor(), 1) << ")\n"
                << "final: load " << fixed(fin.load_N, 1) << " N, sinking "
                << fixed(fin.sinking_m * 1e3, 3) << " mm, contact length "
                << fixed(fin.contact_length_m * 1e3, 2) << " mm, rolling resistance "
                << fixed(r.rolling_resistance_N, 2) << " N\n";
      if (config.ground.soil())
        std::cout << "on the soil "
                  << (config.ground.name.empty() ? ground::to_string(config.ground.model)
                                                 : config.ground.name)
                  << ": soil sinkage " << fixed(fin.soil_sinkage_m * 1e3, 3)
                  << " mm (sinking is the axle's approach to the undisturbed surface)\n";
      if (bands) print_transient_bands(*bands);
    }
  });
}

}  // namespace modaltyre::app
