#pragma once
// The wheel as the FMU sees it: the host's wheel state (world frame) reduced to the wheel
// plane, and the in-plane tyre forces turned back into a world-frame wheel load.
//
// Frames (ISO 8855, as Project Chrono): world x forward, y left, z up; the wheel frame's y is
// the spin axis. The quaternion (e0 scalar) turns wheel-frame vectors into world ones. The
// wheel plane's heading e_x is the wheel's x axis projected on the horizontal (the in-plane
// model has no camber or slip angle: it reads the state along e_x and the vertical only). The
// wheel frame turns with the spin about y, so e_x is taken as (spin axis) x (world z), which
// does not turn with it.
#include <array>

namespace modaltyre::fmu {

using Vec3 = std::array<double, 3>;

struct WheelState {
  Vec3 pos{0, 0, 0};
  std::array<double, 4> rot{1, 0, 0, 0};  ///< e0, e1, e2, e3
  Vec3 lin_vel{0, 0, 0};
  Vec3 ang_vel{0, 0, 0};
};

/// The state in the wheel plane.
struct PlaneState {
  Vec3 heading{1, 0, 0};    ///< e_x: horizontal, (spin axis) x z normalised
  Vec3 spin_axis{0, 1, 0};  ///< the wheel's y axis in the world frame
  double x_m = 0;           ///< position along the heading (pos . e_x)
  double z_m = 0;           ///< height of the wheel centre
  double speed_m_s = 0;     ///< forward speed lin_vel . e_x
  double vertical_m_s = 0;  ///< lin_vel.z
  double spin_rad_s = 0;    ///< ang_vel . spin_axis (forward rolling > 0)
};

/// Rotates v by the unit quaternion q = (e0, e1, e2, e3).
Vec3 rotate(const std::array<double, 4>& q, const Vec3& v);

/// The plane state of a wheel state (the quaternion normalised); false (and `why` set) when
/// |q|^2 is off 1 by more than 1e-3 or the spin axis is within 1e-6 of vertical (no heading).
bool plane_state(const WheelState& s, PlaneState& out, const char** why);

/// The in-plane forces on the wheel: longitudinal along the heading, vertical, and the moment
/// about the spin axis (the road's moment on the wheel about its centre).
struct PlaneLoad {
  double fx_N = 0, fz_N = 0, my_Nm = 0;
};

/// World-frame force and moment of a plane load.
void world_load(const PlaneState& p, const PlaneLoad& l, Vec3& force, Vec3& moment);

}  // namespace modaltyre::fmu
