// modaltyre ema FRF_FILE [--format uff|csv] [--band LO:HI] [--max-order N] [--frf-type T]
//                [--unscaled] [--json] [--plot FILE] [--output HAMMER.csv]
// Experimental modal analysis of a hammer test (docs/ema.md); --output feeds fit-modes and the
// tyre configs (hammer_csv).
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/atomic_file.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/ema/ema.h"
#include "modaltyre/ema/frf_csv.h"
#include "modaltyre/ema/uff58.h"
#include "modaltyre/report/uncertainty_json.h"

namespace modaltyre::app {
namespace {

struct EmaArgs {
  std::string file, format, band, frf_type, plot, output;
  int max_order = ema::EmaOptions{}.max_order;
  bool unscaled = false, json = false;
};

void parse_band(const std::string& text, ema::EmaOptions& o) {
  const auto colon = text.find(':');
  const auto lo =
      colon == std::string::npos ? std::nullopt : parse_finite_double(text.substr(0, colon));
  const auto hi =
      colon == std::string::npos ? std::nullopt : parse_finite_double(text.substr(colon + 1));
  if (!lo || !hi) {
    throw InputError({"--band", 0, ""},
                     "'" + printable(text) + "' is not LO:HI in Hz (e.g. --band 80:350)");
  }
  o.band_lo_hz = *lo;
  o.band_hi_hz = *hi;
}

ema::FrfSet read_frfs(const EmaArgs& a) {
  std::optional<ema::FrfType> given;
  if (!a.frf_type.empty()) given = ema::parse_frf_type(a.frf_type, "--frf-type");
  std::string format = a.format;
  if (format.empty()) {
    const auto dot = a.file.rfind('.');
    format = dot != std::string::npos && a.file.substr(dot) == ".csv" ? "csv" : "uff";
  }
  if (format == "csv") {
    return ema::read_frf_csv(a.file, given.value_or(ema::FrfType::accelerance));
  }
  return ema::with_frf_type(ema::read_uff58(a.file), given);
}

// A shape value, or null where no FRF measured the DOF.
nlohmann::json shape_value(double v) {
  return std::isnan(v) ? nlohmann::json() : nlohmann::json(round_sig(v, 7));
}

nlohmann::json to_json(const ema::EmaResult& r) {
  nlohmann::json modes = nlohmann::json::array();
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const auto& m = r.modes[k];
    nlohmann::json shape = nlohmann::json::array();
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      shape.push_back({{"point", r.points[i]},
                       {"angle_deg", round_sig(r.angle_deg[i])},
                       {"radial", shape_value(m.radial[i])},
                       {"tangential", shape_value(m.tangential[i])}});
      if (!m.radial_std.empty()) {  // docs/uncertainty.md section 5
        shape.back()["radial_std"] = shape_value(m.radial_std[i]);
        shape.back()["tangential_std"] = shape_value(m.tangential_std[i]);
      }
    }
    const auto std_or_null = [](double v) {
      return std::isfinite(v) ? nlohmann::json(round_sig(v, 4)) : nlohmann::json();
    };
    modes.push_back({{"mode", k + 1},
                     {"freq_hz", round_sig(m.freq_hz, 8)},
                     {"damping_ratio", round_sig(m.damping_ratio, 6)},
                     {"freq_std_hz", std_or_null(m.freq_std_hz)},
                     {"damping_std", std_or_null(m.damping_std)},
                     {"mpc", round_sig(m.mpc, 6)},
                     {"complexity", round_sig(m.complexity, 6)},
                     {"recurrence", round_sig(m.recurrence, 4)},
                     {"shape", shape}});
  }
  nlohmann::json dropped = nlohmann::json::array();
  for (const auto& d : r.dropped) {
    dropped.push_back({{"freq_hz", round_sig(d.freq_hz, 8)},
                       {"damping_ratio", round_sig(d.damping_ratio, 6)},
                       {"reason", d.reason}});
  }
  return {{"frf_type", ema::to_string(r.frf_type)},
          {"reference", {{"point", r.reference.point}, {"direction", to_string(r.reference.dir)}}},
          {"roving_hammer", r.roving_hammer},
          {"mass_normalised", r.scaled},
          {"band_hz", {r.band_lo_hz, r.band_hi_hz}},
          {"modes", modes},
          {"dropped", dropped},
          {"notes", r.notes},
          {"warnings", r.warnings},
          {"synthesis_error", round_sig(r.synthesis_error, 6)}};
}

void print_table(const ema::EmaResult& r) {
  std::cout << "FRFs " << r.path << ": " << ema::to_string(r.frf_type) << ", reference "
            << to_string(r.reference) << (r.roving_hammer ? " (roving hammer)" : "") << ", "
            << r.points.size() << " points, band " << fixed(r.band_lo_hz, 2) << "-"
            << fixed(r.band_hi_hz, 2) << " Hz\n\n";
  // Frequency and damping +- 2 sigma from the FRFs' noise (docs/uncertainty.md section 5).
  std::cout << " mode  freq_Hz (+-2sigma)    damping_% (+-2sigma)  MPC     complexity  "
               "recurrence\n";
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const auto& m = r.modes[k];
    const std::string f = report::plus_minus(m.freq_hz, 2 * m.freq_std_hz, 3);
    const std::string z = report::plus_minus(100 * m.damping_ratio, 200 * m.damping_std, 3);
    char line[200];
    std::snprintf(line, sizeof line, " %4zu  %-20s  %-20s  %.4f  %10.4f  %10.2f\n", k + 1,
                  f.c_str(), z.c_str(), m.mpc, m.complexity, m.recurrence);
    std::cout << line;
  }
  for (const auto& d : r.dropped) {
    std::cout << "left out: " << fixed(d.freq_hz, 3) << " Hz (damping "
              << fixed(100 * d.damping_ratio, 2) << " %): " << d.reason << "\n";
  }
  for (const auto& n : r.notes) std::cout << "note: " << n << "\n";
  std::cout << "\nShapes " << (r.scaled ? "mass-normalised [kg^-1/2]" : "UNSCALED (largest 1)")
            << "; re-synthesis error " << fixed(100 * r.synthesis_error, 2)
            << " % (relative RMS)\n";
}

