#include "identify_output.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "cli_support.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/rheology/contact_geometry.h"

namespace modaltyre::app {

namespace rh = modaltyre::rheology;

void print_report(const nlohmann::json& out, const std::string& source) {
  rh::FitReport r;
  r.method = out["method"];
  r.rows = out["rows"];
  r.residual_rms = out["residual_rms"];
  r.residual_unit = out["residual_unit"];
  for (auto it = out["parameters"].begin(); it != out["parameters"].end(); ++it)
    r.parameters.push_back(
        {it.key(), it.value()["value"], it.value()["unit"], it.value()["std_error"]});
  for (const auto& n : out["notes"]) r.notes.push_back(n);
  if (out.contains("pressure_unit"))
    r.notes.push_back(std::string("p_W in (1 + p_W) is gauge pressure in ") +
                      out["pressure_unit"].get<std::string>());
  std::cout << "identify " << r.method << (source.empty() ? "" : " " + source) << ": " << r.rows
            << " rows, residual RMS " << round_sig(r.residual_rms, 4) << " " << r.residual_unit
            << "\n\n";
  std::cout << "  parameter                      value           std_error       unit\n";
  for (const auto& p : r.parameters) {
    char error[32] = "closed form";  // std_error 0: no redundancy, no error estimate
    if (p.std_error != 0) std::snprintf(error, sizeof error, "%.3g", p.std_error);
    char line[256];
    std::snprintf(line, sizeof line, "  %-28s %-15.6g %-15s %s\n", p.name.c_str(),
                  round_sig(p.value, 6), error, p.unit.c_str());
    std::cout << line;
  }
  if (!r.notes.empty()) std::cout << "\n";
  for (const auto& n : r.notes) std::cout << "  note: " << n << "\n";
}

void write_rheology_record(const std::string& path, const RecordSource& source,
                           const nlohmann::json& out) {
  YAML::Emitter e;
  e.SetDoublePrecision(8);
  e << YAML::BeginMap << YAML::Key << "rheology" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "method" << YAML::Value << source.method;
  if (!source.data_file.empty()) e << YAML::Key << "data" << YAML::Value << source.data_file;
  if (!source.tyre_config.empty())
    e << YAML::Key << "tyre_config" << YAML::Value << source.tyre_config;
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
      "# Rheological parameters identified by 'modaltyre identify " + source.method +
      "' (seed 000).\n# A separate document: the tyre config reader rejects unknown keys, so "
      "these values are\n# kept next to the tyre config rather than inside it "
      "(docs/rheology.md).\n";
  text += e.c_str();
  text += "\n";
  write_file_atomically(path, text);
}

void plot_load_deflection(const rh::LoadDeflectionData& data, const rh::LoadDeflectionResult& res,
                          const std::string& path) {
  std::map<long long, PlotSeries> meas;
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
  PlotPanel p{"eq. (3): K_Z = " + fixed(res.K_Z_m * 1e3, 4) + " mm N^{-3/4}",
              "load P_Z [N]",
              "deflection h_Z [mm]",
              {}};
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
  render_plot(PlotFigure{{p}}, path);
}

void plot_b_factors(const rh::SlopeFactorResult& res, const std::string& path) {
  PlotPanel p1{
      "eq. (6): B1 = " + fixed(res.B1, 4), "sin phi1 - phi1 cos phi1", "(1 - cos phi1)^{4/3}", {}};
  PlotPanel p2{"eq. (10): B2 = " + fixed(res.B2, 4),
               "cos phi1 (phi1 - cos phi1 atanh sin phi1)",
               "(1 - cos phi1)^{4/3}",
               {}};
  p1.series.push_back({"exact", res.x1, res.y, "points"});
  p2.series.push_back({"exact", res.x2, res.y, "points"});
  PlotSeries l1{"B1 x",
                {0, res.x1.back()},
                {res.intercept1, res.intercept1 + res.B1 * res.x1.back()},
                "lines"};
  PlotSeries l2{"B2 x",
                {0, res.x2.back()},
                {res.intercept2, res.intercept2 + res.B2 * res.x2.back()},
                "lines"};
  p1.series.push_back(l1);
  p2.series.push_back(l2);
  render_plot(PlotFigure{{p1, p2}, 1200, 500}, path);
}

void plot_contact_stress(const rh::StressData& data, const rh::ContactStressResult& res,
                         double r0_m, const std::string& path) {
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
    f.y.push_back(rh::contact_stress_law(res.K1_Pa_per_m, x, res.deflection_m, r0_m) * 1e-3);
  }
  render_plot(
      PlotFigure{{PlotPanel{"eq. (8)-(12): K1 = " + fixed(res.K1_Pa_per_m * 1e-6, 3) + " MPa/m",
                            "x along the road [mm]",
                            "contact stress [kPa]",
                            {m, f}}}},
      path);
}

