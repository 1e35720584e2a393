// modaltyre identify METHOD [FILE] [options] [--json] [--plot FILE] [--write-config FILE]
// Rheological parameters from simple tyre and soil tests (seed 000).
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/rheology/contact_geometry.h"
#include "modaltyre/rheology/contact_stress.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/slope_factors.h"
#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"

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

Geometry resolve_geometry(const IdentifyArgs& a) {
  Geometry g;
  if (!a.config.empty()) {
    const ConfigTree tree = ConfigTree::load(a.config);
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

nlohmann::json report_json(const rh::FitReport& r) {
  nlohmann::json params = nlohmann::json::object();
  for (const auto& p : r.parameters)
    params[p.name] = {{"value", round_sig(p.value)},
                      {"unit", p.unit},
                      {"std_error", round_sig(p.std_error, 6)}};
  return {{"method", r.method},
          {"parameters", params},
          {"residual_rms", round_sig(r.residual_rms, 6)},
          {"residual_unit", r.residual_unit},
          {"rows", r.rows},
          {"notes", r.notes}};
}

void print_report(const rh::FitReport& r, const std::string& source) {
  std::cout << "identify " << r.method << (source.empty() ? "" : " " + source) << ": " << r.rows
            << " rows, residual RMS " << round_sig(r.residual_rms, 4) << " " << r.residual_unit
            << "\n\n";
  std::cout << "  parameter                      value           std_error       unit\n";
  for (const auto& p : r.parameters) {
    char line[256];
    std::snprintf(line, sizeof line, "  %-28s %-15.6g %-15.3g %s\n", p.name.c_str(), p.value,
                  p.std_error, p.unit.c_str());
    std::cout << line;
  }
  if (!r.notes.empty()) std::cout << "\n";
  for (const auto& n : r.notes) std::cout << "  note: " << n << "\n";
}

void write_rheology_yaml(const IdentifyArgs& a, const nlohmann::json& out) {
  YAML::Emitter e;
  e.SetDoublePrecision(8);
  e << YAML::BeginMap << YAML::Key << "rheology" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "method" << YAML::Value << a.method;
  if (!a.file.empty()) e << YAML::Key << "data" << YAML::Value << a.file;
  if (!a.config.empty()) e << YAML::Key << "tyre_config" << YAML::Value << a.config;
  if (out.contains("pressure_unit"))
    e << YAML::Key << "pressure_unit" << YAML::Value << out["pressure_unit"].get<std::string>();
  e << YAML::Key << "parameters" << YAML::Value << YAML::BeginMap;
  for (auto it = out["parameters"].begin(); it != out["parameters"].end(); ++it) {
    e << YAML::Key << it.key() << YAML::Value << YAML::Flow << YAML::BeginMap;
    e << YAML::Key << "value" << YAML::Value << it.value()["value"].get<double>();
    e << YAML::Key << "unit" << YAML::Value << it.value()["unit"].get<std::string>();
    e << YAML::Key << "std_error" << YAML::Value << it.value()["std_error"].get<double>();
    e << YAML::EndMap;
  }
  e << YAML::EndMap;
  e << YAML::Key << "residual_rms" << YAML::Value << out["residual_rms"].get<double>();
  e << YAML::Key << "residual_unit" << YAML::Value << out["residual_unit"].get<std::string>();
  e << YAML::Key << "rows" << YAML::Value << out["rows"].get<int>();
  e << YAML::EndMap << YAML::EndMap;
  std::string text =
      "# Rheological parameters identified by 'modaltyre identify " + a.method +
      "' (seed 000).\n# A separate document: the tyre config reader rejects unknown keys, so "
      "these values are\n# kept next to the tyre config rather than inside it "
      "(docs/rheology.md).\n";
  text += e.c_str();
  text += "\n";
  write_file_atomically(a.write_config, text);
}

// ---- methods --------------------------------------------------------------------------------

nlohmann::json run_load_deflection(const IdentifyArgs& a, const Geometry& g) {
  const auto data = rh::read_load_deflection_csv(a.file);
  rh::LoadDeflectionOptions o;
  o.r0_m = g.r0_m;
  o.reference_pressure_Pa = g.pressure_Pa;
  const auto res = rh::identify_load_deflection(data, o);
  nlohmann::json out = report_json(res.report);
  out["pressure_unit"] = rh::kPressureUnitName;
  out["reference_pressure_kPa"] = round_sig(res.reference_pressure_Pa * 1e-3);
  out["law"] = "h_Z[mm] = K_Z P_Z[N]^(3/4) / (1 + p_W[bar, gauge])";
  if (!a.plot.empty()) {
    std::map<long long, PlotSeries> meas, fit;
    double pmax = 0;
    for (const auto& r : data.rows) pmax = std::max(pmax, r.load_N);
    for (const auto& r : data.rows) {
      const long long key = std::llround(r.pressure_Pa * 1e-3);
      auto& m = meas[key];
      m.title = "measured " + std::to_string(key) + " kPa";
      m.style = "points";
      m.x.push_back(r.load_N);
      m.y.push_back(r.deflection_m * 1e3);
    }
    PlotPanel p{"eq. (3): K_Z = " + fixed(res.K_Z_m * 1e3, 4) + " mm N^{-3/4}", "load P_Z [N]",
                "deflection h_Z [mm]", {}};
    for (auto& [key, m] : meas) {
      PlotSeries f{"eq. (3) at " + std::to_string(key) + " kPa", {}, {}, "lines"};
      for (int i = 0; i <= 60; ++i) {
        const double P = pmax * 1.05 * i / 60;
        f.x.push_back(P);
        f.y.push_back(rh::law_deflection(res.K_Z_m, P, key * 1e3) * 1e3);
      }
      p.series.push_back(m);
      p.series.push_back(f);
    }
    render_plot(PlotFigure{{p}}, a.plot);
  }
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
  if (!a.plot.empty()) {
    PlotPanel p1{"eq. (6): B1 = " + fixed(res.B1, 4), "sin phi1 - phi1 cos phi1",
                 "(1 - cos phi1)^{4/3}", {}};
    PlotPanel p2{"eq. (10): B2 = " + fixed(res.B2, 4), "cos phi1 (phi1 - cos phi1 atanh sin phi1)",
                 "(1 - cos phi1)^{4/3}", {}};
    p1.series.push_back({"exact", res.x1, res.y, "points"});
    p2.series.push_back({"exact", res.x2, res.y, "points"});
    PlotSeries l1{"B1 x", {0, res.x1.back()}, {res.intercept1, res.intercept1 + res.B1 * res.x1.back()}, "lines"};
    PlotSeries l2{"B2 x", {0, res.x2.back()}, {res.intercept2, res.intercept2 + res.B2 * res.x2.back()}, "lines"};
    p1.series.push_back(l1);
    p2.series.push_back(l2);
    render_plot(PlotFigure{{p1, p2}, 1200, 500}, a.plot);
  }
  return out;
}

nlohmann::json run_contact_stress(const IdentifyArgs& a, const Geometry& g) {
  const auto data = rh::read_contact_stress_csv(a.file);
  rh::ContactStressOptions o;
  o.r0_m = g.r0_m;
  o.tread_width_m = g.tread_width_m;
  o.contact_length_m = positive_or_zero(a.contact_length_mm, "--contact-length-mm") * 1e-3;
  const auto res = rh::identify_contact_stress(data, o);
  nlohmann::json out = report_json(res.report);
  out["pressure_unit"] = rh::kPressureUnitName;
  if (!a.plot.empty()) {
    PlotSeries m{"measured", {}, {}, "points"}, f{"sigma = K1 Delta_P", {}, {}, "lines"};
    double xmax = 0;
    for (const auto& r : data.rows) {
      m.x.push_back(r.x_m * 1e3);
      m.y.push_back(r.stress_Pa * 1e-3);
      xmax = std::max(xmax, std::abs(r.x_m));
    }
    for (int i = -100; i <= 100; ++i) {
      const double x = xmax * i / 100.0;
      f.x.push_back(x * 1e3);
      f.y.push_back(rh::contact_stress_law(res.K1_Pa_per_m, x, res.deflection_m, o.r0_m) * 1e-3);
    }
    render_plot(PlotFigure{{PlotPanel{"eq. (8)-(12): K1 = " + fixed(res.K1_Pa_per_m * 1e-6, 3) +
                                          " MPa/m", "x along the road [mm]",
                                      "contact stress [kPa]", {m, f}}}},
                a.plot);
  }
  return out;
}

nlohmann::json run_free_vibration(const IdentifyArgs& a, const Geometry& g) {
  const auto signal = rh::read_free_vibration_csv(a.file);
  rh::ThreeElementOptions o;
  o.r0_m = g.r0_m;
  o.tread_width_m = g.tread_width_m;
  o.mass_kg = positive_or_zero(a.mass_kg, "--mass-kg");
  o.contact_length_m = positive_or_zero(a.contact_length_mm, "--contact-length-mm") * 1e-3;
  o.section_height_m = positive_or_zero(a.section_height_mm, "--section-height-mm") * 1e-3;
  std::unique_ptr<rh::StaticLoop> loop;
  if (!a.static_file.empty())
    loop = std::make_unique<rh::StaticLoop>(rh::read_static_loop_csv(a.static_file));
  const auto res = rh::identify_free_vibration(signal, loop.get(), o);
  nlohmann::json out = report_json(res.report);
  nlohmann::json amps = nlohmann::json::array();
  for (std::size_t i = 0; i < res.decay.amplitude_m.size(); ++i)
    amps.push_back({{"t_s", round_sig(res.decay.extremum_t_s[i])},
                    {"amplitude_mm", round_sig(res.decay.amplitude_m[i] * 1e3, 6)}});
  out["amplitudes"] = amps;
  if (!a.plot.empty()) {
    PlotSeries m{"measured", signal.t_s, {}, "points"}, f{"fitted damped sine", {}, {}, "lines"};
    for (double y : signal.deflection_m) m.y.push_back(y * 1e3);
    const double t0 = signal.t_s.front(), t1 = signal.t_s.back();
    for (int i = 0; i <= 1000; ++i) {
      const double t = t0 + (t1 - t0) * i / 1000.0;
      f.x.push_back(t);
      f.y.push_back(rh::decay_value(res.decay, t) * 1e3);
    }
    PlotFigure fig{{PlotPanel{"T = " + fixed(res.decay.period_s * 1e3, 2) + " ms, delta = " +
                                  fixed(res.decay.log_decrement, 4),
                              "time [s]", "deflection h_Z [mm]", {m, f}}}};
    if (res.static_fit) {
      PlotPanel sp{"static loop: E1 = " + fixed(res.static_fit->E1_Pa * 1e-6, 3) +
                       " MPa, chi = " + fixed(res.static_fit->chi, 4),
                   "deflection h_Z [mm]", "load P_Z [N]", {}};
      PlotSeries ml{"loading", {}, {}, "points"}, mu{"unloading", {}, {}, "points"};
      double hmax = 0;
      for (const auto& r : loop->rows) {
        auto& s = r.loading ? ml : mu;
        s.x.push_back(r.deflection_m * 1e3);
        s.y.push_back(r.load_N);
        hmax = std::max(hmax, r.deflection_m);
      }
      PlotSeries fl{"eq. (14) loading", {}, {}, "lines"}, fu{"eq. (14) unloading", {}, {}, "lines"};
      for (int i = 1; i <= 60; ++i) {
        const double h = hmax * i / 60;
        fl.x.push_back(h * 1e3);
        fu.x.push_back(h * 1e3);
        fl.y.push_back(rh::static_loop_load(res.static_fit->E1_Pa, res.static_fit->chi, h, true, o));
        fu.y.push_back(rh::static_loop_load(res.static_fit->E1_Pa, res.static_fit->chi, h, false, o));
      }
      sp.series = {ml, mu, fl, fu};
      fig.panels.push_back(sp);
      fig.width_px = 1200;
    }
    render_plot(fig, a.plot);
  }
  return out;
}

nlohmann::json run_soil(const IdentifyArgs& a, const Geometry& g) {
  const auto data = rh::read_soil_rolling_csv(a.file);
  rh::SoilOptions o{g.r0_m, g.tread_width_m};
  const auto res = rh::identify_soil(data, o);
  nlohmann::json out = report_json(res.report);
  if (!a.plot.empty()) {
    PlotSeries z{"P_Z", {}, {}, "points"}, x{"P_X", {}, {}, "points"}, d{"equal", {}, {}, "lines"};
    double fmax = 0;
    for (std::size_t i = 0; i < data.rows.size(); ++i) {
      z.x.push_back(data.rows[i].load_N);
      z.y.push_back(res.predicted_load_N[i]);
      x.x.push_back(data.rows[i].longitudinal_force_N);
      x.y.push_back(res.predicted_longitudinal_N[i]);
      fmax = std::max({fmax, data.rows[i].load_N, std::abs(data.rows[i].longitudinal_force_N)});
    }
    d.x = {0, fmax * 1.05};
    d.y = d.x;
    render_plot(PlotFigure{{PlotPanel{"eq. (25)-(28): E2 = " + fixed(res.E2_Pa * 1e-6, 3) +
                                          " MPa, eta2 = " + fixed(res.eta2_Pa_s * 1e-3, 3) + " kPa s",
                                      "measured force [N]", "model force [N]", {z, x, d}}}},
                a.plot);
  }
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
      ->check(CLI::IsMember({"load-deflection", "b-factors", "contact-stress", "free-vibration",
                             "soil-rolling"}));
  cmd->add_option("FILE", args->file, "measurement CSV (not for b-factors)");
  cmd->add_option("--config", args->config,
                  "tyre config: tyre.outer_radius_mm, tyre.inflation_pressure_kPa, "
                  "tread.contact_width_mm");
  cmd->add_option("--r0-mm", args->r0_mm, "free (outer) radius r0 [mm]");
  cmd->add_option("--tread-width-mm", args->tread_width_mm, "tread / contact width B_tr [mm]");
  cmd->add_option("--mass-kg", args->mass_kg, "reduced oscillating mass m (free-vibration) [kg]");
  cmd->add_option("--contact-length-mm", args->contact_length_mm,
                  "contact length L_C (free-vibration; fixes the deflection in contact-stress)");
  cmd->add_option("--section-height-mm", args->section_height_mm,
                  "section height H of eps1 = Delta_P / H (free-vibration with --static)");
  cmd->add_option("--static", args->static_file,
                  "static loop CSV load_N,deflection_mm,branch for E1 and chi (free-vibration)");
  cmd->add_option("--pressure-kPa", args->pressure_kPa,
                  "gauge pressure at which load-deflection reports C_P (default: the config's, "
                  "else the median of the data)");
  cmd->add_option("--samples", args->samples, "b-factors: points over the range (default 6)");
  cmd->add_option("--sampling", args->sampling, "b-factors: uniform in 'deflection' or 'angle'")
      ->check(CLI::IsMember({"deflection", "angle"}));
  cmd->add_flag("--intercept", args->intercept, "b-factors: fit y = B x + c instead of y = B x");
  cmd->add_option("--max-h-r0", args->max_h_r0, "b-factors: upper end of h_Z/r0 (default 0.117)");
  cmd->add_flag("--json", args->json, "print JSON instead of a table");
  cmd->add_option("--plot", args->plot, "draw the fitted curve over the data (.svg/.png)");
  cmd->add_option("--write-config", args->write_config,
                  "write the identified parameters as a 'rheology:' YAML document");
  cmd->callback([args] {
    const auto& a = *args;
    if (a.method == "b-factors") {
      if (!a.file.empty())
        throw InputError({a.file, 0, ""}, "b-factors takes no FILE (it samples eq. 6 and 10)");
    } else if (a.file.empty()) {
      throw InputError("identify " + a.method + " needs a measurement FILE (docs/rheology.md)");
    }
    if (!a.static_file.empty() && a.method != "free-vibration")
      throw InputError({"--static", 0, ""}, "--static is only used by free-vibration");
    const Geometry g = resolve_geometry(a);
    nlohmann::json out;
    if (a.method == "load-deflection") out = run_load_deflection(a, g);
    else if (a.method == "b-factors") out = run_b_factors(a);
    else if (a.method == "contact-stress") out = run_contact_stress(a, g);
    else if (a.method == "free-vibration") out = run_free_vibration(a, g);
    else out = run_soil(a, g);
    if (!a.file.empty()) out["file"] = a.file;
    check_finite(out);
    if (!a.write_config.empty()) write_rheology_yaml(a, out);
    if (a.json) {
      print_json(out);
    } else {
      rh::FitReport r;
      r.method = out["method"];
      r.rows = out["rows"];
      r.residual_rms = out["residual_rms"];
      r.residual_unit = out["residual_unit"];
      for (auto it = out["parameters"].begin(); it != out["parameters"].end(); ++it)
        r.parameters.push_back({it.key(), it.value()["value"], it.value()["unit"],
                                it.value()["std_error"]});
      for (const auto& n : out["notes"]) r.notes.push_back(n);
      if (out.contains("pressure_unit"))
        r.notes.push_back(std::string("p_W in (1 + p_W) is gauge pressure in ") +
                          out["pressure_unit"].get<std::string>());
      print_report(r, a.file);
    }
  });
}

}  // namespace modaltyre::app
