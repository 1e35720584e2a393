// The evidence study of the 3D footprint (docs/validation.md): one config against every
// comparison side by side. Not a test and not a benchmark: it prints the table that decides the
// default tyre.
//
//   footprint3d_study CONFIG TABLE3_CSV [--set key=value ...]
//                     [--calibrate key,key,key --rows i,j --observables obs,obs]
//
// Calibration (declared): at most 3 scalar keys fitted by Levenberg-Marquardt (on their
// logarithms) to the relative errors of the named observables on at most 2 rows of the table;
// every other row is a prediction and the RMS errors are over those rows only.
// Comparisons:
//   Table 3       sinking, length, width per row (seed 001)
//   Fig. 5        lengths at 2.1, 5.4, 8.3 kN (about 70, 110, 130 mm in the seed's figure) and
//                 the centre-line pressure shape (peak / mean, centre / peak)
//   exponents     d ln L / d ln F and d ln W / d ln F, least squares over Table 3's loads
//                 (real passenger tyres: length 0.55-0.67, width 0.14-0.27; accepted band for
//                 the length 0.45-0.70)
//   MF-Tool law   2a/R0 = 2 (Q_RA2 rho/R0 + Q_RA1 sqrt(rho/R0)) at the model's own rho/R0,
//                 1.5-9.5 kN (Pacejka 2012 eq. A3.7, TNO 205/60R15 MF-Swift 6.2 example:
//                 Q_RA1 = 0.6715, Q_RA2 = 0.7308)
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/levenberg_marquardt.h"
#include "modaltyre/studies/measurements.h"

using namespace modaltyre;
using namespace modaltyre::contact;

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(item);
  return out;
}

struct Case {
  std::vector<Patch3dResult> results;
  double R0_m = 0;
};

/// Builds the model of a config (with overrides) and solves the loads.
Case run(const std::string& config, const std::vector<std::string>& sets,
         const std::vector<double>& loads) {
  const TyreConfig c = load_tyre_config(config, sets);
  if (!c.footprint_3d) throw InputError(config + ": no footprint_3d: section");
  const TyreModel model = build_tyre_model(c);
  // Through the product's prediction path (predictor.h), so that modal.pneumatic_share acts.
  std::vector<OperatingConditions> cases;
  for (double F : loads) cases.push_back(c.default_conditions(F));
  Case out;
  out.R0_m = c.outer_radius_m;
  for (const Prediction& p : predict_all(model, cases)) {
    if (!p.ok() || !p.patch3d) {
      throw ComputationError("load " + std::to_string(p.footprint.load.load_N) + ": " + p.message);
    }
    out.results.push_back(*p.patch3d);
  }
  return out;
}

double observable(const Patch3dResult& r, const std::string& name) {
  if (name == "sinking_mm") return r.sinking_m * 1e3;
  if (name == "length_mm") return r.length_m * 1e3;
  if (name == "width_mm") return r.width_m * 1e3;
  throw InputError("unknown observable " + name + " (sinking_mm, length_mm, width_mm)");
}

double log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  const double n = double(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]) / n, my += std::log(y[i]) / n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

