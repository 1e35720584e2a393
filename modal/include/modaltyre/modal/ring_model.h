#pragma once
// The tensioned ring on a two-parameter elastic foundation: what ties a tyre's in-plane
// natural frequencies to its modal masses, its inflation tension and its static compliance.
// Derivation: docs/ring_model.md; tests: tests/modal/ring_model_test.cc.
//
// The belt (with tread) is an inextensible ring of radius R, mass mu per length, bending
// stiffness EI, hoop tension T = p b R from the inflation pressure p acting over the belt
// width b, on the sidewalls' radial and tangential foundation k_r, k_t (per length). A mode of
// order n >= 1 is w = a cos n(theta - psi) radially and v = -(a/n) sin n(theta - psi)
// tangentially (inextensible: w = -dv/dtheta). Its energies per cycle give
//   modal mass      M_n = pi R mu (1 + 1/n^2)                       (radial + tangential inertia)
//   static stiffness K_n = EI (n^2-1)^2 / R^4 + (T / R^2)(n^2 - 1) + k_r + k_t / n^2   [N/m^2]
//   omega_n^2       = K_n / (mu (1 + 1/n^2))
// so that a radial point load F at the belt deflects it by F/(pi R) sum_n cos(n theta) / K_n
// (rim held). Frequencies alone fix K_n / mu: the mass scale is a separate fact. It comes
// from the tension (T = p b R is the one term whose size the pressure and geometry fix), or
// from a stated belt mass; the two checked against each other are the consistency test of the
// data. Order 0 (breathing) is extensional and not part of the family.
//
// The modal test's boundary condition: in a free test (tyre on its wheel, hung or on foam)
// the wheel moves with the order-1 (translation) and the order-0 rotation modes; the footprint
// holds the wheel. A two-mass system gives omega_fixed^2 = omega_free^2 m_wheel / (m_belt +
// m_wheel) (Kung, Soedel and Yang 1986: only the n = 1 radial modes feel the wheel's freedom;
// the rotation mode likewise with the polar inertias).
#include <string>
#include <vector>

namespace modaltyre::modal {

/// The stiffness per unit mass of order n, K_n / mu = a + b (n^2-1) + c (n^2-1)^2 + d / n^2
/// [rad^2/s^2]: a = k_r / mu (radial foundation), b = T / (mu R^2) (tension), c = EI / (mu R^4)
/// (bending), d = k_t / mu (tangential foundation).
struct RingCoefficients {
  double radial_foundation = 0;
  double tension = 0;
  double bending = 0;
  double tangential_foundation = 0;

  /// K_n / mu for order n >= 1 [rad^2/s^2].
  double stiffness_per_mass(int n) const;
  /// omega_n^2 = (K_n / mu) / (1 + 1/n^2) for n >= 1 [rad^2/s^2].
  double omega_sq(int n) const;
};

/// 1 + 1/n^2: the tangential share of an inextensible mode's kinetic energy (n >= 1).
double ring_mass_factor(int n);

struct RingFit {
  bool valid = false;
  RingCoefficients coefficients;
  int orders_used = 0;       ///< distinct orders >= 1 in the fit
  double rms_rel_error = 0;  ///< RMS relative error of the fitted frequencies
  std::string reason;        ///< why the fit is invalid
};

/// Fits the coefficients (non-negative) to (order, rim-held frequency) pairs by least squares
/// on omega^2 (1 + 1/n^2), each row relative to its value; orders < 1 are ignored. Needs at
/// least two distinct orders; with fewer than four distinct orders only the supports with at
/// most that many coefficients are tried (each exact for its size).
RingFit fit_ring(const std::vector<int>& orders, const std::vector<double>& freq_hz);

/// mu from the tension: b_coefficient = T / (mu R^2) with T = p b R  ->  mu = p b / (R tension)
/// [kg/m]. pressure_Pa > 0, belt_width_m > 0, radius_m > 0, tension_coefficient > 0.
double mass_per_length_from_tension(const RingCoefficients& c, double pressure_Pa,
                                    double belt_width_m, double radius_m);

/// The hoop tension T = mu R^2 b_coefficient a mass per length implies [N].
double implied_tension_N(const RingCoefficients& c, double mass_per_length_kg_m, double radius_m);

/// The section geometry the belt's net hoop tension depends on (docs/ring_model.md section 3a).
struct BeltSection {
  double belt_width_m = 0;        ///< b: the belt band the pressure pushes out
  double edge_radius_m = 0;       ///< r_e: the carcass line's radius at the belt edge
  double max_width_radius_m = 0;  ///< r_m: the radius of the section's widest point (r_m < r_e)
  double edge_angle_rad = 0;      ///< psi_e: the sidewall meridian's angle to the axis at r_e
};

/// The belt's net hoop tension of a radial-carcass section [N]: radial equilibrium of the belt
/// band, p b r_e = H + 2 N_e sin(psi_e) r_e, with the sidewall's meridional tension N_e from the
/// axial equilibrium of the sidewall between the belt edge and its widest point (where the
/// meridian is radial), N_e cos(psi_e) r_e = p (r_e^2 - r_m^2) / 2:
///     H = p [b r_e - (r_e^2 - r_m^2) tan(psi_e)].
/// psi_e = 0 or r_e = r_m gives the gross p b r_e. InputError-free: checks its arguments.
double net_hoop_tension_N(double pressure_Pa, const BeltSection& section);

/// A free test's frequency of an order-1 (translation) or rotation mode moved to the rim-held
/// boundary: omega_fixed = omega_free sqrt(m_wheel / (m_belt + m_wheel)) (inertias for the
/// rotation). Both masses > 0.
double rim_held_frequency_hz(double free_hz, double belt_mass, double wheel_mass);

/// The coefficients at another inflation pressure: the tension term exactly in proportion to
/// the pressure (T = p b R), the foundation's pneumatic share `foundation_pneumatic_fraction`
/// (0..1) in proportion, bending unchanged. p_test, p > 0.
RingCoefficients at_pressure(const RingCoefficients& c, double test_pressure_Pa, double pressure_Pa,
                             double foundation_pneumatic_fraction);

}  // namespace modaltyre::modal
