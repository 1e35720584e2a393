// `tir compare --slip` (tir/slip_compare.h) and the reading of the laws it compares
// (tir/mf_tyre.h): a file carrying the very laws the runs were made from compares to zero, in
// absolute units and, scaled to another size with the same dimensionless laws, in dimensionless
// form; a file without a law says which keys it lacks; the coefficients of a public MF 6.2 file
// and of an MF 5.2 file are read as their writers state them.
#include "modaltyre/tir/slip_compare.h"

#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/tir/mf_tyre.h"
#include "planted_slip.h"

namespace {

using namespace modaltyre_test;

const std::string kSlipTirData = std::string(MODALTYRE_SOURCE_DIR) + "/tests/data/tir/";

SlipRuns planted_runs() {
  const Planted p = planted();
  SlipRuns r;
  r.speed_m_s = basis().longvl_m_s;
  r.mu = 1;
  for (double share : {0.5, 1.0, 1.5})
    r.curves.push_back(planted_run(p, share * 4000, r.speed_m_s, {-0.2, -0.02, 0.02, 0.2}));
  for (double v : {10.0, 30.0}) r.free_runs.push_back(planted_run(p, 4000, v, {}));
  return r;
}

/// A file holding the planted laws; `size` scales R0 and FNOMIN (C_z with FNOMIN / R0, so that
/// every dimensionless law stays the same).
MfTyre planted_file(double size) {
  const Planted p = planted();
  MfTyre t;
  t.fittyp = 62;
  t.unloaded_radius_m = basis().unloaded_radius_m * size;
  t.vertical.unloaded_radius_m = t.unloaded_radius_m;
  t.vertical.fnomin_N = basis().fnomin_N * size * size;
  t.vertical.vertical_stiffness_N_m = basis().vertical_stiffness_N_m * size;
  t.longvl_m_s = basis().longvl_m_s;
  t.longitudinal = p.fx;
  t.rolling = p.my;
  t.effective_radius = p.re;
  return t;
}

TEST(SlipCompare, TheRunsOwnLawsCompareToZero) {
  const SlipComparison c = compare_slip_runs(planted_file(1), planted_runs(), false, 4000, 0.3);
  ASSERT_TRUE(c.rms_fx_over_fz && c.rms_rolling && c.rms_radius_over_r0);
  EXPECT_LT(*c.max_fx_over_fz, 1e-12);
  EXPECT_LT(*c.max_rolling, 1e-12);
  EXPECT_LT(*c.rms_radius_over_r0, 1e-12);
  EXPECT_EQ(c.force.size(), 3u * 5u);    // each load's free rolling and 4 slips
  EXPECT_EQ(c.rolling.size(), 3u + 2u);  // free rolling at each load and further speed
  EXPECT_EQ(c.radius.size(), 3u);
}

TEST(SlipCompare, AnotherSizeWithTheSameDimensionlessLawsComparesToZero) {
  const SlipComparison c = compare_slip_runs(planted_file(1.5), planted_runs(), true, 4000, 0.3);
  // Zero to rounding (the scaled loads pass through exp and atan).
  EXPECT_LT(*c.max_fx_over_fz, 1e-9);
  EXPECT_LT(*c.max_rolling, 1e-9);
  EXPECT_LT(*c.rms_radius_over_r0, 1e-9);
  // In absolute units the larger tyre's laws differ: the comparison sees it.
  const SlipComparison a = compare_slip_runs(planted_file(1.5), planted_runs(), false, 4000, 0.3);
  EXPECT_GT(*a.rms_radius_over_r0, 0.1);
}

TEST(SlipCompare, AFileWithoutTheLawsSaysWhichKeysItLacks) {
  const MfTyre t = read_mf_tyre(kSlipTirData + "mfswift62_mm_kN.tir");
  const SlipComparison c = compare_slip_runs(t, planted_runs(), true, 4000, 0.3);
  EXPECT_FALSE(c.rms_fx_over_fz);
  EXPECT_NE(c.force_reason.find("PCX1, PDX1 and PKX1"), std::string::npos) << c.force_reason;
  EXPECT_FALSE(c.rms_rolling);
  EXPECT_NE(c.rolling_reason.find("QSY1"), std::string::npos) << c.rolling_reason;
  EXPECT_TRUE(c.rms_radius_over_r0);  // it states Q_RE0 = 1: R_e = R0
  ASSERT_EQ(c.force.size(), 15u);
  EXPECT_FALSE(c.force[0].tir_fx_N);
}

TEST(SlipCompare, PublicMf62FileIsReadAsWritten) {
  const MfTyre t = read_mf_tyre(kSlipTirData + "tyredyn_car205_60R19_mf62.tir");
  ASSERT_TRUE(t.longitudinal && t.rolling && t.effective_radius);
  EXPECT_DOUBLE_EQ(t.longitudinal->pcx1, 1.579);
  EXPECT_DOUBLE_EQ(t.longitudinal->pkx1, 21.69);
  EXPECT_DOUBLE_EQ(t.longitudinal->ppx4, 0.06447);
  EXPECT_DOUBLE_EQ(t.rolling->qsy7, 0.9008);
  EXPECT_DOUBLE_EQ(t.rolling->qsy8, -0.4089);
  EXPECT_DOUBLE_EQ(t.effective_radius->breff, 8.39);
  EXPECT_DOUBLE_EQ(t.longvl_m_s, 16.7);
  EXPECT_DOUBLE_EQ(t.scaling.lmux, 1);
  EXPECT_DOUBLE_EQ(t.scaling.lmuv, 0);  // not stated: 0
}

// MF 5.2 states M_y = -R0 F_z (QSY1 + ...): the same law as MF 6.x's with QSY7 = 1.
TEST(SlipCompare, Mf52RollingMomentIsProportionalToTheLoad) {
  const MfTyre t = read_mf_tyre(kSlipTirData + "chrono_generic_mf52.tir");
  ASSERT_TRUE(t.rolling);
  EXPECT_EQ(t.rolling->qsy7, 1);
  EXPECT_EQ(t.rolling->qsy8, 0);
  const MfBasis b = t.mf_basis();
  const double my = mf_rolling_moment_Nm(*t.rolling, t.scaling, b, 0, 3000, 0);
  EXPECT_NEAR(my, -t.unloaded_radius_m * 3000 * t.rolling->qsy1, 1e-12);
  EXPECT_DOUBLE_EQ(t.longvl_m_s, 15);
}

TEST(SlipCompare, LongvlIsASpeedInTheFilesUnits) {
  const std::string text =
      "[UNITS]\nLENGTH = 'mm'\nFORCE = 'newton'\nTIME = 'second'\n"
      "[MODEL]\nFITTYP = 62\nLONGVL = 16700\n"
      "[DIMENSION]\nUNLOADED_RADIUS = 300\n"
      "[VERTICAL]\nFNOMIN = 4000\nVERTICAL_STIFFNESS = 200\n";
  const MfTyre t = interpret_tir(parse_tir(text, "mm.tir"));
  EXPECT_DOUBLE_EQ(t.longvl_m_s, 16.7);
}

}  // namespace
