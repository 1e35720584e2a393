// The wheel state reduced to the wheel plane (fmu/wheel.h): the heading does not turn with the
// spin, a yawed wheel rolls along its yaw, velocities project, a drifted quaternion is
// normalised, and the plane load goes back to the world frame.
#include "modaltyre/fmu/wheel.h"

#include <gtest/gtest.h>

#include <cmath>

namespace modaltyre::fmu {
namespace {

std::array<double, 4> about(double angle, double x, double y, double z) {
  const double s = std::sin(angle / 2);
  return {std::cos(angle / 2), s * x, s * y, s * z};
}

/// q1 * q2 (Hamilton product, e0 scalar).
std::array<double, 4> times(const std::array<double, 4>& a, const std::array<double, 4>& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

TEST(FmuWheel, HeadingDoesNotTurnWithTheSpin) {
  for (double spin_angle : {0.0, 0.7, M_PI / 2, 2.5, M_PI, 4.0}) {
    WheelState s;
    s.rot = about(spin_angle, 0, 1, 0);
    s.pos = {3, 0, 0.28};
    s.lin_vel = {10, 0, -0.2};
    s.ang_vel = {0, 34, 0};
    PlaneState p;
    const char* why = nullptr;
    ASSERT_TRUE(plane_state(s, p, &why)) << spin_angle;
    EXPECT_NEAR(p.heading[0], 1, 1e-12);
    EXPECT_NEAR(p.heading[1], 0, 1e-12);
    EXPECT_NEAR(p.speed_m_s, 10, 1e-12);
    EXPECT_NEAR(p.vertical_m_s, -0.2, 1e-12);
    EXPECT_NEAR(p.spin_rad_s, 34, 1e-12);
    EXPECT_NEAR(p.x_m, 3, 1e-12);
  }
}

TEST(FmuWheel, YawedWheelRollsAlongItsHeading) {
  const double yaw = 0.6;
  WheelState s;
  s.rot = times(about(yaw, 0, 0, 1), about(1.3, 0, 1, 0));  // spun, then yawed
  s.lin_vel = {10 * std::cos(yaw), 10 * std::sin(yaw), 0};
  s.ang_vel = {-30 * std::sin(yaw), 30 * std::cos(yaw), 0};  // spin axis (-sin, cos, 0)
  PlaneState p;
  const char* why = nullptr;
  ASSERT_TRUE(plane_state(s, p, &why));
  EXPECT_NEAR(p.heading[0], std::cos(yaw), 1e-12);
  EXPECT_NEAR(p.heading[1], std::sin(yaw), 1e-12);
  EXPECT_NEAR(p.speed_m_s, 10, 1e-12);
  EXPECT_NEAR(p.spin_rad_s, 30, 1e-12);
  // The load back in the world frame: F_x along the heading, M_y about the spin axis.
  Vec3 force, moment;
  world_load(p, PlaneLoad{-500, 4000, 120}, force, moment);
  EXPECT_NEAR(force[0], -500 * std::cos(yaw), 1e-9);
  EXPECT_NEAR(force[1], -500 * std::sin(yaw), 1e-9);
  EXPECT_NEAR(force[2], 4000, 1e-9);
  EXPECT_NEAR(moment[0], -120 * std::sin(yaw), 1e-9);
  EXPECT_NEAR(moment[1], 120 * std::cos(yaw), 1e-9);
  EXPECT_NEAR(moment[2], 0, 1e-9);
}

TEST(FmuWheel, DriftedQuaternionIsNormalisedAndABadOneRefused) {
  WheelState s;
  s.rot = {1 + 2e-4, 0, 0, 0};  // |q|^2 = 1.0004: a host's drift
  s.ang_vel = {0, 20, 0};
  PlaneState p;
  const char* why = nullptr;
  ASSERT_TRUE(plane_state(s, p, &why));
  EXPECT_NEAR(p.spin_rad_s, 20, 1e-12);
  s.rot = {0.5, 0, 0, 0};
  EXPECT_FALSE(plane_state(s, p, &why));
  EXPECT_NE(std::string(why).find("unit quaternion"), std::string::npos);
  s.rot = about(M_PI / 2, 1, 0, 0);  // spin axis turned vertical
  EXPECT_FALSE(plane_state(s, p, &why));
  EXPECT_NE(std::string(why).find("vertical"), std::string::npos);
}

}  // namespace
}  // namespace modaltyre::fmu
