#include "modaltyre/rheology/contact_geometry.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::rheology {

double half_contact_angle(double deflection_m, double r0_m) {
  MODALTYRE_CHECK(r0_m > 0 && deflection_m >= 0 && deflection_m < r0_m,
                  "half_contact_angle needs 0 <= h < r0");
  return std::acos((r0_m - deflection_m) / r0_m);
}

double contact_length(double deflection_m, double r0_m) {
  return 2.0 * r0_m * std::sin(half_contact_angle(deflection_m, r0_m));
}

double deflection_power(double phi1) { return std::pow(1.0 - std::cos(phi1), 4.0 / 3.0); }

double kelvin_voigt_load_function(double phi1) {
  // seed 000 eq. (2): 2 C_P r0 * int_0^phi1 (cos phi - cos phi1) dphi / ... = sin - phi cos.
  if (phi1 < 1e-3) return phi1 * phi1 * phi1 / 3.0;  // series, avoids cancellation
  return std::sin(phi1) - phi1 * std::cos(phi1);
}

double arc_stress_load_function(double phi1) {
  // seed 000 eq. (8): int_0^phi1 K1 r0 (1 - cos phi1/cos phi) cos phi * rho dphi,
  // rho = r0 cos phi1 / cos phi  ->  r0^2 cos phi1 (phi1 - cos phi1 atanh(sin phi1)).
  if (phi1 < 1e-3) return phi1 * phi1 * phi1 / 3.0;
  const double c = std::cos(phi1);
  return c * (phi1 - c * std::atanh(std::sin(phi1)));
}

double radial_deformation_at(double x_m, double deflection_m, double r0_m) {
  const double rho = std::hypot(x_m, r0_m - deflection_m);
  return std::max(0.0, r0_m - rho);
}

}  // namespace modaltyre::rheology
