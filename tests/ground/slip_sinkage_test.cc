// The slip sinkage (ground/soil_options.h, ground/slip_sinkage.h; Lyasko 2010): the factor, the
// stretched law's branches and memory, and the rigid wheel on it against the equivalent Bekker
// soil.
#include "modaltyre/ground/slip_sinkage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "modaltyre/ground/ground_settings.h"
#include "modaltyre/ground/rigid_wheel.h"

namespace modaltyre::ground {
namespace {

GroundSettings lete_slip_sinkage() {
  GroundSettings g;  // Wong, Theory of Ground Vehicles, 4th ed., Table 2.3 (LETE sand)
  g.model = GroundModel::bekker;
  g.bekker.n = 0.79, g.bekker.k_c = 102, g.bekker.k_phi = 5301;
  g.bekker_shear = {1.3, 31.1, 12};
  g.slip_sinkage.enabled = true;
  return g;
}

TEST(SlipSinkage, LyaskosFactorDoublesTheSinkageAtHalfSlipAndIsOneOffOrAtZero) {
  SlipSinkage s;
  EXPECT_EQ(s.factor(0.4), 1.0);  // off
  s.enabled = true;
  EXPECT_EQ(s.factor(0.0), 1.0);
  EXPECT_DOUBLE_EQ(s.factor(0.5), 2.0);   // (1 + 0.5) / (1 - 0.25)
  EXPECT_DOUBLE_EQ(s.factor(-0.5), 2.0);  // braking excavates too
  EXPECT_DOUBLE_EQ(s.factor(0.2), 1.2 / 0.9);
}

TEST(SlipSinkage, TheStretchedLawSinksFTimesOnEveryBranch) {
  BekkerParams p;
  p.n = 0.79, p.k_c = 102, p.k_phi = 5301;
  p.unloading = WongUnloading{0, 5e5};
  const double f = 1.7, b = 0.12;
  const BekkerWong plain(p, b);
  const SlipSinkageLaw stretched(std::make_unique<BekkerWong>(p, b), f);
  // Bekker's law stretched by f is Bekker's law with the modulus divided by f^n.
  BekkerParams soft = p;
  soft.k_c /= std::pow(f, p.n), soft.k_phi /= std::pow(f, p.n);
  const BekkerWong equivalent(soft, b);
  for (double pr : {1e3, 5e4, 2e5}) {
    EXPECT_NEAR(stretched.loading_sinkage_m(pr), f * plain.loading_sinkage_m(pr), 1e-15);
    EXPECT_NEAR(stretched.loading_sinkage_m(pr), equivalent.loading_sinkage_m(pr), 1e-12);
    const double zmax = 0.03;
    EXPECT_NEAR(stretched.sinkage_m(pr, zmax), f * plain.sinkage_m(pr, zmax / f), 1e-15);
    EXPECT_NEAR(stretched.work_J_m2(pr, zmax), f * plain.work_J_m2(pr, zmax / f), 1e-9);
    double dz = 0;
    const double z = stretched.virgin_sinkage_m(pr, dz);
    EXPECT_NEAR(z, stretched.loading_sinkage_m(pr), 1e-15);
    EXPECT_NEAR(dz, stretched.compliance_m_per_Pa(pr, 0), 1e-9 * dz);
  }
  EXPECT_NEAR(stretched.rebound_depth_m(0.03), f * plain.rebound_depth_m(0.03 / f), 1e-15);
  EXPECT_NEAR(stretched.pressure_Pa(0.02, 0.02), plain.pressure_Pa(0.02 / f, 0.02 / f), 1e-9);
}

TEST(SlipSinkage, TheRigidWheelRollsAsOnTheSoilWithTheModulusDividedByFToTheN) {
  // Bekker's b = the width here (a contact longer than 100 mm wide wheel) so that only the slip's
  // factor differs between the two soils.
  const RigidWheel wheel{0.2948, 0.10};
  for (double s : {-0.2, 0.1, 0.4}) {
    const GroundSettings g = lete_slip_sinkage();
    GroundSettings soft = g;
    soft.slip_sinkage.enabled = false;
    const double scale = std::pow(g.slip_sinkage.factor(s), -g.bekker.n);
    soft.bekker.k_c *= scale, soft.bekker.k_phi *= scale;
    const RigidWheelResult a = rigid_wheel_rolling(g, wheel, 3000, s);
    const RigidWheelResult b = rigid_wheel_rolling(soft, wheel, 3000, s);
    ASSERT_TRUE(a.ok() && b.ok()) << a.message << b.message;
    EXPECT_NEAR(a.sinkage_m, b.sinkage_m, 1e-9 * b.sinkage_m) << s;
    EXPECT_NEAR(a.drawbar_pull_N, b.drawbar_pull_N, 1e-6 * 3000) << s;
    GroundSettings off = g;
    off.slip_sinkage.enabled = false;
    EXPECT_GT(a.sinkage_m, rigid_wheel_rolling(off, wheel, 3000, s).sinkage_m) << s;
  }
  // Off, or k1 = k2 = 0: the law itself, bit for bit.
  GroundSettings zero = lete_slip_sinkage(), off = lete_slip_sinkage();
  zero.slip_sinkage.k1 = zero.slip_sinkage.k2 = 0;
  off.slip_sinkage.enabled = false;
  EXPECT_EQ(rigid_wheel_rolling(zero, wheel, 3000, 0.3).sinkage_m,
            rigid_wheel_rolling(off, wheel, 3000, 0.3).sinkage_m);
}

}  // namespace
}  // namespace modaltyre::ground
