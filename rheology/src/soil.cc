#include "modaltyre/rheology/soil.h"

#include <cmath>

#include "measured_ranges.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/linear_least_squares.h"

namespace modaltyre::rheology {

SoilData read_soil_rolling_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"load_N",           "longitudinal_force_N", "alpha1_deg", "alpha2_deg",
                     "total_sinking_mm", "elastic_sinking_mm",   "layer_mm",   "speed_m_s"};
  const CsvTable t = read_csv(path, schema);
  SoilData d;
  d.path = path;
  const double deg = M_PI / 180.0;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    SoilRow s;
    s.line = t.line(r);
    s.load_N = t.number(r, "load_N");
    s.longitudinal_force_N = t.number(r, "longitudinal_force_N");
    s.alpha1_rad = t.number(r, "alpha1_deg") * deg;
    s.alpha2_rad = t.number(r, "alpha2_deg") * deg;
    s.total_sinking_m = t.number(r, "total_sinking_mm") * 1e-3;
    s.elastic_sinking_m = t.number(r, "elastic_sinking_mm") * 1e-3;
    s.layer_m = t.number(r, "layer_mm") * 1e-3;
    s.speed_m_s = t.number(r, "speed_m_s");
    auto bad = [&](const char* col, const std::string& msg) {
      throw InputError({path, s.line, col}, msg);
    };
    require_measured_load(path, s.line, s.load_N);
    if (!(std::abs(s.longitudinal_force_N) <= kMaxMeasuredForce_N))
      bad("longitudinal_force_N", "must be in [-1e7, 1e7] N");
    if (!(s.alpha1_rad > 0 && s.alpha1_rad < M_PI / 2)) bad("alpha1_deg", "must be in (0, 90) deg");
    if (!(s.alpha2_rad > 0 && s.alpha2_rad <= s.alpha1_rad))
      bad("alpha2_deg", "must be in (0, alpha1_deg]: the rear contact needs elastic recovery");
    if (s.total_sinking_m <= 0) bad("total_sinking_mm", "must be > 0 mm");
    if (!(s.elastic_sinking_m > 0 && s.elastic_sinking_m <= s.total_sinking_m))
      bad("elastic_sinking_mm", "must be in (0, total_sinking_mm]");
    if (s.layer_m <= s.total_sinking_m)
      bad("layer_mm", "the deformed layer must be thicker than the total sinking");
    if (s.speed_m_s <= 0) bad("speed_m_s", "must be > 0 m/s");
    d.rows.push_back(s);
  }
  return d;
}

SoilCoefficients soil_coefficients(const SoilRow& s, const SoilOptions& o) {
  const double r0 = o.r0_m, V = s.speed_m_s, A = s.layer_m;
  const double Ac = A - (s.total_sinking_m - s.elastic_sinking_m);  // compacted layer
  const double kE = s.elastic_sinking_m / s.total_sinking_m;        // seed 000 eq. (24)
  const double a1 = s.alpha1_rad, a2 = s.alpha2_rad;
  // int eps cos, int eps sin, int deps/dt cos, int deps/dt sin over each zone
  const double Ic1 = r0 / (2 * A) * (a1 - std::sin(a1) * std::cos(a1));
  const double Is1 = r0 / (2 * A) * std::pow(1 - std::cos(a1), 2);
  const double Jc1 = V / A * (1 - std::cos(a1));
  const double Js1 = V / A * (std::atanh(std::sin(a1)) - std::sin(a1));
  const double Ic2 = r0 / (2 * Ac) * (a2 - std::sin(a2) * std::cos(a2));
  const double Is2 = r0 / (2 * Ac) * std::pow(1 - std::cos(a2), 2);
  const double Jc2 = -V / Ac * (1 - std::cos(a2));
  const double Js2 = -V / Ac * (std::atanh(std::sin(a2)) - std::sin(a2));
  SoilCoefficients c;
  c.z_E = kE * Ic1 + Ic2;  // seed 000 eq. (25)
  c.z_eta = kE * Jc1 + Jc2;
  c.x_E = kE * Is1 - Is2;  // seed 000 eq. (26)
  c.x_eta = kE * Js1 - Js2;
  return c;
}

