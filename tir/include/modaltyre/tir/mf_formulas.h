#pragma once
// The Magic Formula's vertical and contact-patch laws for a standing tyre on a flat road
// (Pacejka 2012, Tire and Vehicle Dynamics, 3rd ed., Appendix 3, with the MF-Tyre/MF-Swift 6.x
// equation manual's reading of them). SI units throughout; deflection rho = R0 - loaded radius.
//
//   (A3.3) F_z = F_z0 (1 + p_Fz1 dp_i) (q_Fz1 rho/R0 + q_Fz2 (rho/R0)^2)
//          (no speed, no horizontal forces, no camber: the factors of q_V2, q_Fcx, q_Fcy and
//          q_Fz3 are 1; no bottoming)
//   (A3.4) q_Fz1 = sqrt((C_z0 R0 / F_z0)^2 - 4 q_Fz2): the tangent stiffness of (A3.3) at F_z0
//          and nominal pressure equals VERTICAL_STIFFNESS C_z0. Derivation: with x = rho/R0,
//          f = q1 x + q2 x^2 = 1 at F_z0 gives x0 = 2 / (q1 + sqrt(q1^2 + 4 q2)), and
//          dF/drho = F_z0/R0 (q1 + 2 q2 x0) = F_z0/R0 sqrt(q1^2 + 4 q2).
//   (A3.5) C_z = C_z0 (1 + p_Fz1 dp_i), dp_i = (p_i - p_i0) / p_i0 (NOMPRES p_i0)
//   (A3.7) a = R0 (q_ra2 rho_z/R0 + q_ra1 sqrt(rho_z/R0))       half contact length
//   (A3.8) b = W  (q_rb2 rho_z/R0 + q_rb1 (rho_z/R0)^(1/3))     half contact width
// In (A3.7)-(A3.8) the MF evaluators (MF-Tool, mfeval, TyreDyn) take rho_z = F_z / C_z, the
// linear deflection, not the deflection of (A3.3); the two agree when q_Fz2 = 0. This file
// follows them, so that an exported .tir evaluates in any simulator as it does here.
#include <optional>

namespace modaltyre::tir {

struct MfVerticalLaw {
  double unloaded_radius_m = 0;       ///< R0, UNLOADED_RADIUS
  double fnomin_N = 0;                ///< F_z0, FNOMIN
  double vertical_stiffness_N_m = 0;  ///< C_z0, VERTICAL_STIFFNESS (at NOMPRES)
  double q_fz1 = 0;                   ///< (A3.4), or Q_FZ1 as a file gives it
  double q_fz2 = 0;                   ///< Q_FZ2
  double pfz1 = 0;                    ///< PFZ1
  double nominal_pressure_Pa = 0;     ///< NOMPRES; 0 = no pressure dependence
};

/// (A3.4): q_Fz1 of a stiffness; nullopt when (C_z0 R0/F_z0)^2 <= 4 q_Fz2.
std::optional<double> q_fz1_from_stiffness(double stiffness_N_m, double unloaded_radius_m,
                                           double fnomin_N, double q_fz2);

/// (A3.4) inverted: C_z0 = F_z0/R0 sqrt(q_Fz1^2 + 4 q_Fz2); nullopt when not positive.
std::optional<double> stiffness_from_q_fz(double q_fz1, double q_fz2, double unloaded_radius_m,
                                          double fnomin_N);

/// dp_i of (A3.5); 0 without a nominal pressure.
double pressure_increment(const MfVerticalLaw& law, double pressure_Pa);

/// (A3.3) F_z at a deflection; pressure_Pa <= 0 means the nominal pressure.
double mf_load_N(const MfVerticalLaw& law, double deflection_m, double pressure_Pa = 0);

/// (A3.3) inverted on its rising branch; nullopt beyond the law's maximum load (q_Fz2 < 0).
std::optional<double> mf_deflection_m(const MfVerticalLaw& law, double load_N,
                                      double pressure_Pa = 0);

/// (A3.5) C_z at a pressure.
double mf_vertical_stiffness(const MfVerticalLaw& law, double pressure_Pa = 0);

/// (A3.7) half contact length a at rho_z = F_z / C_z.
double mf_half_length_m(double unloaded_radius_m, double q_ra1, double q_ra2, double rho_z_m);

/// (A3.8) half contact width b at rho_z = F_z / C_z.
double mf_half_width_m(double unloaded_radius_m, double width_m, double q_rb1, double q_rb2,
                       double rho_z_m);

}  // namespace modaltyre::tir
