// modaltyre transient CONFIG --scenario NAME [--ground SOIL.yaml] [--csv FILE] [--json]
//                     [--plot FILE] [--set k=v]...
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
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
#include "modaltyre/transient/decay.h"
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

// The scenario's conditions for the plot's title, e.g. "SF-350, cleat 10 x 20 mm at 30 km/h,
// 4000 N".
std::string scenario_title(const contact::TyreConfig& config, transient::Scenario scenario) {
  using transient::Scenario;
  const contact::TransientSettings& T = config.transient;
  std::ostringstream o;
  o << (config.name.empty() ? std::string("tyre") : config.name) << ", "
    << transient::to_string(scenario);
  switch (scenario) {
    case Scenario::load_hold:
      o << " " << fixed(T.load_hold.load_N, 0) << " N for " << fixed(T.load_hold.hold_s, 1) << " s";
      break;
    case Scenario::free_vibration:
      o << " " << fixed(T.free_vibration.initial_load_N, 0) << " -> "
        << fixed(T.free_vibration.load_N, 0) << " N";
      break;
    case Scenario::rolling:
      o << " " << fixed(T.rolling.load_N, 0) << " N at " << fixed(T.rolling.speed_m_s * 3.6, 1)
        << " km/h";
      break;
    case Scenario::cleat:
      o << " " << fixed(T.cleat.height_m * 1e3, 1) << " x " << fixed(T.cleat.length_m * 1e3, 1)
        << " mm, " << fixed(T.cleat.load_N, 0) << " N at " << fixed(T.cleat.speed_m_s * 3.6, 1)
        << " km/h";
      break;
  }
  if (config.ground.soil())
    o << ", on "
      << (config.ground.name.empty() ? ground::to_string(config.ground.model) : config.ground.name);
  return o.str();
}

// The time series, one panel per signal that varies; a signal that stays within 0.5 % of its
// scale over the run (a constant width while rolling, F_x = 0 while the load is held) is named
// with its value in the first panel's title instead of drawn as a panel of its own (issue 44:
// dead panels, and axes zoomed until a constant looked like a signal). The load and F_x panels
// mark the extremes over the integrator's steps (the grid may pass between them).
void transient_plot(const transient::TransientResult& r, const std::string& title,
                    const std::string& path) {
  struct Signal {
    std::string name, unit, label;
    double scale_factor;
    std::function<double(const transient::TransientSample&)> get;
  };
  std::vector<Signal> signals = {
      {"vertical load", "N", "load [N]", 1, [](const auto& s) { return s.load_N; }},
      {"sinking", "mm", "sinking [mm]", 1, [](const auto& s) { return s.sinking_m * 1e3; }},
      {"contact length", "mm", "length [mm]", 1,
       [](const auto& s) { return s.contact_length_m * 1e3; }},
      {"longitudinal force", "N", "F_x [N]", 0,
       [](const auto& s) { return s.longitudinal_force_N; }}};
  if (r.patch_3d)
    signals.push_back(
        {"contact width", "mm", "width [mm]", 1, [](const auto& s) { return s.width_m * 1e3; }});
  if (r.on_soil)
    signals.push_back({"soil sinkage", "mm", "soil sinkage [mm]", 1,
                       [](const auto& s) { return s.soil_sinkage_m * 1e3; }});
  double largest_load = 0;
  for (const auto& s : r.samples) largest_load = std::max(largest_load, std::abs(s.load_N));
  PlotFigure fig;
  fig.width_px = 1200;
  std::vector<std::string> constants;
  std::vector<double> spans;
  for (const Signal& sig : signals) {
    PlotSeries series{sig.name, {}, {}};
    double lo = INFINITY, hi = -INFINITY, big = 0;
    for (const auto& s : r.samples) {
      const double v = sig.get(s);
      series.x.push_back(s.t_s), series.y.push_back(v);
      lo = std::min(lo, v), hi = std::max(hi, v), big = std::max(big, std::abs(v));
    }
    // Forces are scaled by the largest vertical load, lengths by their own size.
    const double scale = sig.scale_factor > 0 ? big : largest_load;
    bool extreme = false;
    const auto* x = sig.name == "vertical load"        ? &r.extremes.load_N
                    : sig.name == "longitudinal force" ? &r.extremes.longitudinal_force_N
                                                       : nullptr;
    if (x && r.extremes.valid) {
      lo = std::min(lo, x->min), hi = std::max(hi, x->max);
      extreme = true;
    }
    if (!(hi - lo > 0.005 * scale)) {
      const int decimals = sig.unit == "N" ? 0 : 1;
      double level = 0.5 * (lo + hi);
      if (std::abs(level) < 0.5 * std::pow(10.0, -decimals)) level = 0;  // not "-0"
      constants.push_back(sig.name + " " + fixed(level, decimals) + " " + sig.unit);
      continue;
    }
    PlotPanel panel{sig.name, "t [s]", sig.label, {series}};
    if (extreme) {
      PlotSeries marks{
          "extremes over the integrator's steps", {x->t_min_s, x->t_max_s}, {x->min, x->max}};
      marks.style = "points";
      panel.series.push_back(marks);
    }
    fig.panels.push_back(panel);
    spans.push_back(0.01 * scale);
  }
  if (fig.panels.empty()) fig.panels.push_back({"", "t [s]", "", {}});
  std::string head = title;
  if (!constants.empty()) {
    head += " (constant: ";
    for (std::size_t i = 0; i < constants.size(); ++i) head += (i ? ", " : "") + constants[i];
    head += ")";
  }
  fig.panels.front().title = head + ": " + fig.panels.front().title;
  for (std::size_t i = 0; i < spans.size(); ++i) ensure_min_y_span(fig.panels[i], spans[i]);
  fig.height_px = 360;  // per row of panels (core/gnuplot.h)
  render_plot(fig, path);
}

