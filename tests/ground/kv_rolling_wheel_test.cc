// The Kelvin-Voigt soil's rate term under the rolling rigid wheel (ground/rigid_wheel.h,
// docs/soil.md section 3.2): sigma = k_E (E2 z + eta2 dz/dt) / H with dz/dt = V tan(theta).
// Checks: eta2 = 0 or V = 0 is the elastic law bit for bit; on a frictionless elastic layer the
// wheel's load and motion resistance at a given sinkage equal the closed-form integrals of the
// linear stress; the first-order resistance dRc/dV at V -> 0; monotone in V and eta2.
#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/ground/kelvin_voigt_soil.h"
#include "modaltyre/ground/rigid_wheel.h"
#include "modaltyre/ground/shear.h"

namespace modaltyre::ground {
namespace {

constexpr double kKvR = 0.3, kKvB = 0.15;  // wheel radius and width [m]
constexpr double kKvE2 = 2e6, kKvH = 0.2;  // E2 [Pa], layer H [m]
constexpr double kKvEta2 = 50e3;           // eta2 [Pa s]

GroundSettings kv_ground(double eta2_kPa_s, double elastic_share = 1.0, bool friction = false) {
  GroundSettings g;
  g.model = GroundModel::kelvin_voigt;
  g.kelvin_voigt = {kKvE2 * 1e-6, eta2_kPa_s, kKvH * 1e3, elastic_share};
  g.kelvin_voigt_shear = friction ? JanosiParams{1, 30, 25} : JanosiParams{0, 0, 25};
  return g;
}

RigidWheelResult roll(const GroundSettings& g, double V, double load_N = 3000, double s = 0.1) {
  const RigidWheelResult r = rigid_wheel_rolling(g, {kKvR, kKvB, V}, load_N, s);
  EXPECT_TRUE(r.ok()) << r.message;
  return r;
}

TEST(KelvinVoigtRollingWheel, NoViscosityOrNoSpeedIsTheElasticLawBitForBit) {
  for (double share : {1.0, 0.6}) {
    const RigidWheelResult elastic = roll(kv_ground(0, share, true), 0);
    for (const RigidWheelResult& r :
         {roll(kv_ground(0, share, true), 5.0), roll(kv_ground(kKvEta2 * 1e-3, share, true), 0)}) {
      EXPECT_EQ(r.sinkage_m, elastic.sinkage_m);
      EXPECT_EQ(r.drawbar_pull_N, elastic.drawbar_pull_N);
      EXPECT_EQ(r.motion_resistance_N, elastic.motion_resistance_N);
      EXPECT_EQ(r.torque_Nm, elastic.torque_Nm);
      EXPECT_EQ(r.exit_angle_rad, elastic.exit_angle_rad);
    }
  }
}

// The frictionless elastic layer (k_E = 1): sigma = [E2 (z0 - R + R cos t) + eta2 V tan t] / H
// on [t2, t1], t2 where sigma = 0 behind the lowest point. Its integrals in closed form:
//   W  = (bR/H) [E2 ((z0 - R) sin t + R (t/2 + sin 2t / 4)) - eta2 V cos t]
//   Rc = (bR/H) [E2 (-(z0 - R) cos t + R sin^2 t / 2) + eta2 V (ln(sec t + tan t) - sin t)]
TEST(KelvinVoigtRollingWheel, LoadAndResistanceAtASinkageAreTheClosedFormIntegrals) {
  const GroundSettings g = kv_ground(kKvEta2 * 1e-3);
  const KelvinVoigtSoil law(g.kelvin_voigt);
  const JanosiHanamoto shear(g.kelvin_voigt_shear);
  for (double V : {0.5, 2.0, 8.0}) {
    for (double z0 : {0.005, 0.02}) {
      SCOPED_TRACE(testing::Message() << "V " << V << " z0 " << z0);
      const RigidWheelResult r =
          rigid_wheel_at_sinkage(law, shear, {kKvR, kKvB, V}, z0, 0.1, 0, true);
      const double t1 = std::acos(1 - z0 / kKvR);
      auto sigma = [&](double t) {
        return kKvE2 * (z0 - kKvR + kKvR * std::cos(t)) + kKvEta2 * V * std::tan(t);
      };
      double lo = -t1, hi = 0;  // sigma(-t1) < 0 < sigma(0)
      for (int k = 0; k < 200; ++k) (sigma(0.5 * (lo + hi)) > 0 ? hi : lo) = 0.5 * (lo + hi);
      const double t2 = hi;
      auto W = [&](double t) {
        return kKvE2 * ((z0 - kKvR) * std::sin(t) + kKvR * (t / 2 + std::sin(2 * t) / 4)) -
               kKvEta2 * V * std::cos(t);
      };
      auto Rc = [&](double t) {
        return kKvE2 * (-(z0 - kKvR) * std::cos(t) + kKvR * std::sin(t) * std::sin(t) / 2) +
               kKvEta2 * V * (std::log(1 / std::cos(t) + std::tan(t)) - std::sin(t));
      };
      const double scale = kKvB * kKvR / kKvH;
      EXPECT_NEAR(r.exit_angle_rad, t2, 1e-12);
      EXPECT_NEAR(r.vertical_N, scale * (W(t1) - W(t2)), 1e-9 * r.vertical_N);
      EXPECT_NEAR(r.motion_resistance_N, scale * (Rc(t1) - Rc(t2)), 1e-8 * r.vertical_N);
      EXPECT_GT(r.motion_resistance_N, 0);
      EXPECT_EQ(r.thrust_N, 0);  // frictionless
    }
  }
}

// To first order in V at a fixed load the exit and the sinkage do not move (sigma vanishes at
// the elastic exit; the rate term's load integral is odd in theta), so
//   Rc = 2 (b R / H) eta2 V (ln(sec t1 + tan t1) - sin t1) + O(V^2)  ~  (2/3) b eta2 V a^3 / (H
//   R^2),
// t1 the elastic entry angle, a = R sin t1 the half contact length.
TEST(KelvinVoigtRollingWheel, SlowRollingResistsInProportionToSpeedAndViscosity) {
  const RigidWheelResult elastic = roll(kv_ground(0), 0);
  const double t1 = elastic.entry_angle_rad;
  const double slope =
      2 * kKvB * kKvR / kKvH * kKvEta2 * (std::log(1 / std::cos(t1) + std::tan(t1)) - std::sin(t1));
  EXPECT_NEAR(elastic.motion_resistance_N, 0, 1e-6 * 3000);  // the elastic layer gives back all
  double error_prev = 1;
  for (double V : {0.04, 0.01}) {
    const RigidWheelResult r = roll(kv_ground(kKvEta2 * 1e-3), V);
    const double error = std::abs(r.motion_resistance_N / (slope * V) - 1);
    EXPECT_LT(error, 0.6 * error_prev) << "V " << V;  // first order: falls with V
    error_prev = error;
  }
  EXPECT_LT(error_prev, 0.01);
  // Faster or more viscous: stiffer (shallower) and more resistant.
  double sink = elastic.sinkage_m, rc = 0;
  for (double V : {0.5, 1.0, 2.0, 4.0}) {
    const RigidWheelResult r = roll(kv_ground(kKvEta2 * 1e-3, 1.0, true), V);
    EXPECT_LT(r.sinkage_m, sink) << V;
    EXPECT_GT(r.motion_resistance_N, rc) << V;
    sink = r.sinkage_m, rc = r.motion_resistance_N;
  }
  rc = 0;
  for (double eta2 : {10.0, 50.0, 200.0}) {
    const RigidWheelResult r = roll(kv_ground(eta2, 0.7, true), 1.0);
    EXPECT_GT(r.motion_resistance_N, rc) << eta2;
    rc = r.motion_resistance_N;
  }
}

}  // namespace
}  // namespace modaltyre::ground
