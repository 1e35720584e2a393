#include "identify_soil_plots.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "cli_support.h"
#include "modaltyre/core/gnuplot.h"

namespace modaltyre::app {

void plot_bevameter(const rheology::PlateData& data, const rheology::BevameterResult& res,
                    const std::string& path) {
  std::map<double, PlotSeries> measured;
  double zmax = 0;
  for (const auto& r : data.rows) {
    PlotSeries& s = measured[r.bekker_b_m];
    s.title = "b = " + fixed(r.bekker_b_m * 1e3, 0) + " mm";
    s.style = "points";
    s.x.push_back(r.sinkage_m * 1e3);
    s.y.push_back(r.pressure_Pa * 1e-3);
    zmax = std::max(zmax, r.sinkage_m);
  }
  PlotPanel panel{"Bekker: n = " + fixed(res.n, 3) + ", k_c = " + fixed(res.k_c, 1) +
                      ", k_phi = " + fixed(res.k_phi, 0),
                  "sinkage [mm]",
                  "pressure [kPa]",
                  {}};
  for (auto& [b, s] : measured) {
    PlotSeries fit{"fit, b = " + fixed(b * 1e3, 0) + " mm", {}, {}, "lines"};
    for (int k = 0; k <= 100; ++k) {
      const double z = zmax * k / 100;
      fit.x.push_back(z * 1e3);
      fit.y.push_back((res.k_c / b + res.k_phi) * std::pow(z, res.n));
    }
    panel.series.push_back(std::move(s));
    panel.series.push_back(std::move(fit));
  }
  render_plot(PlotFigure{{panel}}, path);
}

void plot_shear(const rheology::ShearData& data, const rheology::ShearResult& res,
                const std::string& path) {
  std::map<double, PlotSeries> measured;
  double jmax = 0;
  for (const auto& r : data.rows) {
    PlotSeries& s = measured[r.normal_stress_Pa];
    s.title = "sigma = " + fixed(r.normal_stress_Pa * 1e-3, 1) + " kPa";
    s.style = "points";
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
  for (auto& [sigma, s] : measured) {
    PlotSeries fit{"fit, " + fixed(sigma * 1e-3, 1) + " kPa", {}, {}, "lines"};
    for (int k = 0; k <= 100; ++k) {
      const double j = jmax * k / 100;
      fit.x.push_back(j * 1e3);
      fit.y.push_back((res.cohesion_kPa + sigma * 1e-3 * tphi) *
                      (1 - std::exp(-j * 1e3 / res.K_mm)));
    }
    panel.series.push_back(std::move(s));
    panel.series.push_back(std::move(fit));
  }
  render_plot(PlotFigure{{panel}}, path);
}

}  // namespace modaltyre::app
