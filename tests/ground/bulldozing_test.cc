// Bekker's bulldozing resistance (ground/soil_options.h) with Vesic's bearing capacity factors.
#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/ground/soil_options.h"

namespace modaltyre::ground {
namespace {

TEST(Bulldozing, VesicsFactorsAreTheTabulatedOnes) {
  // Vesic (1973), as tabulated in soil-mechanics texts: phi = 30 deg: N_c 30.14, N_q 18.40,
  // N_g 22.40; phi = 20 deg: 14.83, 6.40, 5.39; phi = 0: N_c = pi + 2 (Prandtl), N_q 1, N_g 0.
  const BearingFactors f30 = bearing_factors(30), f20 = bearing_factors(20),
                       f0 = bearing_factors(0);
  EXPECT_NEAR(f30.N_c, 30.14, 0.01);
  EXPECT_NEAR(f30.N_q, 18.40, 0.01);
  EXPECT_NEAR(f30.N_g, 22.40, 0.01);
  EXPECT_NEAR(f20.N_c, 14.83, 0.01);
  EXPECT_NEAR(f20.N_q, 6.40, 0.01);
  EXPECT_NEAR(f20.N_g, 5.39, 0.01);
  EXPECT_NEAR(f0.N_c, M_PI + 2, 1e-12);
  EXPECT_NEAR(f0.N_q, 1.0, 1e-15);
  EXPECT_NEAR(f0.N_g, 0.0, 1e-15);
  EXPECT_NEAR(bearing_factors(1e-9).N_c, M_PI + 2, 1e-6);  // the limit, continuous
}

TEST(Bulldozing, BekkersResistanceIsTheCohesiveAndTheFrictionalWedge) {
  Bulldozing b;
  EXPECT_EQ(bulldozing_resistance_N(b, 1.3, 31.1, 0.15, 0.03), 0.0);  // off
  b.enabled = true;
  EXPECT_EQ(bulldozing_resistance_N(b, 1.3, 31.1, 0.15, 0.0), 0.0);  // not sunk
  // phi = 30 deg, c = 2 kPa, gamma 15.7 kN/m^3, b = 0.15 m, z = 0.04 m, by hand:
  // K_pc = (30.14 - 0.5774) 0.75 = 22.17, K_pg = (4 (18.40 + 1) + 1) 0.75 = 58.96,
  // R_b = 0.15 (0.67 * 2000 * 0.04 * 22.17 + 0.5 * 15700 * 0.0016 * 58.96) = 289.3 N.
  const BearingFactors f = bearing_factors(30);
  const double Kpc = (f.N_c - std::tan(M_PI / 6)) * 0.75, Kpg = (4 * (f.N_q + 1) + 1) * 0.75;
  const double expected = 0.15 * (0.67 * 2000 * 0.04 * Kpc + 0.5 * 15700 * 0.04 * 0.04 * Kpg);
  EXPECT_NEAR(bulldozing_resistance_N(b, 2.0, 30, 0.15, 0.04), expected, 1e-9 * expected);
  EXPECT_NEAR(expected, 289.3, 0.5);
  // Frictionless clay: K_pc = pi + 2 and K_pg = 4 (N_q + 1) + 1 = 9 (2 N_g / tan phi's limit;
  // no 1/tan phi singularity).
  EXPECT_NEAR(bulldozing_resistance_N(b, 10, 0, 0.15, 0.02),
              0.15 * (0.67 * 1e4 * 0.02 * (M_PI + 2) + 0.5 * 15700 * 0.02 * 0.02 * 9), 1e-9);
  // Deeper sinks resist more than linearly (the frictional wedge grows with z^2).
  EXPECT_GT(bulldozing_resistance_N(b, 1.3, 31.1, 0.15, 0.06),
            2 * bulldozing_resistance_N(b, 1.3, 31.1, 0.15, 0.03));
}

}  // namespace
}  // namespace modaltyre::ground
