#pragma once
// Geometry of a ring of free radius r0 pressed by h onto a flat rigid road (seed 000 Fig. 1)
// and the angle functions that the seed's integrals reduce to. Angles in rad, lengths in m.
#include <string>

namespace modaltyre::rheology {

/// Unit of p_W in the seed's factor (1 + p_W) of eq. (3): the bar (1e5 Pa), gauge pressure.
/// Then 1 + p_W is close to the absolute pressure in bar; see docs/rheology.md for the choice.
inline constexpr double kPressureUnit_Pa = 1e5;
inline constexpr const char* kPressureUnitName = "bar";

/// The seed's pressure factor 1 + p_W with p_W in bar (gauge).
inline double pressure_factor(double gauge_pressure_Pa) {
  return 1.0 + gauge_pressure_Pa / kPressureUnit_Pa;
}

/// Half contact angle phi1 = arccos((r0 - h) / r0) (seed 000, below eq. 2); needs 0 <= h < r0.
double half_contact_angle(double deflection_m, double r0_m);

/// Contact length at a deflection on a flat road: L_C = 2 r0 sin(phi1).
double contact_length(double deflection_m, double r0_m);

/// (1 - cos phi1)^(4/3): left side of eq. (6) and (10).
double deflection_power(double phi1);

/// sin phi1 - phi1 cos phi1: P_Z = 2 C_P r0 (sin phi1 - phi1 cos phi1), seed eq. (2).
double kelvin_voigt_load_function(double phi1);

/// cos phi1 (phi1 - cos phi1 * atanh(sin phi1)), atanh(s) = 1/2 ln((1+s)/(1-s)):
/// P_Z = 2 K1 B_tr r0^2 * this, seed eq. (8) with sigma = K1 Delta_P acting on the arc.
double arc_stress_load_function(double phi1);

/// Radial deformation of the ring element at angle phi inside the patch:
/// Delta_P = r0 - rho = r0 (1 - cos phi1 / cos phi) (seed eq. 1), at road abscissa x:
/// Delta_P = r0 - sqrt(x^2 + (r0 - h)^2), clipped at 0 outside the patch.
double radial_deformation_at(double x_m, double deflection_m, double r0_m);

}  // namespace modaltyre::rheology
