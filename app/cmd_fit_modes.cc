// modaltyre fit-modes HAMMER.csv [--json] [--plot FILE]
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/mode_identification.h"
#include "modaltyre/report/modes_json.h"
#include "modaltyre/uncertainty/order_probability.h"

namespace modaltyre::app {
namespace {

struct FitModesArgs {
  std::string hammer;
  bool json = false;
  std::string plot;
};

void print_table(const modal::ModeIdentification& id, const std::string& path) {
  std::cout << "Hammer data " << path << ": " << id.modes.size() << " modes at " << id.points
            << " equally spaced points (orders >= " << (id.points + 1) / 2 << " cannot be resolved";
  if ((id.points - 1) / 2 > modal::kMaxFittedOrder) {
    std::cout << "; orders above " << modal::kMaxFittedOrder << " are not fitted";
  }
  std::cout << ")\n\n";
  std::cout << " mode  freq_Hz  damping_%  kind        order  aliased  R2      note\n";
  for (const auto& m : id.modes) {
    char line[256];
    std::snprintf(line, sizeof line, " %4d  %7.2f  %9.3f  %-10s  %5d  %-7s  %.4f  ", m.id,
                  m.freq_hz, 100 * m.damping_ratio, modal::to_string(m.kind), m.apparent_order,
                  m.aliased ? "yes" : "no", m.r2);
    std::cout << line << m.note;
    if (m.aliased && m.likely_order >= 0) std::cout << " (likely order " << m.likely_order << ")";
    // The probability of each candidate order (docs/uncertainty.md section 6), best first.
    const auto chances = uncertainty::alias_order_probabilities(id, m);
    for (std::size_t c = 0; c < std::min<std::size_t>(chances.size(), 3); ++c) {
      std::cout << (c ? ", " : "; P(order): ") << chances[c].order << ": "
                << (chances[c].probability < 1e-3 ? std::string("<0.001")
                                                  : fixed(chances[c].probability, 3));
    }
    std::cout << "\n";
  }
  if (id.dispersion.valid) {
    std::cout << "\nDispersion of the resolved radial orders: f_k = sqrt(s0 + s1 k^2 + s2 k^4)/2pi,"
              << " RMS error " << fixed(100 * id.dispersion.rms_rel_error, 2) << " % over "
              << id.dispersion.orders_used << " orders\n";
  }
}

// A figure of hundreds of panels (or of 10^6 points each) is not readable and took gnuplot
// minutes: the first kMaxPlottedModes modes are drawn, each with at most kMaxPlottedPoints of
// its measured points (evenly thinned).
constexpr std::size_t kMaxPlottedModes = 24;
constexpr std::size_t kMaxPlottedPoints = 720;

std::size_t raw_points(const modal::HammerData& data) {
  return data.modes.empty() ? 0 : data.modes.front().radial.size();
}

void plot_modes(const modal::HammerData& data, const modal::ModeIdentification& id,
                const std::string& path) {
  PlotFigure fig;
  fig.width_px = 1200;
  fig.height_px = 300;
  if (id.modes.size() > kMaxPlottedModes) {
    std::cerr << "note: the plot shows the first " << kMaxPlottedModes << " of " << id.modes.size()
              << " modes\n";
  }
  const std::size_t stride =
      std::max<std::size_t>(1, (raw_points(data) + kMaxPlottedPoints - 1) / kMaxPlottedPoints);
  for (std::size_t i = 0; i < std::min(id.modes.size(), kMaxPlottedModes); ++i) {
    const auto& m = id.modes[i];
    const auto& raw = data.modes[i];
    PlotPanel p;
    p.title = "mode " + std::to_string(m.id) + ": " + fixed(m.freq_hz, 1) + " Hz, " +
              modal::to_string(m.kind) + " k=" + std::to_string(m.apparent_order) +
              (m.aliased ? " (aliased)" : "");
    p.xlabel = "angle [deg]";
    p.ylabel = "shape [kg^{-1/2}]";
    const bool rot = m.kind == modal::ModeKind::rotation;
    PlotSeries pts{rot ? "tangential, measured" : "radial, measured", {}, {}, "points"};
    const auto& measured = rot ? raw.tangential : raw.radial;
    double amplitude = 0;
    for (std::size_t j = 0; j < measured.size(); ++j) {
      amplitude = std::max(amplitude, std::abs(measured[j]));
      if (j % stride) continue;
      pts.x.push_back(raw.angle_rad[j] * 180 / M_PI);
      pts.y.push_back(measured[j]);
    }
    PlotSeries fit{"fitted harmonic", {}, {}, "lines"};
    const auto& series = rot ? m.tangential : m.radial;
    const int k = m.apparent_order;
    const auto c = series.coefficient(k);
    for (int s = 0; s <= 360; s += 2) {
      const double th = s * M_PI / 180;
      fit.x.push_back(s);
      fit.y.push_back((c * std::polar(1.0, k * th)).real());
    }
    p.series = {pts, fit};
    // Beside the plot: below it, the legend ran into the x label of these short panels.
    p.key = "outside right top vertical";
    p.xmin = 0;
    p.xmax = 360;
    // Symmetric about zero: a breathing or rotation shape (order 0) is a constant, and an
    // autoscaled axis would blow its few per cent of scatter up to the full panel height.
    p.ymin = -1.15 * amplitude;
    p.ymax = 1.15 * amplitude;
    fig.panels.push_back(p);
  }
  render_plot(fig, path);
}

}  // namespace

void register_fit_modes(CLI::App& app) {
  auto args = std::make_shared<FitModesArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fit-modes",
      "Fit the trigonometric series of seed 001 eq. (20)-(21) to each mode of an N-point hammer "
      "test; report harmonic order, kind (radial / rotation / unresolved), fit quality R2 and "
      "spatial aliasing.");
  cmd->add_option("HAMMER", args->hammer,
                  "long-format CSV: mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential")
      ->required();
  cmd->add_flag("--json", args->json, "print JSON instead of a table");
  cmd->add_option("--plot", args->plot, "draw each mode's points and fitted harmonic (.svg/.png)");
  cmd->callback([args, cmd] {
    CommandFiles files;
    files.input(args->hammer, "HAMMER");
    if (cmd->count("--plot")) files.output(args->plot, "--plot");
    files.check();
    const auto data = modal::read_hammer_csv(args->hammer);
    const auto id = modal::identify_modes(data);
    if (!args->plot.empty()) plot_modes(data, id, args->plot);
    if (args->json) {
      print_json(report::modes_json(id));
    } else {
      print_table(id, args->hammer);
    }
  });
}

}  // namespace modaltyre::app