SoilRow soil_forces(SoilRow row, double E2, double eta2, const SoilOptions& o) {
  const SoilCoefficients c = soil_coefficients(row, o);
  const double s = o.tread_width_m * o.r0_m;
  row.load_N = s * (c.z_E * E2 + c.z_eta * eta2);
  row.longitudinal_force_N = s * (c.x_E * E2 + c.x_eta * eta2);
  return row;
}

SoilResult identify_soil(const SoilData& d, const SoilOptions& o) {
  if (!(o.r0_m > 0))
    throw InputError(
        "soil-rolling needs the rigid test wheel's radius r0 (--r0-mm; a tyre config's "
        "outer_radius_mm is the tyre's, not the test wheel's)");
  if (!(o.tread_width_m > 0))
    throw InputError("soil-rolling needs the rigid test wheel's width B_tr (--tread-width-mm)");
  const std::size_t n = d.rows.size();
  if (n < 2)
    throw InputError({d.path, 0, ""}, "soil-rolling needs at least two rows (got " +
                                          std::to_string(n) +
                                          ") to estimate E2 and eta2 with "
                                          "standard errors");
  for (const auto& r : d.rows)
    if (r.total_sinking_m >= o.r0_m)
      throw InputError({d.path, r.line, "total_sinking_mm"}, "sinking exceeds the wheel radius");
  const double s = o.tread_width_m * o.r0_m;
  Eigen::MatrixXd A(2 * n, 2);
  Eigen::VectorXd b(2 * n);
  double kE_sum = 0, kE_sum2 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& r = d.rows[i];
    const SoilCoefficients c = soil_coefficients(r, o);
    const double wz = 1.0 / r.load_N;
    const double wx = 1.0 / std::max(std::abs(r.longitudinal_force_N), 1e-3 * r.load_N);
    const auto iz = static_cast<Eigen::Index>(2 * i), ix = iz + 1;
    A(iz, 0) = wz * s * c.z_E, A(iz, 1) = wz * s * c.z_eta, b(iz) = 1.0;
    A(ix, 0) = wx * s * c.x_E, A(ix, 1) = wx * s * c.x_eta, b(ix) = wx * r.longitudinal_force_N;
    const double kE = r.elastic_sinking_m / r.total_sinking_m;
    kE_sum += kE, kE_sum2 += kE * kE;
  }
  solvers::LinearFit fit;
  try {
    fit = solvers::solve_linear_least_squares(A, b);
  } catch (const ComputationError&) {
    throw InputError({d.path, 0, ""}, "these rows cannot separate E2 from eta2");
  }
  SoilResult res;
  res.E2_Pa = fit.coef(0), res.E2_se = fit.std_error(0);
  res.eta2_Pa_s = fit.coef(1), res.eta2_se = fit.std_error(1);
  res.k_E = kE_sum / static_cast<double>(n);
  res.k_E_se = std::sqrt(std::max(0.0, kE_sum2 / static_cast<double>(n) - res.k_E * res.k_E) /
                         static_cast<double>(n - 1));
  double rss = 0;
  for (const auto& r : d.rows) {
    const SoilRow p = soil_forces(r, res.E2_Pa, res.eta2_Pa_s, o);
    res.predicted_load_N.push_back(p.load_N);
    res.predicted_longitudinal_N.push_back(p.longitudinal_force_N);
    rss += std::pow(p.load_N - r.load_N, 2) +
           std::pow(p.longitudinal_force_N - r.longitudinal_force_N, 2);
  }
  auto& rep = res.report;
  rep.method = "soil-rolling";
  rep.rows = static_cast<int>(n);
  rep.residual_rms = std::sqrt(rss / static_cast<double>(2 * n));
  rep.residual_unit = "N";
  rep.parameters = {{"E2", res.E2_Pa, "Pa", res.E2_se},
                    {"eta2", res.eta2_Pa_s, "Pa s", res.eta2_se},
                    {"k_E", res.k_E, "-", res.k_E_se},
                    {"relative_residual_rms", fit.residual_rms, "-", 0.0}};
  rep.notes.push_back(
      "E2, eta2: least squares of eq. (25)-(26) over all rows on relative "
      "residuals; k_E = h_E / h_G (eq. 24), mean over rows");
  if (!(res.E2_Pa > 0)) rep.notes.push_back("warning: E2 is not positive; check the data");
  if (!(res.eta2_Pa_s >= 0)) rep.notes.push_back("warning: eta2 is negative; check the data");
  return res;
}

}  // namespace modaltyre::rheology
