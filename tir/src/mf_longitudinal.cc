// MF 6.2 longitudinal force, rolling resistance and effective radius (mf_longitudinal.h).
#include "modaltyre/tir/mf_longitudinal.h"

#include <algorithm>
#include <cmath>

namespace modaltyre::tir {
namespace {

/// A_mu of 4.E8 (Pacejka 2012: 10).
constexpr double kFrictionDecayA = 10;
/// eps_x of 4.E16: keeps B_x finite where C_x D_x vanishes.
constexpr double kEpsX = 1e-6;

double load_increment(const MfScaling& s, const MfBasis& b, double fz_N) {
  const double fz0 = s.lfzo * b.fnomin_N;  // 4.E1
  return (fz_N - fz0) / fz0;               // 4.E2a
}

double pressure_increment(const MfBasis& b) {
  return b.nominal_pressure_Pa > 0 && b.pressure_Pa > 0
             ? (b.pressure_Pa - b.nominal_pressure_Pa) / b.nominal_pressure_Pa  // 4.E2b
             : 0.0;
}

double sign(double x) { return x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0; }

}  // namespace

double mf_curvature_x(const MfLongitudinal& c, const MfScaling& s, const MfBasis& b, double kappa,
                      double fz_N) {
  const double dfz = load_increment(s, b, fz_N);
  const double kappa_x = kappa + (c.phx1 + c.phx2 * dfz) * s.lhx;  // 4.E10, 4.E17
  return (c.pex1 + c.pex2 * dfz + c.pex3 * dfz * dfz) * (1 - c.pex4 * sign(kappa_x)) * s.lex;
}

double mf_fx0_N(const MfLongitudinal& c, const MfScaling& s, const MfBasis& b, double kappa,
                double fz_N, double vx_m_s) {
  const double dfz = load_increment(s, b, fz_N), dp = pressure_increment(b);
  const double slip_speed = std::abs(kappa * vx_m_s);
  const double lmu_star =
      b.longvl_m_s > 0 ? s.lmux / (1 + s.lmuv * slip_speed / b.longvl_m_s) : s.lmux;  // 4.E7
  const double lmu_prime = kFrictionDecayA * lmu_star / (1 + (kFrictionDecayA - 1) * lmu_star);
  const double shx = (c.phx1 + c.phx2 * dfz) * s.lhx;                     // 4.E17
  const double svx = fz_N * (c.pvx1 + c.pvx2 * dfz) * s.lvx * lmu_prime;  // 4.E18
  const double kappa_x = kappa + shx;                                     // 4.E10
  const double cx = c.pcx1 * s.lcx;                                       // 4.E11
  const double mux = (c.pdx1 + c.pdx2 * dfz) * (1 + c.ppx3 * dp + c.ppx4 * dp * dp) * lmu_star;
  const double dx = mux * fz_N;                                           // 4.E12-4.E13
  const double ex = std::min(1.0, mf_curvature_x(c, s, b, kappa, fz_N));  // 4.E14
  const double kxk = fz_N * (c.pkx1 + c.pkx2 * dfz) * std::exp(c.pkx3 * dfz) *
                     (1 + c.ppx1 * dp + c.ppx2 * dp * dp) * s.lkx;  // 4.E15
  const double bx = kxk / (cx * dx + kEpsX);                        // 4.E16
  const double u = bx * kappa_x;
  return dx * std::sin(cx * std::atan(u - ex * (u - std::atan(u)))) + svx;  // 4.E9
}

double mf_rolling_moment_Nm(const MfRolling& c, const MfScaling& s, const MfBasis& b, double fx_N,
                            double fz_N, double vx_m_s) {
  const double fz0 = b.fnomin_N, v = b.longvl_m_s > 0 ? vx_m_s / b.longvl_m_s : 0.0;
  const double p_ratio =
      b.nominal_pressure_Pa > 0 && b.pressure_Pa > 0 ? b.pressure_Pa / b.nominal_pressure_Pa : 1.0;
  const double sum = c.qsy1 + c.qsy2 * fx_N / fz0 + c.qsy3 * std::abs(v) + c.qsy4 * std::pow(v, 4);
  return -b.unloaded_radius_m * fz0 * s.lmy * sum * std::pow(fz_N / fz0, c.qsy7) *
         std::pow(p_ratio, c.qsy8);
}

double mf_effective_radius_m(const MfEffectiveRadius& c, const MfBasis& b, double fz_N,
                             double spin_rad_s) {
  const double r0 = b.unloaded_radius_m;
  const double speed_ratio = b.longvl_m_s > 0 ? r0 * spin_rad_s / b.longvl_m_s : 0.0;
  const double r_omega = r0 * (c.q_re0 + c.q_v1 * speed_ratio * speed_ratio);  // A3.1
  const double load_ratio = fz_N / b.fnomin_N;
  return r_omega - b.fnomin_N / b.vertical_stiffness_N_m *
                       (c.freff * load_ratio + c.dreff * std::atan(c.breff * load_ratio));  // A3.6
}

}  // namespace modaltyre::tir
