#pragma once
// The shear displacement along a rolling contact's deformed contour (docs/soil.md section 5.1),
// internal to the contact library: the 2D and 3D rolling fixed points (traction.cc,
// traction3d.cc) and the rolling radius (rolling_radius.cc) share it.
//
// In steady rolling the material point with reference angle theta sits at its deformed position
// P(theta) (the belt moved by the carcass, radially and tangentially, the tread tip by its
// spring; on a soil its surface) and theta falls at the wheel's rate omega. Between two points
// along the contour the tread therefore travels the contour's length dl = |dP| in the time
// dtheta / omega, while the ground, moving at V against the axle, travels V dtheta / omega =
// rho R0 dtheta (rho = V / (omega R0)), of which cos(alpha) lies along the contour (alpha its
// slope). The shear displacement from the front edge, positive where the tread moves backward
// relative to the ground (a driven wheel), is
//   j = sum (dl - rho R0 cos(alpha) dtheta).
// On the rigid wheel's circle (dl = R dtheta, alpha = theta) this is Wong's
// j = R [(theta1 - theta) - rho (sin theta1 - sin theta)]; in the flat patch j = dx - rho R0
// dtheta: a belt that keeps its length (the belt's tangential displacement makes dx = R0 dtheta)
// rolls freely at rho = 1, one whose flattened contour is shorter at rho < 1 (a rolling radius
// below R0).
#include <cmath>

namespace modaltyre::contact::detail {

class ContourSlip {
 public:
  /// Starts at the front edge: its position x [m] ahead of the axle, the contact's depth there
  /// below the undisturbed surface [m] and its reference angle [rad].
  ContourSlip(double R0_m, double rho, double x_m, double depth_m, double theta_rad)
      : R0_(R0_m), rho_(rho), x_(x_m), depth_(depth_m), theta_(theta_rad) {}
  /// Moves to the next contour point rearward and returns j there [m].
  double advance(double x_m, double depth_m, double theta_rad) {
    const double dx = x_ - x_m, dz = depth_m - depth_;
    const double dl = std::hypot(dx, dz);
    const double cos_alpha = dl > 0 ? dx / dl : 1.0;
    j_ += dl - rho_ * R0_ * cos_alpha * (theta_ - theta_rad);
    x_ = x_m, depth_ = depth_m, theta_ = theta_rad;
    return j_;
  }
  double displacement_m() const { return j_; }

 private:
  double R0_, rho_, x_, depth_, theta_;
  double j_ = 0;
};

}  // namespace modaltyre::contact::detail
