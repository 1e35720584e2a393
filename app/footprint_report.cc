#include "footprint_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_support.h"
#include "modaltyre/contact/validity.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/report/condition_settings.h"
#include "modaltyre/report/footprint_json.h"
#include "modaltyre/report/uncertainty_json.h"

namespace modaltyre::app {

using report::describe_conditions;

using report::cell_area_in_contact_m2;
using report::enabled_effects;
using report::peak_pressure_Pa;

void warn_outside_validity(const contact::TyreConfig& config,
                           const std::vector<contact::Prediction>& predictions) {
  for (const auto& p : predictions) {
    const auto& r = p.footprint;
    const contact::Validity v = contact::validity(config, r);
    if (v.valid) continue;
    std::cerr << "warning: load " << r.load.load_N
              << " N is outside the model's validity range: " << v.reason
              << "; the footprint is not a prediction (README, \"Validity range\")\n";
  }
}

void print_footprint_table(const contact::TyreModel& model,
                           const std::vector<contact::Prediction>& predictions,
                           const contact::OperatingConditions& conditions) {
  const auto& c = model.config;
  std::cout << c.name << " (" << c.source << "): " << model.candidates() << " candidate units of "
            << fixed(model.unit_length_m * 1e3, 3) << " mm, modal orders 0.."
            << model.basis.max_order << " (" << model.basis.measured_terms << " measured modes)\n";
  for (const auto& w : model.basis.warnings) std::cout << "warning: " << w << "\n";
  if (const auto on = enabled_effects(c.effects); !on.empty()) {
    std::cout << "effects on:";
    for (const auto& name : on) std::cout << " " << name;
    std::cout << "\n";
  }
  // Conditions act only through effects; stated always so that a run says what it assumed.
  std::cout << "conditions: " << describe_conditions(conditions, c.ground) << "\n";
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
        p.patch3d ? cell_area_in_contact_m2(*p.patch3d) : r.contact_length_m * p.width_mm * 1e-3;
    const double mean = r.load.load_N / area;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%8.0f  %10.2f  %9.1f  %8.1f  %14.1f  %8.0f  %8.0f  %5d  %11.1e  %15.1e\n",
                  r.load.load_N, r.sinking_m * 1e3, r.contact_length_m * 1e3, p.width_mm,
                  r.vertical_stiffness_N_m() * 1e-3, peak * 1e-3, mean * 1e-3, r.iterations,
                  r.equilibrium_residual, r.complementarity_residual);
    std::cout << line;
  }
  // On a soil: sinking is the axle's approach to the undisturbed surface (docs/soil.md 1).
  if (predictions.empty() || !predictions.front().on_soil) return;
  std::cout << "\n  load_N  soil_sinkage_mm  tyre_deflection_mm  bekker_width_mm\n";
  for (const auto& p : predictions) {
    std::printf("%8.0f  %15.2f  %18.2f  %15.1f\n", p.footprint.load.load_N, p.soil_sinkage_mm,
                p.tyre_deflection_mm, p.bekker_width_mm);
  }
  std::fflush(stdout);
}

namespace {

void print_uncertainty_inputs(const uncertainty::PropagationResult& r) {
  std::cout << "inputs (relative standard deviation, source):";
  if (r.inputs.empty()) std::cout << " none";
  std::cout << "\n";
  for (const auto& e : r.inputs) {
    std::printf("  %-28s %6.2f %%  %s\n", e.input.name.c_str(), 100 * e.input.rel_std,
                e.input.source.c_str());
  }
  std::fflush(stdout);
}

}  // namespace

void print_uncertainty_table(const uncertainty::PropagationResult& r) {
  std::cout << "\nuncertainty (" << r.method << ": " << r.check << "), " << report::kBandHeading
            << ":\n";
  const int plain[] = {2, 1, 1, 0, 0};
  const char* names[] = {"sinking_mm", "length_mm", "width_mm", "peak_kPa", "mean_kPa"};
  std::vector<std::vector<std::string>> cells;
  std::vector<std::size_t> width(std::size(names), 0);
  for (std::size_t q = 0; q < width.size(); ++q) width[q] = std::string(names[q]).size();
  for (const auto& c : r.cases) {
    cells.emplace_back();
    for (std::size_t q = 0; q < c.bands.size() && q < width.size(); ++q) {
      cells.back().push_back(report::band_text(c.bands[q], plain[q]));
      width[q] = std::max(width[q], cells.back().back().size());
    }
  }
  std::printf("  load_N");
  for (std::size_t q = 0; q < width.size(); ++q) std::printf("  %-*s", int(width[q]), names[q]);
  std::printf("\n");
  for (std::size_t k = 0; k < r.cases.size(); ++k) {
    std::printf("%8.0f", r.cases[k].load_N);
    for (std::size_t q = 0; q < cells[k].size(); ++q)
      std::printf("  %-*s", int(width[q]), cells[k][q].c_str());
    std::printf("\n");
  }
  print_uncertainty_inputs(r);
}

void print_named_bands(const std::vector<std::string>& names,
                       const uncertainty::PropagationResult& r) {
  std::cout << "uncertainty (" << r.method << ": " << r.check << "), " << report::kBandHeading
            << ":\n";
  const auto& row = r.cases.front().bands;
  for (std::size_t q = 0; q < names.size() && q < row.size(); ++q) {
    std::printf("  %-26s %s\n", names[q].c_str(), report::band_text(row[q], 4).c_str());
  }
  print_uncertainty_inputs(r);
}

std::string footprint_plot_subject(const contact::TyreConfig& config,
                                   const std::vector<contact::Prediction>& cases) {
  const ground::GroundSettings& g = config.ground;
  const std::string model = ground::to_string(g.model);
  std::string on;
  if (g.soil()) {
    on = g.name.empty() ? "a " + model + " soil" : g.name + " (" + model + ")";
  } else if (g.model == ground::GroundModel::profile) {
    on = "the road profile " + std::filesystem::path(g.profile_csv).filename().string();
  } else {
    on = "the rigid road";
  }
  double lo = 0, hi = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const double F = cases[k].footprint.load.load_N / 1000;
    lo = k ? std::min(lo, F) : F, hi = k ? std::max(hi, F) : F;
  }
  const std::string loads =
      cases.empty() ? "" : ", " + fixed(lo, 2) + (hi > lo ? "-" + fixed(hi, 2) : "") + " kN";
  return config.name + " on " + on + loads;
}

void plot_pressures(const std::vector<contact::Prediction>& predictions,
                    const contact::TyreConfig& config, const std::string& path) {
  PlotPanel p;
  p.title = footprint_plot_subject(config, predictions) + ": contact pressure along the patch";
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