void plot_free_vibration(const rh::DecaySignal& signal, const rh::StaticLoop* loop,
                         const rh::FreeVibrationResult& res, const rh::ThreeElementOptions& o,
                         const std::string& path) {
  PlotSeries m{"measured", signal.t_s, {}, "points"}, f{"fitted damped sine", {}, {}, "lines"};
  for (double y : signal.deflection_m) m.y.push_back(y * 1e3);
  const double t0 = signal.t_s.front(), t1 = signal.t_s.back();
  for (int i = 0; i <= 1000; ++i) {
    const double t = t0 + (t1 - t0) * i / 1000.0;
    f.x.push_back(t);
    f.y.push_back(rh::decay_value(res.decay, t) * 1e3);
  }
  PlotFigure fig{{PlotPanel{"T = " + fixed(res.decay.period_s * 1e3, 2) +
                                " ms, delta = " + fixed(res.decay.log_decrement, 4),
                            "time [s]",
                            "deflection h_Z [mm]",
                            {m, f}}}};
  if (res.static_fit) {
    PlotPanel sp{"static loop: E1 = " + fixed(res.static_fit->E1_Pa * 1e-6, 3) +
                     " MPa, chi = " + fixed(res.static_fit->chi, 4),
                 "deflection h_Z [mm]",
                 "load P_Z [N]",
                 {}};
    PlotSeries ml{"loading", {}, {}, "points"}, mu{"unloading", {}, {}, "points"};
    double hmax = 0;
    for (const auto& r : loop->rows) {
      auto& s = r.loading ? ml : mu;
      s.x.push_back(r.deflection_m * 1e3);
      s.y.push_back(r.load_N);
      hmax = std::max(hmax, r.deflection_m);
    }
    PlotSeries fl{"eq. (14) loading", {}, {}, "lines"}, fu{"eq. (14) unloading", {}, {}, "lines"};
    // A tyre cannot pull the road: where a branch of eq. (14) falls below zero load the wheel
    // has left the road, and the curve starts at that zero (it went to -100 N, issue 38).
    const auto branch = [&](PlotSeries& s, bool loading) {
      double h_prev = 0, p_prev = 0;
      for (int i = 1; i <= 60; ++i) {
        const double h = hmax * i / 60;
        const double p =
            rh::static_loop_load(res.static_fit->E1_Pa, res.static_fit->chi, h, loading, o);
        if (p >= 0) {
          if (s.x.empty() && i > 1 && p_prev < 0) {  // the zero between the two samples
            s.x.push_back((h_prev + (h - h_prev) * (-p_prev) / (p - p_prev)) * 1e3);
            s.y.push_back(0);
          }
          s.x.push_back(h * 1e3);
          s.y.push_back(p);
        }
        h_prev = h;
        p_prev = p;
      }
    };
    branch(fl, true);
    branch(fu, false);
    sp.series = {ml, mu, fl, fu};
    fig.panels.push_back(sp);
    fig.width_px = 1200;
  }
  render_plot(fig, path);
}

void plot_soil(const rh::SoilData& data, const rh::SoilResult& res, const std::string& path) {
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
                                    "measured force [N]",
                                    "model force [N]",
                                    {z, x, d}}}},
              path);
}

}  // namespace modaltyre::app
