#include "footprint_map.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "cli_support.h"
#include "footprint_report.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"

namespace modaltyre::app {
namespace {

namespace fs = std::filesystem;

// The map of a case (every case of `footprint` on a 3D config has one).
const contact::Patch3dResult& patch_of(const contact::Prediction& p) {
  if (!p.patch3d) throw ComputationError("the pressure map needs the 3D patch (footprint_3d:)");
  return *p.patch3d;
}

// The image needs uniform pixels; the sections' deformed positions are not quite (ds cos theta
// and the belt's own motion): each row of the map is interpolated linearly onto as many
// equally spaced x.
PlotImage uniform_image(const contact::PressureMap& map) {
  PlotImage im;
  im.y = map.y_mm;
  const std::size_t n = map.x_mm.size();
  if (n < 2) return im;
  const double x0 = map.x_mm.front(), x1 = map.x_mm.back();
  for (std::size_t i = 0; i < n; ++i) im.x.push_back(x0 + (x1 - x0) * i / (n - 1));
  for (const auto& row : map.pressure_kPa) {
    std::vector<double> out;
    std::size_t k = 0;
    for (double x : im.x) {
      while (k + 2 < n && map.x_mm[k + 1] < x) ++k;
      const double t = (x - map.x_mm[k]) / (map.x_mm[k + 1] - map.x_mm[k]);
      out.push_back(row[k] + std::clamp(t, 0.0, 1.0) * (row[k + 1] - row[k]));
    }
    im.values.push_back(std::move(out));
  }
  return im;
}

// The outline: front edges of the columns in contact across the tread, back along their rear
// edges, closed.
PlotSeries contour(const contact::Patch3dResult& r) {
  PlotSeries s{"contour", {}, {}, "lines lc 8"};
  std::vector<int> cols;
  for (int j = 0; j < r.columns; ++j)
    if (r.column_edges[j].contact) cols.push_back(j);
  for (int j : cols)
    s.x.push_back(r.column_edges[j].front_x_m * 1e3), s.y.push_back(r.y_m[j] * 1e3);
  for (auto it = cols.rbegin(); it != cols.rend(); ++it) {
    s.x.push_back(r.column_edges[*it].rear_x_m * 1e3);
    s.y.push_back(r.y_m[*it] * 1e3);
  }
  if (!s.x.empty()) s.x.push_back(s.x.front()), s.y.push_back(s.y.front());
  return s;
}

}  // namespace

uncertainty::ExtraOutputs map_cell_outputs(const std::vector<contact::Prediction>& nominal) {
  // The nominal maps fix which cells each case reports: a perturbed patch is read at the same
  // sections and columns.
  std::vector<std::pair<int, int>> range;  // first section, sections
  std::size_t count = 0;
  int columns = 0;
  for (const auto& p : nominal) {
    const contact::PressureMap map = contact::pressure_map(patch_of(p));
    range.emplace_back(map.first_section, static_cast<int>(map.x_mm.size()));
    columns = static_cast<int>(map.y_mm.size());
    count = std::max(count, map.x_mm.size() * map.y_mm.size());
  }
  uncertainty::ExtraOutputs e;
  e.count = count;
  e.label = "map cell";
  e.values = [range, columns](std::size_t c, const contact::Prediction& p) {
    const contact::Patch3dResult& r = patch_of(p);
    std::vector<double> v;
    const auto [first, nx] = range[c];
    for (int j = 0; j < std::min(columns, r.columns); ++j) {
      for (int i = first; i < first + nx; ++i) {
        v.push_back(i < r.sections ? r.pressure_Pa(i, j) * 1e-3 : 0.0);
      }
    }
    return v;
  };
  return e;
}

MapBands take_map_bands(uncertainty::PropagationResult& r) {
  MapBands m;
  const std::size_t keep = uncertainty::output_names().size();
  for (auto& c : r.cases) {
    m.cells.emplace_back(c.bands.begin() + static_cast<std::ptrdiff_t>(keep), c.bands.end());
    c.bands.resize(keep);
  }
  for (auto& e : r.inputs) {
    for (auto& s : e.sensitivity) s.resize(keep);
  }
  return m;
}

void write_map_csv(const std::vector<contact::Prediction>& cases, const std::string& path,
                   const MapBands* bands) {
  std::string text = bands ? "load_N,x_mm,y_mm,pressure_kPa,pressure_p025_kPa,pressure_p975_kPa\n"
                           : "load_N,x_mm,y_mm,pressure_kPa\n";
  char line[192];
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const auto& p = cases[c];
    const contact::PressureMap map = contact::pressure_map(patch_of(p));
    const std::size_t nx = map.x_mm.size();
    for (std::size_t j = 0; j < map.y_mm.size(); ++j) {
      for (std::size_t i = 0; i < nx; ++i) {
        int n = std::snprintf(line, sizeof line, "%.10g,%.6f,%.6f,%.6g", p.footprint.load.load_N,
                              map.x_mm[i], map.y_mm[j], map.pressure_kPa[j][i]);
        if (bands) {
          // A band never below zero: a cell's pressure is a contact force's, >= 0.
          const auto& b = bands->cells[c][j * nx + i];
          n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), ",%.6g,%.6g",
                             std::max(b.p025, 0.0), std::max(b.p975, 0.0));
        }
        text += line;
        text += '\n';
      }
    }
  }
  write_file_atomically(path, text);
}

