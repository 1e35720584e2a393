// The tangential contact of the FMU (fmu/longitudinal_contact.h) against the brush model's
// closed form: a parabolic pressure over the patch, steady rolling at a slip, the tread's
// stick-slip at mu sigma through ground::CoulombFriction.
#include "modaltyre/fmu/longitudinal_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace modaltyre::fmu {
namespace {

// A patch of 2a = 100 mm on 0.5 mm units, 4 kN, parabolic pressure; tread G / h = 1e8 Pa/m on
// a 130 mm width (c_px = 1.3e7 N/m^2); base radius 0.287 m; mu 0.8.
constexpr double kDs = 0.5e-3, kA = 0.05, kWidth = 0.13, kLoad = 4000, kK = 1e8, kMu = 0.8;
constexpr double kRb = 0.287, kSpeed = 10;
// The discrete patch matches the continuous brush to the unit's share of the patch (0.5 %); the
// steady state is reached when every element has crossed the patch several times.
constexpr double kBrushTolerance = 0.01;

struct Patch {
  int units = 0, lo = 0, hi = 0;
  std::vector<double> f;
};

Patch parabolic_patch() {
  Patch p;
  p.units = 2 * static_cast<int>(std::lround(0.1 / kDs));  // a window twice the patch
  p.lo = 0;
  p.hi = p.units - 1;
  p.f.assign(p.units, 0.0);
  double sum = 0;
  for (int i = 0; i < p.units; ++i) {
    const double x = (i - p.units / 2 + 0.5) * kDs;
    if (std::abs(x) < kA) p.f[i] = 1 - (x / kA) * (x / kA), sum += p.f[i];
  }
  for (double& v : p.f) v *= kLoad / sum;
  return p;
}

LongitudinalProperties props(double carcass_compliance) {
  LongitudinalProperties p;
  p.stick_stiffness_Pa_m = kK;
  p.unit_area_m2 = kWidth * kDs;
  p.unit_length_m = kDs;
  p.base_radius_m = kRb;
  p.carcass_compliance_m_N = carcass_compliance;
  return p;
}

/// Steady force at practical slip sigma = (Omega R_b - V) / (Omega R_b).
double steady_force(double sigma, double carcass_compliance) {
  const Patch p = parabolic_patch();
  LongitudinalContact c(props(carcass_compliance), p.lo, p.hi);
  const double spin = kSpeed / (kRb * (1 - sigma));
  const double dt = 1e-3;
  for (int k = 0; k < 200; ++k) c.advance(dt, p.f.data(), spin, kSpeed, kMu);  // 2 s: 20 m
  return c.force_N();
}

/// Pacejka's brush with a parabolic pressure (Tyre and Vehicle Dynamics, 3rd ed., eq. 3.16):
/// theta = 2 c_px a^2 / (3 mu Fz); F = mu Fz (3 theta s - 3 (theta s)^2 + (theta s)^3) for
/// theta |s| <= 1, mu Fz sign(s) beyond.
double brush(double sigma) {
  const double cpx = kK * kWidth;
  const double theta = 2 * cpx * kA * kA / (3 * kMu * kLoad);
  const double ts = theta * std::abs(sigma);
  const double F = ts >= 1 ? kMu * kLoad : kMu * kLoad * (3 * ts - 3 * ts * ts + ts * ts * ts);
  return std::copysign(F, sigma);
}

TEST(LongitudinalContact, SteadyForceFollowsTheBrushModelFromStickToFullSliding) {
  for (double sigma : {-0.3, -0.1, -0.04, -0.01, 0.005, 0.02, 0.08}) {
    const double F = steady_force(sigma, 0);
    EXPECT_NEAR(F, brush(sigma), kBrushTolerance * kMu * kLoad) << "sigma " << sigma;
  }
}

TEST(LongitudinalContact, SlipStiffnessIsTwoCpxASquared) {
  const double sigma = 1e-3;  // all in stick
  const double expected = 2 * kK * kWidth * kA * kA;
  EXPECT_NEAR(steady_force(sigma, 0) / sigma, expected, kBrushTolerance * expected);
}

TEST(LongitudinalContact, CarcassComplianceLeavesTheSteadyStateAndSlowsTheBuildUp) {
  // A uniform carcass displacement does not shear the tread once it is steady. The whole-unit
  // shifts of the sub-steps make F ripple by about one element's share (1 / 200 of the
  // patch), which the compliance turns into a ripple of u_x: the means agree to 1e-3.
  constexpr double kRippleTolerance = 1e-3;
  const double C = 5e-6;  // m/N, a soft belt
  const double rigid = steady_force(-0.05, 0);
  EXPECT_NEAR(steady_force(-0.05, C), rigid, kRippleTolerance * std::abs(rigid));
  // The build-up after a step in slip is slower with the compliance (relaxation length).
  const Patch p = parabolic_patch();
  LongitudinalContact stiff(props(0), p.lo, p.hi), soft(props(C), p.lo, p.hi);
  const double spin = kSpeed / (kRb * 1.01);
  for (int k = 0; k < 3; ++k) {
    stiff.advance(1e-3, p.f.data(), spin, kSpeed, kMu);
    soft.advance(1e-3, p.f.data(), spin, kSpeed, kMu);
  }
  EXPECT_LT(soft.force_N(), 0);
  EXPECT_GT(soft.force_N(), stiff.force_N());  // less braking force so far
  EXPECT_NEAR(soft.carcass_displacement_m(), C * soft.force_N(), 1e-12);
}

TEST(LongitudinalContact, NoForceWithoutSlipOrWithoutFriction) {
  EXPECT_NEAR(steady_force(0, 0), 0, 1e-9);
  const Patch p = parabolic_patch();
  LongitudinalContact c(props(0), p.lo, p.hi);
  for (int k = 0; k < 100; ++k) c.advance(1e-3, p.f.data(), 30, kSpeed, 0.0);
  EXPECT_EQ(c.force_N(), 0);
  EXPECT_EQ(c.sliding_share(), 1);
}

}  // namespace
}  // namespace modaltyre::fmu
