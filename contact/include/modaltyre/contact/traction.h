#pragma once
// Steady rolling at slip on a soil (docs/soil.md sections 5 and 9): drawbar pull, thrust, motion
// resistance, torque, sinkage and rut of the tyre (2D patch below; a footprint_3d model on the 3D
// patch, contact/src/traction3d.h: the same fixed point per column) or of the rigid cylinder of
// its outer radius (tyre.rigid: ground/rigid_wheel.h).
//
// Slip: driven s = 1 - V / (omega r) > 0, braked s = omega r / V - 1 < 0 (Wong's forms), r the
// slip's reference radius: the rolling radius r_e of the same tyre at the same load free-rolling
// on the rigid road (rolling_radius.h; ISTVS, the default), or the outer radius R0
// (SlipReference::unloaded). The rigid cylinder's r_e is its radius R0.
//
// The flexible tyre (2D patch, ground_patch.h) in steady rolling, as a fixed point:
//  1. Normal contact: the static problem on the soil, each unit's ground with the memory of the
//     ground ahead of it: a ground point under unit i has passed under every unit in front, so
//     its z_max is max(prior, max_{j ahead of i} z_j). Loading where the unit is the deepest so
//     far, the unloading branch behind (and the rut's reloading branch on a later pass).
//  2. Shear: j = sum (dl - (V / omega) cos(alpha) dtheta) along the units' deformed contour from
//     its front edge (dl its length, alpha its slope; contact/src/traction_kinematics.h: the
//     rigid wheel's j(theta) when the contour is the circle); tau_i from the ground's shear law
//     (shear.h) marched from the front;
//     horizontal force on unit i: tau_i b dx_i minus the normal force's horizontal component
//     f_i tan alpha_i (alpha_i the soil surface's slope under the unit); the shear's vertical
//     component tau_i b dx_i tan alpha_i shares the load.
//  3. The horizontal forces act on the carcass (seed 001's f_xi through H_tr, H_tt: the vertical
//     displacement they cause enters the gap, vertical_from_horizontal) and on the tread.
// Repeated until the sinkage profile, the drawbar pull and the load share settle.
// Resultants: thrust H = sum tau b dx, compaction resistance R_c = sum f tan alpha, the motion
// resistance R = R_c + the tyre's flexing loss + the soil's bulldozing, drawbar pull DP = H - R,
// torque T = sum (f_x h + f_z x) about the axle (h the axle's height above the
// point, x its position ahead of the axle); tractive efficiency DP V / (T omega) where the wheel
// is driven (T > 0) and pulls (DP > 0), else 0.
#include <map>
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/solve_status.h"
#include "modaltyre/ground/ground_settings.h"

