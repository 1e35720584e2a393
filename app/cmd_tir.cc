// modaltyre tir export CONFIG --output FILE.tir [--loads N...] [--fnomin N] [--set k=v]...
//                      [--no-slip | --slip-loads N... --speed-kmh V --mu MU --slips K...
//                       --rr-speeds-kmh V...] [--uncertainty [--uncertainty-method M] [--samples
//                       K]]
// modaltyre tir compare CONFIG FILE.tir [--json] [--plot FILE] [--fnomin N] [--points K]
// The MF-Tyre/MF-Swift .tir bridge (tir/, docs/tir.md).
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/core/progress.h"
#include "modaltyre/tir/tir_compare.h"
#include "modaltyre/tir/tir_export.h"
#include "tir_bands.h"

namespace modaltyre::app {
namespace {

struct TirArgs {
  std::string config, tir_file, output, plot;
  std::vector<double> loads;
  double fnomin = 0;
  int points = 12;
  std::vector<std::string> overrides;
  bool json = false;
  bool uncertainty = false;
  UncertaintyMethodArgs method;
  // The longitudinal laws (export) and their comparison (compare --slip).
  bool no_slip = false, slip = false;
  std::vector<double> slip_loads, slips, rr_speeds_kmh;
  double speed_kmh = 60, mu = 0.8;
};

/// The slip runs' options from the arguments, with a progress bar on a terminal.
tir::SlipExportOptions slip_options(const TirArgs& a, std::shared_ptr<ProgressBar>& bar) {
  tir::SlipExportOptions o;
  o.enabled = true;
  o.loads_N = a.slip_loads;
  o.run.speed_m_s = a.speed_kmh / 3.6;
  o.run.mu = a.mu;
  o.run.slips = a.slips;
  for (double v : a.rr_speeds_kmh) o.speeds_m_s.push_back(v / 3.6);
  o.progress = [&bar, last = 0](int done, int total) mutable {
    if (!bar) bar = std::make_shared<ProgressBar>(static_cast<std::size_t>(total), "slip runs");
    bar->tick(static_cast<std::size_t>(done - last));
    last = done;
  };
  return o;
}

void print_slip_fit(const tir::TirSlipFit& s) {
  const tir::MfLongitudinal& c = s.longitudinal;
  std::cout << "  longitudinal (pure slip), " << s.curves.size() << " loads, F_z "
            << fixed(s.fz_min_N, 0) << "-" << fixed(s.fz_max_N, 0) << " N, "
            << fixed(s.basis.longvl_m_s * 3.6, 1) << " km/h, kappa " << s.kappa_min << " to "
            << s.kappa_max << ", mu " << s.mu << ":\n"
            << "    PCX1 " << c.pcx1 << ", PDX1 " << c.pdx1 << ", PDX2 " << c.pdx2 << ", PEX1 "
            << c.pex1 << ", PEX2 " << c.pex2 << ", PEX3 " << c.pex3 << ", PEX4 " << c.pex4
            << "\n    PKX1 " << c.pkx1 << ", PKX2 " << c.pkx2 << ", PKX3 " << c.pkx3 << ", PHX1 "
            << c.phx1 << ", PHX2 " << c.phx2 << ", PVX1 " << c.pvx1 << ", PVX2 " << c.pvx2
            << "\n  rolling resistance: QSY1 " << s.rolling.qsy1 << ", QSY2 " << s.rolling.qsy2
            << ", QSY3 " << s.rolling.qsy3 << ", QSY4 " << s.rolling.qsy4 << ", QSY7 "
            << s.rolling.qsy7 << "\n  effective rolling radius: Q_RE0 " << s.radius.q_re0
            << ", BREFF " << s.radius.breff << ", DREFF " << s.radius.dreff << ", FREFF "
            << s.radius.freff << "\n  fit residuals: F_x RMS " << pct(s.fx_over_fz.rms)
            << " of F_z (max " << pct(s.fx_over_fz.max) << "), M_y RMS " << pct(s.rolling_rel.rms)
            << " (max " << pct(s.rolling_rel.max) << ") at free rolling, RMS "
            << pct(s.rolling_slip_rel.rms) << " (max " << pct(s.rolling_slip_rel.max)
            << ") at slip, R_e max " << fixed(s.radius_m.max * 1e3, 4) << " mm; E_x at most "
            << fixed(s.max_curvature, 3) << "\n";
}

nlohmann::json opt(const std::optional<double>& v, double scale = 1) {
  return v ? nlohmann::json(round_sig(*v * scale, 6)) : nlohmann::json(nullptr);
}

std::string pct(const std::optional<double>& v) { return v ? fixed(100 * *v, 2) + " %" : "-"; }

void run_export(const TirArgs& a, CLI::App* cmd) {
  refuse_repeated_overrides(a.overrides);
  const auto config = contact::load_tyre_config(a.config, a.overrides);
  CommandFiles files;  // before the fit: a .tir written over the config loses the tyre
  report::add_config_inputs(files, config);
  files.output(a.output, "--output");
  files.check();
  const auto model = contact::build_tyre_model(config);
  tir::TirExportOptions o;
  if (cmd->count("--fnomin")) o.fnomin_N = a.fnomin;
  o.loads_N = a.loads;
  o.config_label = a.config;
  std::shared_ptr<ProgressBar> slip_bar;
  if (!a.no_slip) o.slip = slip_options(a, slip_bar);
  const tir::TirFit f = tir::fit_tir(model, o);
  if (slip_bar) slip_bar->finish();
  std::optional<TirBands> bands;
  if (a.uncertainty) {
    uncertainty::PropagationOptions uo = a.method.options();
    UncertaintyProgress bar;
    uo.progress = bar.callback();
    tir::TirExportOptions vertical = o;  // the bands are the vertical coefficients'
    vertical.slip.enabled = false;
    bands = tir_bands(config, vertical, f, uo);
    bar.finish();
    o.comments = tir_band_comments(*bands);
  }
  write_file_atomically(a.output, tir::tir_text(f, config, o));
  std::cout << "wrote " << a.output << " (MF-Tyre 6.2, FITTYP 62, SI units)\n"
            << "  FNOMIN              " << fixed(f.fnomin_N, 1) << " N\n"
            << "  VERTICAL_STIFFNESS  " << fixed(f.vertical_stiffness_N_m * 1e-3, 2)
            << " N/mm (model's tangent stiffness at FNOMIN "
            << fixed(f.model_tangent_stiffness_N_m * 1e-3, 2) << " N/mm, "
            << fixed(100 * (f.vertical_stiffness_N_m / f.model_tangent_stiffness_N_m - 1), 2)
            << " %)\n"
            << "  Q_FZ2 " << f.q_fz2 << ", Q_RA1 " << f.q_ra1 << ", Q_RA2 " << f.q_ra2;
  if (f.q_rb1) std::cout << ", Q_RB1 " << *f.q_rb1 << ", Q_RB2 " << *f.q_rb2;
  if (f.pfz1) std::cout << ", PFZ1 " << *f.pfz1;
  std::cout << "\n  fit to " << f.curve.points.size() << " footprints (relative residuals):"
            << " load RMS " << pct(f.load.rms_rel) << ", sinking RMS " << pct(f.sinking.rms_rel)
            << ", length RMS " << pct(f.length.rms_rel) << ", width "
            << (f.width ? "RMS " + pct(f.width->rms_rel) : "not fitted: " + f.curve.width_reason)
            << "\n";
  if (!f.pfz1) std::cout << "  " << f.pfz1_reason << "\n";
  if (f.slip) print_slip_fit(*f.slip);
  if (bands) print_tir_bands(*bands);
}

nlohmann::json comparison_json(const tir::TirComparison& c) {
  const tir::MfTyre& t = c.tir;
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : c.rows) {
    rows.push_back({{"rho_mm", round_sig(r.rho_m * 1e3, 6)},
                    {"load_N", round_sig(r.load_N, 6)},
                    {"tir_load_N", opt(r.tir_load_N)},
                    {"model_length_mm", round_sig(r.model_length_m * 1e3, 6)},
                    {"tir_length_mm", opt(r.tir_length_m, 1e3)},
                    {"model_width_mm", opt(r.model_width_m, 1e3)},
                    {"tir_width_mm", opt(r.tir_width_m, 1e3)}});
  }
  return {{"tir",
           {{"path", t.path},
            {"model", t.model_name},
            {"fittyp", t.fittyp ? nlohmann::json(t.fittyp) : nlohmann::json(nullptr)},
            {"unloaded_radius_mm", round_sig(t.unloaded_radius_m * 1e3, 6)},
            {"width_mm", opt(t.width_m, 1e3)},
            {"fnomin_N", round_sig(t.vertical.fnomin_N, 6)},
            {"vertical_stiffness_N_per_mm", round_sig(t.vertical_stiffness_N_m() * 1e-3, 6)},
            {"vertical_law", t.vertical_source},
            {"notes", t.notes}}},
          {"model", {{"fnomin_N", round_sig(c.model_fnomin_N, 6)}}},
          {"dimensionless", c.dimensionless},
          {"basis", c.basis},
          {"rows", rows},
          {"rms_rel_diff",
           {{"load", opt(c.rms_load)}, {"length", opt(c.rms_length)}, {"width", opt(c.rms_width)}}},
          {"reasons",
           {{"load", c.load_reason}, {"length", c.length_reason}, {"width", c.width_reason}}}};
}

void print_comparison(const tir::TirComparison& c) {
  const tir::MfTyre& t = c.tir;
  std::cout << t.path << ": " << t.model_name << ", R0 " << fixed(t.unloaded_radius_m * 1e3, 1)
            << " mm, FNOMIN " << fixed(t.vertical.fnomin_N, 0) << " N, C_z "
            << fixed(t.vertical_stiffness_N_m() * 1e-3, 2)
            << " N/mm; vertical law: " << t.vertical_source << "\n"
            << c.basis << "; the model's FNOMIN " << fixed(c.model_fnomin_N, 0) << " N\n";
  for (const auto& n : t.notes) std::cout << "note: " << n << "\n";
  std::cout << "\n"
            << "  rho_mm    load_N  tir_load_N  length_mm  tir_length_mm  width_mm  tir_width_mm\n";
  const auto cell = [](const std::optional<double>& v, double scale, int w, int d) {
    const std::string s = v ? fixed(*v * scale, d) : "-";
    return std::string(s.size() < std::size_t(w) ? w - s.size() : 1, ' ') + s;
  };
  for (const auto& r : c.rows) {
    std::cout << cell(r.rho_m, 1e3, 8, 2) << cell(r.load_N, 1, 10, 0)
              << cell(r.tir_load_N, 1, 12, 0) << cell(r.model_length_m, 1e3, 11, 1)
              << cell(r.tir_length_m, 1e3, 15, 1) << cell(r.model_width_m, 1e3, 10, 1)
              << cell(r.tir_width_m, 1e3, 14, 1) << "\n";
  }
  std::cout << "\nRMS relative difference (.tir - model) / model:\n";
  const auto line = [](const char* q, const std::optional<double>& v, const std::string& why) {
    std::cout << "  " << q << (v ? pct(v) : "null: " + why) << "\n";
  };
  line("load    ", c.rms_load, c.load_reason);
  line("length  ", c.rms_length, c.length_reason);
  line("width   ", c.rms_width, c.width_reason);
}

nlohmann::json slip_comparison_json(const tir::SlipComparison& s) {
  nlohmann::json force = nlohmann::json::array(), rolling = nlohmann::json::array(),
                 radius = nlohmann::json::array();
  for (const auto& r : s.force) {
    force.push_back({{"load_N", round_sig(r.target_load_N, 6)},
                     {"fz_N", round_sig(r.fz_N, 6)},
                     {"kappa", round_sig(r.kappa, 6)},
                     {"model_fx_N", round_sig(r.model_fx_N, 6)},
                     {"tir_fx_N", opt(r.tir_fx_N)}});
  }
  for (const auto& r : s.rolling) {
    rolling.push_back({{"speed_kmh", round_sig(r.speed_m_s * 3.6, 6)},
                       {"fz_N", round_sig(r.fz_N, 6)},
                       {"model_my_Nm", round_sig(r.model_moment_Nm, 6)},
                       {"tir_my_Nm", opt(r.tir_moment_Nm)}});
  }
  for (const auto& r : s.radius) {
    radius.push_back({{"fz_N", round_sig(r.fz_N, 6)},
                      {"model_re_mm", round_sig(r.model_radius_m * 1e3, 7)},
                      {"tir_re_mm", opt(r.tir_radius_m, 1e3)}});
  }
  return {
      {"speed_kmh", round_sig(s.speed_m_s * 3.6, 6)},
      {"mu", s.mu},
      {"force_rows", force},
      {"rolling_rows", rolling},
      {"radius_rows", radius},
      {"rms",
       {{"fx_over_fz", opt(s.rms_fx_over_fz)},
        {"rolling_rel", opt(s.rms_rolling)},
        {"radius_over_r0", opt(s.rms_radius_over_r0)}}},
      {"max", {{"fx_over_fz", opt(s.max_fx_over_fz)}, {"rolling_rel", opt(s.max_rolling)}}},
      {"reasons",
       {{"force", s.force_reason}, {"rolling", s.rolling_reason}, {"radius", s.radius_reason}}}};
}

void print_slip_comparison(const tir::SlipComparison& s, bool dimensionless) {
  std::cout << "\nLongitudinal laws at " << fixed(s.speed_m_s * 3.6, 1) << " km/h, road mu " << s.mu
            << ", against the model's steady runs on a prescribed wheel (each law at its own "
               "slip"
            << (dimensionless
                    ? "; the file's laws at the same F_z/FNOMIN, scaled to the model's size"
                    : "")
            << "):\n";
  if (!s.rms_fx_over_fz) {
    std::cout << "  F_x (pure slip)  null: " << s.force_reason << "\n";
  } else {
    std::cout << "  F_x (pure slip): RMS (.tir - model) / F_z " << pct(s.rms_fx_over_fz) << " (max "
              << pct(s.max_fx_over_fz) << ")\n    load_N   kappa  model_fx_N  tir_fx_N\n";
    // The table shows kappa 0, +-0.02, +-0.1, +-0.3 of the default grid; --json has every row.
    const auto shown = [](double k) {
      for (double m : {0.0, 0.02, 0.1, 0.3})
        if (std::abs(std::abs(k) - m) < 1e-9) return true;
      return false;
    };
    for (const auto& r : s.force) {
      if (!shown(r.kappa)) continue;
      std::cout << "  " << std::setw(8) << fixed(r.target_load_N, 0) << std::setw(8)
                << fixed(r.kappa, 3) << std::setw(12) << fixed(r.model_fx_N, 1) << std::setw(10)
                << (r.tir_fx_N ? fixed(*r.tir_fx_N, 1) : "-") << "\n";
    }
  }
  if (!s.rms_rolling) {
    std::cout << "  M_y (rolling resistance)  null: " << s.rolling_reason << "\n";
  } else {
    std::cout << "  M_y (rolling resistance, free rolling): RMS (.tir - model) / model "
              << pct(s.rms_rolling) << " (max " << pct(s.max_rolling)
              << ")\n    speed_kmh    fz_N  model_my_Nm  tir_my_Nm\n";
    for (const auto& r : s.rolling) {
      std::cout << "  " << std::setw(11) << fixed(r.speed_m_s * 3.6, 1) << std::setw(8)
                << fixed(r.fz_N, 0) << std::setw(13) << fixed(r.model_moment_Nm, 3) << std::setw(11)
                << (r.tir_moment_Nm ? fixed(*r.tir_moment_Nm, 3) : "-") << "\n";
    }
  }
  if (!s.rms_radius_over_r0) {
    std::cout << "  R_e  null: " << s.radius_reason << "\n";
  } else {
    std::cout << "  R_e (free rolling): RMS (.tir - model) / R0 " << pct(s.rms_radius_over_r0)
              << "\n      fz_N  model_re_mm  tir_re_mm\n";
    for (const auto& r : s.radius) {
      std::cout << "  " << std::setw(8) << fixed(r.fz_N, 0) << std::setw(13)
                << fixed(r.model_radius_m * 1e3, 3) << std::setw(11)
                << (r.tir_radius_m ? fixed(*r.tir_radius_m * 1e3, 3) : "-") << "\n";
    }
  }
}

void plot_comparison(const tir::TirComparison& c, const std::string& path) {
  PlotFigure fig;
  fig.width_px = 1350;
  fig.height_px = 480;
  // Another tyre size is compared dimensionless: the .tir law is drawn scaled to the model's
  // size, and its legend says so (issue 38).
  const auto panel = [&](const char* title, const char* ylabel, auto model_of, auto tir_of,
                         const char* scaled) {
    PlotPanel p{title, "deflection rho [mm]", ylabel, {}};
    PlotSeries m{"model", {}, {}, "linespoints"},
        t{c.dimensionless ? std::string(".tir law scaled to the model's size: ") + scaled
                          : std::string(".tir law"),
          {},
          {},
          "linespoints"};
    for (const auto& r : c.rows) {
      if (auto v = model_of(r)) m.x.push_back(r.rho_m * 1e3), m.y.push_back(*v);
      if (auto v = tir_of(r)) t.x.push_back(r.rho_m * 1e3), t.y.push_back(*v);
    }
    if (m.x.empty()) p.title += " (model: none)";
    if (t.x.empty()) p.title += " (.tir: none)";
    if (!m.x.empty()) p.series.push_back(m);
    if (!t.x.empty()) p.series.push_back(t);
    fig.panels.push_back(p);
  };
  using R = tir::CompareRow;
  using O = std::optional<double>;
  const auto mm = [](const O& v) { return v ? O(*v * 1e3) : O(); };
  panel(
      "vertical load", "load [N]", [](const R& r) { return O(r.load_N); },
      [](const R& r) { return r.tir_load_N; }, "load/FNOMIN x the model's FNOMIN, at rho/R0");
  panel(
      "contact length", "2a [mm]", [](const R& r) { return O(r.model_length_m * 1e3); },
      [&](const R& r) { return mm(r.tir_length_m); }, "2a/R0 x the model's R0");
  panel(
      "contact width", "2b [mm]", [&](const R& r) { return mm(r.model_width_m); },
      [&](const R& r) { return mm(r.tir_width_m); }, "2b/W x the model's width");
  render_plot(fig, path);
}

void run_compare(const TirArgs& a, CLI::App* cmd) {
  // The .tir first: a wrong file is refused before the model is built.
  const tir::MfTyre t = tir::read_mf_tyre(a.tir_file);
  refuse_repeated_overrides(a.overrides);
  const auto config = contact::load_tyre_config(a.config, a.overrides);
  CommandFiles files;
  report::add_config_inputs(files, config);
  files.input(a.tir_file, "TIR");
  if (cmd->count("--plot")) files.output(a.plot, "--plot");
  files.check();
  const auto model = contact::build_tyre_model(config);
  tir::CompareOptions o;
  if (cmd->count("--fnomin")) o.fnomin_N = a.fnomin;
  o.points = a.points;
  std::shared_ptr<ProgressBar> slip_bar;
  if (a.slip) o.slip = slip_options(a, slip_bar);
  const auto c = tir::compare_tir(model, t, o);
  if (slip_bar) slip_bar->finish();
  if (!a.plot.empty()) plot_comparison(c, a.plot);
  if (a.json) {
    nlohmann::json j = comparison_json(c);
    if (c.slip) j["slip"] = slip_comparison_json(*c.slip);
    print_json(j);
  } else {
    print_comparison(c);
    if (c.slip) print_slip_comparison(*c.slip, c.dimensionless);
  }
}

/// The slip runs' options, shared by export and compare --slip.
void add_slip_options(CLI::App* cmd, TirArgs& a) {
  cmd->add_option("--slip-loads", a.slip_loads,
                  "loads of the slip curves [N] (default 0.5, 0.75, 1, 1.25, 1.5 x FNOMIN; at "
                  "least 3)");
  cmd->add_option("--speed-kmh", a.speed_kmh, "speed of the slip curves, LONGVL [km/h] (60)");
  cmd->add_option("--mu", a.mu, "road friction coefficient of the runs (0.8, the FMU's default)");
  cmd->add_option("--slips", a.slips,
                  "slips of the curves (default +-0.0025 ... +-0.3, 24 values)");
  cmd->add_option("--rr-speeds-kmh", a.rr_speeds_kmh,
                  "further free-rolling speeds for the rolling resistance [km/h] (40 80 100 120)");
}

}  // namespace

