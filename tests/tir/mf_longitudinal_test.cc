// The MF 6.2 longitudinal laws (tir/mf_longitudinal.h) against their closed forms: the slope at
// zero slip is K_xk (Pacejka 2012 4.E15-4.E16: B C D = K), the peak of a shape C > 1 is
// D + S_Vx, the shifts move the curve, the load terms, and the rolling moment and effective
// radius by hand.
#include "modaltyre/tir/mf_longitudinal.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace modaltyre::tir;

MfBasis reference_basis() {
  MfBasis b;
  b.unloaded_radius_m = 0.3;
  b.fnomin_N = 4000;
  b.longvl_m_s = 16.7;
  b.nominal_pressure_Pa = b.pressure_Pa = 2.2e5;
  b.vertical_stiffness_N_m = 2e5;
  return b;
}

// A passenger tyre's values (the order of TyreDyn's generic MF 6.2 car file).
MfLongitudinal car() {
  MfLongitudinal c;
  c.pcx1 = 1.58, c.pdx1 = 1.04, c.pdx2 = -0.083;
  c.pex1 = 0.11, c.pex2 = 0.31, c.pex3 = 0.05, c.pex4 = 0.0016;
  c.pkx1 = 21.7, c.pkx2 = 13.8, c.pkx3 = -0.41;
  c.phx1 = 2e-4, c.phx2 = 1e-3, c.pvx1 = 1.6e-5, c.pvx2 = 1e-4;
  return c;
}

double dfz(double fz) { return (fz - reference_basis().fnomin_N) / reference_basis().fnomin_N; }

TEST(MfLongitudinal, SlopeAtZeroShiftedSlipIsTheSlipStiffness) {
  const MfLongitudinal c = car();
  for (double fz : {2000.0, 4000.0, 6500.0}) {
    const double d = dfz(fz);
    const double shx = c.phx1 + c.phx2 * d;
    const double h = 1e-7;
    const double slope = (mf_fx0_N(c, {}, reference_basis(), -shx + h, fz) -
                          mf_fx0_N(c, {}, reference_basis(), -shx - h, fz)) /
                         (2 * h);
    const double kxk = fz * (c.pkx1 + c.pkx2 * d) * std::exp(c.pkx3 * d);  // 4.E15
    EXPECT_NEAR(slope, kxk, 1e-5 * kxk) << fz;
    // At kappa = -S_Hx the force is the vertical shift alone (4.E18).
    EXPECT_NEAR(mf_fx0_N(c, {}, reference_basis(), -shx, fz), fz * (c.pvx1 + c.pvx2 * d),
                1e-9 * fz);
  }
}

TEST(MfLongitudinal, PeakIsDPlusTheVerticalShift) {
  MfLongitudinal c = car();
  const double fz = 5000, d = dfz(fz);
  const double D = (c.pdx1 + c.pdx2 * d) * fz;  // 4.E12-4.E13
  double peak = -1e9;
  for (double k = 0; k < 1; k += 1e-4)
    peak = std::max(peak, mf_fx0_N(c, {}, reference_basis(), k, fz));
  EXPECT_NEAR(peak, D + fz * (c.pvx1 + c.pvx2 * d), 1e-4 * D);
}

TEST(MfLongitudinal, HorizontalShiftMovesTheCurve) {
  MfLongitudinal c = car();
  c.phx2 = c.pvx1 = c.pvx2 = 0;
  MfLongitudinal unshifted = c;
  unshifted.phx1 = 0;
  for (double k : {-0.2, -0.03, 0.01, 0.1}) {
    EXPECT_NEAR(mf_fx0_N(c, {}, reference_basis(), k, 4000),
                mf_fx0_N(unshifted, {}, reference_basis(), k + c.phx1, 4000), 1e-9);
  }
}