// What the scenario was and what it measured: speed and cleat, the free vibration's period and
// damping, the force extremes over the integrator's steps, and the output grid.
void print_scenario_summary(const transient::TransientModel& model, transient::Scenario scenario,
                            const transient::TransientResult& r) {
  using transient::Scenario;
  const contact::TransientSettings& T = model.settings;
  if (scenario == Scenario::rolling || scenario == Scenario::cleat) {
    const modal::CriticalSpeed c = transient::critical_speed_of(model);
    const double v = scenario == Scenario::rolling ? T.rolling.speed_m_s : T.cleat.speed_m_s;
    if (v >= transient::kNearCriticalShare * c.speed_m_s)
      std::cout << "near the carcass's critical speed: " << fixed(v * 3.6, 1) << " km/h is "
                << fixed(100 * v / c.speed_m_s, 0) << " % of " << fixed(c.speed_km_h(), 1)
                << " km/h (order " << c.order
                << "): a standing wave grows behind the contact, lengthening it and raising the "
                   "rolling resistance steeply (docs/transient.md section 3a)\n";
  }
  if (scenario == Scenario::rolling)
    std::cout << "rolling at " << fixed(T.rolling.speed_m_s * 3.6, 1) << " km/h (ramp "
              << fixed(T.rolling.ramp_s, 2) << " s)\n";
  if (scenario == Scenario::cleat) {
    std::cout << "cleat " << fixed(T.cleat.height_m * 1e3, 1) << " mm high, "
              << fixed(T.cleat.length_m * 1e3, 1) << " mm long, ";
    if (T.cleat.width_m > 0)
      std::cout << fixed(T.cleat.width_m * 1e3, 1) << " mm wide";
    else
      std::cout << "across the tread";
    std::cout << ", at " << fixed(T.cleat.speed_m_s * 3.6, 1) << " km/h\n";
  }
  if (scenario == Scenario::free_vibration) {
    const transient::BounceDecay d = transient::bounce_decay(r);
    if (d.peaks >= 2)
      std::cout << "free vibration: period " << fixed(d.period_s * 1e3, 3) << " ms ("
                << fixed(1 / d.period_s, 2) << " Hz), log decrement " << fixed(d.log_decrement, 4)
                << " (damping ratio " << fixed(100 * d.damping_ratio(), 2) << " %), " << d.peaks
                << " peaks over the " << (d.from_steps ? "integrator's steps" : "output samples")
                << "\n";
    else
      std::cout << "free vibration: fewer than two peaks above the final mean (no period)\n";
  }
  if (r.extremes.valid) {
    const auto& L = r.extremes.load_N;
    const auto& X = r.extremes.longitudinal_force_N;
    std::cout << "extremes over the integrator's steps: load " << fixed(L.min, 1) << " N (t "
              << fixed(L.t_min_s, 4) << " s) to " << fixed(L.max, 1) << " N (t "
              << fixed(L.t_max_s, 4) << " s); F_x " << fixed(X.min, 1) << " N (t "
              << fixed(X.t_min_s, 4) << " s) to " << fixed(X.max, 1) << " N (t "
              << fixed(X.t_max_s, 4) << " s)\n";
  }
  std::cout << r.output_grid.describe() << "\n";
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
    // Without a CSV or a plot the printed outputs read only the samples' forces and the final
    // sample (TransientRunOptions::summary_samples).
    opts.summary_samples = a->csv.empty() && a->plot.empty();
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
    if (!a->plot.empty()) transient_plot(r, scenario_title(config, scenario), a->plot);
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
      print_scenario_summary(model, scenario, r);
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
