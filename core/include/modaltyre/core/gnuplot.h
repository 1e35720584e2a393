#pragma once
// Publication-style plots through Debian's gnuplot (SVG or PNG chosen by the file extension).
// The library describes the figure; gnuplot draws it. gnuplot runs without a shell, reads its
// script (data included) on stdin and writes the image to stdout; the image is checked (exit
// status, complete file) and written through write_file_atomically: whole or not at all.
#include <string>
#include <vector>

namespace modaltyre {

struct PlotSeries {
  std::string title;
  std::vector<double> x;
  std::vector<double> y;
  std::string style = "lines";  ///< gnuplot style: "lines", "points", "linespoints", "steps"
};

/// A map drawn as an image, one pixel per grid point coloured by its value (gnuplot `with
/// image`), e.g. a contact-pressure map printed like a pressure-sensitive film. The grids must be
/// uniform: values[j][i] at (x[i], y[j]); white at cbmin, darkest at cbmax.
struct PlotImage {
  std::vector<double> x, y;
  std::vector<std::vector<double>> values;
  std::string cblabel;          ///< colour-bar label with unit
  double cbmin = 0, cbmax = 0;  ///< fixed colour range when cbmax > cbmin
  bool empty() const { return x.empty() || y.empty(); }
};

struct PlotPanel {
  std::string title;
  std::string xlabel;  ///< with unit, e.g. "x along the road [mm]"
  std::string ylabel;
  std::vector<PlotSeries> series;
  /// gnuplot legend placement. Outside the plot area by default: a legend inside it covered
  /// data (issue 38: validate's width panel, the 2D footprint); e.g. "outside right top".
  std::string key = "below";
  double xmin = 0, xmax = 0;  ///< fixed x range when xmax > xmin
  double ymin = 0, ymax = 0;  ///< fixed y range when ymax > ymin
  PlotImage image = {};       ///< drawn under the series when not empty
  bool equal_axes = false;    ///< one unit as long on both axes (a footprint's true shape)
  /// Distance between x tick labels (0: gnuplot's choice, which crowds a narrow equal-axes
  /// panel until the labels collide; see nice_tick_step).
  double xtics_step = 0;
};

/// A tick distance of 1, 2 or 5 x 10^k giving at most `max_ticks` intervals over `span`.
double nice_tick_step(double span, int max_ticks);

struct PlotFigure {
  std::vector<PlotPanel> panels;  ///< drawn side by side (1..3) or in a grid
  int width_px = 900;
  int height_px = 560;
};

/// Fixes the panel's y range to span at least `min_span` around its data when the data span
/// less: a constant signal with numerical noise (+-1e-11 N) is then drawn flat at its level
/// instead of being auto-scaled into what looks like a signal. No change when the data span
/// enough, when min_span <= 0, or when the range is already fixed.
void ensure_min_y_span(PlotPanel& panel, double min_span);

/// Renders the figure to `path` (.svg or .png). Throws InputError for an unknown extension or
/// an unwritable path, ComputationError when gnuplot is missing or fails.
void render_plot(const PlotFigure& figure, const std::string& path);

/// The gnuplot script for the figure (data inline), image to stdout. Every text of the figure
/// is a single-quoted gnuplot string with control characters removed, so no title or label
/// can end the command or run a backquoted shell command. Exposed for tests.
std::string gnuplot_script(const PlotFigure& figure, const std::string& terminal);

/// A gnuplot single-quoted string literal for arbitrary text (no escapes are interpreted
/// inside single quotes; a quote is doubled; control characters become spaces).
std::string gnuplot_quote(const std::string& text);

}  // namespace modaltyre