void plot_footprint_maps(const std::vector<contact::Prediction>& cases,
                         const contact::TyreConfig& config, const std::string& path) {
  PlotFigure fig;
  PlotPanel centre{footprint_plot_subject(config, cases) + ": centre-line contact pressure",
                   "x along the road from the contact centre [mm]",
                   "pressure on the centre line [kPa]",
                   {}};
  double cbmax = 0;
  std::vector<PlotPanel> maps;
  for (const auto& p : cases) {
    const auto& r = patch_of(p);
    PlotPanel m;
    m.title = fixed(p.footprint.load.load_N / 1000, 2) + " kN: L = " + fixed(p.length_mm, 0) +
              " mm, W = " + fixed(p.width_mm, 0) + " mm";
    m.xlabel = "x along the road [mm]";
    m.ylabel = "y across the tread [mm]";
    m.image = uniform_image(contact::pressure_map(r));
    m.image.cblabel = "pressure [kPa]";
    for (const auto& row : m.image.values)
      for (double v : row) cbmax = std::max(cbmax, v);
    m.series.push_back(contour(r));
    m.key = "off";
    m.equal_axes = true;
    // A light load's map is narrow: at most four tick intervals, or the labels collide
    // ("-50-40-30..." on the 2.1 kN panel, issue 38).
    if (!m.image.x.empty()) {
      m.xtics_step = nice_tick_step(m.image.x.back() - m.image.x.front(), 4);
    }
    maps.push_back(std::move(m));
    PlotSeries s{fixed(p.footprint.load.load_N / 1000, 2) + " kN", {}, {}, "lines"};
    s.x.push_back(p.footprint.rear_edge_x_m * 1e3), s.y.push_back(0);
    for (const auto& u : p.footprint.units)
      s.x.push_back(u.x_m * 1e3), s.y.push_back(u.pressure_Pa * 1e-3);
    s.x.push_back(p.footprint.front_edge_x_m * 1e3), s.y.push_back(0);
    centre.series.push_back(std::move(s));
  }
  // One colour scale for every load, as on films of one sensitivity.
  for (auto& m : maps) m.image.cbmax = cbmax;
  fig.panels = std::move(maps);
  fig.panels.push_back(std::move(centre));
  const int n = static_cast<int>(fig.panels.size());
  fig.width_px = n <= 3 ? 520 * n : 1100;
  fig.height_px = 420;
  render_plot(fig, path);
}

}  // namespace modaltyre::app
