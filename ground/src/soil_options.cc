#include "modaltyre/ground/soil_options.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace modaltyre::ground {

void WongReeceStress::validate() const {
  auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!(c1 >= 0 && c1 <= 1)) bad("bekker.wong_reece.c1 must be in [0, 1]");
  if (!(c2 >= 0 && c2 <= 1)) bad("bekker.wong_reece.c2 must be in [0, 1]");
  if (!(c3 >= 0 && c3 <= 0.99)) bad("bekker.wong_reece.c3 must be in [0, 0.99]");
}

double WongReeceStress::peak_ratio(double slip) const {
  return std::clamp(c1 + c2 * slip, 0.0, 1.0);
}

bool WongReeceStress::has_rear_region(double slip) const {
  return enabled && (c3 > 0 || peak_ratio(slip) > 0);
}

void SlipSinkage::validate() const {
  auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!(k1 >= 0 && k1 <= 10)) bad("bekker.slip_sinkage.k1 must be in [0, 10]");
  if (!(k2 >= 0 && k2 <= 0.99)) bad("bekker.slip_sinkage.k2 must be in [0, 0.99]");
}

double SlipSinkage::factor(double slip) const {
  if (!enabled) return 1.0;
  const double s = std::min(std::abs(slip), 1.0);
  return (1 + k1 * s) / (1 - k2 * s);
}

void Bulldozing::validate() const {
  if (!(unit_weight_kN_m3 > 0 && unit_weight_kN_m3 <= 30))
    throw std::invalid_argument("bekker.bulldozing.unit_weight_kN_m3 must be in (0, 30]");
}

BearingFactors bearing_factors(double friction_angle_deg) {
  const double phi = friction_angle_deg * M_PI / 180, t = std::tan(phi);
  BearingFactors f;
  f.N_q = std::exp(M_PI * t) * std::pow(std::tan(M_PI / 4 + phi / 2), 2);
  // N_c's limit at phi -> 0 is pi + 2 (Prandtl); below 1e-6 rad the quotient cancels.
  f.N_c = phi > 1e-6 ? (f.N_q - 1) / t : M_PI + 2;
  f.N_g = 2 * (f.N_q + 1) * t;
  return f;
}

double bulldozing_resistance_N(const Bulldozing& b, double cohesion_kPa, double friction_angle_deg,
                               double width_m, double sinkage_m) {
  if (!b.enabled || !(sinkage_m > 0) || !(width_m > 0)) return 0.0;
  b.validate();
  const BearingFactors f = bearing_factors(friction_angle_deg);
  const double phi = friction_angle_deg * M_PI / 180, cos2 = std::pow(std::cos(phi), 2);
  const double K_pc = (f.N_c - std::tan(phi)) * cos2;
  const double K_pg = (4 * (f.N_q + 1) + 1) * cos2;  // 2 N_g / tan phi = 4 (N_q + 1)
  const double c = cohesion_kPa * 1e3, gamma = b.unit_weight_kN_m3 * 1e3, z = sinkage_m;
  return width_m * (0.67 * c * z * K_pc + 0.5 * gamma * z * z * K_pg);
}

}  // namespace modaltyre::ground
