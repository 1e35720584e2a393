#include "modaltyre/fmu/wheel.h"

#include <cmath>

namespace modaltyre::fmu {
namespace {

/// Largest departure of |q|^2 from 1 accepted (and normalised away): a host integrating the
/// wheel's rotation drifts by far less; a quaternion off by more is not a rotation.
constexpr double kQuaternionTolerance = 1e-3;

}  // namespace

Vec3 rotate(const std::array<double, 4>& q, const Vec3& v) {
  // v' = v + 2 w (u x v) + 2 u x (u x v), u = (e1, e2, e3), w = e0.
  const double w = q[0], ux = q[1], uy = q[2], uz = q[3];
  const double cx = uy * v[2] - uz * v[1], cy = uz * v[0] - ux * v[2], cz = ux * v[1] - uy * v[0];
  const double ccx = uy * cz - uz * cy, ccy = uz * cx - ux * cz, ccz = ux * cy - uy * cx;
  return {v[0] + 2 * (w * cx + ccx), v[1] + 2 * (w * cy + ccy), v[2] + 2 * (w * cz + ccz)};
}

bool plane_state(const WheelState& s, PlaneState& out, const char** why) {
  const double norm2 =
      s.rot[0] * s.rot[0] + s.rot[1] * s.rot[1] + s.rot[2] * s.rot[2] + s.rot[3] * s.rot[3];
  if (!(std::abs(norm2 - 1) <= kQuaternionTolerance)) {
    *why = "wheel_state.rot is not a unit quaternion (|q|^2 off 1 by more than 1e-3)";
    return false;
  }
  // A host's integrated quaternion drifts from unit length: normalised here.
  const double n = std::sqrt(norm2);
  const std::array<double, 4> q{s.rot[0] / n, s.rot[1] / n, s.rot[2] / n, s.rot[3] / n};
  // The heading does not turn with the spin: it is the spin axis crossed with the vertical
  // (x = y x z in a right-handed frame), horizontal whatever the wheel's rotation angle.
  out.spin_axis = rotate(q, {0, 1, 0});
  const Vec3& a = out.spin_axis;
  const double hx = a[1], hy = -a[0];  // a x (0, 0, 1)
  const double h = std::hypot(hx, hy);
  if (!(h > 1e-6)) {
    *why = "the wheel's spin axis is vertical: the wheel plane has no heading";
    return false;
  }
  out.heading = {hx / h, hy / h, 0};
  out.x_m = s.pos[0] * out.heading[0] + s.pos[1] * out.heading[1];
  out.z_m = s.pos[2];
  out.speed_m_s = s.lin_vel[0] * out.heading[0] + s.lin_vel[1] * out.heading[1];
  out.vertical_m_s = s.lin_vel[2];
  out.spin_rad_s = s.ang_vel[0] * out.spin_axis[0] + s.ang_vel[1] * out.spin_axis[1] +
                   s.ang_vel[2] * out.spin_axis[2];
  return true;
}

void world_load(const PlaneState& p, const PlaneLoad& l, Vec3& force, Vec3& moment) {
  force = {l.fx_N * p.heading[0], l.fx_N * p.heading[1], l.fz_N};
  moment = {l.my_Nm * p.spin_axis[0], l.my_Nm * p.spin_axis[1], l.my_Nm * p.spin_axis[2]};
}

}  // namespace modaltyre::fmu
