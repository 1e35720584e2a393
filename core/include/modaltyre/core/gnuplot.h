#pragma once
// Publication-style plots through Debian's gnuplot (SVG or PNG chosen by the file extension).
// The library describes the figure; gnuplot draws it. The output is written atomically.
#include <string>
#include <vector>

namespace modaltyre {

struct PlotSeries {
  std::string title;
  std::vector<double> x;
  std::vector<double> y;
  std::string style = "lines";  ///< gnuplot style: "lines", "points", "linespoints", "steps"
};

struct PlotPanel {
  std::string title;
  std::string xlabel;  ///< with unit, e.g. "x along the road [mm]"
  std::string ylabel;
  std::vector<PlotSeries> series;
  std::string key = "top left box opaque";  ///< gnuplot legend placement, e.g. "below"
  double xmin = 0, xmax = 0;                ///< fixed x range when xmax > xmin
};

struct PlotFigure {
  std::vector<PlotPanel> panels;  ///< drawn side by side (1..3) or in a grid
  int width_px = 900;
  int height_px = 560;
};

/// Renders the figure to `path` (.svg or .png). Throws InputError for an unknown extension,
/// ComputationError when gnuplot is missing or fails.
void render_plot(const PlotFigure& figure, const std::string& path);

}  // namespace modaltyre