/// Centre-line pressure shape: peak / mean over the contact, centre / peak.
void centre_line_shape(const Patch3dResult& r, double& peak_over_mean, double& centre_over_peak) {
  const int j = r.columns / 2;
  double peak = 0, sum = 0, centre = 0, best = 1e300;
  int n = 0;
  for (int i = 0; i < r.sections; ++i) {
    const double p = r.pressure_Pa(i, j);
    if (!(p > 0)) continue;
    peak = std::max(peak, p);
    sum += p;
    ++n;
    if (std::abs(r.x_m[i]) < best) best = std::abs(r.x_m[i]), centre = p;
  }
  peak_over_mean = n ? peak / (sum / n) : 0;
  centre_over_peak = peak > 0 ? centre / peak : 0;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::cerr << "usage: footprint3d_study CONFIG TABLE3_CSV [--set k=v ...] [--calibrate "
                 "k1,k2,k3 --rows i,j --observables o1,o2]\n";
    return 2;
  }
  const std::string config = argv[1];
  const auto set = studies::read_measurements(argv[2], load_tyre_config(config));
  const std::vector<studies::MeasuredRow>& table = set.rows;
  std::vector<std::string> sets, keys, observables = {"sinking_mm"};
  std::vector<int> rows;
  for (int a = 3; a < argc; ++a) {
    const std::string arg = argv[a];
    if (a + 1 >= argc) throw InputError("missing value after " + arg);
    const std::string v = argv[++a];
    if (arg == "--set")
      sets.push_back(v);
    else if (arg == "--calibrate")
      keys = split(v);
    else if (arg == "--rows")
      for (const auto& s : split(v)) rows.push_back(std::stoi(s));
    else if (arg == "--observables")
      observables = split(v);
    else
      throw InputError("unknown option " + arg);
  }
  if (keys.size() > 3 || rows.size() > 2) throw InputError("at most 3 keys on at most 2 rows");
  for (int row : rows) {
    if (row < 1 || row > int(table.size())) throw InputError("row out of range");
  }
  std::vector<double> t3_loads;
  for (const auto& m : table) t3_loads.push_back(m.conditions.load_N);

  // Declared calibration on the named rows.
  std::vector<double> values(keys.size());
  if (!keys.empty()) {
    const TyreConfig base = load_tyre_config(config, sets);
    if (!base.footprint_3d) throw InputError(config + ": no footprint_3d: section");
    const Patch3dSettings& patch = *base.footprint_3d;
    Eigen::VectorXd x0(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const std::string& key = keys[k];
      const double v0 =
          key == "modal.compliance_scale"               ? base.compliance_scale
          : key == "tread.modulus_MPa"                  ? base.tread.modulus_Pa * 1e-6
          : key == "footprint_3d.crown.radius_mm"       ? patch.crown.radius_m * 1e3
          : key == "modal.extension_bending_s2_rad2_s2" ? std::max(base.extension_s2, 1.0)
          : key == "footprint_3d.lateral_belt.foundation_MPa_per_m"
              ? patch.lateral_belt.foundation_Pa_m * 1e-6
          : key == "modal.pneumatic_share" ? std::max(base.pneumatic_share, 0.01)
          : key == "footprint_3d.lateral_belt.bending_stiffness_Nm"
              ? patch.lateral_belt.bending_stiffness_Nm
          : key == "footprint_3d.crown.exponent" ? patch.crown.exponent
                                                 : throw InputError("cannot calibrate " + key);
      x0(k) = std::log(v0);
    }
    std::vector<double> cal_loads;
    for (int row : rows) cal_loads.push_back(table[row - 1].conditions.load_N);
    auto with = [&](const Eigen::VectorXd& x) {
      std::vector<std::string> s = sets;
      for (std::size_t k = 0; k < keys.size(); ++k) {
        std::ostringstream o;
        o.precision(10);
        o << keys[k] << "=" << std::exp(x(k));
        s.push_back(o.str());
      }
      return s;
    };
    auto residual = [&](const Eigen::VectorXd& x) {
      const Case c = run(config, with(x), cal_loads);
      Eigen::VectorXd r(rows.size() * observables.size());
      int n = 0;
      for (std::size_t q = 0; q < rows.size(); ++q) {
        for (const auto& o : observables) {
          const double meas = *table[rows[q] - 1].value(o);
          r(n++) = observable(c.results[q], o) / meas - 1;
        }
      }
      return r;
    };
    const auto fit = solvers::levenberg_marquardt(residual, x0);
    sets = with(fit.x);
    std::printf("calibrated on rows");
    for (int row : rows) std::printf(" %d", row);
    std::printf(" (");
    for (const auto& o : observables) std::printf(" %s", o.c_str());
    std::printf(" ): rms %.2f %%, %s\n", 100 * std::sqrt(2 * fit.cost / fit.residual.size()),
                fit.message.c_str());
    for (std::size_t k = 0; k < keys.size(); ++k) {
      std::printf("  %s = %.5g\n", keys[k].c_str(), std::exp(fit.x(k)));
    }
  }

  // Table 3.
  const Case t3 = run(config, sets, t3_loads);
  std::printf(
      "\nTable 3 (seed 001)         sinking mm            length mm             width mm\n");
  std::printf(
      "row  load N  role     meas  pred    err    meas  pred    err    meas  pred    err\n");
  double se[3] = {0, 0, 0};
  int np = 0;
  std::vector<double> lengths, widths;
  for (std::size_t q = 0; q < table.size(); ++q) {
    const auto& m = table[q];
    const auto& r = t3.results[q];
    const bool cal = std::find(rows.begin(), rows.end(), int(q + 1)) != rows.end();
    const double pred[3] = {r.sinking_m * 1e3, r.length_m * 1e3, r.width_m * 1e3};
    const double meas[3] = {*m.value("sinking_mm"), *m.value("length_mm"), *m.value("width_mm")};
    std::printf("%3zu %7.0f  %-5s", q + 1, m.conditions.load_N, cal ? "cal" : "pred");
    for (int k = 0; k < 3; ++k) {
      const double e = pred[k] / meas[k] - 1;
      std::printf("  %5.0f %6.2f %+6.1f%%", meas[k], pred[k], 100 * e);
      if (!cal) se[k] += e * e;
    }
    np += !cal;
    std::printf("\n");
    lengths.push_back(pred[1]);
    widths.push_back(pred[2]);
  }
  std::printf("RMS over %d predicted rows: sinking %.1f %%, length %.1f %%, width %.1f %%\n", np,
              100 * std::sqrt(se[0] / np), 100 * std::sqrt(se[1] / np),
              100 * std::sqrt(se[2] / np));
  std::vector<double> t3_len, t3_wid;
  for (const auto& m : table)
    t3_len.push_back(*m.value("length_mm")), t3_wid.push_back(*m.value("width_mm"));
  std::printf("\nExponents over %.0f-%.0f N (least squares on ln-ln):\n", t3_loads.front(),
              t3_loads.back());
  std::printf("  length %.3f (Table 3 %.3f; real tyres 0.55-0.67; band 0.45-0.70)\n",
              log_slope(t3_loads, lengths), log_slope(t3_loads, t3_len));
  std::printf("  width  %.3f (Table 3 %.3f; real tyres 0.14-0.27)\n", log_slope(t3_loads, widths),
              log_slope(t3_loads, t3_wid));
  std::printf("  secant stiffness %.0f -> %.0f N/mm (Table 3 %.0f -> %.0f)\n",
              t3.results.front().vertical_stiffness_N_m() * 1e-3,
              t3.results.back().vertical_stiffness_N_m() * 1e-3,
              table.front().conditions.load_N / *table.front().value("sinking_mm"),
              table.back().conditions.load_N / *table.back().value("sinking_mm"));

  // Seed 001 Fig. 5.
  const Case f5 = run(config, sets, {2100, 5400, 8300});
  const double fig5[3] = {70, 110, 130};
  std::printf("\nFig. 5 (seed 001)  load N  length mm (fig.)  peak/mean  centre/peak  width mm\n");
  for (int k = 0; k < 3; ++k) {
    const auto& r = f5.results[k];
    double pm = 0, cp = 0;
    centre_line_shape(r, pm, cp);
    std::printf("                   %6.0f  %6.1f (%3.0f)     %6.2f     %6.2f     %6.1f\n", r.load_N,
                r.length_m * 1e3, fig5[k], pm, cp, r.width_m * 1e3);
  }

  // MF-Tool contact-length law in dimensionless form.
  std::vector<double> mf_loads;
  for (double f = 1500; f <= 9500 + 1; f += 1000) mf_loads.push_back(f);
  const Case mf = run(config, sets, mf_loads);
  const double qa1 = 0.6715, qa2 = 0.7308;
  std::printf("\nMF-Tool law (Pacejka 2012 eq. A3.7, TNO 205/60R15): 2a/R0 vs rho/R0\n");
  std::printf("  load N  rho/R0   2a/R0 model  law     err\n");
  double sq = 0;
  for (const auto& r : mf.results) {
    const double x = r.sinking_m / mf.R0_m;
    const double law = 2 * (qa2 * x + qa1 * std::sqrt(x));
    const double model = r.length_m / mf.R0_m;
    const double e = model / law - 1;
    sq += e * e;
    std::printf("  %6.0f  %.4f   %.4f      %.4f  %+5.1f%%\n", r.load_N, x, model, law, 100 * e);
  }
  std::printf("  RMS %.1f %%\n", 100 * std::sqrt(sq / mf.results.size()));
  return 0;
} catch (const InputError& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 2;
} catch (const std::exception& e) {
  std::cerr << "error: " << e.what() << "\n";
  return 1;
}
