#include "modaltyre/rheology/load_deflection.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "measured_ranges.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/rheology/contact_geometry.h"
#include "modaltyre/solvers/linear_least_squares.h"

namespace modaltyre::rheology {
namespace {

constexpr double kMmPerM = 1e3;
// Plausible pressures, as the tyre config has them (tyre.inflation_pressure_kPa): beyond them a
// typo or a wrong unit, and the fit would overflow instead of saying so (loads: measured_ranges.h).
constexpr double kMaxPressure_kPa = 2000;

// Groups rows by a key rounded to a tolerance (equal within it = "one value").
std::map<long long, std::vector<std::size_t>> group_by(const std::vector<LoadDeflectionRow>& rows,
                                                       double LoadDeflectionRow::*field,
                                                       double step) {
  std::map<long long, std::vector<std::size_t>> g;
  for (std::size_t i = 0; i < rows.size(); ++i) g[std::llround(rows[i].*field / step)].push_back(i);
  return g;
}

}  // namespace

LoadDeflectionData read_load_deflection_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"load_N", "pressure_kPa", "deflection_mm"};
  const CsvTable t = read_csv(path, schema);
  LoadDeflectionData d;
  d.path = path;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    LoadDeflectionRow row;
    row.line = t.line(r);
    row.load_N = t.number(r, "load_N");
    row.pressure_Pa = t.number(r, "pressure_kPa") * 1e3;
    row.deflection_m = t.number(r, "deflection_mm") / kMmPerM;
    require_measured_load(path, row.line, row.load_N);
    // Eq. (3) is a law of the inflated tyre: at zero gauge pressure the carcass alone carries
    // the load, which (1 + p_W) does not describe.
    if (!(row.pressure_Pa > 0 && row.pressure_Pa <= kMaxPressure_kPa * 1e3))
      throw InputError({path, row.line, "pressure_kPa"},
                       "gauge inflation pressure must be in (0, 2000] kPa: eq. (3) describes an "
                       "inflated tyre");
    if (row.deflection_m <= 0)
      throw InputError({path, row.line, "deflection_mm"},
                       "deflection must be > 0 mm (measured from the unloaded tyre)");
    d.rows.push_back(row);
  }
  return d;
}

double law_deflection(double K_Z_m, double load_N, double pressure_Pa) {
  return K_Z_m * std::pow(load_N, 0.75) / pressure_factor(pressure_Pa);  // seed 000 eq. (3)
}

double k_z_two_loads(double load1_N, double defl1_m, double load2_N, double defl2_m,
                     double pressure_Pa) {
  // seed 000: K_Z = dh_Z (1 + p_W) / (P_Z2^(3/4) - P_Z1^(3/4))
  const double den = std::pow(load2_N, 0.75) - std::pow(load1_N, 0.75);
  if (den == 0) throw InputError("two-load formula: the two loads are equal");
  return (defl2_m - defl1_m) * pressure_factor(pressure_Pa) / den;
}

double k_z_two_pressures(double pressure1_Pa, double defl1_m, double pressure2_Pa, double defl2_m,
                         double load_N) {
  // seed 000: K_Z = dh_Z (1 + p_W1)(1 + p_W2) / (P_Z^(3/4) (p_W1 - p_W2)), dh_Z = h2 - h1
  const double dp = (pressure1_Pa - pressure2_Pa) / kPressureUnit_Pa;
  if (dp == 0) throw InputError("two-pressure formula: the two pressures are equal");
  return (defl2_m - defl1_m) * pressure_factor(pressure1_Pa) * pressure_factor(pressure2_Pa) /
         (std::pow(load_N, 0.75) * dp);
}

double c_p_eq5(double K_Z_m, double r0_m, double pressure_Pa, double load_N) {
  const double h = law_deflection(K_Z_m, load_N, pressure_Pa);
  if (h >= r0_m) throw InputError("eq. (5): deflection from eq. (3) exceeds the radius r0");
  const double phi1 = half_contact_angle(h, r0_m);
  // seed 000 eq. (5)
  return std::cbrt(r0_m) * std::pow(pressure_factor(pressure_Pa) / K_Z_m, 4.0 / 3.0) *
         deflection_power(phi1) / (2.0 * kelvin_voigt_load_function(phi1));
}

double c_p_eq7(double K_Z_m, double r0_m, double pressure_Pa, double B1) {
  // seed 000 eq. (7)
  return B1 * std::cbrt(r0_m) * std::pow(pressure_factor(pressure_Pa) / K_Z_m, 4.0 / 3.0) / 2.0;
}

