#include "modaltyre/core/gnuplot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/subprocess.h"

namespace modaltyre {
namespace {

constexpr double kGnuplotTimeout_s = 120.0;
constexpr std::size_t kMaxImageBytes = 256u << 20;

// Keyword arguments (legend placement, plot style) come from the program, never from input;
// they are still reduced to letters, digits and spaces so that nothing else can reach gnuplot.
std::string keywords_only(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == ' ') out.push_back(c);
  }
  return out;
}

void write_number(std::ostream& out, double v) {
  if (std::isfinite(v)) {
    out << v;
  } else {
    out << "NaN";  // gnuplot leaves the point out
  }
}

// A complete image: gnuplot writes the closing tag (SVG) or IEND chunk (PNG) last.
bool image_is_complete(const std::string& bytes, const std::string& ext) {
  if (ext == ".svg") return bytes.find("</svg>") != std::string::npos;
  static const std::string png_magic = "\x89PNG\r\n\x1a\n";
  return bytes.rfind(png_magic, 0) == 0 && bytes.find("IEND") != std::string::npos;
}

std::string first_line(const std::string& text) {
  const auto end = text.find('\n');
  return text.substr(0, std::min<std::size_t>(end, 300));
}

}  // namespace

std::string gnuplot_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') {
      out += "''";
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      out.push_back(' ');  // a newline would end the command
    } else {
      out.push_back(c);
    }
  }
  return out + "'";
}

std::string gnuplot_script(const PlotFigure& figure, const std::string& terminal) {
  std::ostringstream gp;
  const int n = static_cast<int>(figure.panels.size());
  const int cols = n <= 3 ? std::max(n, 1) : 2;
  const int rows = (std::max(n, 1) + cols - 1) / cols;
  gp << "set terminal " << terminal << " size " << figure.width_px << "," << figure.height_px * rows
     << "\n";
  // Data first, as inline datablocks: one per series, no file names anywhere.
  int block = 0;
  for (const auto& panel : figure.panels) {
    for (const auto& ser : panel.series) {
      gp << "$d" << block++ << " << EOD\n";
      for (std::size_t i = 0; i < ser.x.size() && i < ser.y.size(); ++i) {
        write_number(gp, ser.x[i]);
        gp << " ";
        write_number(gp, ser.y[i]);
        gp << "\n";
      }
      gp << "EOD\n";
    }
  }
  int image = 0;
  for (const auto& panel : figure.panels) {
    if (panel.image.empty()) continue;
    gp << "$m" << image++ << " << EOD\n";
    const auto& im = panel.image;
    for (std::size_t j = 0; j < im.y.size() && j < im.values.size(); ++j) {
      for (std::size_t i = 0; i < im.x.size() && i < im.values[j].size(); ++i) {
        write_number(gp, im.x[i]);
        gp << " ";
        write_number(gp, im.y[j]);
        gp << " ";
        write_number(gp, im.values[j][i]);
        gp << "\n";
      }
      gp << "\n";  // one scan line per y
    }
    gp << "EOD\n";
  }
  gp << "set grid lc rgb '#dddddd'\n";
  // Pressure-sensitive film: white where nothing pressed, deepening magenta with pressure.
  gp << "set palette defined (0 '#ffffff', 0.15 '#fbe3ee', 0.5 '#e0529b', 1 '#6e0b40')\n";
  if (n > 1) gp << "set multiplot layout " << rows << "," << cols << "\n";
  block = 0;
  image = 0;
  for (const auto& panel : figure.panels) {
    gp << "set title " << gnuplot_quote(panel.title) << "\n";
    gp << (panel.equal_axes ? "set size ratio -1\n" : "set size noratio\n");
    const auto& im = panel.image;
    if (!im.empty()) {
      gp << "set cblabel " << gnuplot_quote(im.cblabel) << "\n";
      if (im.cbmax > im.cbmin) {
        gp << "set cbrange [" << im.cbmin << ":" << im.cbmax << "]\n";
      } else {
        gp << "set autoscale cb\n";
      }
    }
    gp << "set key " << keywords_only(panel.key) << "\n";
    if (panel.xtics_step > 0) {
      gp << "set xtics " << panel.xtics_step << "\n";
    } else {
      gp << "set xtics autofreq\n";
    }
    if (panel.xmax > panel.xmin) {
      gp << "set xrange [" << panel.xmin << ":" << panel.xmax << "]\n";
    } else {
      gp << "set autoscale x\n";
    }
    if (panel.ymax > panel.ymin) {
      gp << "set yrange [" << panel.ymin << ":" << panel.ymax << "]\n";
    } else {
      gp << "set autoscale y\n";
    }
    gp << "set xlabel " << gnuplot_quote(panel.xlabel) << "\nset ylabel "
       << gnuplot_quote(panel.ylabel) << "\n";
    std::string plot = "plot ";
    if (!im.empty()) plot += "$m" + std::to_string(image++) + " with image notitle";
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const auto& ser = panel.series[s];
      const std::string style =
          ser.style == "points" ? "points pt 7 ps 1.2" : keywords_only(ser.style) + " lw 2";
      plot += (s || !im.empty() ? ", " : "") + std::string("$d") + std::to_string(block++) +
              " with " + style + " title " + gnuplot_quote(ser.title);
    }
    gp << (panel.series.empty() && im.empty() ? "plot 0 notitle" : plot) << "\n";
  }
  if (n > 1) gp << "unset multiplot\n";
  return gp.str();
}