// Stabilisation diagram: model order against frequency, one series per stability class, and
// the FRF sum (log scale) drawn across the order axis behind it.
void plot_diagram(const ema::EmaResult& r, const std::string& path) {
  PlotPanel p;
  p.title = "stabilisation diagram (LSCF) over the FRF sum";
  p.xlabel = "frequency [Hz]";
  p.ylabel = "model order";
  const char* classes = "odfs";
  const char* names[] = {"new pole", "frequency stable", "frequency + damping stable",
                         "stable (also shape)"};
  for (int c = 0; c < 4; ++c) {
    PlotSeries s{names[c], {}, {}, "points"};
    for (const auto& o : r.diagram.orders) {
      for (const auto& q : o.poles) {
        if (q.status == classes[c]) s.x.push_back(q.freq_hz), s.y.push_back(o.order);
      }
    }
    if (!s.x.empty()) p.series.push_back(s);
  }
  const int top = r.diagram.orders.empty() ? 1 : r.diagram.orders.back().order;
  double lo = 1e300, hi = -1e300;
  for (double v : r.sum_magnitude) {
    if (v > 0) lo = std::min(lo, std::log10(v)), hi = std::max(hi, std::log10(v));
  }
  PlotSeries sum{"sum of |H| (log, scaled to the order axis)", {}, {}, "lines"};
  for (std::size_t i = 0; i < r.sum_freq_hz.size() && hi > lo; ++i) {
    if (r.sum_magnitude[i] <= 0) continue;
    sum.x.push_back(r.sum_freq_hz[i]);
    sum.y.push_back(top * (std::log10(r.sum_magnitude[i]) - lo) / (hi - lo));
  }
  p.series.push_back(sum);
  PlotSeries chosen{"identified modes", {}, {}, "points"};
  for (const auto& m : r.modes) chosen.x.push_back(m.freq_hz), chosen.y.push_back(top + 2);
  if (!chosen.x.empty()) p.series.push_back(chosen);
  p.key = "below horizontal";
  p.xmin = r.band_lo_hz;
  p.xmax = r.band_hi_hz;
  p.ymin = 0;
  p.ymax = top + 4;
  PlotFigure fig;
  fig.panels = {p};
  fig.width_px = 1100;
  fig.height_px = 650;
  render_plot(fig, path);
}

}  // namespace

void register_ema(CLI::App& app) {
  auto a = std::make_shared<EmaArgs>();
  CLI::App* cmd = app.add_subcommand(
      "ema",
      "Experimental modal analysis of a hammer test: FRFs (UFF 58 or CSV) -> poles (LSCF "
      "stabilisation diagram) -> residues (LSFD) -> mass-normalised shapes; --output writes "
      "the hammer CSV of fit-modes and the tyre configs.");
  cmd->add_option("FRF_FILE", a->file,
                  "UFF dataset 58/58b file, or CSV: response_point,response_dir,"
                  "reference_point,reference_dir,freq_hz,re,im")
      ->required();
  cmd->add_option("--format", a->format, "uff or csv (default: csv for *.csv, else uff)")
      ->check(CLI::IsMember({"uff", "csv"}));
  cmd->add_option("--band", a->band, "frequency band LO:HI [Hz] (default: all lines > 0 Hz)");
  cmd->add_option("--max-order", a->max_order, "highest LSCF model order (4-200)");
  cmd->add_option("--frf-type", a->frf_type,
                  "accelerance, mobility or receptance (UFF: read from the file; CSV default: "
                  "accelerance)")
      ->check(CLI::IsMember({"accelerance", "mobility", "receptance"}));
  cmd->add_flag("--unscaled", a->unscaled,
                "without a driving-point FRF: shapes scaled to a largest value of 1");
  cmd->add_flag("--json", a->json, "print JSON");
  cmd->add_option("--plot", a->plot, "draw the stabilisation diagram (.svg or .png)");
  cmd->add_option("--output", a->output, "write the hammer CSV (mode,freq_hz,...) to this file");
  cmd->callback([a, cmd] {
    ema::EmaOptions o;
    if (!a->band.empty()) parse_band(a->band, o);
    o.max_order = a->max_order;
    o.unscaled = a->unscaled;
    o.validate();
    CommandFiles files;  // an FRF measurement must never become a hammer CSV by a typo
    files.input(a->file, "FRF_FILE");
    if (cmd->count("--plot")) files.output(a->plot, "--plot");
    if (cmd->count("--output")) files.output(a->output, "--output");
    files.check();
    const ema::FrfSet set = read_frfs(*a);
    const ema::EmaResult r = ema::run_ema(set, o);
    const nlohmann::json j = to_json(r);
    check_finite(j);  // before any file: a failed run leaves none
    if (!a->plot.empty()) plot_diagram(r, a->plot);
    if (!a->output.empty()) write_file_atomically(a->output, ema::hammer_csv(r));
    for (const auto& w : r.warnings) std::cerr << "warning: " << w << "\n";
    if (a->json) {
      print_json(j);
    } else {
      print_table(r);
    }
  });
}

}  // namespace modaltyre::app
