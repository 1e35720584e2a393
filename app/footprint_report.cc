#include "footprint_report.h"

#include <iostream>
#include <sstream>

#include "cli_support.h"
#include "modaltyre/contact/validity.h"
#include "footprint_map.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"

namespace modaltyre::app {

namespace {

// Names of the effects switched on, in catalogue order.
std::vector<std::string> enabled_effects(const contact::EffectsConfig& effects) {
  std::vector<std::string> names;
  for (const auto& e : contact::effect_catalogue()) {
    if (effects.enabled(e.id)) names.push_back(e.name);
  }
  return names;
}

// The highest pressure: of the units on the 2D patch, of the whole map on the 3D patch (off the
// centre line with a lateral belt).
double peak_pressure_Pa(const contact::Prediction& p) {
  double peak = 0;
  for (const auto& u : p.footprint.units) peak = std::max(peak, u.pressure_Pa);
  if (p.patch3d) {
    const auto& m = *p.patch3d;
    for (int i = 0; i < m.sections; ++i)
      for (int j = 0; j < m.columns; ++j) peak = std::max(peak, m.pressure_Pa(i, j));
  }
  return peak;
}

}  // namespace

void require_converged(const std::vector<contact::Prediction>& cases) {
  for (const auto& p : cases) {
    if (!p.ok) {
      const auto& r = p.footprint;
      std::ostringstream msg;
      msg << "load case " << r.load.load_N << " N did not converge after " << r.iterations
          << " iterations: " << p.message;
      throw ComputationError(msg.str());
    }
  }
}

nlohmann::json footprint_json(const contact::TyreModel& model,
                              const std::vector<contact::Prediction>& predictions) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& p : predictions) {
    const auto& r = p.footprint;
    nlohmann::json units = nlohmann::json::array();
    for (const auto& u : r.units) {
      units.push_back({{"x_mm", round_sig(u.x_m * 1e3)},
                       {"dx_mm", round_sig(u.dx_m * 1e3)},
                       {"fz_N", round_sig(u.fz_N)},
                       {"fx_N", round_sig(u.fx_N)},
                       {"pressure_kPa", round_sig(u.pressure_Pa * 1e-3)}});
    }
    const double peak = peak_pressure_Pa(p);
    const contact::Validity v = contact::validity(model.config, r.sinking_m, r.contact_length_m);
    cases.push_back({{"load_N", r.load.load_N},
                     {"valid", v.valid},
                     {"validity", v.valid ? nlohmann::json(nullptr) : nlohmann::json(v.reason)},
                     {"horizontal_force_N", r.load.horizontal_force_N},
                     {"sinking_mm", round_sig(r.sinking_m * 1e3)},
                     {"contact_length_mm", round_sig(r.contact_length_m * 1e3)},
                     {"rear_edge_x_mm", round_sig(r.rear_edge_x_m * 1e3)},
                     {"front_edge_x_mm", round_sig(r.front_edge_x_m * 1e3)},
                     {"vertical_stiffness_N_mm", round_sig(r.vertical_stiffness_N_m() * 1e-3)},
                     {"peak_pressure_kPa", round_sig(peak * 1e-3)},
                     {"width_mm", round_sig(p.width_mm)},
                     {"rolling_resistance_N", round_sig(p.rolling_resistance_N)},
                     {"converged", r.converged},
                     {"iterations", r.iterations},
                     {"residuals",
                      {{"vertical_equilibrium", r.equilibrium_residual},
                       {"complementarity", r.complementarity_residual}}},
                     {"units", units}});
    if (p.patch3d) {
      cases.back()["contact_area_mm2"] = round_sig(contact_area_m2(*p.patch3d) * 1e6);
      cases.back()["map"] = pressure_map_json(*p.patch3d);
    }
  }
  const auto& c = model.config;
  nlohmann::json out = {{"tyre", c.name},
                        {"config", c.source},
                        {"effects", enabled_effects(c.effects)},
                        {"model",
                         {{"outer_radius_mm", c.outer_radius_m * 1e3},
                          {"unit_length_mm", round_sig(model.unit_length_m * 1e3)},
                          {"units_around", model.units_around},
                          {"candidate_units", model.candidates()},
                          {"max_order", model.basis.max_order},
                          {"measured_modal_terms", model.basis.measured_terms},
                          {"patch", c.footprint_3d ? "3d" : "2d"}}},
                        {"cases", cases}};
  auto& m = out["model"];
  if (c.footprint_3d) {  // the width is a result; units[].pressure_kPa is the centre line's
    const auto& s = *c.footprint_3d;
    m["tread_width_mm"] = s.tread_width_m * 1e3;
    m["lateral_cell_mm"] = round_sig(s.lateral_cell_m * 1e3);
    m["lateral_belt"] = s.lateral_belt.enabled;
  } else {
    m["contact_width_mm"] = c.tread.width_m * 1e3;
  }
  return out;
}

