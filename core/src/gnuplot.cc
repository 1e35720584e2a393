#include "modaltyre/core/gnuplot.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out.push_back('\\');
    out.push_back(c);
  }
  return out + "\"";
}

}  // namespace

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
  const fs::path target(path);
  const std::string stem = "." + target.filename().string() + std::to_string(getpid());
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const fs::path data = dir / (stem + ".dat");
  const fs::path script = dir / (stem + ".gp");
  const fs::path tmp_out = dir / (stem + ext);

  std::ostringstream gp;
  const int n = static_cast<int>(figure.panels.size());
  const int cols = n <= 3 ? n : 2;
  const int rows = (n + cols - 1) / cols;
  gp << "set terminal " << terminal << " size " << figure.width_px * (cols > 1 ? 1 : 1) << ","
     << figure.height_px * rows << "\n";
  gp << "set output " << quote(tmp_out.string()) << "\n";
  gp << "set grid lc rgb '#dddddd'\n";
  if (n > 1) gp << "set multiplot layout " << rows << "," << cols << "\n";
  {
    std::ofstream d(data);
    if (!d) throw InputError({path, 0, "--plot"}, "cannot write next to the plot file");
    int block = 0;
    for (const auto& panel : figure.panels) {
      gp << "set title " << quote(panel.title) << "\n";
      gp << "set key " << panel.key << "\n";
      if (panel.xmax > panel.xmin) {
        gp << "set xrange [" << panel.xmin << ":" << panel.xmax << "]\n";
      } else {
        gp << "set autoscale x\n";
      }
      gp << "set xlabel " << quote(panel.xlabel) << "\nset ylabel " << quote(panel.ylabel) << "\n";
      std::string plot = "plot ";
      for (std::size_t s = 0; s < panel.series.size(); ++s) {
        const auto& ser = panel.series[s];
        for (std::size_t i = 0; i < ser.x.size() && i < ser.y.size(); ++i) {
          d << ser.x[i] << " " << ser.y[i] << "\n";
        }
        d << "\n\n";
        std::string style = ser.style == "points" ? "points pt 7 ps 1.2" : ser.style + " lw 2";
        plot += (s ? ", " : "") + quote(data.string()) + " index " + std::to_string(block++) +
                " with " + style + " title " + quote(ser.title);
      }
      gp << (panel.series.empty() ? "plot 0 notitle" : plot) << "\n";
    }
  }
  if (n > 1) gp << "unset multiplot\n";
  gp << "set output\n";
  {
    std::ofstream s(script);
    s << gp.str();
  }
  const std::string cmd = "gnuplot " + quote(script.string()) + " 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  std::error_code ec;
  fs::remove(data, ec);
  fs::remove(script, ec);
  if (rc != 0 || !fs::exists(tmp_out)) {
    fs::remove(tmp_out, ec);
    throw ComputationError("plotting failed: gnuplot is missing or returned an error (install "
                           "the Debian package gnuplot-nox)");
  }
  fs::rename(tmp_out, target, ec);
  if (ec) throw InputError({path, 0, "--plot"}, "cannot move the finished plot into place");
}

}  // namespace modaltyre
