#pragma once
// The rigid wheel on soil, terramechanics' reference (Bekker 1956; Wong & Reece 1967; Wong,
// Theory of Ground Vehicles, 4th ed., 2008, section 2.7; docs/soil.md section 3).
//
// A rigid cylinder of radius R and width b_w, its lowest point z0 below the undisturbed surface.
// Angles theta from the downward vertical through the axle, positive forward. The wheel's
// surface at theta lies z(theta) = z0 - R (1 - cos theta) below the undisturbed surface.
// Normal stress sigma(theta) from the soil's normal law along the path of a ground point
// (pressure_sinkage.h): loading ahead of the lowest point while z exceeds the point's z_max,
// the unloading branch behind it (and on the reloading part of a rut). Contact from the entry
// angle theta1 (z = the incoming surface: 0, or the rut of a previous pass) to the exit angle
// theta2 <= 0 (z = the rebound depth; theta2 = 0 for a rigid-plastic soil).
//
// Shear: the shear displacement from the entry point (Wong & Reece)
//   j(theta) = R [(theta1 - theta) - (V / (omega R)) (sin theta1 - sin theta)],
// V / (omega R) = 1 - s for a driven wheel (s = 1 - V / (omega R) > 0), 1 / (1 + s) for a
// braked one (s = omega R / V - 1 < 0) (Wong's definitions, eq. 2.1, 2.2), advanced through the
// ground's shear law (shear.h) from entry to exit. Resultants per unit width b_w:
//   W  = b_w R int (sigma cos + tau sin) dtheta        (vertical load)
//   H  = b_w R int tau cos dtheta                      (thrust)
//   Rc = b_w R int sigma sin dtheta                    (motion (compaction) resistance)
//   DP = H - Rc,   T = b_w R^2 int tau dtheta          (drawbar pull, driving torque)
// Static (pressed, not rolling): the symmetric contact W = 2 b_w R int_0^theta1 sigma cos.
// Bekker's b = min(b_w, contact length): solved as a fixed point with the sinkage.
// With ground.bekker.wong_reece enabled the rolling wheel's normal stress is Wong and Reece's
// (soil_options.h): its peak at theta_m = (c1 + c2 s) theta1, the rear region the front's mirror,
// the rear angle theta2 = -c3 theta1.
#include <string>

#include "modaltyre/core/solve_status.h"
#include "modaltyre/ground/ground_settings.h"

namespace modaltyre::ground {

struct RigidWheel {
  double radius_m = 0.3;
  double width_m = 0.15;
};

struct RigidWheelResult {
  SolveStatus status = SolveStatus::failed;
  std::string message;
  double load_N = 0, slip = 0;
  double sinkage_m = 0;        ///< z0, the lowest point below the undisturbed surface
  double z_max_m = 0;          ///< the ground's memory after the wheel (per point of the track)
  double rut_depth_m = 0;      ///< the surface behind the wheel once unloaded
  double entry_angle_rad = 0;  ///< theta1
  double exit_angle_rad = 0;   ///< theta2 (<= 0 rolling; -theta1 static)
  double contact_length_m = 0;
  double bekker_width_m = 0;  ///< Bekker's b used
  double thrust_N = 0, motion_resistance_N = 0, drawbar_pull_N = 0, torque_Nm = 0;
  double vertical_N = 0;  ///< the integral W at the solution (= load to the tolerance)
  bool ok() const { return modaltyre::ok(status); }
};

/// The integrals at a given sinkage z0 (no equilibrium solve): for tests and the root search.
/// `prior_z_max_m`: the track's memory (0: virgin soil); `rolling` false: the static symmetric
/// contact (no shear); `wong_reece` enabled: Wong and Reece's normal stress while rolling
/// (soil_options.h; off: the front's loading stress and the memory's unloading branch behind the
/// lowest point).
RigidWheelResult rigid_wheel_at_sinkage(const PressureSinkage& law, const ShearLaw& shear,
                                        const RigidWheel& wheel, double sinkage_m, double slip,
                                        double prior_z_max_m, bool rolling,
                                        const WongReeceStress& wong_reece = {}, int panels = 48);

/// Static sinkage under `load_N`, pressed straight down onto soil of memory prior_z_max_m.
RigidWheelResult rigid_wheel_static(const GroundSettings& ground, const RigidWheel& wheel,
                                    double load_N, double prior_z_max_m = 0);

/// Steady rolling at slip s in (-1, 1] under `load_N` on a track of memory prior_z_max_m
/// (0: the first pass; a previous pass's z_max_m: the next).
RigidWheelResult rigid_wheel_rolling(const GroundSettings& ground, const RigidWheel& wheel,
                                     double load_N, double slip, double prior_z_max_m = 0);

/// V / (omega R) from Wong's slip (see the top of this file).
double speed_ratio(double slip);

}  // namespace modaltyre::ground
