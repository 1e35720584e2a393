#pragma once
// Switchable laws of a Bekker soil beyond its pressure-sinkage and shear laws (docs/soil.md
// sections 3.1, 5.2 and 5.3), each off by default (off reproduces the laws without them exactly).
// Keys under `ground.bekker.` (ground_settings.h):
//
//   wong_reece: {enabled: false, c1: 0.43, c2: 0.32, c3: 0}
//     The rigid wheel's normal stress with its peak moved back with slip (Wong & Reece 1967,
//     Part I; Wong, Theory of Ground Vehicles, 4th ed., 2008, section 2.7): the front region
//     theta_m <= theta <= theta1 carries the soil's loading law at the wheel's depth, the rear
//     region theta2 <= theta <= theta_m the front's stress mapped onto it,
//       sigma(theta) = sigma_front(theta1 - (theta - theta2)(theta1 - theta_m)/(theta_m - theta2)),
//     with theta_m = (c1 + c2 s) theta1 (clamped to [0, theta1]) and the rear angle
//     theta2 = -c3 theta1 behind the vertical. c1 0.43, c2 0.32: Wong and Reece's compact sand
//     (loose sand c1 0.18); c3 0: no rebound (the rigid-plastic soil's theta2 = 0).
//     On the flexible tyre (contact/src/wong_reece_flexible.h, docs/soil.md section 10) the rear
//     region's soil flows at that stress inside the rolling contact problem.
//
//   slip_sinkage: {enabled: false, k1: 1, k2: 0.5}
//     Sinkage that grows with slip as the shear excavates the soil under the contact (M. Lyasko,
//     "Slip sinkage effect in soil-vehicle mechanics", J. Terramechanics 47 (2010) 21-31): the
//     sinkage at slip s is the free-rolling one times
//       f(s) = (1 + k1 |s|) / (1 - k2 |s|),     Lyasko's k1 = 1, k2 = 0.5 (soil-independent),
//     f(0.5) = 2. Applied to the soil's pressure-sinkage law at the slip rolled (ISTVS slip,
//     against the rolling radius): at a pressure p the soil sinks f times its law's sinkage
//     (slip_sinkage.h), under the rigid wheel and the flexible tyre alike; |s| because a braked
//     wheel excavates too.
//
//   bulldozing: {enabled: false, unit_weight_kN_m3: 15.7}
//     The resistance of the soil pushed ahead of a sinking wheel, Bekker's simplified form (M. G.
//     Bekker, Introduction to Terrain-Vehicle Systems, 1969; Wong, Theory of Ground Vehicles, 4th
//     ed., section 2.7):
//       R_b = b (0.67 c z K_pc + 0.5 gamma z^2 K_pg),
//       K_pc = (N_c - tan phi) cos^2 phi,   K_pg = (2 N_g / tan phi + 1) cos^2 phi,
//     b the contact's width, z the soil sinkage, c, phi the soil's cohesion and friction angle
//     (its Janosi-Hanamoto keys), N_c, N_g the bearing capacity factors of a general shear
//     failure, Vesic's set (A. S. Vesic, "Analysis of ultimate loads of shallow foundations",
//     J. Soil Mech. Found. Div. ASCE 99, 1973; Wong quotes Terzaghi's, within 10-25 %):
//     N_q = exp(pi tan phi) tan^2(pi/4 + phi/2), N_c = (N_q - 1) / tan phi (pi + 2 at phi = 0),
//     N_g = 2 (N_q + 1) tan phi, so 2 N_g / tan phi = 4 (N_q + 1).
//     gamma the soil's unit weight: 15.7 kN/m^3, a dry sand's 1.6 t/m^3 (Wong's Table 2.3 gives
//     none; an assumption to state or measure).
namespace modaltyre::ground {

struct WongReeceStress {
  bool enabled = false;
  double c1 = 0.43;       ///< theta_m / theta1 at zero slip, [0, 1]
  double c2 = 0.32;       ///< its growth with slip, [0, 1]
  double c3 = 0;          ///< rear angle over entry angle, [0, 0.99]
  void validate() const;  ///< std::invalid_argument naming the key
  /// theta_m / theta1 at slip s, clamped to [0, 1].
  double peak_ratio(double slip) const;
  /// Whether the stress is shifted at slip s: enabled, and a rear region [theta2, theta_m)
  /// exists (c3 > 0 or theta_m > 0); otherwise the soil's own law holds everywhere.
  bool has_rear_region(double slip) const;
};

struct SlipSinkage {
  bool enabled = false;
  double k1 = 1.0;        ///< Lyasko's numerator coefficient, [0, 10]
  double k2 = 0.5;        ///< Lyasko's denominator coefficient, [0, 0.99]
  void validate() const;  ///< std::invalid_argument naming the key
  /// f(s) = (1 + k1 |s|) / (1 - k2 |s|), 1 when off.
  double factor(double slip) const;
};

struct Bulldozing {
  bool enabled = false;
  double unit_weight_kN_m3 = 15.7;  ///< gamma, (0, 30]
  void validate() const;            ///< std::invalid_argument naming the key
};

/// Vesic's N_c, N_q and N_g at the friction angle phi [deg] (see above).
struct BearingFactors {
  double N_c = 0, N_q = 0, N_g = 0;
};
BearingFactors bearing_factors(double friction_angle_deg);

/// Bekker's bulldozing resistance [N] of a contact `width_m` wide sunk `sinkage_m` into a soil
/// of cohesion c and friction angle phi (0 when off or not sunk).
double bulldozing_resistance_N(const Bulldozing& b, double cohesion_kPa, double friction_angle_deg,
                               double width_m, double sinkage_m);

}  // namespace modaltyre::ground