LoadDeflectionResult identify_load_deflection(const LoadDeflectionData& data,
                                              const LoadDeflectionOptions& options) {
  const auto& rows = data.rows;
  const std::string& path = data.path;
  if (rows.size() < 2)
    throw InputError({path, 0, ""},
                     "load-deflection needs at least two rows (got " + std::to_string(rows.size()) +
                         "): two loads at one pressure or two pressures at one load");
  if (!(options.r0_m > 0))
    throw InputError(
        "load-deflection needs the free radius r0 (--r0-mm or tyre.outer_radius_mm "
        "in --config) for C_P");
  if (!(options.B1 > 0)) throw InputError("B1 must be > 0");

  const std::size_t n = rows.size();
  Eigen::MatrixXd A(n, 1);
  Eigen::VectorXd b(n);
  for (std::size_t i = 0; i < n; ++i) {
    A(i, 0) = std::pow(rows[i].load_N, 0.75) / pressure_factor(rows[i].pressure_Pa);  // eq. (3)
    b(i) = rows[i].deflection_m;
    if (rows[i].deflection_m >= options.r0_m)
      throw InputError({path, rows[i].line, "deflection_mm"}, "deflection exceeds the radius r0");
  }
  if (A.maxCoeff() - A.minCoeff() <= 1e-9 * A.maxCoeff())
    throw InputError({path, rows.back().line, "load_N"},
                     "all rows have equal loads at the same pressure (as line " +
                         std::to_string(rows.front().line) +
                         "): eq. (3) needs two loads at one pressure or two pressures at one load");

  LoadDeflectionResult res;
  const solvers::LinearFit fit = solvers::solve_linear_least_squares(A, b);
  res.K_Z_m = fit.coef(0);
  res.K_Z_se_m = fit.std_error(0);
  if (!(res.K_Z_m > 0))
    throw ComputationError(
        "K_Z from least squares is not positive; deflection does not grow "
        "with load / fall with pressure in these data");

  auto& rep = res.report;
  rep.method = "load-deflection";
  rep.rows = static_cast<int>(n);
  rep.residual_rms = fit.residual_rms * kMmPerM;
  rep.residual_unit = "mm";
  rep.parameters.push_back({"K_Z", res.K_Z_m * kMmPerM, "mm N^-3/4", res.K_Z_se_m * kMmPerM});
  rep.notes.push_back("K_Z: least squares of eq. (3) through the origin over all rows");

  // Two-load formula: at the pressure whose rows span the widest load range.
  {
    const auto groups = group_by(rows, &LoadDeflectionRow::pressure_Pa, 10.0);  // 0.01 kPa
    double best_span = 0;
    double k = 0;
    for (const auto& [key, idx] : groups) {
      if (idx.size() < 2) continue;
      auto lo = *std::min_element(idx.begin(), idx.end(),
                                  [&](auto a, auto c) { return rows[a].load_N < rows[c].load_N; });
      auto hi = *std::max_element(idx.begin(), idx.end(),
                                  [&](auto a, auto c) { return rows[a].load_N < rows[c].load_N; });
      const double span = rows[hi].load_N - rows[lo].load_N;
      if (span > best_span * (1 + 1e-12) && span > 1e-9 * rows[hi].load_N) {
        best_span = span;
        k = k_z_two_loads(rows[lo].load_N, rows[lo].deflection_m, rows[hi].load_N,
                          rows[hi].deflection_m, rows[lo].pressure_Pa);
      }
    }
    if (best_span > 0) rep.parameters.push_back({"K_Z_two_loads", k * kMmPerM, "mm N^-3/4", 0});
  }
  // Two-pressure formula: at the load whose rows span the widest pressure range.
  {
    const auto groups = group_by(rows, &LoadDeflectionRow::load_N, 0.01);
    double best_span = 0;
    double k = 0;
    for (const auto& [key, idx] : groups) {
      if (idx.size() < 2) continue;
      auto lo = *std::min_element(idx.begin(), idx.end(), [&](auto a, auto c) {
        return rows[a].pressure_Pa < rows[c].pressure_Pa;
      });
      auto hi = *std::max_element(idx.begin(), idx.end(), [&](auto a, auto c) {
        return rows[a].pressure_Pa < rows[c].pressure_Pa;
      });
      const double span = rows[hi].pressure_Pa - rows[lo].pressure_Pa;
      if (span > best_span && span > 10.0) {
        best_span = span;
        k = k_z_two_pressures(rows[hi].pressure_Pa, rows[hi].deflection_m, rows[lo].pressure_Pa,
                              rows[lo].deflection_m, rows[lo].load_N);
      }
    }
    if (best_span > 0) rep.parameters.push_back({"K_Z_two_pressures", k * kMmPerM, "mm N^-3/4", 0});
  }

  // Reference pressure for C_P: given, else the median pressure of the rows.
  if (options.reference_pressure_Pa >= 0) {
    res.reference_pressure_Pa = options.reference_pressure_Pa;
  } else {
    std::vector<double> p;
    for (const auto& r : rows) p.push_back(r.pressure_Pa);
    std::nth_element(p.begin(), p.begin() + static_cast<long>(p.size() / 2), p.end());
    res.reference_pressure_Pa = p[p.size() / 2];
  }
  const double rel_k = res.K_Z_se_m / res.K_Z_m;
  // eq. (5), evaluated at each measured load (deflection from eq. 3 at the reference pressure)
  double sum = 0, sum2 = 0;
  for (const auto& r : rows) {
    const double c = c_p_eq5(res.K_Z_m, options.r0_m, res.reference_pressure_Pa, r.load_N);
    sum += c;
    sum2 += c * c;
  }
  res.C_P_eq5 = sum / static_cast<double>(n);
  const double var = std::max(0.0, sum2 / static_cast<double>(n) - res.C_P_eq5 * res.C_P_eq5);
  res.C_P_eq5_se =
      std::sqrt(std::pow(4.0 / 3.0 * rel_k * res.C_P_eq5, 2) + var / static_cast<double>(n));
  res.C_P_eq7 = c_p_eq7(res.K_Z_m, options.r0_m, res.reference_pressure_Pa, options.B1);
  res.C_P_eq7_se = 4.0 / 3.0 * rel_k * res.C_P_eq7;
  rep.parameters.push_back({"C_P", res.C_P_eq7, "N/(m rad)", res.C_P_eq7_se});
  rep.parameters.push_back({"C_P_eq5", res.C_P_eq5, "N/(m rad)", res.C_P_eq5_se});
  rep.notes.push_back("C_P: closed form eq. (7) with B1 = " + std::to_string(options.B1) +
                      "; C_P_eq5: eq. (5) averaged over the measured loads; both at the "
                      "reference pressure");
  return res;
}

}  // namespace modaltyre::rheology