void register_tir(CLI::App& app) {
  CLI::App* tir = app.add_subcommand(
      "tir",
      "MF-Tyre/MF-Swift .tir bridge: export the model's vertical and contact-patch laws, "
      "or compare any .tir with the model (docs/tir.md)");
  tir->require_subcommand(1);

  auto e = std::make_shared<TirArgs>();
  CLI::App* ex = tir->add_subcommand(
      "export",
      "write an MF-Tyre 6.2 .tir whose [VERTICAL] and [CONTACT_PATCH] are fitted to "
      "the model's footprints over 0.25-2 x FNOMIN");
  ex->add_option("CONFIG", e->config, "tyre config (YAML)")->required();
  ex->add_option("--output", e->output, "the .tir file to write")->required();
  ex->add_option("--loads", e->loads, "loads to fit [N] (default: 12 over 0.25-2 x FNOMIN)");
  ex->add_option("--fnomin", e->fnomin, "nominal load FNOMIN [N] (default: middle of loads_N)");
  ex->add_option("--set", e->overrides, "override a config key");
  ex->add_flag("--uncertainty", e->uncertainty,
               "propagate the inputs' uncertainty (the hammer shapes' noise, stated std) to the "
               "fitted coefficients: printed and in the header's comments (docs/uncertainty.md)");
  add_uncertainty_method_options(ex, e->method);
  add_slip_options(ex, *e);
  ex->add_flag("--no-slip", e->no_slip,
               "leave out the longitudinal, rolling-resistance and effective-radius laws (no "
               "transient runs): the vertical and contact-patch file alone");
  ex->callback([e, ex] { run_export(*e, ex); });

  auto c = std::make_shared<TirArgs>();
  CLI::App* cmp =
      tir->add_subcommand("compare",
                          "a .tir's vertical and contact-patch laws against the model's footprints "
                          "(absolute units for the same tyre size, dimensionless otherwise)");
  cmp->add_option("CONFIG", c->config, "tyre config (YAML)")->required();
  cmp->add_option("TIR", c->tir_file, "MF-Tyre/MF-Swift property file (.tir)")->required();
  cmp->add_option("--fnomin", c->fnomin, "the model's FNOMIN [N] (default: middle of loads_N)");
  cmp->add_option("--points", c->points, "model footprints over 0.25-2 x FNOMIN (3-200)");
  cmp->add_option("--set", c->overrides, "override a config key");
  cmp->add_flag("--json", c->json, "print JSON");
  cmp->add_option("--plot", c->plot, "draw load, length and width against deflection (.svg/.png)");
  cmp->add_flag("--slip", c->slip,
                "also compare the file's longitudinal force, rolling resistance and effective "
                "radius with the model's steady runs on a prescribed wheel (runs the transient: "
                "seconds to a minute)");
  add_slip_options(cmp, *c);
  cmp->callback([c, cmp] { run_compare(*c, cmp); });
}

}  // namespace modaltyre::app
