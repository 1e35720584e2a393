#include "modaltyre/rheology/contact_stress.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/rheology/contact_geometry.h"

namespace modaltyre::rheology {
namespace {

// Variable projection: for a fixed deflection the best K1 is linear least squares.
struct Projection {
  double K1 = 0.0;
  double rss = 0.0;
};

Projection project(const StressData& d, double h, double r0) {
  double sxy = 0, sxx = 0;
  for (const auto& r : d.rows) {
    const double D = radial_deformation_at(r.x_m, h, r0);
    sxy += D * r.stress_Pa;
    sxx += D * D;
  }
  Projection p;
  p.K1 = sxx > 0 ? sxy / sxx : 0.0;
  for (const auto& r : d.rows) {
    const double e = p.K1 * radial_deformation_at(r.x_m, h, r0) - r.stress_Pa;
    p.rss += e * e;
  }
  return p;
}

}  // namespace

StressData read_contact_stress_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"x_mm", "stress_kPa"};
  const CsvTable t = read_csv(path, schema);
  StressData d;
  d.path = path;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    StressRow row{t.number(r, "x_mm") * 1e-3, t.number(r, "stress_kPa") * 1e3, t.line(r)};
    if (row.stress_Pa < 0)
      throw InputError({path, row.line, "stress_kPa"}, "contact stress must be >= 0 kPa");
    d.rows.push_back(row);
  }
  return d;
}

double contact_stress_law(double K1, double x_m, double deflection_m, double r0_m) {
  return K1 * radial_deformation_at(x_m, deflection_m, r0_m);  // sigma = K1 Delta_P
}

double k1_eq11(double K_Z_m, double r0_m, double tread_width_m, double pressure_Pa, double B2) {
  // seed 000 eq. (11)
  return B2 * std::pow(pressure_factor(pressure_Pa) / K_Z_m, 4.0 / 3.0) /
         (2.0 * tread_width_m * std::pow(r0_m, 2.0 / 3.0));
}

double c_p_eq12(double K1, double r0_m, double tread_width_m, double B1, double B2) {
  return B1 * tread_width_m * r0_m / B2 * K1;  // seed 000 eq. (12)
}

