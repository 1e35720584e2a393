// modaltyre discover CONFIG MEASURED.csv [--ground SOIL.yaml] [--set key=value]... [--json]
//                   [--plot FILE]
//                   [--out-config FILE] [--threads N] [--unit-length-mm L] [--max-effects N]
//                   [--exact-rows N]
//
// Locates where the model and the measurements disagree, names the missing effect (if any is
// significant) and writes the augmented config. Exit 0 whether or not an effect is named
// (naming nothing is a result); 1 when the baseline cannot be fitted; 2 for bad input.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <set>
#include <tuple>

#include "cli_support.h"
#include "commands.h"
#include "discover_limits.h"
#include "discover_traction_plot.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/core/progress.h"
#include "modaltyre/discover/discover.h"
#include "modaltyre/report/discover_json.h"
#include "modaltyre/report/ground_input.h"
#include "modaltyre/report/traction_flexing.h"
#include "modaltyre/studies/measurements.h"
#include "modaltyre/studies/traction_rows.h"

namespace modaltyre::app {
namespace {

namespace fs = std::filesystem;

struct DiscoverArgs {
  std::string config;
  std::string measured;
  std::string ground;
  std::vector<std::string> overrides;
  bool json = false;
  std::string plot;
  std::string out_config;
  int threads = 0;
  double unit_length_mm = 2;
  int max_effects = 2;
  int exact_rows = 64;
  bool uncertainty = false;
  bool no_mesh_check = false;
};

// "length_mm and sinking_mm": the observables with a relative residual (a non-zero
// measurement), which the pooled cross-validated RMS covers.
std::string observables_text(const std::map<std::string, double>& gaps) {
  std::string out;
  std::size_t i = 0;
  for (const auto& kv : gaps) {
    out += (i == 0 ? "" : i + 1 == gaps.size() ? " and " : ", ") + kv.first;
    ++i;
  }
  return out;
}

void print_text(const discover::DiscoverReport& r, const studies::MeasurementSet& data) {
  std::cout << "discover: " << data.path << ", " << data.rows.size() << " rows; evaluated on "
            << r.evaluation_mesh << "\n";
  if (r.method != "exact") std::cout << "method: " << r.method << "\n";
  std::cout << "\nGap (RMS of (predicted - measured) / measured"
            << (data.traction_rows() > 0
                    ? "; drawbar pull and torque against at least 0.1 load and 0.1 load x R0"
                    : "")
            << "):\n";
  std::cout << "  observable              config   baseline  baseline(CV)    after  after(CV)\n";
  for (const auto& kv : r.gap_before) {
    const auto& o = kv.first;
    char line[200];
    std::snprintf(line, sizeof line, "  %-22s %8s %10s %13s %8s %10s\n", o.c_str(),
                  pct(r.gap_config.at(o)).c_str(), pct(kv.second).c_str(),
                  pct(r.cv_gap_before.at(o)).c_str(), pct(r.gap_after.at(o)).c_str(),
                  pct(r.cv_gap_after.at(o)).c_str());
    std::cout << line;
  }
  std::cout << "\nLocate (baseline re-fitted on all rows):\n";
  for (const auto& f : r.regimes) std::cout << "  " << f.summary << "\n";
  std::cout << "  rows worst off:";
  for (int w : r.worst_rows) std::cout << " " << w;
  std::cout << "\n";
  for (std::size_t k = 0; k < r.rounds.size(); ++k) {
    std::cout << "\nName, round " << k + 1
              << " (significant: Delta BIC > 10, CV RMS falls >= 25 % on an observable, "
                 "grows <= 10 % on none; CV = cross-validated RMS of the relative residual, "
                 "pooled over "
              << observables_text(r.gap_before) << "):\n";
    for (const auto& c : r.rounds[k]) {
      if (!c.testable) {
        std::cout << "  " << c.name << ": not testable (" << c.reason << ")\n";
        continue;
      }
      char line[240];
      std::snprintf(line, sizeof line, "  %-20s dBIC %9.1f  CV %8s -> %8s%s\n", c.name.c_str(),
                    c.delta_bic, pct(c.cv_rms_before).c_str(), pct(c.cv_rms_after).c_str(),
                    c.significant ? "  significant" : "");
      std::cout << line;
      if (c.uncertainty_discount >= 0.05) {  // docs/uncertainty.md section 9
        std::snprintf(line, sizeof line,
                      "  %-20s   of which the model's uncertain inputs could produce %.1f: "
                      "%.1f left\n",
                      "", c.uncertainty_discount, c.delta_bic - c.uncertainty_discount);
        std::cout << line;
      }
    }
  }
  std::cout << "\n" << r.conclusion << "\n";
  print_limits(r);
  for (const auto& e : r.effects) {
    std::cout << "  " << e.name << ":";
    for (const auto& kv : e.parameters) {
      std::cout << " " << kv.first << " = " << kv.second << " +- "
                << e.standard_errors.at(kv.first);
      const auto b = e.bands.find(kv.first);
      if (b != e.bands.end()) {
        std::cout << " (two standard errors: " << b->second.lower
                  << (b->second.lower_at_bound ? " (range bound)" : "") << " to " << b->second.upper
                  << (b->second.upper_at_bound ? " (range bound)" : "") << ")";
      }
    }
    for (const auto& kv : e.mesh.shift) {
      const auto b = e.bands_with_mesh.find(kv.first);
      if (b == e.bands_with_mesh.end()) continue;
      std::cout << "\n    " << kv.first << " moves by " << kv.second << " on "
                << e.mesh.fine_unit_length_mm << " mm units (fitted on " << e.mesh.unit_length_mm
                << "); with the mesh's share to the continuum (twice that): " << b->second.lower
                << " to " << b->second.upper;
    }
    if (e.mesh.change_rms >= 0) {
      std::cout << "\n    mesh check: on " << e.mesh.fine_unit_length_mm
                << " mm units the predictions move by " << 100 * e.mesh.change_rms
                << " % RMS (to the continuum about twice that) against the fit's residual "
                << 100 * e.mesh.residual_rms << " % RMS";
      if (discover::mesh_is_coarse(e.mesh))
        std::cout << ": the mesh is a sizable part of the gap; refit with a finer --unit-length-mm";
    }
    if (!e.mesh.note.empty()) std::cout << "\n    mesh check: " << e.mesh.note;
    for (const auto& k : e.at_bound) {
      std::cout << "\n    " << k << " ended at a bound of its range: the data bound it from one "
                << "side only";
    }
    std::cout << "\n";
  }
}

void write_out_config(const DiscoverArgs& a, const contact::TyreConfig& cfg,
                      const discover::DiscoverReport& r) {
  std::vector<std::string> ov = a.overrides;
  ov.insert(ov.end(), r.out_overrides.begin(), r.out_overrides.end());
  // The hammer data path is relative to the config; re-anchor it to the new file's folder.
  fs::path folder = fs::absolute(fs::path(a.out_config)).parent_path();
  if (!cfg.hammer_csv.empty())  // a frequency list has no file to re-anchor
    ov.push_back("modal.hammer_csv=" +
                 fs::relative(fs::absolute(cfg.hammer_csv), folder).generic_string());
  const std::string text = "# Written by modaltyre discover from " + a.config + " and " +
                           a.measured + ".\n# " + r.conclusion + "\n" +
                           ConfigTree::load(a.config, ov).dump() + "\n";
  write_file_atomically(a.out_config, text);
}

// "load_N" -> "load [N]", "sinking_mm" -> "sinking [mm]" (gnuplot's enhanced text would read
// an underscore as a subscript).
std::string axis_label(const std::string& name) {
  for (const char* unit : {"_kPa", "_mm", "_N", "_s", "_kmh"}) {
    const std::string u(unit);
    if (name.size() > u.size() && name.compare(name.size() - u.size(), u.size(), u) == 0) {
      return name.substr(0, name.size() - u.size()) + " [" + u.substr(1) + "]";
    }
  }
  std::string out = name;
  for (char& c : out) c = c == '_' ? ' ' : c;
  return out;
}

// "sinking_mm" -> "sinking", "rolling_resistance_N" -> "rolling resistance".
std::string observable_word(const std::string& name) {
  std::string label = axis_label(name);
  const auto unit = label.find(" [");
  return unit == std::string::npos ? label : label.substr(0, unit);
}

void plot(const std::string& path, const discover::DiscoverReport& r,
          const studies::MeasurementSet& data, double outer_radius_m) {
  const std::string var = r.regimes.empty() ? "" : r.regimes.front().variable;
  PlotFigure fig;
  for (const auto& obs : data.observables) {
    if (studies::is_traction_observable(obs)) continue;   // drawn as curves against slip below
    std::vector<std::tuple<double, double, double>> pts;  // x, before, after (percent)
    for (std::size_t i = 0; i < data.rows.size(); ++i) {
      const auto& row = r.rows[i];
      if (!row.cv_before.count(obs)) continue;
      const double x =
          var.empty() ? row.row : studies::condition_value(data.rows[i].conditions, var);
      pts.emplace_back(x, 100 * row.cv_before.at(obs), 100 * row.cv_after.at(obs));
    }
    if (pts.empty()) continue;  // e.g. a rolling resistance measured as 0 on every row
    // An observable the model reproduces exactly on every row (e.g. a width that is the
    // config's own, from a sweep) would be an all-zero panel: left out.
    bool all_zero = true;
    for (const auto& [x, b, a] : pts)
      all_zero = all_zero && std::abs(b) < 1e-9 && std::abs(a) < 1e-9;
    if (all_zero) continue;
    std::sort(pts.begin(), pts.end());
    PlotPanel p;
    // The panel's axis is a relative residual in %, so the title names the observable without
    // its unit ("sinking", not "sinking [mm]").
    p.title = observable_word(obs) + (r.effects.empty() ? ": nothing named" : ": before and after");
    p.xlabel = var.empty() ? "row" : axis_label(var);
    p.ylabel = "cross-validated (predicted - measured) / measured [%]";
    // Points, not lines: rows at one value of the regime variable differ in load and other
    // conditions, and a line through them drew a sawtooth that no quantity follows (issue 38).
    PlotSeries before{"baseline", {}, {}, "points"};
    PlotSeries after{
        r.effects.empty() ? "baseline (unchanged)" : "with the named effects", {}, {}, "points"};
    for (const auto& [x, b, a] : pts) {
      before.x.push_back(x), before.y.push_back(b);
      after.x.push_back(x), after.y.push_back(a);
    }
    p.series = {before, after};
    p.key = "below";
    fig.panels.push_back(p);
  }
  add_traction_panels(fig, r, data, outer_radius_m);
  if (fig.panels.empty()) {
    throw InputError({data.path, 0, ""},
                     "nothing to plot: no observable has a non-zero measurement or a residual");
  }
  fig.width_px = 420 * static_cast<int>(std::min<std::size_t>(fig.panels.size(), 3)) + 60;
  fig.height_px = fig.panels.size() > 3 ? 900 : 520;
  render_plot(fig, path);
}

}  // namespace

void register_discover(CLI::App& app) {
  auto a = std::make_shared<DiscoverArgs>();
  CLI::App* cmd = app.add_subcommand(
      "discover",
      "Discrepancy workflow: locate where the model and measured footprints disagree, name the "
      "missing effect (Delta BIC and cross-validation over every candidate of `modaltyre "
      "effects`), write the augmented config and show the gap before and after.");
  cmd->add_option("CONFIG", a->config, "tyre config (YAML), e.g. configs/sf350.yaml")->required();
  cmd->add_option("MEASURED", a->measured,
                  "measured CSV: load_N, optional pressure_kPa, hold_s, speed_kmh, branch, "
                  "surface; any of sinking_mm, length_mm, width_mm, rolling_resistance_N; rows "
                  "of a traction test: slip, optional pass, any of drawbar_pull_N, "
                  "soil_sinkage_mm, torque_Nm (docs/discover.md)")
      ->required();
  cmd->add_option("--ground", a->ground,
                  "soil file (YAML with a ground: section, e.g. configs/soils/lete_sand.yaml) the "
                  "rows ran on, as `traction --ground`; default: the config's ground: section");
  cmd->add_option("--set", a->overrides, "override a config key, e.g. --set tread.tan_delta=0.2");
  cmd->add_flag("--json", a->json, "print the report as JSON on stdout");
  cmd->add_option("--plot", a->plot,
                  "residuals before/after against the regime variable (.svg/.png)");
  cmd->add_option("--out-config", a->out_config, "write the augmented config (YAML) here");
  cmd->add_option("--threads", a->threads, "OpenMP threads over candidates (default: all cores)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--unit-length-mm", a->unit_length_mm,
                  "patch unit length of the evaluations (default 2 mm; 0 = the config's)")
      ->check(CLI::Range(0.0, 50.0));
  cmd->add_flag("--uncertainty", a->uncertainty,
                "weigh each candidate against the model's own uncertainty too (the config's "
                "uncertain inputs, propagated): the evidence they could produce is taken off its "
                "Delta BIC (docs/uncertainty.md)");
  cmd->add_flag("--no-mesh-check", a->no_mesh_check,
                "skip the named effects' mesh shift (their fitted values on half the unit length, "
                "docs/discover.md \"The mesh's share\")");
  cmd->add_option("--max-effects", a->max_effects, "effects to name at most (default 2)")
      ->check(CLI::Range(1, 9));
  cmd->add_option("--exact-rows", a->exact_rows,
                  "fit and cross-validate exactly up to this many rows, above by a subset search "
                  "and one-step cross-validation (default 64; docs/discover.md)")
      ->check(CLI::Range(4, 1000000));
  cmd->callback([a, cmd] {
    discover::DiscoverOptions opt;
    opt.threads = a->threads;
    opt.unit_length_mm = a->unit_length_mm;
    opt.max_effects = a->max_effects;
    opt.fit.exact_rows = a->exact_rows;
    opt.model_uncertainty = a->uncertainty;
    opt.mesh_check = !a->no_mesh_check;
    opt.validate();  // CLI::Range lets NaN through (every comparison with it is false)
    refuse_repeated_overrides(a->overrides);
    const contact::TyreConfig cfg = report::config_on_ground(a->config, a->ground, a->overrides);
    const studies::MeasurementSet data = studies::read_measurements(a->measured, cfg);
    CommandFiles files;  // no output over an input or another output
    report::add_config_inputs(files, cfg);
    files.input(a->measured, "MEASURED");
    files.input(a->ground, "--ground");
    if (cmd->count("--plot")) files.output(a->plot, "--plot");
    if (cmd->count("--out-config")) files.output(a->out_config, "--out-config");
    files.check();
    // Checked before minutes of fitting, not after the augmented config has been written.
    if (!a->plot.empty()) {
      const std::string ext = fs::path(a->plot).extension().string();
      if (ext != ".svg" && ext != ".png") {
        throw InputError({a->plot, 0, "--plot"}, "plot file must end in .svg or .png");
      }
    }
    // One bar per phase on stderr (a terminal only): the baseline's fit and cross-validation,
    // then each round's candidates, a tick per fit and per cross-validation (done = 0 opens a
    // phase).
    std::mutex m;
    std::unique_ptr<ProgressBar> bar;
    std::string phase;
    opt.progress = [&](const std::string& p, int done, int total) {
      std::lock_guard<std::mutex> lock(m);
      if (!bar || p != phase) {
        if (bar) bar->finish();
        phase = p;
        bar = std::make_unique<ProgressBar>(static_cast<std::size_t>(total), "discover " + p);
      }
      if (done > 0) bar->tick();
    };
    // Traction rows: the tyre's flexing loss on the rigid road, as `traction` takes it.
    opt.traction_flexing = report::flexing_resistance_N;
    const discover::DiscoverReport r = discover::discover(cfg, data, opt);
    if (bar) bar->finish();
    for (const auto& t : r.traction_windows) {
      if (!t.window.grown) continue;  // as `traction`'s "window grew" note: only a grown window
      std::cerr << "note: the traction rows at " << t.load_N << " N, " << t.speed_kmh
                << " km/h rolled on a window of " << t.window.why
                << ", decided once from the data (traction_windows in --json)\n";
    }
    // Output files only once the report is known to be printable (the JSON finite), the plot
    // (which can still refuse) before the config, so that a failure leaves neither behind.
    auto write_outputs = [&] {
      if (!a->plot.empty()) plot(a->plot, r, data, cfg.outer_radius_m);
      if (!a->out_config.empty()) write_out_config(*a, cfg, r);
    };
    if (!a->json) {
      write_outputs();
      print_text(r, data);
      if (!a->out_config.empty()) std::cout << "augmented config: " << a->out_config << "\n";
      return;
    }
    nlohmann::json j = report::discover_json(r, a->measured, data.rows.size());
    if (!a->out_config.empty()) j["out_config"] = a->out_config;
    check_finite(j);
    write_outputs();
    print_json(j);
  });
}

}  // namespace modaltyre::app
