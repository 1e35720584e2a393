// Pacejka 2012 App. 3, (A3.3)-(A3.8) for a standing tyre (mf_formulas.h).
#include "modaltyre/tir/mf_formulas.h"

#include <algorithm>
#include <cmath>

namespace modaltyre::tir {

std::optional<double> q_fz1_from_stiffness(double stiffness_N_m, double unloaded_radius_m,
                                           double fnomin_N, double q_fz2) {
  const double k = stiffness_N_m * unloaded_radius_m / fnomin_N;
  const double radicand = k * k - 4 * q_fz2;  // (A3.4)
  if (!(radicand > 0) || !std::isfinite(radicand)) return std::nullopt;
  return std::sqrt(radicand);
}

std::optional<double> stiffness_from_q_fz(double q_fz1, double q_fz2, double unloaded_radius_m,
                                          double fnomin_N) {
  const double radicand = q_fz1 * q_fz1 + 4 * q_fz2;
  if (!(radicand > 0) || !std::isfinite(radicand)) return std::nullopt;
  return fnomin_N / unloaded_radius_m * std::sqrt(radicand);
}

double pressure_increment(const MfVerticalLaw& law, double pressure_Pa) {
  if (!(law.nominal_pressure_Pa > 0) || !(pressure_Pa > 0)) return 0;
  return (pressure_Pa - law.nominal_pressure_Pa) / law.nominal_pressure_Pa;  // (A3.5)
}

double mf_load_N(const MfVerticalLaw& law, double deflection_m, double pressure_Pa) {
  const double x = deflection_m / law.unloaded_radius_m;
  const double scale = 1 + law.pfz1 * pressure_increment(law, pressure_Pa);
  return law.fnomin_N * scale * (law.q_fz1 * x + law.q_fz2 * x * x);  // (A3.3)
}

std::optional<double> mf_deflection_m(const MfVerticalLaw& law, double load_N, double pressure_Pa) {
  const double scale = 1 + law.pfz1 * pressure_increment(law, pressure_Pa);
  const double f = load_N / (law.fnomin_N * scale);
  const double disc = law.q_fz1 * law.q_fz1 + 4 * law.q_fz2 * f;
  if (!(disc >= 0) || !(scale > 0)) return std::nullopt;
  const double denom = law.q_fz1 + std::sqrt(disc);
  if (!(denom > 0)) return std::nullopt;
  // Root of q2 x^2 + q1 x - f = 0 on the rising branch, in the form without cancellation.
  return law.unloaded_radius_m * 2 * f / denom;
}

double mf_vertical_stiffness(const MfVerticalLaw& law, double pressure_Pa) {
  return law.vertical_stiffness_N_m * (1 + law.pfz1 * pressure_increment(law, pressure_Pa));
}

double mf_half_length_m(double unloaded_radius_m, double q_ra1, double q_ra2, double rho_z_m) {
  const double x = std::max(rho_z_m, 0.0) / unloaded_radius_m;
  return unloaded_radius_m * (q_ra2 * x + q_ra1 * std::sqrt(x));  // (A3.7)
}

double mf_half_width_m(double unloaded_radius_m, double width_m, double q_rb1, double q_rb2,
                       double rho_z_m) {
  const double x = std::max(rho_z_m, 0.0) / unloaded_radius_m;
  return width_m * (q_rb2 * x + q_rb1 * std::cbrt(x));  // (A3.8)
}

}  // namespace modaltyre::tir