double nice_tick_step(double span, int max_ticks) {
  if (!(span > 0) || max_ticks < 1 || !std::isfinite(span)) return 0;
  const double raw = span / max_ticks;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * decade >= raw * (1 - 1e-12)) return m * decade;
  }
  return 10 * decade;
}

void ensure_min_y_span(PlotPanel& panel, double min_span) {
  if (!(min_span > 0) || panel.ymax > panel.ymin) return;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : panel.series) {
    for (double y : s.y) {
      if (!std::isfinite(y)) continue;
      lo = std::min(lo, y);
      hi = std::max(hi, y);
    }
  }
  if (!(hi >= lo) || hi - lo >= min_span) return;
  const double mid = 0.5 * (lo + hi);
  panel.ymin = mid - 0.5 * min_span;
  panel.ymax = mid + 0.5 * min_span;
}

void render_plot(const PlotFigure& figure, const std::string& path) {
  namespace fs = std::filesystem;
  const std::string ext = fs::path(path).extension().string();
  std::string terminal;
  if (ext == ".svg") {
    terminal = "svg enhanced background rgb 'white' font 'Helvetica,13'";
  } else if (ext == ".png") {
    terminal = "pngcairo enhanced font 'Helvetica,11'";
  } else {
    throw InputError({path, 0, "--plot"}, "plot file must end in .svg or .png");
  }
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    throw InputError({path, 0, "--plot"}, "is a directory; give a file name ending in " + ext);
  }
  // gnuplot's image goes to its stdout (no `set output`): it is held in memory, checked, and
  // only then written; a failed run leaves nothing behind.
  const SubprocessResult run = run_subprocess({"gnuplot"}, gnuplot_script(figure, terminal),
                                              kGnuplotTimeout_s, kMaxImageBytes);
  if (!run.started) {
    throw ComputationError(
        "plotting failed: gnuplot was not found (install the Debian package "
        "gnuplot-nox)");
  }
  if (run.timed_out || run.exit_status != 0 || !image_is_complete(run.out, ext)) {
    std::string why =
        run.timed_out ? "it ran longer than 120 s"
        : run.exit_status != 0
            ? "it exited with status " + std::to_string(run.exit_status)
            : "its image is incomplete (" + std::to_string(run.out.size()) + " bytes)";
    if (!run.err.empty()) why += ": " + first_line(run.err);
    throw ComputationError("plotting " + path + " failed: gnuplot " + why);
  }
  write_file_atomically(path, run.out);
}

}  // namespace modaltyre
