#include "traction_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "cli_support.h"
#include "modaltyre/contact/traction_curve.h"
#include "modaltyre/core/gnuplot.h"

namespace modaltyre::app {
namespace {

std::string soil_name(const ground::GroundSettings& g) {
  return g.name.empty() ? ground::to_string(g.model) : g.name;
}

double contact_width_m(const TractionRun& run) {
  const contact::TyreConfig& c = *run.config;
  const bool patch_3d = !run.rigid && c.footprint_3d.has_value();
  return patch_3d ? c.footprint_3d->tread_width_m : c.tread.width_m;
}

}  // namespace

void print_traction_table(const TractionRun& run,
                          const std::vector<contact::TractionResult>& results) {
  const contact::TyreConfig& config = *run.config;
  const bool patch_3d = !run.rigid && config.footprint_3d.has_value();
  const bool rolling = run.reference == contact::SlipReference::rolling;
  std::cout << (run.rigid  ? "rigid cylinder"
                : patch_3d ? "flexible tyre (3D patch)"
                           : "flexible tyre (2D patch)")
            << " R0 " << fixed(config.outer_radius_m * 1e3, 1) << " mm, width "
            << fixed(contact_width_m(run) * 1e3, 1) << " mm on " << soil_name(*run.ground)
            << "; slip against " << (rolling ? "the rolling radius r_e (ISTVS)" : "R0") << "\n";
  std::cout << "  load_N    slip" << (run.passes > 1 ? "  pass" : "")
            << "  sinkage_mm  rut_mm  drawbar_N  thrust_N  resist_N  (compact   flex  "
               "bulldoze)  torque_Nm  entry_deg  exit_deg  b_mm   eta\n";
  std::vector<std::string> notes;  // why rows are marked
  for (const auto& r : results) {
    char line[256];
    std::snprintf(line, sizeof line, "%8.0f  %6.3f", r.load_N, r.slip);
    std::cout << line;
    if (run.passes > 1)
      std::cout << "  " << std::string(4 - std::to_string(r.pass).size(), ' ') << r.pass;
    if (!r.ok()) {
      std::cout << "  failed: " << r.message << "\n";
      continue;
    }
    std::snprintf(line, sizeof line,
                  "  %10.2f  %6.2f  %9.1f  %8.1f  %8.1f  (%7.1f %6.1f  %8.1f)  %9.1f  %9.2f  %8.2f"
                  "  %5.1f  %4.2f",
                  r.soil_sinkage_m * 1e3, r.rut_depth_m * 1e3, r.drawbar_pull_N, r.thrust_N,
                  r.motion_resistance_N, r.compaction_resistance_N, r.flexing_resistance_N,
                  r.bulldozing_resistance_N, r.torque_Nm, r.entry_angle_rad * 180 / M_PI,
                  r.exit_angle_rad * 180 / M_PI, r.bekker_width_m * 1e3, r.tractive_efficiency);
    std::cout << line;
    if (!r.valid) {
      notes.push_back(r.validity);
      std::cout << "  *" << notes.size();
    }
    if (r.rut_reach_units >= 0) std::cout << "  ~" << fixed(r.rut_reach_units, 1);
    std::cout << "\n";
  }
  for (std::size_t k = 0; k < notes.size(); ++k)
    std::cout << "  *" << k + 1 << " outside the validity range, not a prediction: " << notes[k]
              << "\n";
  if (std::any_of(results.begin(), results.end(),
                  [](const contact::TractionResult& r) { return r.rut_reach_units >= 0; }))
    std::cout << "  ~R: Wong-Reece's rut behind theta2 extrapolated R of a unit behind the last "
                 "rear cell, not to theta2, where the rolling did not settle (an O(h) error on "
                 "coarse units; docs/soil.md section 10, \"Mesh\")\n";
  for (const contact::TractionCurve& c : contact::traction_curves(results)) {
    const contact::TractionResult& first = *c.rows.front();
    if (!(first.rolling_radius_m > 0)) continue;
    std::cout << "  " << fixed(c.load_N, 0) << " N" << (run.passes > 1 ? ", pass " : "")
              << (run.passes > 1 ? std::to_string(c.pass) : "") << ": r_e "
              << fixed(first.rolling_radius_m * 1e3, 2) << " mm (loaded radius "
              << fixed(first.loaded_radius_m * 1e3, 2) << " mm on the road); towed point ";
    if (c.towed)
      std::cout << "s " << fixed(c.towed->slip, 4) << ", drawbar pull " << fixed(c.towed->value, 1)
                << " N";
    else
      std::cout << "outside the slips given";
    std::cout << "; self-propelled point ";
    if (c.self_propelled)
      std::cout << "s " << fixed(c.self_propelled->slip, 4) << ", torque "
                << fixed(c.self_propelled->value, 1) << " N m\n";
    else
      std::cout << "outside the slips given\n";
  }
}

// Three panels against slip (braked to driven, through zero, the zero lines drawn): drawbar pull
// over load with the towed and self-propelled points, soil sinkage, tractive efficiency. One
// colour per curve (load and pass) for its line, its points and its marks; invalid rows again as
// open circles in that colour.
void plot_traction(const TractionRun& run, const std::vector<contact::TractionResult>& results,
                   const std::string& path) {
  const bool rolling = run.reference == contact::SlipReference::rolling;
  const std::string xlabel =
      rolling ? "slip s against the rolling radius r_e [-]" : "slip s against R0 [-]";
  std::string loads;
  for (const contact::TractionCurve& c : contact::traction_curves(results))
    if (loads.find(fixed(c.load_N, 0) + " N") == std::string::npos)
      loads += (loads.empty() ? "" : ", ") + fixed(c.load_N, 0) + " N";
  // The titles together name the tyre, the soil and the loads.
  PlotPanel dp{
      (run.rigid ? "rigid cylinder of " : "") + run.config->name + " on " + soil_name(*run.ground),
      xlabel,
      "drawbar pull / load [-]",
      {}};
  PlotPanel sink{"soil sinkage at " + loads, xlabel, "soil sinkage [mm]", {}};
  PlotPanel eta{"tractive efficiency DP V / (T omega)", xlabel, "tractive efficiency [-]", {}};
  double lo = 0, hi = 0;
  int colour = 0;
  for (const contact::TractionCurve& c : contact::traction_curves(results)) {
    const std::string lc = plot_colour(colour++);
    const std::string name =
        fixed(c.load_N, 0) + " N" + (c.pass > 1 ? ", pass " + std::to_string(c.pass) : "");
    PlotSeries d{name, {}, {}, "linespoints pt 7" + lc}, z{name, {}, {}, "linespoints pt 7" + lc},
        e{name, {}, {}, "linespoints pt 7" + lc};
    PlotSeries bad{name + ": outside the validity range", {}, {}, "points pt 6 ps 2" + lc};
    std::vector<const contact::TractionResult*> rows = c.rows;
    std::sort(rows.begin(), rows.end(),
              [](const auto* a, const auto* b) { return a->slip < b->slip; });
    for (const auto* r : rows) {
      if (!r->ok()) continue;
      lo = std::min(lo, r->slip), hi = std::max(hi, r->slip);
      d.x.push_back(r->slip), d.y.push_back(r->drawbar_pull_N / r->load_N);
      z.x.push_back(r->slip), z.y.push_back(r->soil_sinkage_m * 1e3);
      e.x.push_back(r->slip), e.y.push_back(r->tractive_efficiency);
      if (!r->valid) bad.x.push_back(r->slip), bad.y.push_back(r->drawbar_pull_N / r->load_N);
    }
    dp.series.push_back(std::move(d));
    if (!bad.x.empty()) dp.series.push_back(std::move(bad));
    if (c.towed)
      dp.series.push_back({name + ": towed (T = 0)",
                           {c.towed->slip},
                           {c.towed->value / c.load_N},
                           "points pt 9 ps 2" + lc});
    if (c.self_propelled)
      dp.series.push_back({name + ": self-propelled (DP = 0)",
                           {c.self_propelled->slip},
                           {0.0},
                           "points pt 5 ps 2" + lc});
    sink.series.push_back(std::move(z));
    eta.series.push_back(std::move(e));
  }
  // The zero lines: the braked side, free rolling and the driven side at a glance.
  const double span = std::max(hi - lo, 0.1);
  dp.xmin = sink.xmin = eta.xmin = std::min(lo, 0.0) - 0.05 * span;
  dp.xmax = sink.xmax = eta.xmax = std::max(hi, 0.0) + 0.05 * span;
  double ylo = 0, yhi = 0;
  for (const auto& s : dp.series)
    for (double y : s.y) ylo = std::min(ylo, y), yhi = std::max(yhi, y);
  dp.series.push_back({"", {dp.xmin, dp.xmax}, {0.0, 0.0}, "lines lc 8"});
  dp.series.push_back({"", {0.0, 0.0}, {ylo, yhi}, "lines lc 8"});
  PlotFigure figure{{dp, sink, eta}};
  figure.width_px = 1600;
  render_plot(figure, path);
}

}  // namespace modaltyre::app
