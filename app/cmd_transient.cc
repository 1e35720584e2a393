// modaltyre transient CONFIG --scenario NAME [--csv FILE] [--json] [--plot FILE] [--set k=v]...
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/transient/transient.h"

namespace modaltyre::app {
namespace {

struct TransientArgs {
  std::string config;
  std::string scenario;
  std::string csv;
  std::string plot;
  bool json = false;
  std::vector<std::string> overrides;
};

std::string transient_csv(const transient::TransientResult& r) {
  std::ostringstream o;
  o.precision(10);
  o << "t_s,load_N,hub_displacement_mm,sinking_mm,contact_length_mm,longitudinal_force_N\n";
  for (const auto& s : r.samples) {
    o << s.t_s << ',' << s.load_N << ',' << s.hub_displacement_m * 1e3 << ',' << s.sinking_m * 1e3
      << ',' << s.contact_length_m * 1e3 << ',' << s.longitudinal_force_N << '\n';
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
  const double scales[] = {force_scale, largest(sink), largest(len), force_scale};
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
  cmd->add_option("CONFIG", a->config,
                  "tyre config (YAML) on the 2D patch, e.g. configs/sf350_2d_table3.yaml")
      ->required();
  cmd->add_option("--scenario", a->scenario, "load-hold | free-vibration | rolling | cleat")
      ->required();
  cmd->add_option("--csv", a->csv,
                  "write the time series (t_s,load_N,hub_displacement_mm,sinking_mm,"
                  "contact_length_mm,longitudinal_force_N)");
  cmd->add_flag("--json", a->json, "print a JSON summary");
  cmd->add_option("--plot", a->plot, "draw the time series (.svg or .png)");
  cmd->add_option("--set", a->overrides,
                  "override a config key, e.g. --set transient.load_hold.hold_s=10");
  cmd->callback([a] {
    const transient::Scenario scenario = transient::parse_scenario(a->scenario);
    const auto config = contact::load_tyre_config(a->config, a->overrides);
    if (config.footprint_3d) {  // refused, not silently run on a patch the config did not ask for
      throw InputError({a->config, 0, "footprint_3d"},
                       "the transient model runs the 2D patch; a config with footprint_3d: (the "
                       "3D patch) has no transient model yet: use a 2D config such as "
                       "configs/sf350_2d_table3.yaml");
    }
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
    const transient::TransientResult r = transient::run_transient(model, scenario, &opts);
    if (drawn) std::fprintf(stderr, "\n");
    if (!r.ok()) throw ComputationError(r.message);

    if (!a->csv.empty()) write_file_atomically(a->csv, transient_csv(r));
    if (!a->plot.empty()) transient_plot(r, a->plot);
    const auto& fin = r.samples.back();
    if (a->json) {
      nlohmann::json j;
      j["scenario"] = transient::to_string(scenario);
      j["simulated_s"] = round_sig(r.simulated_s);
      j["wall_s"] = round_sig(r.wall_s, 4);
      j["real_time_factor"] = round_sig(r.real_time_factor(), 4);
      j["steps"] = r.stats.steps;
      j["final"] = {{"load_N", round_sig(fin.load_N)},
                    {"sinking_mm", round_sig(fin.sinking_m * 1e3)},
                    {"contact_length_mm", round_sig(fin.contact_length_m * 1e3)},
                    {"rolling_resistance_N", round_sig(r.rolling_resistance_N)},
                    {"hub_displacement_mm", round_sig(fin.hub_displacement_m * 1e3)},
                    {"pressure_centre_mm", round_sig(fin.pressure_centre_m * 1e3)},
                    {"contact_units", fin.contact_units}};
      j["contact_switches"] = r.contact_events;
      j["solver"] = {{"rhs_evals", r.stats.rhs_evals},
                     {"jacobian_evals", r.stats.jac_evals},
                     {"linear_setups", r.stats.lin_setups},
                     {"nonlinear_iterations", r.stats.nonlin_iters},
                     {"error_test_fails", r.stats.error_test_fails},
                     {"restarts", r.stats.reinits}};
      j["model"] = {{"dynamic_coordinates", model.nq},
                    {"residual_coordinates", model.nr},
                    {"candidate_units", model.m},
                    {"states", model.state_size()},
                    {"tread_time_constant_s", round_sig(model.tread_time_constant_s)},
                    {"residual_time_constant_s", round_sig(model.tau_residual_s)}};
      j["samples"] = r.samples.size();
      print_json(j);
    } else {
      std::cout << "scenario " << transient::to_string(scenario) << ": " << r.message << "\n"
                << "simulated " << fixed(r.simulated_s, 3) << " s in " << fixed(r.wall_s, 3)
                << " s (real-time factor " << fixed(r.real_time_factor(), 1) << ")\n"
                << "final: load " << fixed(fin.load_N, 1) << " N, sinking "
                << fixed(fin.sinking_m * 1e3, 3) << " mm, contact length "
                << fixed(fin.contact_length_m * 1e3, 2) << " mm, rolling resistance "
                << fixed(r.rolling_resistance_N, 2) << " N\n";
    }
  });
}

}  // namespace modaltyre::app
