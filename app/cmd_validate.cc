// modaltyre validate CONFIG MEASURED.csv [--set key=value]... [--json] [--plot FILE]
//                    [--uncertainty [--uncertainty-method M] [--samples N]]
#include <algorithm>
#include <array>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/validity.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/report/condition_settings.h"
#include "modaltyre/report/footprint_json.h"
#include "modaltyre/report/uncertainty_json.h"
#include "modaltyre/report/validation_json.h"
#include "modaltyre/studies/validation.h"
#include "validate_bands.h"

namespace modaltyre::app {

using report::apply_condition_settings;
using report::ConditionSetting;
using report::settings_json;
using report::settings_text;
using report::take_condition_settings;
namespace {

struct ValidateArgs {
  std::string config;
  std::string measured;
  std::vector<std::string> overrides;
  bool json = false;
  std::string plot;
  bool uncertainty = false;
  UncertaintyMethodArgs method;
};

using report::row_validity;

// The rows with the model's band: measured (+- 2 sigma where stated) against the predicted
// value and its 2.5-97.5 % band, and whether the measurement lies outside the band (its noise
// added).
void print_band_table(const studies::ValidationReport& rep, const ValidationBands& b) {
  const auto& r = b.result;
  std::cout << "\nuncertainty (" << r.method << ": " << r.check << "); measured +- 2 sigma "
            << "(its stated noise), predicted " << report::kBandHeading
            << "; 'outside': the measured value lies outside the model's band widened by its "
               "own stated noise\n";
  std::cout << " row  load_N  observable   measured             predicted\n";
  for (std::size_t i = 0; i < b.rows; ++i) {
    const auto& row = rep.rows[i].measured;
    for (const auto& o : band_observables()) {
      const auto v = row.value(o.observable);
      if (!v) continue;
      const auto s = row.observed_std.find(o.observable);
      const auto& band = r.cases[i].bands[o.output];
      const std::string meas =
          report::plus_minus(*v, s == row.observed_std.end() ? 0.0 : 2 * s->second, 2);
      const std::string pred = report::band_text(band, 2);
      const auto& off = b.outside[i];
      const bool out = std::find(off.begin(), off.end(), o.observable) != off.end();
      char line[256];
      std::snprintf(line, sizeof line, " %3d  %6.0f  %-11s  %-19s  %-24s%s\n", row.row,
                    row.conditions.load_N, o.observable, meas.c_str(), pred.c_str(),
                    out ? "  outside" : "");
      std::cout << line;
    }
  }
}

void print_table(const studies::ValidationReport& rep, const std::string& measured_path,
                 const std::vector<ConditionSetting>& settings) {
  const auto& c = rep.calibration;
  std::cout << rep.model.config.name << " vs " << measured_path << "\n";
  if (!settings.empty()) {
    std::cout << "conditions: " << settings_text(settings)
              << " (--set, on every row; the file has no such column)\n";
  }
  if (c.keys.empty()) {
    std::cout << "No calibration: every row is a prediction.\n";
  } else {
    std::cout << "Calibrated on rows";
    for (int r : c.rows) std::cout << " " << r;
    std::cout << " (observables:";
    for (const auto& o : c.observables) std::cout << " " << o;
    std::cout << "):\n";
    for (std::size_t i = 0; i < c.keys.size(); ++i) {
      std::cout << "  " << c.keys[i] << " = " << round_sig(c.values[i], 5);
      if (i < c.std_errors.size()) {
        std::cout << "  (+- " << round_sig(2 * c.std_errors[i], 2) << " at 2 sigma)";
      }
      std::cout << "  (was " << c.initial_values[i] << ")";
      if (!c.at_bound[i].empty()) {
        std::cout << "  warning: at the " << c.at_bound[i]
                  << " bound of its search range: the rows bound it from one side only, or a "
                     "better fit lies elsewhere (try another starting value with --set)";
      }
      std::cout << "\n";
    }
    std::cout << "  standard errors: " << c.covariance_note << "\n";
  }
  if (const auto on = report::enabled_effects(rep.model.config.effects); !on.empty()) {
    std::cout << "Effects on:";
    for (const auto& e : on) std::cout << " " << e;
    std::cout << "\n";
  }
  if (rep.with_conditions) {
    std::cout << "Each row is predicted at its own operating conditions (file columns; the "
                 "config's where absent).\n";
  }
  bool width = false;
  for (const auto& r : rep.rows) width = width || r.measured.value("width_mm").has_value();
  std::cout << "\n row  load_N  role         sinking_mm meas/pred    err%   length_mm meas/pred"
               "    err%"
            << (width ? "    width_mm meas/pred    err%" : "") << "\n";
  auto cell = [](const std::optional<double>& m, double p, const std::optional<double>& e) {
    char b[96];
    if (m) {
      std::snprintf(b, sizeof b, "%8.1f / %-8.2f %6.1f", *m, p, unsigned_zero(100 * *e, 1));
    } else {
      std::snprintf(b, sizeof b, "%8s / %-8.2f %6s", "-", p, "-");
    }
    return std::string(b);
  };
  for (const auto& r : rep.rows) {
    char head[64];
    std::snprintf(head, sizeof head, " %3d  %6.0f  %-11s  ", r.measured.row,
                  r.measured.conditions.load_N, r.calibration ? "calibration" : "prediction");
    std::cout << head << cell(r.measured.value("sinking_mm"), r.sinking_mm, r.sinking_rel_error)
              << "   " << cell(r.measured.value("length_mm"), r.length_mm, r.length_rel_error);
    if (width)
      std::cout << "   " << cell(r.measured.value("width_mm"), r.width_mm, r.width_rel_error);
    if (!row_validity(rep.model.config, r).valid) std::cout << "   outside the validity range";
    std::cout << "\n";
  }
  std::cout << "\nRMS relative error over predicted rows:";
  for (const auto& [k, v] : rep.rms_rel_error) {
    std::cout << "  " << k << " " << fixed(100 * v, 1) << " % (" << rep.predicted_rows.at(k)
              << " rows)";
  }
  std::cout << "\n";
}

// One warning on stderr per row outside the validity range, the first five of them.
void warn_outside_validity(const studies::ValidationReport& rep) {
  int outside = 0;
  for (const auto& r : rep.rows) {
    const contact::Validity v = row_validity(rep.model.config, r);
    if (v.valid) continue;
    if (++outside <= 5) {
      std::cerr << "warning: row " << r.measured.row << " (load " << r.measured.conditions.load_N
                << " N) is outside the model's validity range: " << v.reason
                << "; its prediction is not one (README, \"Validity range\")\n";
    }
  }
  if (outside > 5) {
    std::cerr << "warning: " << outside - 5 << " more rows are outside the validity range\n";
  }
}

// The model's curve at the config's conditions and those stated with --set, as every row
// (effects act as on the rows).
std::vector<contact::OperatingConditions> validation_curve(
    const studies::ValidationReport& rep, const std::vector<ConditionSetting>& settings) {
  double lo = 1e300, hi = 0;
  for (const auto& r : rep.rows)
    lo = std::min(lo, r.measured.conditions.load_N),
    hi = std::max(hi, r.measured.conditions.load_N);
  std::vector<contact::OperatingConditions> curve;
  const int n = 24;
  for (int i = 0; i <= n; ++i) {
    curve.push_back(rep.model.config.default_conditions(0.8 * lo + (1.1 * hi - 0.8 * lo) * i / n));
    apply_condition_settings(settings, curve.back());
  }
  return curve;
}

// With bands: the ends of the model's 95 % band at each row and the measured rows outside it
// (their noise added) marked apart.
void plot_validation(const studies::ValidationReport& rep, const std::string& path,
                     const std::vector<ConditionSetting>& settings, const ValidationBands* bands) {
  const auto curve = validation_curve(rep, settings);
  const std::string stated = settings.empty() ? "" : " (" + settings_text(settings) + ")";
  const auto res = contact::predict_all(rep.model, curve);
  // One panel per compared observable: the model's curve, the measured rows (calibration rows
  // marked apart).
  struct Observable {
    const char* name;
    const char* title;
    const char* ylabel;
  };
  const Observable observables[] = {
      {"sinking_mm", "sinking versus load", "sinking [mm]"},
      {"length_mm", "contact length versus load", "contact length [mm]"},
      {"width_mm", "contact width versus load", "contact width [mm]"}};
  PlotFigure fig;
  for (const auto& o : observables) {
    PlotSeries model{"model", {}, {}, "lines"};
    for (const auto& p : res) {
      if (!p.ok()) continue;  // a failed prediction is left out of the curve
      model.x.push_back(p.footprint.load.load_N / 1000);
      model.y.push_back(p.observable(o.name));
    }
    PlotSeries measured{"measured (prediction rows)", {}, {}, "points"};
    PlotSeries calibration{"measured (calibration rows)", {}, {}, "points"};
    PlotSeries outside{"measured, outside the band", {}, {}, "points"};
    // The band at the rows, its 2.5 and 97.5 % points (the JSON's p025, p975) joined in load
    // order: computed at the rows only (the rows may stand at other conditions than the curve).
    std::vector<std::array<double, 3>> band_at;  // load kN, p025, p975
    std::size_t q = 0;
    for (const auto& b : band_observables()) {
      if (o.name == std::string(b.observable)) q = b.output;
    }
    for (std::size_t i = 0; i < rep.rows.size(); ++i) {
      const auto& r = rep.rows[i];
      auto& s = r.calibration ? calibration : measured;
      if (const auto v = r.measured.value(o.name)) {
        s.x.push_back(r.measured.conditions.load_N / 1000);
        s.y.push_back(*v);
        if (bands) {
          const auto& b = bands->result.cases[i].bands[q];
          band_at.push_back({s.x.back(), b.p025, b.p975});
        }
        if (bands && std::find(bands->outside[i].begin(), bands->outside[i].end(), o.name) !=
                         bands->outside[i].end()) {
          outside.x.push_back(s.x.back());
          outside.y.push_back(*v);
        }
      }
    }
    if (measured.x.empty() && calibration.x.empty()) continue;  // not measured: not compared
    PlotPanel panel;
    panel.title = rep.model.config.name + ": " + o.title + stated;
    panel.xlabel = "vertical load [kN]";
    panel.ylabel = o.ylabel;
    panel.series = {model, measured};
    if (!calibration.x.empty()) panel.series.push_back(calibration);
    if (bands) {
      std::sort(band_at.begin(), band_at.end());
      PlotSeries lo{"model band, 2.5 % (at the rows)", {}, {}, "linespoints dashtype 2 pt 1 lc 4"};
      PlotSeries hi{"model band, 97.5 % (at the rows)", {}, {}, "linespoints dashtype 2 pt 1 lc 4"};
      for (const auto& [x, p025, p975] : band_at) {
        lo.x.push_back(x), lo.y.push_back(p025);
        hi.x.push_back(x), hi.y.push_back(p975);
      }
      panel.series.push_back(lo);
      panel.series.push_back(hi);
      if (!outside.x.empty()) panel.series.push_back(outside);
    }
    fig.panels.push_back(std::move(panel));
  }
  fig.width_px = 600 * static_cast<int>(fig.panels.size());
  fig.height_px = 480;
  render_plot(fig, path);
}

}  // namespace

void register_validate(CLI::App& app) {
  auto a = std::make_shared<ValidateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "validate",
      "Compare predicted sinking and contact length with measured footprints (e.g. seed 001 "
      "Table 3); calibration, if any, is declared in the config's validation section "
      "(at most three parameters on at most two rows) and only the other rows count.");
  cmd->add_option("CONFIG", a->config, "tyre config (YAML)")->required();
  cmd->add_option("MEASURED", a->measured,
                  "CSV with load_N and any of sinking_mm, length_mm, width_mm; optional "
                  "condition columns pressure_kPa, hold_s, speed_kmh, horizontal_force_N, branch, "
                  "surface (e.g. a sweep's output)")
      ->required();
  cmd->add_option("--set", a->overrides,
                  "override a config key, e.g. --set tread.modulus_MPa=8, or state a condition "
                  "the file has no column of for every row: pressure_kPa, hold_s, speed_kmh, "
                  "branch, surface, horizontal_force_N (e.g. --set hold_s=60)");
  cmd->add_flag("--json", a->json, "print JSON");
  cmd->add_option("--plot", a->plot,
                  "draw sinking, length and (where measured) width versus load (.svg or .png); "
                  "with --uncertainty the model's 95 % band and the rows outside it");
  cmd->add_flag("--uncertainty", a->uncertainty,
                "the model's band at every row (the config's uncertain inputs and the calibrated "
                "scalars' covariance; docs/uncertainty.md) and the measured values outside it");
  add_uncertainty_method_options(cmd, a->method);
  cmd->callback([a, cmd] {
    // The config decides how the file is read (effects need every row's conditions).
    auto overrides = a->overrides;
    const auto settings = take_condition_settings(overrides);
    const auto config = contact::load_tyre_config(a->config, overrides);
    CommandFiles files;
    report::add_config_inputs(files, config);
    files.input(a->measured, "MEASURED");
    if (cmd->count("--plot")) files.output(a->plot, "--plot");
    files.check();
    auto measured = studies::read_validation_measurements(a->measured, config);
    report::apply_to_measurements(settings, measured, a->measured);
    const auto rep = studies::validate_footprints(config, measured);
    warn_outside_validity(rep);
    std::optional<ValidationBands> bands;
    if (a->uncertainty) {
      bands = validation_bands(rep, a->method.options());
    }
    std::optional<nlohmann::json> j;
    if (a->json) {
      j = report::validation_json(rep);
      (*j)["conditions"] = settings_json(settings);
      if (bands) add_validation_bands_json(*j, *bands);
      check_finite(*j);  // before the plot: a failed run leaves no file
    }
    if (!a->plot.empty()) plot_validation(rep, a->plot, settings, bands ? &*bands : nullptr);
    if (j) {
      print_json(*j);
    } else {
      print_table(rep, a->measured, settings);
      if (bands) print_band_table(rep, *bands);
    }
  });
}

}  // namespace modaltyre::app