TEST(MfLongitudinal, CurvatureIsLimitedToOneAndSignedByTheSlip) {
  MfLongitudinal c = car();
  c.pex1 = 0.5, c.pex4 = 0.4;
  // (1 - PEX4 sgn kappa_x): braking 0.7, driving 0.3.
  EXPECT_NEAR(mf_curvature_x(c, {}, reference_basis(), -0.1, 4000), 0.7, 1e-12);
  EXPECT_NEAR(mf_curvature_x(c, {}, reference_basis(), 0.1, 4000), 0.3, 1e-12);
  // Braking E_x = 2 x 1.3 evaluates as E_x = 1 exactly (4.E14): as PEX1 = 1 / 1.3.
  c.pex1 = 2.0, c.pex4 = 0.3;
  MfLongitudinal one = c;
  one.pex1 = 1 / 1.3;
  EXPECT_NEAR(mf_curvature_x(one, {}, reference_basis(), -0.2, 4000), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(mf_fx0_N(c, {}, reference_basis(), -0.2, 4000),
                   mf_fx0_N(one, {}, reference_basis(), -0.2, 4000));
}

TEST(MfLongitudinal, ScalingFactorsScaleTheirTerms) {
  const MfLongitudinal c = car();
  MfScaling s;
  s.lmux = 0.5;
  // The peak halves (and lambda'_mux = 10 * 0.5 / (1 + 9 * 0.5) scales the vertical shift).
  double peak = 0, peak_half = 0;
  for (double k = 0; k < 1; k += 1e-4) {
    peak = std::max(peak, mf_fx0_N(c, {}, reference_basis(), k, 4000));
    peak_half = std::max(peak_half, mf_fx0_N(c, s, reference_basis(), k, 4000));
  }
  const double sv = 4000 * c.pvx1;
  EXPECT_NEAR(peak_half - sv * 10 * 0.5 / 5.5, 0.5 * (peak - sv), 1e-3 * peak);
}

TEST(MfLongitudinal, RollingMomentByHand) {
  MfRolling q;
  q.qsy1 = 0.01, q.qsy2 = 0.002, q.qsy3 = 0.001, q.qsy4 = 2e-4, q.qsy7 = 0.85;
  const MfBasis b = reference_basis();
  const double fx = -300, fz = 6000, v = 25;
  const double vr = v / b.longvl_m_s;
  const double expected = -0.3 * 4000 *
                          (0.01 + 0.002 * fx / 4000 + 0.001 * vr + 2e-4 * std::pow(vr, 4)) *
                          std::pow(fz / 4000, 0.85);
  EXPECT_NEAR(mf_rolling_moment_Nm(q, {}, b, fx, fz, v), expected, 1e-12);
  EXPECT_LT(mf_rolling_moment_Nm(q, {}, b, 0, fz, v), 0);  // opposes forward rolling
  // QSY8 with the pressure: (p / p0)^QSY8.
  q.qsy8 = -0.4;
  MfBasis high = b;
  high.pressure_Pa = 1.1 * b.nominal_pressure_Pa;
  EXPECT_NEAR(
      mf_rolling_moment_Nm(q, {}, high, fx, fz, v) / mf_rolling_moment_Nm(q, {}, b, fx, fz, v),
      std::pow(1.1, -0.4), 1e-12);
}

TEST(MfLongitudinal, EffectiveRadiusByHand) {
  MfEffectiveRadius r;
  r.q_re0 = 0.998, r.q_v1 = 1e-3, r.breff = 8, r.dreff = 0.26, r.freff = 0.07;
  const MfBasis b = reference_basis();
  const double omega = 50, fz = 5000;
  const double r_omega = 0.3 * (0.998 + 1e-3 * std::pow(0.3 * omega / 16.7, 2));
  const double expected =
      r_omega - 4000 / 2e5 * (0.07 * fz / 4000 + 0.26 * std::atan(8 * fz / 4000));
  EXPECT_NEAR(mf_effective_radius_m(r, b, fz, omega), expected, 1e-15);
  // Unloaded and standing: the free radius R0 Q_RE0.
  EXPECT_NEAR(mf_effective_radius_m(r, b, 0, 0), 0.3 * 0.998, 1e-15);
}

}  // namespace