void warn_outside_validity(const contact::TyreConfig& config,
                           const std::vector<contact::Prediction>& predictions) {
  for (const auto& p : predictions) {
    const auto& r = p.footprint;
    const contact::Validity v = contact::validity(config, r.sinking_m, r.contact_length_m);
    if (v.valid) continue;
    std::cerr << "warning: load " << r.load.load_N
              << " N is outside the model's validity range: " << v.reason
              << "; the footprint is not a prediction (README, \"Validity range\")\n";
  }
}

void print_footprint_table(const contact::TyreModel& model,
                           const std::vector<contact::Prediction>& predictions) {
  const auto& c = model.config;
  std::cout << c.name << " (" << c.source << "): " << model.candidates() << " candidate units of "
            << fixed(model.unit_length_m * 1e3, 3) << " mm, modal orders 0.."
            << model.basis.max_order << " (" << model.basis.measured_terms << " measured modes)\n";
  for (const auto& w : model.basis.warnings) std::cout << "warning: " << w << "\n";
  if (const auto on = enabled_effects(c.effects); !on.empty()) {
    std::cout << "effects on:";
    for (const auto& name : on) std::cout << " " << name;
    std::cout << " (at the config's conditions: " << fixed(c.inflation_pressure_Pa * 1e-3, 0)
              << " kPa, standing, loading, rigid road)\n";
  }
  if (c.footprint_3d) {
    const auto& s = *c.footprint_3d;
    std::cout
        << "3D patch: tread " << fixed(s.tread_width_m * 1e3, 0) << " mm in columns of "
        << fixed(s.lateral_cell_m * 1e3, 2) << " mm"
        << (s.lateral_belt.enabled ? ", lateral belt" : ", laterally rigid belt")
        << "; width and mean pressure over the contact area from the model, peak on the map\n";
  }
  std::cout << "\n  load_N  sinking_mm  length_mm  width_mm  stiffness_N/mm  peak_kPa  mean_kPa"
               "  iters  equilibrium  complementarity\n";
  for (const auto& p : predictions) {
    const auto& r = p.footprint;
    const double peak = peak_pressure_Pa(p);
    const double area =
        p.patch3d ? contact_area_m2(*p.patch3d) : r.contact_length_m * p.width_mm * 1e-3;
    const double mean = r.load.load_N / area;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%8.0f  %10.2f  %9.1f  %8.1f  %14.1f  %8.0f  %8.0f  %5d  %11.1e  %15.1e\n",
                  r.load.load_N, r.sinking_m * 1e3, r.contact_length_m * 1e3, p.width_mm,
                  r.vertical_stiffness_N_m() * 1e-3, peak * 1e-3, mean * 1e-3, r.iterations,
                  r.equilibrium_residual, r.complementarity_residual);
    std::cout << line;
  }
}

void plot_pressures(const std::vector<contact::Prediction>& predictions,
                    const contact::TyreConfig& config, const std::string& path) {
  PlotPanel p;
  p.title = config.name + ": contact pressure along the patch";
  p.xlabel = "x along the road from the contact centre [mm]";
  p.ylabel = "contact pressure [kPa]";
  for (const auto& prediction : predictions) {
    const auto& r = prediction.footprint;
    PlotSeries s;
    s.title =
        fixed(r.load.load_N / 1000, 2) + " kN, L = " + fixed(r.contact_length_m * 1e3, 0) + " mm";
    s.style = "lines";
    // Close the curve to zero at the patch edges so that the length reads off the plot.
    s.x.push_back(r.rear_edge_x_m * 1e3);
    s.y.push_back(0);
    for (const auto& u : r.units) {
      s.x.push_back(u.x_m * 1e3);
      s.y.push_back(u.pressure_Pa * 1e-3);
    }
    s.x.push_back(r.front_edge_x_m * 1e3);
    s.y.push_back(0);
    p.series.push_back(s);
  }
  PlotFigure fig;
  fig.panels.push_back(p);
  render_plot(fig, path);
}

}  // namespace modaltyre::app
