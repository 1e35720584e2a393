#pragma once
// The tyre's rolling radius r_e: V / omega of the same tyre at the same load rolling freely
// (no longitudinal force) on the rigid flat road, the reference of slip as terramechanics defines
// it (ISTVS: s = 1 - V / (omega r_e) driven, omega r_e / V - 1 braked; docs/soil.md section 5.1).
//
// The static footprint on the road (the 2D patch, or a footprint_3d model's 3D patch) gives
// each contact point's deformed position (the belt moved by the carcass radially and
// tangentially, the tread tip by its spring); the shear displacement along the flat contour
// from the front edge is j = a - rho b, a = x_f - x the contour's length, b = R0 (theta_f -
// theta) the ground's travel (traction_kinematics.h). With the tread stuck to the road (the
// brush model's free rolling: Coulomb friction with the tread's stick stiffness k per unit area,
// tau = k j), the longitudinal force sum k A j vanishes at
//   rho_0 = sum A a / sum A b,     r_e = rho_0 R0.
// What this leaves out: sliding at the contact's edges (where mu sigma falls below k |j|) and the
// vertical displacement the free-rolling shear forces cause (they sum to zero).
#include <string>

#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/solve_status.h"

namespace modaltyre::contact {

struct RollingRadius {
  SolveStatus status = SolveStatus::failed;
  std::string message;
  double radius_m = 0;           ///< r_e
  double loaded_radius_m = 0;    ///< the axle's height above the road, R0 - deflection
  double deflection_m = 0;       ///< the tyre's deflection on the road at this load
  bool window_exceeded = false;  ///< failed: the contact reached the candidate window's edge
  bool ok() const { return modaltyre::ok(status); }
};

/// r_e at `load_N` on the rigid road (the model's 3D patch when it has footprint_3d, else its 2D
/// patch).
RollingRadius rolling_radius(const TyreModel& model, double load_N);

}  // namespace modaltyre::contact
