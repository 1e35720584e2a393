#include "modaltyre/rheology/soil.h"

#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/core/errors.h"
#include "rheology_test_support.h"

namespace modaltyre::rheology {
namespace {

constexpr double kE2 = 3.0e6, kEta2 = 5.0e4;

SoilOptions soil_opts() { return {0.5, 0.3}; }

SoilData rows(double noise_rel, unsigned seed = 21) {
  test::Noise noise;
  noise.rng.seed(seed);
  SoilData d;
  const double deg = M_PI / 180, r0 = soil_opts().r0_m;
  int line = 2;
  for (double a1 : {12.0, 16.0, 20.0, 24.0})
    for (double V : {0.5, 1.5, 3.0}) {
      SoilRow r;
      r.alpha1_rad = a1 * deg;
      r.alpha2_rad = 0.55 * a1 * deg;
      r.total_sinking_m = r0 * (1 - std::cos(r.alpha1_rad));
      r.elastic_sinking_m = r0 * (1 - std::cos(r.alpha2_rad));
      r.layer_m = 0.30;
      r.speed_m_s = V;
      r.line = line++;
      r = soil_forces(r, kE2, kEta2, soil_opts());
      r.load_N *= 1 + noise_rel * noise();
      r.longitudinal_force_N *= 1 + noise_rel * noise();
      d.rows.push_back(r);
    }
  return d;
}

TEST(rheology_Soil, RoundTripWithoutNoiseWithin1Percent) {
  const auto r = identify_soil(rows(0.0), soil_opts());
  EXPECT_NEAR(r.E2_Pa / kE2, 1.0, 1e-6);
  EXPECT_NEAR(r.eta2_Pa_s / kEta2, 1.0, 1e-6);
  EXPECT_NEAR(r.k_E, r.k_E, 0);  // mean elastic share, reported
  EXPECT_GT(r.k_E, 0.2);
  EXPECT_LT(r.k_E, 0.4);
}

TEST(rheology_Soil, RoundTripWith2PercentNoise) {
  // Stated tolerance: 3 % on E2 and 15 % on eta2 with 2 % noise on both forces over 12 rows
  // (viscous forces are a minor share of P_Z and P_X).
  for (unsigned seed : {21u, 22u, 23u}) {
    const auto r = identify_soil(rows(0.02, seed), soil_opts());
    EXPECT_NEAR(r.E2_Pa / kE2, 1.0, 0.03) << seed;
    EXPECT_NEAR(r.eta2_Pa_s / kEta2, 1.0, 0.15) << seed;
    EXPECT_GT(r.E2_se, 0.0);
  }
}

TEST(rheology_Soil, DegenerateInputs) {
  SoilData one;
  one.rows.push_back(rows(0.0).rows.front());
  EXPECT_THROW(identify_soil(one, soil_opts()), InputError);
  EXPECT_THROW(identify_soil(rows(0.0), SoilOptions{}), InputError);
  const auto f = test::temp_file(
      "soilbad.csv",
      "load_N,longitudinal_force_N,alpha1_deg,alpha2_deg,total_sinking_mm,elastic_sinking_mm,"
      "layer_mm,speed_m_s\n5000,600,20,11,30,-9,300,1\n5000,600,20,11,30,9,300,1\n");
  try {
    read_soil_rolling_csv(f);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().key, "elastic_sinking_mm");
  }
  EXPECT_EQ(test::run_cli("identify soil-rolling " + f + " --r0-mm 500 --tread-width-mm 300"), 2);
  const std::string src = MODALTYRE_SOURCE_DIR;
  const std::string ex = src + "/tests/data/rheology/soil_rolling.csv";
  EXPECT_EQ(test::run_cli("identify soil-rolling " + ex + " --r0-mm 500 --tread-width-mm 300"), 0);
  EXPECT_EQ(test::run_cli("identify soil-rolling " + ex + " --r0-mm 500"), 2);
}

}  // namespace
}  // namespace modaltyre::rheology
