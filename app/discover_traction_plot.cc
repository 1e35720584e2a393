#include "discover_traction_plot.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "cli_support.h"
#include "modaltyre/discover/traction_evidence.h"

namespace modaltyre::app {
namespace {

// One curve: a load, speed and pass; per slip the measured value and the two predictions.
using Curve = std::map<double, std::tuple<double, double, double>>;
using CurveKey = std::tuple<double, double, int>;  // load, speed, pass

std::map<CurveKey, Curve> curves(const discover::DiscoverReport& r,
                                 const studies::MeasurementSet& data, const std::string& obs,
                                 double R0, bool per_load) {
  std::map<CurveKey, Curve> out;
  for (std::size_t i = 0; i < data.rows.size(); ++i) {
    const auto& row = data.rows[i];
    const auto measured = row.value(obs);
    const auto& res = r.rows[i];
    if (!row.traction || !measured || !res.before.count(obs) || !res.after.count(obs)) continue;
    const double scale = discover::residual_scale(row, obs, *measured, R0);
    const double f = per_load ? 1 / row.conditions.load_N : 1;
    out[{row.conditions.load_N, row.conditions.speed_kmh, row.traction->pass}][row.traction->slip] =
        {f * *measured, f * (*measured + res.before.at(obs) * scale),
         f * (*measured + res.after.at(obs) * scale)};
  }
  return out;
}

PlotPanel panel(const discover::DiscoverReport& r, const studies::MeasurementSet& data,
                const std::string& obs, double R0, bool per_load, const std::string& ylabel) {
  const std::string xlabel = "slip s against the rolling radius r_e [-]";
  const std::string after =
      r.effects.empty() ? "baseline (nothing named)" : "with the named effects";
  PlotPanel p{ylabel.substr(0, ylabel.find(" [")) + ": measured and predicted", xlabel, ylabel, {}};
  int colour = 0;
  for (const auto& [key, curve] : curves(r, data, obs, R0, per_load)) {
    const auto& [load, speed, pass] = key;
    const std::string lc = plot_colour(colour++);
    std::string name = fixed(load, 0) + " N";
    if (speed > 0) name += ", " + fixed(speed, 1) + " km/h";
    if (pass > 1) name += ", pass " + std::to_string(pass);
    PlotSeries m{name + " measured", {}, {}, "points pt 7" + lc},
        b{name + " baseline", {}, {}, "lines dt 2" + lc},
        a{name + " " + after, {}, {}, "lines" + lc};
    for (const auto& [slip, v] : curve) {
      m.x.push_back(slip), m.y.push_back(std::get<0>(v));
      b.x.push_back(slip), b.y.push_back(std::get<1>(v));
      a.x.push_back(slip), a.y.push_back(std::get<2>(v));
    }
    p.series.push_back(std::move(m));
    p.series.push_back(std::move(b));
    if (!r.effects.empty()) p.series.push_back(std::move(a));  // else the baseline's again
  }
  return p;
}

}  // namespace

void add_traction_panels(PlotFigure& figure, const discover::DiscoverReport& report,
                         const studies::MeasurementSet& data, double outer_radius_m) {
  if (data.traction_rows() == 0) return;
  const auto has = [&](const char* o) {
    return std::find(data.observables.begin(), data.observables.end(), o) != data.observables.end();
  };
  if (has("drawbar_pull_N"))
    figure.panels.push_back(
        panel(report, data, "drawbar_pull_N", outer_radius_m, true, "drawbar pull / load [-]"));
  if (has("soil_sinkage_mm"))
    figure.panels.push_back(
        panel(report, data, "soil_sinkage_mm", outer_radius_m, false, "soil sinkage [mm]"));
}

}  // namespace modaltyre::app