namespace modaltyre::contact {

enum class SlipReference {
  rolling,   ///< r_e: the rolling radius on the rigid road at the same load (ISTVS)
  unloaded,  ///< R0: the outer radius
};

struct TractionCase {
  double load_N = 0;
  double slip = 0;           ///< in (-1, 1]
  double slip_radius_m = 0;  ///< the radius the slip is taken against (0: R0)
  /// The rolling radius r_e (rolling_radius.h; 0: unknown), which the slip sinkage's slip is
  /// taken against (ground/soil_options.h).
  double rolling_radius_m = 0;
};

/// V / (omega R0) at the case's slip and reference radius (R0 the outer radius).
double speed_ratio_over_R0(const TractionCase& c, double R0_m);

/// The case's slip against its rolling radius (ISTVS), the slip as given when r_e is unknown.
double rolling_radius_slip(const TractionCase& c, double R0_m);

struct TractionResult {
  SolveStatus status = SolveStatus::failed;
  std::string message;
  double load_N = 0, slip = 0;
  int pass = 1;
  double soil_sinkage_m = 0;  ///< deepest point below the undisturbed surface
  double rut_depth_m = 0;     ///< the track behind the tyre, unloaded
  double z_max_m = 0;         ///< the track's memory after this pass
  /// 3D patch: the track's memory per column after this pass (empty on the 2D patch).
  std::vector<double> column_z_max_m;
  double sinking_m = 0;  ///< axle approach to the undisturbed surface
  double tyre_deflection_m = 0;
  /// Drawbar pull DP = H - motion resistance, motion resistance = compaction + flexing +
  /// bulldozing (docs/soil.md section 5.4).
  double drawbar_pull_N = 0, thrust_N = 0, motion_resistance_N = 0, torque_Nm = 0;
  double compaction_resistance_N = 0;  ///< the soil's: sum f tan(alpha) (the rigid wheel's R_c)
  double flexing_resistance_N = 0;     ///< the tyre's hysteresis on the rigid road (0: rigid)
  double bulldozing_resistance_N = 0;  ///< the soil pushed ahead (ground.bekker.bulldozing)
  double entry_angle_rad = 0, exit_angle_rad = 0;  ///< contact edges seen from the axle
  double contact_length_m = 0, bekker_width_m = 0;
  double rolling_radius_m = 0;     ///< r_e at this load (rolling_radius.h; R0 for the rigid wheel)
  double loaded_radius_m = 0;      ///< R0 - the deflection on the rigid road at this load
  double slip_radius_m = 0;        ///< the radius the slip is taken against (r_e or R0)
  double tractive_efficiency = 0;  ///< DP V / (T omega) when T > 0 and DP > 0, else 0
  /// In the model's validity range on a soil (validity.h: the tyre's deflection, the contact's
  /// extent and the soil's sinkage each against its own range); the reason when not.
  bool valid = false;
  std::string validity;
  bool window_exceeded = false;  ///< failed: the contact reached the candidate window's edge
  double window_m = 0;           ///< the candidate window it ran on (contact.window_mm)
  int iterations = 0;
  /// Wong and Reece's rut behind theta2 extrapolated this many cell spacings behind the last rear
  /// cell, shorter than TractionOptions::wong_reece_exit_reach because the rolling did not settle
  /// with that (-1: the option's reach).
  double rut_reach_units = -1;
  bool ok() const { return modaltyre::ok(status); }
};

struct TractionOptions {
  bool rigid = false;  ///< the rigid cylinder of the outer radius (ground/rigid_wheel.h)
  int passes = 1;      ///< 1..20: each pass meets the previous pass's rut
  SlipReference slip_reference = SlipReference::rolling;
  /// Per load [N]: the tyre's own rolling resistance on the rigid road at the same load and
  /// speed, its flexing (hysteresis) loss (report/traction_flexing.h measures it with the
  /// transient's rolling scenario); a load not in the map: 0.
  std::map<double, double> flexing_resistance_N;
  /// Travel speed V [m/s]: the Kelvin-Voigt soil's rate term eta2 acts at dz/dt = V tan(theta)
  /// under the rigid wheel (ground/rigid_wheel.h, docs/soil.md section 3.2); 0: the elastic law.
  double speed_m_per_s = 0;
  int max_iterations = 200;
  /// Settled when a step changes the drawbar pull, the shear's load share and every unit's
  /// horizontal force by at most tolerance x load, Bekker's b by tolerance x width, and the
  /// sinkage profile by depth_tolerance x the sinkage (the figures printed, to 4-5 digits; the
  /// ground's memory makes the last digits of the profile creep at the patch's rear).
  double tolerance = 1e-5;
  double depth_tolerance = 1e-4;
  /// A run whose Anderson-mixed rolling orbits a limit cycle (contact/src/traction_cycle.h,
  /// docs/soil.md section 10) fails there, as it would at its last step, sooner (false), or goes
  /// on with plain steps, which settle on the cases met (true; it then rolls where it failed,
  /// and discover's fits, whose rows then roll in that corner, spend more time there).
  bool plain_steps_on_cycle = false;
  /// Wong and Reece's rear region on the flexible tyre (docs/soil.md section 10, "Mesh"): the rut
  /// the cells behind theta2 press is the depth profile extrapolated from the last rear cell
  /// towards theta2 by at most this many cell spacings (1: to theta2; 0: that cell's depth, an
  /// O(h) error). A case whose rolling does not settle with it is rolled again with 0.5 (the
  /// cell's own segment's edge), then 0, and says so (TractionResult::rut_reach_units).
  double wong_reece_exit_reach = 1;
};

/// Every case for passes 1..P, in the order case by case, pass by pass. A 2D model runs its
/// patch at its contact width; a model with footprint_3d runs the 3D patch (docs/soil.md
/// section 9; laterally rigid belt, no sidewall softening). `ground` must be a soil.
std::vector<TractionResult> steady_traction(const TyreModel& model,
                                            const ground::GroundSettings& ground,
                                            const std::vector<TractionCase>& cases,
                                            const TractionOptions& options = {});

/// steady_traction with the candidate window grown where the contact reaches its edge: the cases
/// whose rows report window_exceeded run again on a model rebuilt (on `modes`, the model's own)
/// with a window 1.5 times longer, up to max_window_m (footprint.h); a case still exceeding the
/// largest keeps its failed rows, their message saying how far the window grew. `modaltyre
/// traction` runs it; discover's traction rows keep the config's window (traction_evidence.cc).
std::vector<TractionResult> steady_traction_growing_window(const TyreModel& model,
                                                           const modal::ModeIdentification& modes,
                                                           const ground::GroundSettings& ground,
                                                           const std::vector<TractionCase>& cases,
                                                           const TractionOptions& options = {});

/// One pass of the flexible tyre on a track of memory prior_z_max_m (2D or 3D patch), its slip
/// against c.slip_radius_m (0: R0).
TractionResult traction_pass(const TyreModel& model, const ground::GroundSettings& ground,
                             const TractionCase& c, double prior_z_max_m,
                             const TractionOptions& options = {});

}  // namespace modaltyre::contact