ContactStressResult identify_contact_stress(const StressData& d, const ContactStressOptions& o) {
  if (!(o.r0_m > 0))
    throw InputError("contact-stress needs the free radius r0 (--r0-mm or tyre.outer_radius_mm)");
  if (!(o.tread_width_m > 0))
    throw InputError(
        "contact-stress needs the tread width B_tr (--tread-width-mm or "
        "tread.contact_width_mm) for eq. (8) and (12)");
  if (d.rows.size() < 3)
    throw InputError({d.path, 0, ""}, "contact-stress needs at least three rows (got " +
                                          std::to_string(d.rows.size()) + ")");
  double smax = 0;
  for (const auto& r : d.rows) {
    smax = std::max(smax, r.stress_Pa);
    if (std::abs(r.x_m) >= o.r0_m)
      throw InputError({d.path, r.line, "x_mm"}, "abscissa beyond the tyre radius r0");
  }
  if (smax <= 0) throw InputError({d.path, 0, "stress_kPa"}, "no positive stress in the file");

  ContactStressResult res;
  const bool fixed_h = o.contact_length_m > 0;
  if (fixed_h) {
    const double a = o.contact_length_m / 2;
    if (a >= o.r0_m) throw InputError("contact length exceeds the tyre diameter");
    res.deflection_m = o.r0_m - std::sqrt(o.r0_m * o.r0_m - a * a);
  } else {
    // 1D search over the deflection: grid, then golden section around the best node.
    const double hmax = 0.3 * o.r0_m;
    const int N = 600;
    double best_h = 0, best = 1e300;
    for (int i = 1; i <= N; ++i) {
      const double h = hmax * i / N;
      const double rss = project(d, h, o.r0_m).rss;
      if (rss < best) best = rss, best_h = h;
    }
    double lo = std::max(1e-9, best_h - hmax / N), hi = std::min(hmax, best_h + hmax / N);
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 200 && hi - lo > 1e-13; ++it) {
      const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
      if (project(d, a, o.r0_m).rss < project(d, b, o.r0_m).rss)
        hi = b;
      else
        lo = a;
    }
    res.deflection_m = (lo + hi) / 2;
  }
  const Projection p = project(d, res.deflection_m, o.r0_m);
  res.K1_Pa_per_m = p.K1;
  if (!(p.K1 > 0)) throw ComputationError("contact-stress: K1 is not positive");

  // Standard errors from the Jacobian in (K1, h) at the optimum.
  const std::size_t n = d.rows.size();
  const int np = fixed_h ? 1 : 2;
  Eigen::MatrixXd J(n, np);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = d.rows[i].x_m;
    const double D = radial_deformation_at(x, res.deflection_m, o.r0_m);
    J(i, 0) = D;
    if (!fixed_h) {
      const double rho = std::hypot(x, o.r0_m - res.deflection_m);
      J(i, 1) = D > 0 ? p.K1 * (o.r0_m - res.deflection_m) / rho : 0.0;
    }
  }
  const double s2 = n > static_cast<std::size_t>(np) ? p.rss / static_cast<double>(n - np) : 0.0;
  // Scale the columns (K1 ~ 1e7 Pa/m against h ~ 1e-2 m) before judging the rank.
  const Eigen::VectorXd scale = J.colwise().norm().transpose().cwiseMax(1e-300);
  const Eigen::MatrixXd Js = J * scale.cwiseInverse().asDiagonal();
  Eigen::FullPivLU<Eigen::MatrixXd> lu(Js.transpose() * Js);
  lu.setThreshold(1e-10);
  if (!lu.isInvertible())
    throw InputError({d.path, 0, "x_mm"},
                     "the stress profile does not determine K1 and the deflection (too few "
                     "points inside the contact patch)");
  const Eigen::MatrixXd cov =
      s2 * scale.cwiseInverse().asDiagonal() * lu.inverse() * scale.cwiseInverse().asDiagonal();
  res.K1_se = std::sqrt(std::max(0.0, cov(0, 0)));
  res.deflection_se_m = fixed_h ? 0.0 : std::sqrt(std::max(0.0, cov(1, 1)));

  const double phi1 = half_contact_angle(res.deflection_m, o.r0_m);
  res.load_N = 2.0 * res.K1_Pa_per_m * o.tread_width_m * o.r0_m * o.r0_m *
               arc_stress_load_function(phi1);  // seed 000 eq. (8)
  res.C_P = c_p_eq12(res.K1_Pa_per_m, o.r0_m, o.tread_width_m, o.B1, o.B2);
  res.C_P_se = res.C_P * res.K1_se / res.K1_Pa_per_m;

  auto& rep = res.report;
  rep.method = "contact-stress";
  rep.rows = static_cast<int>(n);
  rep.residual_rms = std::sqrt(p.rss / static_cast<double>(n)) * 1e-3;
  rep.residual_unit = "kPa";
  rep.parameters = {{"K1", res.K1_Pa_per_m, "Pa/m", res.K1_se},
                    {"C_P", res.C_P, "N/(m rad)", res.C_P_se},
                    {"deflection", res.deflection_m * 1e3, "mm", res.deflection_se_m * 1e3},
                    {"contact_length", 2 * o.r0_m * std::sin(phi1) * 1e3, "mm", 0.0},
                    {"load_eq8", res.load_N, "N", res.load_N * res.K1_se / res.K1_Pa_per_m}};
  rep.notes.push_back(fixed_h ? "deflection fixed by the given contact length"
                              : "deflection fitted together with K1 (variable projection)");
  rep.notes.push_back("C_P = B1 B_tr r0 K1 / B2 (eq. 12) with B1 = " + std::to_string(o.B1) +
                      ", B2 = " + std::to_string(o.B2));
  return res;
}

}  // namespace modaltyre::rheology
