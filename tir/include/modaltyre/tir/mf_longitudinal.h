#pragma once
// The Magic Formula 6.2 laws of a wheel rolling straight on a flat road: the longitudinal force
// at pure slip, the rolling-resistance moment and the effective rolling radius. Zero camber, no
// turn slip (the zeta factors are 1), forward rolling; SI units.
//
// Longitudinal force, pure slip (Pacejka 2012, Tire and Vehicle Dynamics, 3rd ed., 4.E9-4.E18,
// with 4.E1-4.E2 and the friction scaling 4.E7-4.E8):
//   dfz = (F_z - F'_z0) / F'_z0,  F'_z0 = LFZO F_z0;   dp = (p - p0) / p0
//   kappa_x = kappa + S_Hx,                   S_Hx = (PHX1 + PHX2 dfz) LHX
//   C_x = PCX1 LCX
//   mu_x = (PDX1 + PDX2 dfz) (1 + PPX3 dp + PPX4 dp^2) lambda*_mux  (PDX3 gamma^2 = 0)
//   lambda*_mux = LMUX / (1 + LMUV V_s / V0),  lambda'_mux = A lambda* / (1 + (A - 1) lambda*),
//   A = 10, V_s = |kappa| V_x the slip speed, V0 = LONGVL
//   D_x = mu_x F_z
//   E_x = (PEX1 + PEX2 dfz + PEX3 dfz^2) (1 - PEX4 sgn kappa_x) LEX   (<= 1)
//   K_xk = F_z (PKX1 + PKX2 dfz) exp(PKX3 dfz) (1 + PPX1 dp + PPX2 dp^2) LKX
//   B_x = K_xk / (C_x D_x + eps_x)
//   S_Vx = F_z (PVX1 + PVX2 dfz) LVX lambda'_mux
//   F_x0 = D_x sin(C_x atan(B_x kappa_x - E_x (B_x kappa_x - atan(B_x kappa_x)))) + S_Vx
// kappa = -(V_x - Omega R_e) / V_x with R_e the effective rolling radius below.
//
// Rolling-resistance moment (MF-Tyre 6.1/6.2, Besselink, Schmeitz & Pacejka 2010, "An improved
// Magic Formula/Swift tyre model that can handle inflation pressure changes", Vehicle System
// Dynamics 48 S1, appendix; with R0 F_z0 in front as TNO's solver evaluates it, where Pacejka
// 2012's 4.E70 prints R0 F_z):
//   M_y = -R0 F_z0 LMY (QSY1 + QSY2 F_x/F_z0 + QSY3 |V_x/V0| + QSY4 (V_x/V0)^4
//                       + (QSY5 + QSY6 F_z/F_z0) gamma^2) (F_z/F_z0)^QSY7 (p/p0)^QSY8
// (< 0 rolling forward: it opposes the spin).
//
// Effective rolling radius (Pacejka 2012 A3.1 and A3.6):
//   R_Omega = R0 (Q_RE0 + Q_V1 (R0 Omega / V0)^2)
//   R_e = R_Omega - (F_z0 / C_z) (FREFF F_z/F_z0 + DREFF atan(BREFF F_z/F_z0))
// with C_z the vertical stiffness at the pressure (A3.5).
//
// Coefficients a file does not state are 0 (scaling factors 1, LMUV 0), as MF evaluators take
// them.

namespace modaltyre::tir {

/// [LONGITUDINAL_COEFFICIENTS], pure slip.
struct MfLongitudinal {
  double pcx1 = 0, pdx1 = 0, pdx2 = 0, pdx3 = 0;
  double pex1 = 0, pex2 = 0, pex3 = 0, pex4 = 0;
  double pkx1 = 0, pkx2 = 0, pkx3 = 0;
  double phx1 = 0, phx2 = 0, pvx1 = 0, pvx2 = 0;
  double ppx1 = 0, ppx2 = 0, ppx3 = 0, ppx4 = 0;
};

/// [ROLLING_COEFFICIENTS].
struct MfRolling {
  double qsy1 = 0, qsy2 = 0, qsy3 = 0, qsy4 = 0, qsy5 = 0, qsy6 = 0, qsy7 = 0, qsy8 = 0;
};

/// The effective rolling radius' keys of [VERTICAL].
struct MfEffectiveRadius {
  double q_re0 = 1, q_v1 = 0, breff = 0, dreff = 0, freff = 0;
};

/// [SCALING_COEFFICIENTS] the laws above use.
struct MfScaling {
  double lfzo = 1, lcx = 1, lmux = 1, lex = 1, lkx = 1, lhx = 1, lvx = 1, lmuv = 0, lmy = 1;
};

/// What the laws are evaluated against: the tyre's size, nominal values and conditions.
struct MfBasis {
  double unloaded_radius_m = 0;       ///< R0
  double fnomin_N = 0;                ///< F_z0
  double longvl_m_s = 0;              ///< V0, LONGVL
  double nominal_pressure_Pa = 0;     ///< p0, NOMPRES (0: no pressure dependence)
  double pressure_Pa = 0;             ///< p, INFLPRES
  double vertical_stiffness_N_m = 0;  ///< C_z at p (A3.5)
};

/// E_x of 4.E14 before its limit at 1 (for checking that a fit keeps it there).
double mf_curvature_x(const MfLongitudinal& c, const MfScaling& s, const MfBasis& b, double kappa,
                      double fz_N);

/// F_x0 of 4.E9 [N]; vx_m_s only enters through LMUV (0: none).
double mf_fx0_N(const MfLongitudinal& c, const MfScaling& s, const MfBasis& b, double kappa,
                double fz_N, double vx_m_s = 0);

/// The rolling-resistance moment M_y [N m] (< 0 rolling forward) at V_x > 0, zero camber.
double mf_rolling_moment_Nm(const MfRolling& c, const MfScaling& s, const MfBasis& b, double fx_N,
                            double fz_N, double vx_m_s);

/// R_e [m] of A3.6 at the spin Omega [rad/s].
double mf_effective_radius_m(const MfEffectiveRadius& c, const MfBasis& b, double fz_N,
                             double spin_rad_s);

}  // namespace modaltyre::tir
