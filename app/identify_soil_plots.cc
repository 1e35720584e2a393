#include "identify_soil_plots.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "cli_support.h"
#include "modaltyre/core/gnuplot.h"

namespace modaltyre::app {
// Each plate's loading rows with its Bekker curve, each unloading cycle's rows with Wong's line
// p = p_max - k_u (z_max - z), k_u = k0 + Au z_max, in the colour of its plate. The title
// writes k_phi as enhanced text (k_{phi}: an underscore alone subscripts one letter).
void plot_bevameter(const rheology::PlateData& data, const rheology::BevameterResult& res,
                    const std::string& path) {
  const bool circular = data.shape == rheology::PlateShape::circular;
  std::map<double, int> plate;  // b -> colour
  for (const auto& r : data.rows) plate.emplace(r.bekker_b_m, 0);
  int k = 0;
  for (auto& [b, c] : plate) c = k++;
  double zmax = 0;
  for (const auto& r : data.rows) zmax = std::max(zmax, r.sinkage_m);
  PlotPanel panel{
      "Bekker: n = " + fixed(res.n, 3) + ", k_c = " + fixed(res.k_c, 1) +
          ", k_{phi} = " + fixed(res.k_phi, 0) +
          (res.has_unloading ? "; Wong: k_0 = " + fixed(res.k0, 0) + ", A_u = " + fixed(res.Au, 0)
                             : std::string()) +
          (circular ? " (b = plate radius)" : " (b = plate width)"),
      "sinkage [mm]",
      "pressure [kPa]",
      {}};
  for (const auto& [b, c] : plate) {
    const std::string size = "b = " + fixed(b * 1e3, 0) + " mm";
    PlotSeries pts{size, {}, {}, "points pt 7" + plot_colour(c)};
    for (const auto& r : data.rows)
      if (r.bekker_b_m == b && r.cycle == 0)
        pts.x.push_back(r.sinkage_m * 1e3), pts.y.push_back(r.pressure_Pa * 1e-3);
    PlotSeries fit{"fit, " + size, {}, {}, "lines" + plot_colour(c)};
    for (int i = 0; i <= 100; ++i) {
      const double z = zmax * i / 100;
      fit.x.push_back(z * 1e3);
      fit.y.push_back((res.k_c / b + res.k_phi) * std::pow(z, res.n));
    }
    panel.series.push_back(std::move(pts));
    panel.series.push_back(std::move(fit));
  }
  // Unloading cycles: their rows as open circles and the identified line over their span.
  std::map<int, std::vector<const rheology::PlateRow*>> cycles;
  for (const auto& r : data.rows)
    if (r.cycle > 0) cycles[r.cycle].push_back(&r);
  for (const auto& [id, rows] : cycles) {
    const int c = plate.at(rows.front()->bekker_b_m);
    const std::string name = "cycle " + std::to_string(id);
    PlotSeries pts{name, {}, {}, "points pt 6" + plot_colour(c)};
    const rheology::PlateRow* top = rows.front();
    double lo = top->sinkage_m;
    for (const auto* r : rows) {
      pts.x.push_back(r->sinkage_m * 1e3), pts.y.push_back(r->pressure_Pa * 1e-3);
      if (r->sinkage_m > top->sinkage_m) top = r;
      lo = std::min(lo, r->sinkage_m);
    }
    panel.series.push_back(std::move(pts));
    if (!res.has_unloading) continue;
    const double ku = res.k0 + res.Au * top->sinkage_m;  // kN/m^3 = kPa/m
    PlotSeries line{"Wong's unloading, " + name, {}, {}, "lines dt 2" + plot_colour(c)};
    for (double z : {lo, top->sinkage_m}) {
      line.x.push_back(z * 1e3);
      line.y.push_back(top->pressure_Pa * 1e-3 - ku * (top->sinkage_m - z));
    }
    panel.series.push_back(std::move(line));
  }
  render_plot(PlotFigure{{panel}}, path);
}

// Each normal stress's rows with its own Janosi-Hanamoto curve, in one colour per stress.
void plot_shear(const rheology::ShearData& data, const rheology::ShearResult& res,
                const std::string& path) {
  std::map<double, PlotSeries> measured;
  double jmax = 0;
  for (const auto& r : data.rows) {
    PlotSeries& s = measured[r.normal_stress_Pa];
    s.title = "sigma = " + fixed(r.normal_stress_Pa * 1e-3, 1) + " kPa";
    s.x.push_back(r.displacement_m * 1e3);
    s.y.push_back(r.shear_stress_Pa * 1e-3);
    jmax = std::max(jmax, r.displacement_m);
  }
  PlotPanel panel{"Janosi-Hanamoto: c = " + fixed(res.cohesion_kPa, 2) + " kPa, phi = " +
                      fixed(res.friction_angle_deg, 1) + " deg, K = " + fixed(res.K_mm, 1) + " mm",
                  "shear displacement [mm]",
                  "shear stress [kPa]",
                  {}};
  const double tphi = std::tan(res.friction_angle_deg * M_PI / 180);
  int c = 0;
  for (auto& [sigma, s] : measured) {
    s.style = "points pt 7" + plot_colour(c);
    PlotSeries fit{"fit, " + fixed(sigma * 1e-3, 1) + " kPa", {}, {}, "lines" + plot_colour(c)};
    for (int k = 0; k <= 100; ++k) {
      const double j = jmax * k / 100;
      fit.x.push_back(j * 1e3);
      fit.y.push_back((res.cohesion_kPa + sigma * 1e-3 * tphi) *
                      (1 - std::exp(-j * 1e3 / res.K_mm)));
    }
    panel.series.push_back(std::move(s));
    panel.series.push_back(std::move(fit));
    ++c;
  }
  render_plot(PlotFigure{{panel}}, path);
}

}  // namespace modaltyre::app
