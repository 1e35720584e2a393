#include "modaltyre/contact/sidewall_membrane.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace modaltyre::contact {

void SidewallMembrane::validate() const {
  if (!(chord_m > 0) || !(length_m > chord_m) || !std::isfinite(length_m)) {
    throw std::invalid_argument("sidewall meridian: need 0 < chord < length");
  }
}

double meridian_half_angle(double ratio) {
  if (!(ratio > 0 && ratio < 1)) return std::numeric_limits<double>::quiet_NaN();
  // sin(a) / a falls from 1 to 0 on (0, pi).
  double lo = 0, hi = M_PI;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (std::sin(mid) / mid > ratio ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double sidewall_pull_N_per_m(double pressure_Pa, double length_m, double chord_m) {
  const double a = meridian_half_angle(chord_m / length_m);
  return 0.5 * pressure_Pa * length_m * std::cos(a) / a;
}

double sidewall_stiffness_N_per_m2(double pressure_Pa, double length_m, double chord_m) {
  // dF/dc = (dF/da) / (dc/da), c = L sin(a) / a.
  const double a = meridian_half_angle(chord_m / length_m);
  const double s = std::sin(a), c = std::cos(a);
  return 0.5 * pressure_Pa * (a * s + c) / (s - a * c);
}

double sidewall_lost_force_N_per_m(const SidewallMembrane& s, double pressure_Pa, double u_m) {
  if (!s.enabled || pressure_Pa == 0 || u_m == 0) return 0;
  const double c0 = s.chord_m, L = s.length_m;
  const double linear = sidewall_stiffness_N_per_m2(pressure_Pa, L, c0) * u_m;
  const double restoring =
      sidewall_pull_N_per_m(pressure_Pa, L, c0) - sidewall_pull_N_per_m(pressure_Pa, L, c0 - u_m);
  return 2 * (linear - restoring);
}

}  // namespace modaltyre::contact
